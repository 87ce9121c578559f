# Verification against SLAMMER 1.1's own results (docs/solvers.md, "Verification against
# SLAMMER's own results"): its 90 rigid analyses x 2 polarities on pyslammer's sample motions,
# recomputed by the slammer scheme and the exact solver, judged by pySLAMMER's rules, the exact
# solver's misses checked by the convergence of SLAMMER's scheme on finer resampled records.
# One job; the reference file is read from verification_dir (STICKSLIP_VERIFICATION_DIR
# overrides it), never from the repository.  Without it the job writes a summary that says so
# and how to get it, the index says the same, and no notebook is rendered.
from stickslip.studies.verification.slammer import verification_source

VERIFICATION_STEP = "stickslip.studies.verification.slammer:write_slammer_verification"
VERIFICATION_DIR = os.environ.get("STICKSLIP_VERIFICATION_DIR") or config.get("verification_dir")
VERIFICATION_DIR = str(Path(VERIFICATION_DIR).resolve()) if VERIFICATION_DIR else None
#: The reference file when it and pyslammer's sample motions are here, else None.
VERIFICATION_FILE = verification_source(VERIFICATION_DIR)["path"]
VERIFICATION_RESULTS = multiext("results/verification/slammer_", "summary.json", "analyses.csv", "convergence.csv")


rule verify_against_slammer:
    """SLAMMER 1.1's rigid analyses recomputed by both schemes, judged, the exact solver's misses explained."""
    input:
        [VERIFICATION_FILE] if VERIFICATION_FILE else [],
        library=library(VERIFICATION_STEP),
    output:
        summary_path=VERIFICATION_RESULTS[0],
        analyses_path=VERIFICATION_RESULTS[1],
        convergence_path=VERIFICATION_RESULTS[2],
    params:
        step=VERIFICATION_STEP,
        # the reference file's folder, or the configured folder that lacks it (the summary says so)
        folder=lambda wildcards, input: str(Path(input[0]).parent) if VERIFICATION_FILE else VERIFICATION_DIR,
    log:
        "logs/verification/slammer.log",
    script:
        STEP


FLEXIBLE_STEP = "stickslip.studies.verification.flexible:write_flexible_verification"
FLEXIBLE_RESULTS = multiext("results/verification/flexible_", "summary.json", "analyses.csv")


rule verify_flexible_against_slammer:
    """SLAMMER 1.1's decoupled and coupled analyses recomputed by the slammer scheme, judged per group, beside
    pySLAMMER's results when they are here; every miss recomputed across the PGA's rounding."""
    input:
        [VERIFICATION_FILE] if VERIFICATION_FILE else [],
        library=library(FLEXIBLE_STEP),
    output:
        summary_path=FLEXIBLE_RESULTS[0],
        analyses_path=FLEXIBLE_RESULTS[1],
    params:
        step=FLEXIBLE_STEP,
        folder=lambda wildcards, input: str(Path(input[0]).parent) if VERIFICATION_FILE else VERIFICATION_DIR,
    log:
        "logs/verification/flexible.log",
    script:
        STEP


# The verdicts in pySLAMMER's style, the scatter, the convergence; rendered only when the reference is
# here (the index's section then says how to get it).
report_page(
    "slammer_verification",
    rank=60,
    rule_name="render_verification_report",
    title="Verification against SLAMMER 1.1",
    notebook="notebooks/slammer_verification.ipynb",
    inputs={"tables": VERIFICATION_RESULTS, "flexible": FLEXIBLE_RESULTS},
    parameters={"results_dir": "results"},
    figures_dir="verification",
    figures={"slammer_scatter.png": "Ours against SLAMMER 1.1's displacements, per scheme and polarity, with the pass band",
             "slammer_tolerance.png": "Each analysis's difference from SLAMMER 1.1 over its tolerance",
             "slammer_convergence.png": "SLAMMER's scheme on finer resampled records converging to the exact answer",
             "flexible_scatter.png": "Ours (slammer scheme) against SLAMMER 1.1's decoupled and coupled displacements, "
                                     "one panel per model and soil model, with the pass band",
             "flexible_exact_scatter.png": "Ours (exact scheme) against SLAMMER 1.1's decoupled and coupled "
                                           "displacements, one panel per model and soil model, with the pass band"},
    category="Verification against SLAMMER",
    caption="slammer_verification.rst",
    index_section=("stickslip.studies.verification.index:verification_section_html",
                   {"summary_path": VERIFICATION_RESULTS[0], "flexible_path": FLEXIBLE_RESULTS[0],
                    "page": "reports/html/slammer_verification.html" if VERIFICATION_FILE else None}),
    index_inputs=[VERIFICATION_RESULTS[0], FLEXIBLE_RESULTS[0]],
    rendered=bool(VERIFICATION_FILE),
)
