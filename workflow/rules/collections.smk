# The many-record study on a record collection (docs/collections.md), in the
# same direction as the paper's part, one job per chunk of records:
#   store_collection_chunk (read, check, store) -> measure_collection_chunk
#   -> sweep_collection_chunk -> gather_collection_study (study.nc, records.csv, skipped.csv)
#   -> measures check against SLAMMER's database, relations, coverage,
#      claims, design chart, scaling law -> notebook and index section.
# Which records: the configured collection, filtered, that are here (or, with
# download, all of them), in chunks of collection_study.chunk_size.

# The study's steps, in stickslip.studies.collections.
STORE_STEP = "stickslip.studies.collections.records:store_chunk"
CHUNK_MEASURES_STEP = "stickslip.studies.collections.measures:write_chunk_measures"
CHUNK_SWEEP_STEP = "stickslip.studies.collections.sweep:write_chunk_sweep"
STUDY_GATHER_STEP = "stickslip.studies.collections.sweep:gather_study"
CHECK_STEP = "stickslip.studies.collections.measures_check:write_measures_check"
ANALYSIS_STEP = "stickslip.studies.collections.analysis:write_collection_analysis"
SCALING_LAW_STEP = "stickslip.studies.collections.scaling_law:write_scaling_law"


wildcard_constraints:
    chunk="[0-9]+",


rule store_collection_chunk:
    input:
        chunk_files,
        library=library(STORE_STEP),
    output:
        store_path=f"{STUDY_DIR}/records/{{chunk}}.nc",
    params:
        step=STORE_STEP,
        ids=chunk_ids,
        collection=COLLECTION,
        g=config["gravity"],
    log:
        f"logs/collections/{STUDY}/records_{{chunk}}.log",
    resources:
        mem_mb=1000,
        runtime=10,
    script:
        STEP


rule measure_collection_chunk:
    input:
        store_path=f"{STUDY_DIR}/records/{{chunk}}.nc",
        library=library(CHUNK_MEASURES_STEP),
    output:
        measures_path=f"{STUDY_DIR}/measures/{{chunk}}.csv",
    params:
        step=CHUNK_MEASURES_STEP,
        g=config["gravity"],
    log:
        f"logs/collections/{STUDY}/measures_{{chunk}}.log",
    script:
        STEP


rule sweep_collection_chunk:
    input:
        store_path=f"{STUDY_DIR}/records/{{chunk}}.nc",
        measures_path=f"{STUDY_DIR}/measures/{{chunk}}.csv",
        library=library(CHUNK_SWEEP_STEP),
    output:
        cube_path=f"{STUDY_DIR}/sweeps/{{chunk}}.nc",
    params:
        step=CHUNK_SWEEP_STEP,
        mu=STUDY_CONFIG["mu"],
        mass=config["block_mass"],
        g=config["gravity"],
        near_optimal_fraction=config["mu_max"]["near_optimal_fraction"],
        reference_mu=STUDY_CONFIG["reference_mu"],
    threads: config.get("sweep_threads", 1)
    log:
        f"logs/collections/{STUDY}/sweep_{{chunk}}.log",
    resources:
        mem_mb=2000,
        runtime=30,
    script:
        STEP


rule gather_collection_study:
    input:
        cube_paths=expand(f"{STUDY_DIR}/sweeps/{{chunk}}.nc", chunk=STUDY_CHUNKS),
        measures_paths=expand(f"{STUDY_DIR}/measures/{{chunk}}.csv", chunk=STUDY_CHUNKS),
        library=library(STUDY_GATHER_STEP),
    output:
        study_path=f"{STUDY_DIR}/study.nc",
        table_path=report(f"{STUDY_DIR}/records.csv", category="Collection study",
                          caption="../report/collection_records.rst"),
        skipped_path=f"{STUDY_DIR}/skipped.csv",
    params:
        step=STUDY_GATHER_STEP,
        collection=COLLECTION,
        g=config["gravity"],
    log:
        f"logs/collections/{STUDY}/gather.log",
    script:
        STEP


rule check_collection_measures:
    input:
        table_path=f"{STUDY_DIR}/records.csv",
        library=library(CHECK_STEP),
    output:
        check_path=f"{STUDY_DIR}/measures_check.csv",
        summary_path=f"{STUDY_DIR}/measures_check.json",
    params:
        step=CHECK_STEP,
        pass_rate=STUDY_CONFIG["check_pass_rate"],
    log:
        f"logs/collections/{STUDY}/measures_check.log",
    script:
        STEP


