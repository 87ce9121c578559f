# The codes' equivalent-linear displacement of a friction pendulum against the exact one (docs/studies.md):
# each code's D from the record's own 5 % spectrum beside the pendulum's exact peak displacement, on the
# planar study's station pairs (one job per chunk of pairs, each component alone and the pair in the plane)
# and on the three-component stations (one job: H1, H2 and the plane, without and with the vertical):
#   list_station_pairs (planar.smk), acquire_three_component (vertical.smk)
#   -> code_exact_pair_chunk (per chunk), code_exact_three_component
#   -> analyse_code_vs_exact (cases.csv, bias.csv, code_vs_exact.json) -> render_code_vs_exact_report, index.
# Without the three-component records that job writes an empty table and the page says how to get them.
from stickslip.studies.vertical.records import missing_message

CODE_EXACT = config["code_vs_exact"]
CODE_EXACT_DIR = "results/code_vs_exact"
CODE_EXACT_PAIRS_STEP = "stickslip.studies.code_vs_exact.cases:write_pair_chunk_cases"
CODE_EXACT_THREE_STEP = "stickslip.studies.code_vs_exact.cases:write_three_component_cases"
CODE_EXACT_ANALYSIS_STEP = "stickslip.studies.code_vs_exact.analysis:write_code_vs_exact_analysis"
CODE_EXACT_RESULTS = [f"{CODE_EXACT_DIR}/{name}" for name in ("cases.csv", "bias.csv", "code_vs_exact.json")]


rule code_exact_pair_chunk:
    """One chunk of station pairs: each code's D from the record's spectrum beside the exact one, per R and mu."""
    input:
        pairs_path=f"{PLANAR_DIR}/pairs.csv",
        store_paths=RECORD_STORES,
        library=library(CODE_EXACT_PAIRS_STEP),
    output:
        cases_path=f"{CODE_EXACT_DIR}/pairs/{{pair_chunk}}.csv",
    params:
        step=CODE_EXACT_PAIRS_STEP,
        chunk=lambda wildcards: wildcards.pair_chunk,
        radii=CODE_EXACT["radii"],
        mu=CODE_EXACT["mu"],
        periods=CODE_EXACT["spectrum_periods"],
        g=config["gravity"],
    threads: config.get("sweep_threads", 1)
    log:
        f"logs/code_vs_exact/pairs_{{pair_chunk}}.log",
    resources:
        mem_mb=2000,
        runtime=30,
    script:
        STEP


rule code_exact_three_component:
    """The three-component stations, without and with the vertical; an empty table without their records."""
    input:
        **({"store_path": f"{VERTICAL_DIR}/records.nc"} if VERTICAL_FILES else {}),
        library=library(CODE_EXACT_THREE_STEP),
    output:
        cases_path=f"{CODE_EXACT_DIR}/three_component.csv",
    params:
        step=CODE_EXACT_THREE_STEP,
        radii=CODE_EXACT["radii"],
        mu=CODE_EXACT["mu"],
        periods=CODE_EXACT["spectrum_periods"],
        g=config["gravity"],
        untold_positive=VERTICAL["untold_vertical_positive"],
    threads: config.get("sweep_threads", 1)
    log:
        "logs/code_vs_exact/three_component.log",
    script:
        STEP


rule analyse_code_vs_exact:
    """Bias and sigma of ln(D_exact/D_code) per code and grouping, the unconservative share, the closest code."""
    input:
        case_paths=[*expand(f"{CODE_EXACT_DIR}/pairs/{{pair_chunk}}.csv", pair_chunk=PAIR_CHUNKS),
                    f"{CODE_EXACT_DIR}/three_component.csv"],
        pairs_path=f"{PLANAR_DIR}/pairs.csv",
        library=library(CODE_EXACT_ANALYSIS_STEP),
    output:
        cases_path=CODE_EXACT_RESULTS[0],
        bias_path=CODE_EXACT_RESULTS[1],
        summary_path=CODE_EXACT_RESULTS[2],
    params:
        step=CODE_EXACT_ANALYSIS_STEP,
        near_fault_km=STUDY_CONFIG["near_fault_km"],
        d_over_r_edges=CODE_EXACT["d_over_r_edges"],
        unconservative_factor=CODE_EXACT["unconservative_factor"],
        radii=CODE_EXACT["radii"],
        mu=CODE_EXACT["mu"],
        three_component_message="" if VERTICAL_FILES else missing_message(VERTICAL_RECORDS_DIR),
    log:
        "logs/code_vs_exact/analysis.log",
    script:
        STEP


report_page(
    "code_vs_exact",
    rank=95,
    rule_name="render_code_vs_exact_report",
    title="The codes' equivalent-linear displacement against the exact one",
    notebook="notebooks/code_vs_exact.ipynb",
    inputs={"tables": CODE_EXACT_RESULTS},
    parameters={"results_dir": "results"},
    figures_dir="code_vs_exact",
    figures={"ratio_vs_d_over_r.png": "ln(D_exact/D_code) against D_code/R, one colour per code, one direction "
                                      "and the plane side by side",
             "ratio_cdf.png": "Cumulative distribution of D_exact/D_code per code, the 1.2 line of the "
                              "unconservative share marked",
             "bias_by_group.png": "Bias and sigma of ln(D_exact/D_code) per code against R, mu and D_code/R"},
    category="Codes against the exact answer",
    caption="code_vs_exact.rst",
    index_section=("stickslip.studies.code_vs_exact.index:code_exact_section_html",
                   {"bias_path": CODE_EXACT_RESULTS[1], "summary_path": CODE_EXACT_RESULTS[2],
                    "page": "reports/html/code_vs_exact.html"}),
    index_inputs=CODE_EXACT_RESULTS[1:],
)
