# Reports: executed notebooks (papermill), their HTML pages (nbconvert, code
# cells hidden: the executed notebooks beside them keep the code), PNG figures
# and reports/index.html.  Notebooks run from shell rules (Snakemake's
# notebook: directive cannot declare the executed notebook as an output); they
# only load what the workflow wrote and draw (docs/reports.md).  Each executed
# notebook is written under a temporary name and renamed when complete.
PAPER_NOTEBOOK = str(PROJECT / "notebooks" / "paper_figures.ipynb")
#: The record report ships with the package (notebooks/record_report.ipynb links to it).
RECORD_NOTEBOOK = str(PROJECT / "src" / "stickslip" / "reports" / "notebooks" / "record_report.ipynb")
TIMESTEP_MUS = config["timestep_study"]["mus"]
PAPER_FIGURES = [
    "fig17_records.png",
    *[f"fig{18 + k}_timestep.png" for k in range(len(TIMESTEP_MUS))],
    "fig21_energy_vs_mu.png",
    "fig22_mu_max_vs_pga.png",
    "fig23_mu_max_vs_rms.png",
    "fig24_scaling_mu_max_vs_pga.png",
    "fig25_scaling_mu_max_vs_rms.png",
]
MODEL_NOTEBOOK = str(PROJECT / "notebooks" / "model_figures.ipynb")
MODEL_FIGURES = [
    "fig2_harmonic_regimes.png",
    "fig3_algorithm1_substitute.png",
    "fig16_friction_kobe.png",
    "fig16_friction_harmonic.png",
    "fig11_12_energy_kobe.png",
    "fig11_12_energy_harmonic.png",
]
RECORD_FIGURES = ["energy_vs_mu", "displacement_vs_mu", "acceleration", "response"]
COMPARISONS = expand("results/tables/{table}_comparison.csv", table=["table4", "table5", "table6", "table7", "table8"])
#: The single solved cases' tables (notebooks/model_figures.ipynb and the index show them).
MODEL_TABLES = expand("results/tables/{table}.csv", table=["table3_table4_model", "table3_comparison",
                                                           "table4_records_comparison", "errata", "paper_fits"])
INDEX_STEP = "stickslip.reports.index_page:write_index"
#: An executed notebook as a page without its code (the notebook in reports/ keeps it).
PAGE_STEP = "stickslip.reports.notebook_page:write_notebook_page"
PAGE_TEMPLATE = str(PROJECT / "src" / "stickslip" / "reports" / "templates" / "offline.html.j2")


rule render_paper_figures:
    """The paper's Figs. 17-25 and the comparison tables, from results/ only."""
    input:
        notebook=PAPER_NOTEBOOK,
        library=library_sources(files=[PAPER_NOTEBOOK]),
        records=expand("results/records/{record}.nc", record=PAPER_RECORDS),
        tables=["results/tables/table5_records.csv", "results/tables/table8_results.csv"],
        sweeps=["results/sweeps/paper.nc", "results/sweeps/fine.nc", f"results/sweeps/timestep_{TIMESTEP_RECORD}.nc"],
        fits="results/fits.json",
        comparisons=COMPARISONS,
    output:
        notebook="reports/paper_figures.ipynb",
        figures=[report(f"reports/figures/{name}", category="Figures of the paper",
                        caption="../report/paper_figures.rst") for name in PAPER_FIGURES],
    params:
        figures_dir=figures_folder,
        timestep_record=TIMESTEP_RECORD,
        timestep_figures=len(TIMESTEP_MUS),
    log:
        "logs/reports/paper_figures.log",
    shell:
        papermill_shell(
            "-p results_dir results -p figures_dir {params.figures_dir}"
            " -p timestep_record {params.timestep_record}"
            " -p timestep_figures {params.timestep_figures}"
        )


rule render_model_figures:
    """The paper's Figs. 2, 3 (substitute), 11-12 (model) and 16, Tables 3-4 model, errata and fits, from results/ only."""
    input:
        notebook=MODEL_NOTEBOOK,
        library=library_sources(files=[MODEL_NOTEBOOK]),
        responses=expand("results/model/{case}.nc", case=MODEL_CASES),
        tables=MODEL_TABLES,
    output:
        notebook="reports/model_figures.ipynb",
        figures=[report(f"reports/figures/{name}", category="Figures of the paper",
                        caption="../report/model_figures.rst") for name in MODEL_FIGURES],
    params:
        figures_dir=figures_folder,
        fig3_reason=config["model_response"]["fig3"]["reason"],
    log:
        "logs/reports/model_figures.log",
    shell:
        papermill_shell(
            "-p results_dir results -p figures_dir {params.figures_dir}"
            " -p fig3_reason {params.fig3_reason:q}"
        )


