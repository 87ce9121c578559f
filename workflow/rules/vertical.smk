# The vertical ground motion on sliders and pendulums (docs/studies.md): fifteen near-fault PEER stations
# with their three components, a flat slider and friction pendulums of the configured radii, in each
# configured direction, without the vertical, with it as recorded and reversed:
#   acquire_three_component (every file checked by its SHA-256) -> sweep_vertical_direction (per direction)
#   -> gather_vertical_study (vertical.nc) -> tabulate_vertical_study -> render_vertical_report, index.
# The records are read from vertical_study.records_dir (STICKSLIP_THREE_COMPONENT_DIR overrides it), never
# from the repository; without them the tables are empty and the page says, in one sentence, how to get them.
from stickslip.studies.vertical.records import FOLDER_ENV, folder_files

VERTICAL = config["vertical_study"]
VERTICAL_DIR = "results/vertical"
VERTICAL_RECORDS_DIR = os.environ.get(FOLDER_ENV) or VERTICAL["records_dir"]
VERTICAL_RECORDS_DIR = str(Path(VERTICAL_RECORDS_DIR).resolve()) if VERTICAL_RECORDS_DIR else None
#: The manifest's files found in the folder: a new or changed one reruns the acquisition; none, no sweep.
VERTICAL_FILES = [str(path) for path in folder_files(VERTICAL_RECORDS_DIR)]
VERTICAL_STORE_STEP = "stickslip.studies.vertical.records:store_three_component"
VERTICAL_SWEEP_STEP = "stickslip.studies.vertical.sweep:write_direction_sweep"
VERTICAL_GATHER_STEP = "stickslip.studies.vertical.sweep:gather_vertical_study"
VERTICAL_TABLES_STEP = "stickslip.studies.vertical.effect:write_vertical_tables"
VERTICAL_RESULTS = [f"{VERTICAL_DIR}/{name}" for name in ("vertical_cases.csv", "vertical_changes.csv",
                                                          "vertical_liftoff.csv", "vertical_summary.csv",
                                                          "vertical_study.json")]
#: numba threads per direction's job: the plane's carries most of the study's work, so it takes more.
VERTICAL_THREADS = {"H1": config.get("sweep_threads", 1), "H2": config.get("sweep_threads", 1),
                    "plane": VERTICAL["plane_threads"]}


wildcard_constraints:
    direction="H1|H2|plane",


rule acquire_three_component:
    """Every file of the three-component manifest read from the folder and checked by its SHA-256, in one store."""
    input:
        lambda wildcards: VERTICAL_FILES,  # an input function, as the paper's records are: the folder is outside
        library=library(VERTICAL_STORE_STEP),
    output:
        store_path=f"{VERTICAL_DIR}/records.nc",
        inventory_path=f"{VERTICAL_DIR}/records.csv",
    params:
        step=VERTICAL_STORE_STEP,
        folder=VERTICAL_RECORDS_DIR,
        g=config["gravity"],
    log:
        "logs/vertical/acquire.log",
    script:
        STEP


rule sweep_vertical_direction:
    """One direction: every station at every radius and vertical variant over mu, with the design answer."""
    input:
        store_path=f"{VERTICAL_DIR}/records.nc",
        library=library(VERTICAL_SWEEP_STEP),
    output:
        cube_path=f"{VERTICAL_DIR}/sweeps/{{direction}}.nc",
    params:
        step=VERTICAL_SWEEP_STEP,
        direction=lambda wildcards: wildcards.direction,
        radii=VERTICAL["radii"],
        mu=VERTICAL["mu"],
        variants=VERTICAL["variants"],
        untold_positive=VERTICAL["untold_vertical_positive"],
        q=config["mu_max"]["near_optimal_fraction"],
        reference_mu=VERTICAL["reference_mu"],
        xatol=VERTICAL["mu_max_tolerance"],
        mass=config["block_mass"],
        g=config["gravity"],
    threads: lambda wildcards: VERTICAL_THREADS[wildcards.direction]
    log:
        "logs/vertical/sweep_{direction}.log",
    resources:
        mem_mb=1000,
        runtime=30,
    script:
        STEP


rule gather_vertical_study:
    input:
        cube_paths=expand(f"{VERTICAL_DIR}/sweeps/{{direction}}.nc", direction=VERTICAL["directions"]),
        library=library(VERTICAL_GATHER_STEP),
    output:
        study_path=f"{VERTICAL_DIR}/vertical.nc",
    params:
        step=VERTICAL_GATHER_STEP,
    log:
        "logs/vertical/gather.log",
    script:
        STEP


rule tabulate_vertical_study:
    """Per case, the vertical's effect, lift-off per station and the summary over stations; or, without the
    records, empty tables and the sentence that says how to get them."""
    input:
        **({"cube_path": f"{VERTICAL_DIR}/vertical.nc", "inventory_path": f"{VERTICAL_DIR}/records.csv"}
           if VERTICAL_FILES else {}),
        library=library(VERTICAL_TABLES_STEP),
    output:
        cases_path=VERTICAL_RESULTS[0],
        changes_path=VERTICAL_RESULTS[1],
        liftoff_path=VERTICAL_RESULTS[2],
        summary_path=VERTICAL_RESULTS[3],
        study_path=VERTICAL_RESULTS[4],
    params:
        step=VERTICAL_TABLES_STEP,
        records_dir=VERTICAL_RECORDS_DIR,
        settings={"mass": config["block_mass"], "g": config["gravity"],
                  "untold_vertical_positive": VERTICAL["untold_vertical_positive"]},
    log:
        "logs/vertical/tables.log",
    script:
        STEP


# The study's page; without the records it says so in one sentence and how to get them.
report_page(
    "vertical_study",
    rank=90,
    rule_name="render_vertical_report",
    title="The vertical ground motion on sliders and pendulums",
    notebook="notebooks/vertical_study.ipynb",
    inputs={"tables": VERTICAL_RESULTS},
    parameters={"results_dir": "results"},
    figures_dir="vertical",
    figures={"vertical_energy_ratio.png": "E_df,max with the vertical over without it, per station, one panel per "
                                          "radius, as recorded and reversed",
             "vertical_base_shear_ratio.png": "Peak base shear V/W at the reference mu with the vertical over "
                                              "without it, per station and radius",
             "vertical_displacement_ratio.png": "Displacement demand at the reference mu with the vertical over "
                                                "without it, per station and radius",
             "vertical_mu_max.png": "mu_max with the vertical against mu_max without it, one panel per radius",
             "vertical_liftoff.png": "Time lifted off per station against the vertical's largest downward "
                                     "acceleration [g]"},
    category="Vertical ground motion",
    caption="vertical_study.rst",
    index_section=("stickslip.studies.vertical.index:vertical_section_html",
                   {"summary_path": VERTICAL_RESULTS[3], "study_path": VERTICAL_RESULTS[4],
                    "page": "reports/html/vertical_study.html"}),
    index_inputs=[VERTICAL_RESULTS[3], VERTICAL_RESULTS[4]],
)
