# The paper's question with a structure (docs/studies.md): a flat friction damper on a one-story building, on the
# paper's stored records (one job) and the collection study's records (one job per chunk), at every mass ratio,
# structure period T and mu, with the exact solver; the mu of most E_df (the paper's mu_max) against the mu of least
# drift, and the drift reduction the first gives up:
#   acquire_record (records.smk), store_collection_chunk (collections.smk)
#   -> damper_paper_records, damper_collection_chunk (per chunk), each per period -> gather_damper_study (damper.nc)
#   -> tabulate_damper_study -> render_damper_report, index.
DAMPER = config["damper_study"]
DAMPER_DIR = "results/damper"
DAMPER_PAPER_STEP = "stickslip.studies.damper.sweep:write_paper_cube"
DAMPER_CHUNK_STEP = "stickslip.studies.damper.sweep:write_collection_chunk_cube"
DAMPER_GATHER_STEP = "stickslip.studies.damper.sweep:gather_damper_study"
DAMPER_TABLES_STEP = "stickslip.studies.damper.tables:write_damper_tables"
DAMPER_RESULTS = [f"{DAMPER_DIR}/{name}" for name in ("damper_cases.csv", "damper_summary.csv", "damper_curves.csv",
                                                      "damper_study.json")]
#: The study's settings, as its steps take them.
DAMPER_SETTINGS = {key: DAMPER[key] for key in ("mass_ratios", "periods", "levels", "damping_ratio")}
#: One job per set of records and period, so that two cores share the work evenly.
DAMPER_PERIODS = [f"{period:g}" for period in DAMPER["periods"]]


wildcard_constraints:
    period="[0-9.]+",


rule damper_paper_records:
    """The paper's stored records (a missing one named with its reason) at one period, every mass ratio and level."""
    input:
        record_paths=expand("results/records/{record}.nc", record=PAPER_RECORDS),
        library=library(DAMPER_PAPER_STEP),
    output:
        cube_path=f"{DAMPER_DIR}/paper/{{period}}.nc",
    params:
        step=DAMPER_PAPER_STEP,
        settings=DAMPER_SETTINGS,
        period=lambda wildcards: float(wildcards.period),
        g=config["gravity"],
    log:
        "logs/damper/paper_{period}.log",
    script:
        STEP


rule damper_collection_chunk:
    """One chunk of the collection study's records at one period, every mass ratio and level."""
    input:
        store_path=f"{STUDY_DIR}/records/{{chunk}}.nc",
        library=library(DAMPER_CHUNK_STEP),
    output:
        cube_path=f"{DAMPER_DIR}/{STUDY}/{{chunk}}/{{period}}.nc",
    params:
        step=DAMPER_CHUNK_STEP,
        collection=STUDY,
        settings=DAMPER_SETTINGS,
        period=lambda wildcards: float(wildcards.period),
        g=config["gravity"],
    threads: config.get("sweep_threads", 1)
    log:
        f"logs/damper/{STUDY}_{{chunk}}_{{period}}.log",
    resources:
        mem_mb=1000,
        runtime=30,
    script:
        STEP


rule gather_damper_study:
    input:
        # the periods of one set of records together, in the order of the configuration
        cube_paths=[*expand(f"{DAMPER_DIR}/paper/{{period}}.nc", period=DAMPER_PERIODS),
                    *[path for chunk in STUDY_CHUNKS
                      for path in expand(f"{DAMPER_DIR}/{STUDY}/{chunk}/{{period}}.nc", period=DAMPER_PERIODS)]],
        library=library(DAMPER_GATHER_STEP),
    output:
        study_path=f"{DAMPER_DIR}/damper.nc",
    params:
        step=DAMPER_GATHER_STEP,
        periods=len(DAMPER_PERIODS),
    log:
        "logs/damper/gather.log",
    script:
        STEP


rule tabulate_damper_study:
    """Per record, mass ratio and T the two optima; their median and 84th percentile over the records."""
    input:
        study_cube_path=f"{DAMPER_DIR}/damper.nc",
        library=library(DAMPER_TABLES_STEP),
    output:
        cases_path=DAMPER_RESULTS[0],
        summary_path=DAMPER_RESULTS[1],
        curves_path=DAMPER_RESULTS[2],
        study_path=DAMPER_RESULTS[3],
    params:
        step=DAMPER_TABLES_STEP,
        settings=DAMPER_SETTINGS,
        collection=STUDY,
    log:
        "logs/damper/tables.log",
    script:
        STEP


report_page(
    "damper_study",
    rank=97,
    rule_name="render_damper_report",
    title="The paper's question with a structure: a friction damper on a building",
    notebook="notebooks/damper_study.ipynb",
    inputs={"tables": DAMPER_RESULTS},
    parameters={"results_dir": "results"},
    figures_dir="damper",
    figures={"damper_mu_scatter.png": "The mu of most energy dissipated against the mu of least drift, per record, "
                                      "mass ratio and period, coloured by the period",
             "damper_given_up.png": "The drift reduction the paper's mu gives up, and mu_Edf over mu_drift, against "
                                    "the period: median and 84th percentile per mass ratio",
             "damper_drift_reduction.png": "Drift reduction against the friction level mu g over the bare floor's "
                                           "peak acceleration, at the middle mass ratio, one line per period: median "
                                           "and 16-84 % band"},
    category="Damper on a structure",
    caption="damper_study.rst",
    index_section=("stickslip.studies.damper.index:damper_section_html",
                   {"study_path": DAMPER_RESULTS[3], "page": "reports/html/damper_study.html"}),
    index_inputs=[DAMPER_RESULTS[3]],
)