rule render_record_report:
    """notebooks/record_report.ipynb rendered for one record, from its stored record and fine-grid sweep."""
    input:
        notebook=RECORD_NOTEBOOK,
        library=library_sources(files=[RECORD_NOTEBOOK]),
        record="results/records/{record}.nc",
        sweep="results/sweeps/fine/{record}.nc",
    output:
        notebook="reports/records/{record}.ipynb",
        figures=[report(f"reports/figures/records/{{record}}_{name}.png", category="Record reports",
                        subcategory="{record}", caption="../report/record_report.rst") for name in RECORD_FIGURES],
    params:
        output_dir=lambda wildcards, output: str(Path(output.notebook).parent),
        figures_dir=figures_folder,
        mass=config["block_mass"],
        g=config["gravity"],
        q=config["mu_max"]["near_optimal_fraction"],
        mu=config["fine_mu"],
    log:
        "logs/reports/record_{record}.log",
    shell:
        papermill_shell(
            "-p record {input.record} -p sweep {input.sweep} -p mass {params.mass} -p g {params.g}"
            " -p near_optimal_fraction {params.q} -p mu_start {params.mu[start]}"
            " -p mu_stop {params.mu[stop]} -p mu_step {params.mu[step]}"
            " -p output_dir {params.output_dir} -p figures_dir {params.figures_dir}"
        )


rule convert_notebook_html:
    """An executed notebook as an HTML page without its code (the links of index.html open as pages)."""
    input:
        PAGE_TEMPLATE,
        notebook_path="reports/{notebook}.ipynb",
        library=library(PAGE_STEP),
    output:
        html_path="reports/html/{notebook}.html",
    params:
        step=PAGE_STEP,
    log:
        "logs/reports/html/{notebook}.log",
    script:
        STEP


rule write_report_index:
    """reports/index.html: status of the records, links to the pages and figures, our values beside the paper's."""
    input:
        "reports/html/paper_figures.html",
        "reports/html/model_figures.html",
        expand("reports/html/records/{record}.html", record=REPORT_RECORDS),
        COMPARISONS,
        "reports/html/collection_study.html",
        multiext(f"{STUDY_DIR}/", "records.csv", "claims.csv", "coverage.csv", "measures_check.json"),
        MODEL_TABLES,
        "results/tables/table8_results.csv",
        VERIFICATION_INDEX_INPUTS,  # the verification against SLAMMER (workflow/rules/verification.smk)
        JIBSON_RESULTS,  # Jibson (2007), recomputed (workflow/rules/jibson2007.smk), and its page
        JIBSON_PAGE,
        measures_paths=expand("results/measures/{record}.json", record=ALL_RECORDS),
        library=library(INDEX_STEP),
    output:
        index_path="reports/index.html",
    params:
        step=INDEX_STEP,
        studies={
            "Tables 5-7, Figs. 17 and 21-23 (the paper's records)": PAPER_RECORDS,
            "Table 8, Figs. 24-25 (scaling study)": SCALING_RECORDS,
            "Figs. 18-20 (time-step study)": [TIMESTEP_RECORD],
            "Mass check": MASS_RECORDS,
            "Record reports": REPORT_RECORDS,
            "Fig. 3 (substitute record)": [FIG3_RECORD],
            "Tables 3-4 seismic rows, Figs. 11-12 and 16 (Kobe x 0.65)": [SEISMIC_RECORD],
        },
        collection={"study_dir": STUDY_DIR, "figures_dir": "reports/figures/collection",
                    "page": "reports/html/collection_study.html", "not_here": len(STUDY_NOT_HERE),
                    "min_records": STUDY_CONFIG["min_records"]},
        verification=VERIFICATION_INDEX,
        jibson=JIBSON_INDEX,
    log:
        "logs/reports/index.log",
    script:
        STEP
