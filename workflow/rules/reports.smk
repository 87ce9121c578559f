# Reports: executed notebooks (papermill), their HTML pages (nbconvert, code
# cells hidden: the executed notebooks beside them keep the code), PNG figures
# and reports/index.html.  Notebooks run from shell rules (Snakemake's
# notebook: directive cannot declare the executed notebook as an output); they
# only load what the workflow wrote and draw (docs/reports.md).  Each executed
# notebook is written under a temporary name and renamed when complete.
TIMESTEP_MUS = config["timestep_study"]["mus"]
COMPARISONS = expand("results/tables/{table}_comparison.csv", table=["table4", "table5", "table6", "table7", "table8"])
#: The single solved cases' tables (notebooks/model_figures.ipynb and the index show them).
MODEL_TABLES = expand("results/tables/{table}.csv", table=["table3_table4_model", "table3_comparison",
                                                           "table4_records_comparison", "errata", "paper_fits"])
from stickslip.reports.record_report import FIGURES as RECORD_REPORT_FIGURES

INDEX_STEP = "stickslip.reports.index_page:write_index"
#: An executed notebook as a page without its code (the notebook in reports/ keeps it).
PAGE_STEP = "stickslip.reports.notebook_page:write_notebook_page"
PAGE_TEMPLATE = str(PROJECT / "src" / "stickslip" / "reports" / "templates" / "offline.html.j2")

# The paper's Figs. 17-25 and the comparison tables, from results/ only.
report_page(
    "paper_figures",
    rank=10,
    rule_name="render_paper_figures",
    title="The paper's Figs. 17-25",
    notebook="notebooks/paper_figures.ipynb",
    inputs={"records": expand("results/records/{record}.nc", record=PAPER_RECORDS),
            "tables": ["results/tables/table5_records.csv", "results/tables/table8_results.csv"],
            "sweeps": ["results/sweeps/paper.nc", "results/sweeps/fine.nc",
                       f"results/sweeps/timestep_{TIMESTEP_RECORD}.nc"],
            "fits": "results/fits.json", "comparisons": COMPARISONS},
    parameters={"results_dir": "results", "timestep_record": TIMESTEP_RECORD, "timestep_figures": len(TIMESTEP_MUS)},
    figures_dir="",
    figures={"fig17_records.png": "The paper's records: ground acceleration against time, significant duration in red",
             **{f"fig{18 + k}_timestep.png": f"Time-step study on {TIMESTEP_RECORD} at mu = {mu:g}: the block's "
                f"response with each time step (the paper's Fig. {18 + k})" for k, mu in enumerate(TIMESTEP_MUS)},
             "fig21_energy_vs_mu.png": "Energy dissipated by friction against mu for each paper record",
             "fig22_mu_max_vs_pga.png": "mu_max against PGA with the fitted line (the paper's Fig. 22)",
             "fig23_mu_max_vs_rms.png": "mu_max against RMS acceleration with the fitted line (the paper's Fig. 23)",
             "fig24_scaling_mu_max_vs_pga.png": "mu_max of the scaled records against PGA (the paper's Fig. 24)",
             "fig25_scaling_mu_max_vs_rms.png": "mu_max of the scaled records against RMS acceleration (Fig. 25)"},
    category="Figures of the paper",
    caption="paper_figures.rst",
)

