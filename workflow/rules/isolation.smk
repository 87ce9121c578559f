# A one-story building on friction pendulums against the same building on a fixed base (docs/studies.md): each
# horizontal component of the planar study's station pairs (one job per chunk of pairs) and of the three-component
# stations, at every fixed-base period T (one job each), radius R and friction mu, with the exact solver:
#   list_station_pairs (planar.smk), acquire_three_component (vertical.smk)
#   -> isolation_pair_chunk (per chunk), isolation_three_component -> gather_isolation_study (isolation.nc)
#   -> tabulate_isolation_study (with near-fault against far-field) -> render_isolation_report, index.
# And the same building in the plane on the three-component stations, with and without the vertical (integrated
# scheme both times), one job per period and chunk of stations:
#   acquire_three_component (vertical.smk) -> isolation_vertical_chunk -> tabulate_isolation_vertical
#   (isolation_vertical.nc and the ratios with / without) -> render_isolation_report.
# And in the plane on the SLAMMER library's station pairs (no vertical), against each component alone, one job per
# period and share of the pairs (the in-plane part's chunks, by their samples; first in line, the longest jobs):
#   list_station_pairs (planar.smk) -> isolation_plane_pair_chunk -> tabulate_isolation_plane_pairs
#   (isolation_plane_pairs.nc, one row per pair with its rupture distance, the ratios' statistics).
# Without the three-component records those jobs write empty cubes; without the SLAMMER library there is no pair;
# without both the tables are empty and the page says how to get the records.
from stickslip.studies.vertical.records import missing_message

ISOLATION = config["isolation_study"]
ISOLATION_DIR = "results/isolation"
ISOLATION_PAIRS_STEP = "stickslip.studies.isolation.sweep:write_pair_chunk_cube"
ISOLATION_THREE_STEP = "stickslip.studies.isolation.sweep:write_three_component_cube"
ISOLATION_GATHER_STEP = "stickslip.studies.isolation.sweep:gather_isolation_study"
ISOLATION_TABLES_STEP = "stickslip.studies.isolation.tables:write_isolation_tables"
ISOLATION_RESULTS = [f"{ISOLATION_DIR}/{name}" for name in ("isolation_cases.csv", "isolation_summary.csv",
                                                            "isolation_study.json", "isolation_near_far.csv")]
#: The study's settings, as its steps take them.
ISOLATION_SETTINGS = {key: ISOLATION[key] for key in ("periods", "radii", "mu", "mass_ratio", "damping_ratio")}
#: One job per set of components and period, so that two cores share the work evenly.
ISOLATION_PERIODS = [f"{period:g}" for period in ISOLATION["periods"]]
ISOLATION_VERTICAL_STEP = "stickslip.studies.isolation.with_vertical:write_vertical_chunk_cube"
ISOLATION_VERTICAL_TABLES_STEP = "stickslip.studies.isolation.with_vertical:write_vertical_tables"
ISOLATION_VERTICAL_RESULTS = [f"{ISOLATION_DIR}/{name}" for name in ("isolation_vertical.nc",
                                                                     "isolation_vertical_ratios.csv",
                                                                     "isolation_vertical_summary.csv")]
#: The in-plane part's periods and chunks of stations: one job each pair.
ISOLATION_VERTICAL_PERIODS = [f"{period:g}" for period in ISOLATION["vertical"]["periods"]]
ISOLATION_VERTICAL_CHUNKS = [str(chunk) for chunk in range(ISOLATION["vertical"]["chunks"])]
ISOLATION_PLANE_PAIRS_STEP = "stickslip.studies.isolation.plane_pairs:write_plane_pair_chunk_cube"
ISOLATION_PLANE_PAIRS_TABLES_STEP = "stickslip.studies.isolation.plane_pairs:write_plane_pair_tables"
ISOLATION_PLANE_PAIRS_RESULTS = [f"{ISOLATION_DIR}/{name}" for name in ("isolation_plane_pairs.nc",
                                                                        "isolation_plane_pairs.csv",
                                                                        "isolation_plane_pairs_summary.csv")]
#: The shares of the station pairs in the plane: none without the library.
ISOLATION_PLANE_PAIR_CHUNKS = ISOLATION_VERTICAL_CHUNKS if PAIR_CHUNKS else []


wildcard_constraints:
    period="[0-9.]+",
    station_chunk="[0-9]+",
    plane_chunk="[0-9]+",


