# Jibson (2007), recomputed (docs/collections.md, "Jibson (2007), recomputed"): one-way
# Newmark displacements of every record of the collection study, at the configured critical
# accelerations a_c [g], both polarities, by the exact solver; then Jibson's two regression
# forms refitted with bootstrap intervals over records, his printed values beside ours.
#   store_collection_chunk, measure_collection_chunk (per chunk, collections.smk)
#   -> compute_jibson2007_displacements (per chunk) -> gather_jibson2007_displacements -> fit_jibson2007
#   -> render_jibson2007_report, index.
JIBSON = config["jibson2007"]
JIBSON_CHUNK_STEP = "stickslip.studies.jibson2007.displacements:write_chunk_displacements"
JIBSON_GATHER_STEP = "stickslip.studies.jibson2007.displacements:gather_displacements"
JIBSON_FIT_STEP = "stickslip.studies.jibson2007.fit:write_jibson_fit"
JIBSON_REFERENCE = str(PROJECT / "src" / "stickslip" / "reference" / "jibson2007.yaml")
JIBSON_RESULTS = [f"{STUDY_DIR}/jibson2007_displacements.csv", f"{STUDY_DIR}/jibson2007_fit.json"]


rule compute_jibson2007_displacements:
    """One chunk's one-way displacements D_n [cm] at every a_c of the grid, both polarities."""
    input:
        store_path=f"{STUDY_DIR}/records/{{chunk}}.nc",
        measures_path=f"{STUDY_DIR}/measures/{{chunk}}.csv",
        library=library(JIBSON_CHUNK_STEP),
    output:
        table_path=f"{STUDY_DIR}/jibson2007/{{chunk}}.csv",
    params:
        step=JIBSON_CHUNK_STEP,
        critical_accelerations_g=JIBSON["critical_accelerations_g"],
        g=config["gravity"],
    log:
        f"logs/collections/{STUDY}/jibson2007_{{chunk}}.log",
    resources:
        mem_mb=1000,
        runtime=10,
    script:
        STEP


rule gather_jibson2007_displacements:
    """The chunks' displacements in one table, with each record's event."""
    input:
        chunk_paths=expand(f"{STUDY_DIR}/jibson2007/{{chunk}}.csv", chunk=STUDY_CHUNKS),
        library=library(JIBSON_GATHER_STEP),
    output:
        table_path=report(JIBSON_RESULTS[0], category="Jibson (2007), recomputed",
                          caption="../report/jibson2007.rst"),
    params:
        step=JIBSON_GATHER_STEP,
        collection=COLLECTION,
    log:
        f"logs/collections/{STUDY}/jibson2007_gather.log",
    script:
        STEP


rule fit_jibson2007:
    """Jibson's two forms refitted (with and without the displacement floor), bootstrap over records."""
    input:
        table_path=JIBSON_RESULTS[0],
        library=library(JIBSON_FIT_STEP),
        paper=JIBSON_REFERENCE,  # Jibson's printed values, set beside ours
    output:
        fit_path=JIBSON_RESULTS[1],
    params:
        step=JIBSON_FIT_STEP,
        critical_accelerations_g=JIBSON["critical_accelerations_g"],
        displacement_floor_cm=JIBSON["displacement_floor_cm"],
        n_boot=JIBSON["n_boot"],
        seed=JIBSON["seed"],
        g=config["gravity"],
    log:
        f"logs/collections/{STUDY}/jibson2007_fit.log",
    script:
        STEP


# Ours beside Jibson's, the data with both curves, residuals, the selection.
report_page(
    "jibson2007",
    rank=70,
    rule_name="render_jibson2007_report",
    title="Jibson (2007), recomputed",
    notebook="notebooks/jibson2007.ipynb",
    inputs={"tables": JIBSON_RESULTS},
    parameters={"results_dir": "results", "study": STUDY},
    figures_dir="jibson2007",
    figures={"jibson2007_form1.png": "log10 D_n against a_c/a_max with Jibson's curve and ours",
             "jibson2007_form2.png": "Predicted against observed log10 D_n, form in I_a and a_c/a_max",
             "jibson2007_residuals.png": "Histograms of the residuals of our two fits"},
    category="Jibson (2007), recomputed",
    caption="jibson2007.rst",
    index_section=("stickslip.studies.jibson2007.index:jibson_section_html",
                   {"fit_path": JIBSON_RESULTS[1], "page": "reports/html/jibson2007.html"}),
    index_inputs=JIBSON_RESULTS,
)