rule analyse_collection:
    input:
        table_path=f"{STUDY_DIR}/records.csv",
        study_path=f"{STUDY_DIR}/study.nc",
        library=library(ANALYSIS_STEP),
        paper=PAPER_REFERENCE,  # the claims set the paper's Tables 6 and 7 beside ours
    output:
        relations_path=f"{STUDY_DIR}/relations.csv",
        coverage_path=f"{STUDY_DIR}/coverage.csv",
        claims_path=f"{STUDY_DIR}/claims.csv",
        near_far_path=f"{STUDY_DIR}/near_far.csv",
        design_path=f"{STUDY_DIR}/design.json",
    params:
        step=ANALYSIS_STEP,
        n_boot=config["relations"]["n_boot"],
        seed=config["relations"]["seed"],
        min_records=STUDY_CONFIG["min_records"],
        reference_mu=STUDY_CONFIG["reference_mu"],
        near_optimal_fraction=config["mu_max"]["near_optimal_fraction"],
        efficiency_target=STUDY_CONFIG["efficiency_target"],
        coverage_target=STUDY_CONFIG["coverage_target"],
        pga_bands_g=STUDY_CONFIG["pga_bands_g"],
        near_fault_km=STUDY_CONFIG["near_fault_km"],
        g=config["gravity"],
    log:
        f"logs/collections/{STUDY}/analysis.log",
    script:
        STEP


rule check_collection_scaling_law:
    input:
        store_path=f"{STUDY_DIR}/records/{STUDY_CHUNKS[0]}.nc",
        library=library(SCALING_LAW_STEP),
    output:
        law_path=f"{STUDY_DIR}/scaling_law.csv",
    params:
        step=SCALING_LAW_STEP,
        mu=STUDY_CONFIG["mu"],
        factors=[0.5, 2.0, 3.0],
        g=config["gravity"],
    log:
        f"logs/collections/{STUDY}/scaling_law.log",
    script:
        STEP


# The study's page; a figure with nothing to draw (no published measures to check, too few records) says why.
report_page(
    "collection_study",
    rank=40,
    rule_name="render_collection_report",
    title="The collection study",
    notebook="notebooks/collection_study.ipynb",
    inputs={"tables": multiext(f"{STUDY_DIR}/", "records.csv", "relations.csv", "coverage.csv", "claims.csv",
                               "near_far.csv", "design.json", "measures_check.csv", "measures_check.json",
                               "scaling_law.csv", "study.nc", "skipped.csv")},
    parameters={"results_dir": "results", "study": STUDY, "reference_mu": STUDY_CONFIG["reference_mu"],
                "near_optimal_fraction": config["mu_max"]["near_optimal_fraction"],
                "pga_bands_g": STUDY_CONFIG["pga_bands_g"], "near_fault_km": STUDY_CONFIG["near_fault_km"],
                "min_records": STUDY_CONFIG["min_records"], "not_here": len(STUDY_NOT_HERE)},
    figures_dir="collection",
    figures={"energy_curves.png": "Energy dissipated by friction against mu for every record studied, absolute and "
                                  "relative to its maximum",
             "mu_max_vs_pga.png": "mu_max against PGA for every record studied, with the paper's eight records and lines",
             "relations.png": "Spearman rho of mu_max with each predictor, and the leave-one-event-out skill of a line",
             "design_chart.png": "Design chart: mu_max against its best predictor with the 95 % prediction band",
             "coverage.png": "Share of records whose near-optimal range contains mu, against mu",
             "ratio_and_efficiency.png": "Histograms of mu_max g/PGA and of the efficiency of the reference mu",
             "scaling_law.png": "Scaling law: mu_max of the scaled record against k times mu_max of the original",
             "measures_check.png": "Our intensity measures against the collection's published values"},
    category="Collection study",
    caption="collection_study.rst",
    index_section=("stickslip.studies.collections.index:collection_section_html",
                   {"study_dir": STUDY_DIR, "figures_dir": "reports/figures/collection",
                    "page": "reports/html/collection_study.html", "not_here": len(STUDY_NOT_HERE),
                    "min_records": STUDY_CONFIG["min_records"]}),
    index_inputs=multiext(f"{STUDY_DIR}/", "records.csv", "skipped.csv", "claims.csv", "coverage.csv",
                          "measures_check.json"),
)