rule isolation_pair_chunk:
    """One chunk of station pairs: each component alone, isolated and on a fixed base, at one T, every R and mu."""
    input:
        pairs_path=f"{PLANAR_DIR}/pairs.csv",
        store_paths=RECORD_STORES,
        library=library(ISOLATION_PAIRS_STEP),
    output:
        cube_path=f"{ISOLATION_DIR}/pairs/{{pair_chunk}}/{{period}}.nc",
    params:
        step=ISOLATION_PAIRS_STEP,
        chunk=lambda wildcards: wildcards.pair_chunk,
        settings=ISOLATION_SETTINGS,
        period=lambda wildcards: float(wildcards.period),
        g=config["gravity"],
    threads: config.get("sweep_threads", 1)
    log:
        "logs/isolation/pairs_{pair_chunk}_{period}.log",
    resources:
        mem_mb=1000,
        runtime=30,
    script:
        STEP


rule isolation_three_component:
    """The three-component stations' H1 and H2 at one T; an empty cube without their records."""
    input:
        **({"store_path": f"{VERTICAL_DIR}/records.nc"} if VERTICAL_FILES else {}),
        library=library(ISOLATION_THREE_STEP),
    output:
        cube_path=f"{ISOLATION_DIR}/three_component/{{period}}.nc",
    params:
        step=ISOLATION_THREE_STEP,
        settings=ISOLATION_SETTINGS,
        period=lambda wildcards: float(wildcards.period),
        g=config["gravity"],
    log:
        "logs/isolation/three_component_{period}.log",
    script:
        STEP


rule isolation_vertical_chunk:
    """One chunk of the three-component stations in the plane at one T, every R and mu, without and with the
    vertical; an empty cube without their records."""
    input:
        **({"store_path": f"{VERTICAL_DIR}/records.nc"} if VERTICAL_FILES else {}),
        library=library(ISOLATION_VERTICAL_STEP),
    output:
        cube_path=f"{ISOLATION_DIR}/vertical/{{station_chunk}}/{{period}}.nc",
    params:
        step=ISOLATION_VERTICAL_STEP,
        settings={**ISOLATION_SETTINGS, "vertical": ISOLATION["vertical"]},
        period=lambda wildcards: float(wildcards.period),
        chunk=lambda wildcards: int(wildcards.station_chunk),
        untold_positive=VERTICAL["untold_vertical_positive"],
        g=config["gravity"],
    log:
        "logs/isolation/vertical_{station_chunk}_{period}.log",
    resources:
        mem_mb=1000,
        runtime=30,
    script:
        STEP


rule tabulate_isolation_vertical:
    """The chunks gathered, the ratios with / without the vertical per station and their median and 16-84 % band."""
    input:
        # the periods of one chunk together, in the order of the configuration
        cube_paths=[path for chunk in ISOLATION_VERTICAL_CHUNKS
                    for path in expand(f"{ISOLATION_DIR}/vertical/{chunk}/{{period}}.nc",
                                       period=ISOLATION_VERTICAL_PERIODS)],
        library=library(ISOLATION_VERTICAL_TABLES_STEP),
    output:
        study_path=ISOLATION_VERTICAL_RESULTS[0],
        ratios_path=ISOLATION_VERTICAL_RESULTS[1],
        summary_path=ISOLATION_VERTICAL_RESULTS[2],
    params:
        step=ISOLATION_VERTICAL_TABLES_STEP,
        periods=len(ISOLATION_VERTICAL_PERIODS),
    log:
        "logs/isolation/vertical_tables.log",
    script:
        STEP


rule isolation_plane_pair_chunk:
    """One share of the SLAMMER library's station pairs in the plane at one T (of the in-plane part), every R and mu."""
    input:
        pairs_path=f"{PLANAR_DIR}/pairs.csv",
        store_paths=RECORD_STORES,
        library=library(ISOLATION_PLANE_PAIRS_STEP),
    output:
        cube_path=f"{ISOLATION_DIR}/plane_pairs/{{plane_chunk}}/{{period}}.nc",
    params:
        step=ISOLATION_PLANE_PAIRS_STEP,
        chunk=lambda wildcards: int(wildcards.plane_chunk),
        settings={**ISOLATION_SETTINGS, "vertical": ISOLATION["vertical"]},
        period=lambda wildcards: float(wildcards.period),
        g=config["gravity"],
    priority: 1
    log:
        "logs/isolation/plane_pairs_{plane_chunk}_{period}.log",
    resources:
        mem_mb=1000,
        runtime=30,
    script:
        STEP


