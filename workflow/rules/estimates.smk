# The simplified estimates against the rigorous answers (docs/estimates.md): every method of
# stickslip.estimates on every record of the collection study, at the configured k_y [g], against
# the rigid D_n of both polarities that the Jibson (2007) study has already solved (jibson2007.smk),
# and the flexible methods against the coupled analysis of layers of the configured periods T_s [s].
#   store_collection_chunk (collections.smk) -> compute_estimate_chunk (per chunk: Sa(1.5 T_s), coupled D)
#   measure_collection_chunk, gather_jibson2007_displacements -> compare_estimates -> render_estimates_report, index.
ESTIMATES = config["estimates"]
ESTIMATES_CHUNK_STEP = "stickslip.studies.estimates.simplified:write_chunk_flexible"
ESTIMATES_STEP = "stickslip.studies.estimates.simplified:write_estimates"
ESTIMATES_RESULTS = [f"{STUDY_DIR}/estimates_summary.csv", f"{STUDY_DIR}/estimates_exceedance.csv",
                     f"{STUDY_DIR}/estimates_rows.csv", f"{STUDY_DIR}/estimates_study.json"]


rule compute_estimate_chunk:
    """One chunk's Sa(1.5 T_s) [g] and coupled displacements D [cm] at every k_y and T_s, both polarities."""
    input:
        store_path=f"{STUDY_DIR}/records/{{chunk}}.nc",
        library=library(ESTIMATES_CHUNK_STEP),
    output:
        table_path=f"{STUDY_DIR}/estimates/{{chunk}}.csv",
    params:
        step=ESTIMATES_CHUNK_STEP,
        critical_accelerations_g=ESTIMATES["ky"],
        site_periods=ESTIMATES["site_periods"],
        vs=ESTIMATES["layer"]["vs"],
        vs_base=ESTIMATES["layer"]["vs_base"],
        damping=ESTIMATES["layer"]["damping"],
        g=config["gravity"],
    log:
        f"logs/collections/{STUDY}/estimates_{{chunk}}.log",
    resources:
        mem_mb=1000,
        runtime=10,
    script:
        STEP


rule compare_estimates:
    """Every estimate beside the rigorous D of each record: rows, summary per method, k_y and T_s, exceedance."""
    input:
        displacements_path=JIBSON_RESULTS[0],
        measures_paths=expand(f"{STUDY_DIR}/measures/{{chunk}}.csv", chunk=STUDY_CHUNKS),
        flexible_paths=expand(f"{STUDY_DIR}/estimates/{{chunk}}.csv", chunk=STUDY_CHUNKS),
        library=library(ESTIMATES_STEP),
    output:
        summary_path=report(ESTIMATES_RESULTS[0], category="Simplified estimates", caption="../report/estimates.rst"),
        exceedance_path=ESTIMATES_RESULTS[1],
        rows_path=ESTIMATES_RESULTS[2],
        study_path=ESTIMATES_RESULTS[3],
    params:
        step=ESTIMATES_STEP,
        collection=COLLECTION,
        critical_accelerations_g=ESTIMATES["ky"],
        site_periods=ESTIMATES["site_periods"],
        layer=ESTIMATES["layer"],
        displacement_floor_cm=ESTIMATES["displacement_floor_cm"],
        exceedance_cm=ESTIMATES["exceedance_cm"],
        min_rows=ESTIMATES["min_rows"],
        g=config["gravity"],
    log:
        f"logs/collections/{STUDY}/estimates.log",
    script:
        STEP


# Which estimate to trust where: bias and spread per method and k_y, zeros, exceedance.
report_page(
    "estimates",
    rank=80,
    rule_name="render_estimates_report",
    title="The simplified estimates against the rigorous answers",
    notebook="notebooks/estimates.ipynb",
    inputs={"tables": ESTIMATES_RESULTS},
    parameters={"results_dir": "results", "study": STUDY},
    figures_dir="estimates",
    figures={"estimates_bias.png": "Bias and spread of the log residual of each simplified estimate against k_y",
             "estimates_scatter.png": "Estimated against exact displacement, one panel per method",
             "estimates_zeros.png": "Share of zero displacements each method predicts against the share observed",
             "estimates_exceedance.png": "Predicted P(D > d) against the observed share, per method"},
    category="Simplified estimates",
    caption="estimates.rst",
    index_section=("stickslip.studies.estimates.index:estimates_section_html",
                   {"summary_path": ESTIMATES_RESULTS[0], "study_path": ESTIMATES_RESULTS[3],
                    "page": "reports/html/estimates.html"}),
    index_inputs=[ESTIMATES_RESULTS[0], ESTIMATES_RESULTS[3]],
)
