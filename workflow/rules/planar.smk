# The paper's question in two dimensions (docs/planar.md): the block sliding in the plane
# under both horizontal components of each station pair of the collection study's records,
# beside each component alone and the pair turned through every azimuth, one job per chunk of pairs:
#   store_collection_chunk (collections.smk) -> list_station_pairs (pairs.csv, unpaired.csv)
#   -> sweep_pair_chunk (per chunk) -> gather_planar_study (planar.nc)
#   -> analyse_planar_study (per pair, R against mu, relations, near/far, design chart)
#   -> render_planar_report, index section.
# The pairs are decided from the collection's metadata when the workflow starts (event, station
# prefix, two horizontal components, one dt), so the chunks are known before any record is read;
# a pair whose component could not be read stays in pairs.csv with the reason and is not swept.
from stickslip.studies.planar.sweep import study_pairs

PLANAR = config["planar_study"]
PLANAR_DIR = f"{STUDY_DIR}/planar"
PAIRS_STEP = "stickslip.studies.planar.sweep:write_pair_tables"
PAIR_SWEEP_STEP = "stickslip.studies.planar.sweep:write_pair_chunk_sweep"
PLANAR_GATHER_STEP = "stickslip.studies.planar.sweep:gather_planar_study"
PLANAR_ANALYSIS_STEP = "stickslip.studies.planar.analysis:write_planar_analysis"

STUDY_PAIRS, STUDY_UNPAIRED = study_pairs(COLLECTION, STUDY_IDS, PLANAR["chunk_size"])
PAIR_CHUNKS = sorted({pair["chunk"] for pair in STUDY_PAIRS})
PLANAR_TABLES = ["pairs.csv", "unpaired.csv", "pair_results.csv", "ratio_by_mu.csv", "relations.csv", "near_far.csv",
                 "design.json", "summary.json"]
PLANAR_RESULTS = [f"{PLANAR_DIR}/{name}" for name in PLANAR_TABLES]
RECORD_STORES = expand(f"{STUDY_DIR}/records/{{chunk}}.nc", chunk=STUDY_CHUNKS)


wildcard_constraints:
    pair_chunk="[0-9]+",


rule list_station_pairs:
    """The station pairs of the study's records, each with its chunk and padding, and the records left unpaired."""
    input:
        store_paths=RECORD_STORES,
        library=library(PAIRS_STEP),
    output:
        pairs_path=f"{PLANAR_DIR}/pairs.csv",
        unpaired_path=f"{PLANAR_DIR}/unpaired.csv",
    params:
        step=PAIRS_STEP,
        collection=COLLECTION,
        ids=STUDY_IDS,
        chunk_size=PLANAR["chunk_size"],
    log:
        f"logs/collections/{STUDY}/planar_pairs.log",
    script:
        STEP


rule sweep_pair_chunk:
    """One chunk of pairs: in the plane, each component alone and turned, at every mu of the grid."""
    input:
        pairs_path=f"{PLANAR_DIR}/pairs.csv",
        store_paths=RECORD_STORES,
        library=library(PAIR_SWEEP_STEP),
    output:
        cube_path=f"{PLANAR_DIR}/sweeps/{{pair_chunk}}.nc",
    params:
        step=PAIR_SWEEP_STEP,
        chunk=lambda wildcards: wildcards.pair_chunk,
        mu=PLANAR["mu"],
        angle_step=PLANAR["angle_step"],
        mass=config["block_mass"],
        g=config["gravity"],
    threads: config.get("sweep_threads", 1)
    log:
        f"logs/collections/{STUDY}/planar_sweep_{{pair_chunk}}.log",
    resources:
        mem_mb=2000,
        runtime=60,
    script:
        STEP


rule gather_planar_study:
    input:
        cube_paths=expand(f"{PLANAR_DIR}/sweeps/{{pair_chunk}}.nc", pair_chunk=PAIR_CHUNKS),
        library=library(PLANAR_GATHER_STEP),
    output:
        study_path=f"{PLANAR_DIR}/planar.nc",
    params:
        step=PLANAR_GATHER_STEP,
    log:
        f"logs/collections/{STUDY}/planar_gather.log",
    script:
        STEP


rule analyse_planar_study:
    input:
        study_path=f"{PLANAR_DIR}/planar.nc",
        pairs_path=f"{PLANAR_DIR}/pairs.csv",
        unpaired_path=f"{PLANAR_DIR}/unpaired.csv",
        library=library(PLANAR_ANALYSIS_STEP),
    output:
        results_path=f"{PLANAR_DIR}/pair_results.csv",
        ratio_path=f"{PLANAR_DIR}/ratio_by_mu.csv",
        relations_path=f"{PLANAR_DIR}/relations.csv",
        near_far_path=f"{PLANAR_DIR}/near_far.csv",
        design_path=f"{PLANAR_DIR}/design.json",
        summary_path=f"{PLANAR_DIR}/summary.json",
    params:
        step=PLANAR_ANALYSIS_STEP,
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
        f"logs/collections/{STUDY}/planar_analysis.log",
    script:
        STEP


# The study's page; with no pair (pyslammer's sample motions are single components) it says so and why.
report_page(
    "planar_study",
    rank=50,
    rule_name="render_planar_report",
    title="The paper's question in two dimensions",
    notebook="notebooks/planar_study.ipynb",
    inputs={"tables": [*PLANAR_RESULTS, f"{PLANAR_DIR}/planar.nc"]},
    parameters={"results_dir": "results", "study": STUDY, "reference_mu": STUDY_CONFIG["reference_mu"],
                "near_fault_km": STUDY_CONFIG["near_fault_km"], "min_records": STUDY_CONFIG["min_records"],
                "example_pairs": PLANAR["example_pairs"], "angle_step": PLANAR["angle_step"],
                "mu_grid": PLANAR["mu"]},
    figures_dir="planar",
    figures={"energy_curves.png": "Energy dissipated by friction against mu for a few typical stations: the block in "
                                  "the plane beside each component alone and the worst azimuth",
             "ratio_distribution.png": "Distribution over the stations of R, the peak displacement in the plane over "
                                       "the largest 1-D one, at the plane's mu_max",
             "ratio_vs_mu.png": "Median and 90th percentile of R across the stations against mu",
             "ratio_vs_pga.png": "R at the plane's mu_max against the peak of the horizontal acceleration vector, "
                                 "near-fault and farther stations in two colours",
             "mu_max_2d_vs_1d.png": "mu_max in the plane against mu_max of each component and of the worst azimuth",
             "mu_max_vs_pga_rms.png": "mu_max against PGA and against RMS acceleration: the plane's fit beside the 1-D "
                                      "components'",
             "design_chart.png": "Design chart in 2-D: the plane's mu_max against the vector PGA with the 95 % "
                                 "prediction band, and the design mu per PGA band"},
    category="Planar study",
    caption="planar_study.rst",
    index_section=("stickslip.studies.planar.index:planar_section_html",
                   {"planar_dir": PLANAR_DIR, "figures_dir": "reports/figures/planar",
                    "page": "reports/html/planar_study.html"}),
    index_inputs=[f"{PLANAR_DIR}/summary.json", f"{PLANAR_DIR}/pairs.csv", f"{PLANAR_DIR}/unpaired.csv"],
)