rule tabulate_isolation_plane_pairs:
    """The pairs' chunks gathered, one row per pair, T, R and mu against each component alone (the per-component
    study's cube), and the ratios' median and 16-84 % band over the near-fault, far-field and all pairs."""
    input:
        # the periods of one chunk together, in the order of the configuration
        cube_paths=[path for chunk in ISOLATION_PLANE_PAIR_CHUNKS
                    for path in expand(f"{ISOLATION_DIR}/plane_pairs/{chunk}/{{period}}.nc",
                                       period=ISOLATION_VERTICAL_PERIODS)],
        components_path=f"{ISOLATION_DIR}/isolation.nc",
        library=library(ISOLATION_PLANE_PAIRS_TABLES_STEP),
    output:
        study_path=ISOLATION_PLANE_PAIRS_RESULTS[0],
        rows_path=ISOLATION_PLANE_PAIRS_RESULTS[1],
        summary_path=ISOLATION_PLANE_PAIRS_RESULTS[2],
    params:
        step=ISOLATION_PLANE_PAIRS_TABLES_STEP,
        periods=len(ISOLATION_VERTICAL_PERIODS),
        near_fault_km=STUDY_CONFIG["near_fault_km"],
    log:
        "logs/isolation/plane_pairs_tables.log",
    script:
        STEP


rule gather_isolation_study:
    input:
        # the periods of one set of components together, in the order of the configuration
        cube_paths=[*[path for chunk in PAIR_CHUNKS
                      for path in expand(f"{ISOLATION_DIR}/pairs/{chunk}/{{period}}.nc", period=ISOLATION_PERIODS)],
                    *expand(f"{ISOLATION_DIR}/three_component/{{period}}.nc", period=ISOLATION_PERIODS)],
        library=library(ISOLATION_GATHER_STEP),
    output:
        study_path=f"{ISOLATION_DIR}/isolation.nc",
    params:
        step=ISOLATION_GATHER_STEP,
        periods=len(ISOLATION_PERIODS),
    log:
        "logs/isolation/gather.log",
    script:
        STEP


rule tabulate_isolation_study:
    """Every case, the median and 16-84 % band over the records per T, R and mu, near-fault against far-field, and
    the study's JSON."""
    input:
        study_cube_path=f"{ISOLATION_DIR}/isolation.nc",
        library=library(ISOLATION_TABLES_STEP),
    output:
        cases_path=ISOLATION_RESULTS[0],
        summary_path=ISOLATION_RESULTS[1],
        study_path=ISOLATION_RESULTS[2],
        near_far_path=ISOLATION_RESULTS[3],
    params:
        step=ISOLATION_TABLES_STEP,
        settings=ISOLATION_SETTINGS,
        collection=STUDY,
        near_fault_km=STUDY_CONFIG["near_fault_km"],
        min_records=STUDY_CONFIG["min_records"],
        three_component_message="" if VERTICAL_FILES else missing_message(VERTICAL_RECORDS_DIR),
    log:
        "logs/isolation/tables.log",
    script:
        STEP


report_page(
    "isolation_study",
    rank=96,
    rule_name="render_isolation_report",
    title="A building on friction pendulums against the fixed base",
    notebook="notebooks/isolation_study.ipynb",
    inputs={"tables": ISOLATION_RESULTS, "vertical": ISOLATION_VERTICAL_RESULTS,
            "plane_pairs": ISOLATION_PLANE_PAIRS_RESULTS},
    parameters={"results_dir": "results"},
    figures_dir="isolation",
    figures={"isolation_drift_ratio.png": "Peak story drift isolated over fixed base against mu, one panel per "
                                          "fixed-base period, one line per radius: median and 16-84 % band",
             "isolation_floor_acceleration_ratio.png": "Peak floor acceleration isolated over fixed base against mu, "
                                                       "per period and radius: median and 16-84 % band",
             "isolation_displacement.png": "Peak isolator displacement against mu, per period and radius: median "
                                           "and 16-84 % band",
             "isolation_near_far.png": "Peak drift isolated over fixed base and peak isolator displacement against "
                                       "the rupture distance at the grid's middle period and radius, one colour per "
                                       "mu: each component a dot, the median within and beyond the near-fault "
                                       "distance a line; the displacement on a log scale",
             "isolation_vertical_ratio.png": "In the plane on the three-component stations: each peak with the "
                                             "vertical over without it against mu, one thin line per station, the "
                                             "median thick and the 16-84 % band"},
    category="Isolated building",
    caption="isolation_study.rst",
    index_section=("stickslip.studies.isolation.index:isolation_section_html",
                   {"study_path": ISOLATION_RESULTS[2], "vertical_summary_path": ISOLATION_VERTICAL_RESULTS[2],
                    "page": "reports/html/isolation_study.html",
                    "plane_pairs_summary_path": ISOLATION_PLANE_PAIRS_RESULTS[2]}),
    index_inputs=[ISOLATION_RESULTS[2], ISOLATION_VERTICAL_RESULTS[2], ISOLATION_PLANE_PAIRS_RESULTS[2]],
)