# The paper's Figs. 2, 3 (substitute), 11-12 (model) and 16, Tables 3-4 model, errata and fits, from results/ only.
report_page(
    "model_figures",
    rank=20,
    rule_name="render_model_figures",
    title="The paper's model figures (Figs. 2, 3, 11-12, 16)",
    notebook="notebooks/model_figures.ipynb",
    inputs={"responses": expand("results/model/{case}.nc", case=MODEL_CASES),
            "flexible": expand("results/model/flexible_{model}.nc", model=["decoupled", "coupled"]),
            "tables": MODEL_TABLES},
    parameters={"results_dir": "results", "fig3_reason": config["model_response"]["fig3"]["reason"]},
    figures_dir="",
    figures={"fig2_harmonic_regimes.png": "Harmonic base motion: stick-slip and permanent slip (the paper's Fig. 2)",
             "fig3_algorithm1_substitute.png": "Algorithm 1 beside the exact solution on a substitute record (Fig. 3)",
             "fig16_friction_kobe.png": "Friction force and relative velocity against time, Kobe KJMA 090 x 0.65",
             "fig16_friction_harmonic.png": "Friction force and relative velocity against time, harmonic base motion",
             "fig11_12_energy_kobe.png": "Energy histories E_I, E_k and E_df, Kobe KJMA 090 x 0.65",
             "fig11_12_energy_harmonic.png": "Energy histories E_I, E_k and E_df, harmonic base motion",
             "flexible_ledger_kobe.png": "Energy ledger per unit mass of a soil layer sliding on Kobe KJMA 090 x 0.65, "
                                         "decoupled beside coupled (beyond the paper)"},
    category="Figures of the paper",
    caption="model_figures.rst",
)

# The record report (package data; notebooks/record_report.ipynb links to it), once per record, from its
# stored record and fine-grid sweep.
report_page(
    "records/{record}",
    rank=30,
    rule_name="render_record_report",
    title="Record reports",
    notebook="src/stickslip/reports/notebooks/record_report.ipynb",
    inputs={"record": "results/records/{record}.nc", "sweep": "results/sweeps/fine/{record}.nc"},
    parameters={"record": lambda wildcards, input, output: input.record,
                "sweep": lambda wildcards, input, output: input.sweep,
                "output_dir": lambda wildcards, input, output: str(Path(output.notebook).parent),
                "mass": config["block_mass"], "g": config["gravity"],
                "near_optimal_fraction": config["mu_max"]["near_optimal_fraction"],
                "mu_start": config["fine_mu"]["start"], "mu_stop": config["fine_mu"]["stop"],
                "mu_step": config["fine_mu"]["step"]},
    figures_dir="records",
    figures={f"{{record}}_{name}.png": alt for name, alt in RECORD_REPORT_FIGURES.items()},  # as the CLI's report
    category="Record reports",
    caption="record_report.rst",
    each={"record": REPORT_RECORDS},
)


# One rendering rule per declared page, the papermill command written once (PAPERMILL_SHELL, common.smk).
for page_name, page in report_pages():
    if not page["rendered"]:
        continue

    rule:
        name:
            page["rule"]
        input:
            notebook=page["notebook"],
            library=library_sources(files=[page["notebook"]]),
            **page["inputs"],
        output:
            notebook=f"reports/{page_name}.ipynb",
            figures=[report(figure, category=page["category"], caption=page["caption"],
                            subcategory=page["subcategory"])
                     for figure in page["figures"]],
        params:
            parameters=page_parameters(page),
        log:
            f"logs/reports/{page_name}.log",
        shell:
            PAPERMILL_SHELL

REPORT_RULES_MADE = True


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
    """reports/index.html: status of the records, links to the pages and figures, our values beside the paper's,
    then each declared page's section (report_page's index_section), in the order of the pages' ranks."""
    input:
        [page_html(name) for name, _ in report_pages()],
        [page["index_inputs"] for _, page in report_pages()],
        COMPARISONS,
        MODEL_TABLES,
        "results/tables/table8_results.csv",
        measures_paths=expand("results/measures/{record}.json", record=ALL_RECORDS),
        library=library_sources([INDEX_STEP] + [page["index_section"][0] for _, page in report_pages()
                                                if page["index_section"]]),
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
        sections=[list(page["index_section"]) for _, page in report_pages() if page["index_section"]],
        figure_alts=figure_alts(),
    log:
        "logs/reports/index.log",
    script:
        STEP
