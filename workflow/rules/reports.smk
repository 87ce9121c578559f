# Reports: executed notebooks, PNG figures and reports/index.html.
# Notebooks run with papermill from a shell rule (Snakemake's notebook:
# directive cannot declare the executed notebook as an output).  They only
# load what the workflow wrote and draw; see docs/reports.md.

REPORT_RECORDS = config.get("report_records", [])
PAPER_FIGURES = [
    "fig17_records.png",
    *[f"fig{18 + k}_timestep.png" for k in range(len(config["timestep_study"]["mus"]))],
    "fig21_energy_vs_mu.png",
    "fig22_mu_max_vs_pga.png",
    "fig23_mu_max_vs_rms.png",
    "fig24_scaling_mu_max_vs_pga.png",
    "fig25_scaling_mu_max_vs_rms.png",
]
RECORD_FIGURES = ["acceleration", "energy_vs_mu", "response"]
COMPARED_TABLES = ["table4", "table5", "table6", "table7", "table8"]


rule paper_figures:
    """The paper's Figs. 17-25 and the comparison tables, from results/ only."""
    input:
        notebook="notebooks/paper_figures.ipynb",
        code=PACKAGE_SOURCES,
        records="results/records",
        table5="results/tables/table5_records.csv",
        grid="results/sweeps/paper_grid.nc",
        fine="results/sweeps/paper_fine.nc",
        fits="results/fits.json",
        table8="results/tables/table8_results.csv",
        timestep=f"results/sweeps/timestep_{TIMESTEP_RECORD}.nc",
        comparisons=expand(
            "results/tables/{table}_comparison.csv", table=COMPARED_TABLES
        ),
    output:
        notebook="reports/paper_figures.ipynb",
        figures=expand("reports/figures/{name}", name=PAPER_FIGURES),
    params:
        figures_dir=lambda wildcards, output: Path(output.figures[0]).parent,
        timestep_record=TIMESTEP_RECORD,
    log:
        "logs/reports/paper_figures.log",
    shell:
        "MPLBACKEND=Agg papermill -k python3 --log-output {input.notebook} {output.notebook}"
        " -p results_dir results -p figures_dir {params.figures_dir}"
        " -p timestep_record {params.timestep_record} > {log} 2>&1"


rule record_report:
    """notebooks/record_report.ipynb rendered for one available paper record."""
    input:
        notebook="notebooks/record_report.ipynb",
        code=PACKAGE_SOURCES,
        records="results/records",
    output:
        notebook="reports/records/{record_id}.ipynb",
        figures=expand(
            "reports/figures/records/{{record_id}}_{name}.png", name=RECORD_FIGURES
        ),
    params:
        figures_dir=lambda wildcards, output: Path(output.figures[0]).parent,
        mass=config["block_mass"],
    log:
        "logs/reports/record_{record_id}.log",
    shell:
        "MPLBACKEND=Agg papermill -k python3 --log-output {input.notebook} {output.notebook}"
        " -p record {input.records}/{wildcards.record_id}.nc -p mass {params.mass}"
        " -p figures_dir {params.figures_dir} > {log} 2>&1"


rule report_index:
    """reports/index.html: links to the notebooks and figures, our values beside the paper's."""
    input:
        "reports/paper_figures.ipynb",
        expand("reports/records/{record_id}.ipynb", record_id=REPORT_RECORDS),
        comparisons=expand(
            "results/tables/{table}_comparison.csv", table=COMPARED_TABLES
        ),
        code=PACKAGE_SOURCES,
    output:
        "reports/index.html",
    log:
        "logs/reports/index.log",
    shell:
        "python -m stickslip.report_index --results results --reports reports --out {output} > {log} 2>&1"
