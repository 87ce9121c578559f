# stickslip workflow, one direction:
#   acquire (per record) -> measures (per record) -> sweeps (per grid and record)
#   -> gathered cubes -> tables, fits, comparisons -> notebooks, figures, index;
#   and beyond the paper, a collection study in per-chunk jobs (collections.smk),
#   with Jibson's (2007) regressions recomputed on it (jibson2007.smk), the simplified estimates
#   measured against the rigorous answers on it (estimates.smk), and its station pairs
#   sliding in the plane (planar.smk); and the vertical ground motion on sliders and pendulums
#   (vertical.smk); and the codes' equivalent-linear displacement of a friction pendulum against the
#   exact one on the station pairs and the three-component stations (code_vs_exact.smk); and a building on
#   friction pendulums against the fixed base on the same records (isolation.smk), and a friction damper on a
#   building, the paper's question with a structure (damper.smk).
# Run it with `make reproduce` (or `snakemake --cores 2 --profile workflow/profiles/default`).
# The rules live in workflow/rules/, one file per thing computed; only the
# default target is here (Snakemake takes the default target from this file).
from snakemake.utils import min_version

min_version("9.0")


report: "workflow/report/workflow.rst"


include: "workflow/rules/common.smk"
include: "workflow/rules/records.smk"
include: "workflow/rules/measures.smk"
include: "workflow/rules/sweeps.smk"
include: "workflow/rules/mu_max.smk"
include: "workflow/rules/relations.smk"
include: "workflow/rules/scaling.smk"
include: "workflow/rules/harmonic.smk"
include: "workflow/rules/timestep.smk"
include: "workflow/rules/mass.smk"
include: "workflow/rules/collections.smk"
include: "workflow/rules/planar.smk"
include: "workflow/rules/verification.smk"
include: "workflow/rules/jibson2007.smk"
include: "workflow/rules/estimates.smk"
include: "workflow/rules/model_response.smk"
include: "workflow/rules/errata.smk"
include: "workflow/rules/paper_fits.smk"
include: "workflow/rules/units.smk"
include: "workflow/rules/vertical.smk"
include: "workflow/rules/code_vs_exact.smk"
include: "workflow/rules/isolation.smk"
include: "workflow/rules/damper.smk"
# Last: the rendering rule of every page declared above (report_page) and the index; a page's rank, not
# the order of these lines, places its section on the index.
include: "workflow/rules/reports.smk"


#: Every table, cube and JSON file the workflow computes, without the notebooks and pages that
#: draw them: the target `results` (a cluster run of the computation, or a test of it).
RESULTS = [
    "results/tables/table5_records.csv",
    "results/tables/units.csv",
    "results/tables/table4_comparison.csv",
    "results/tables/table6_comparison.csv",
    "results/tables/table7_comparison.csv",
    "results/fits.json",
    "results/tables/table8_comparison.csv",
    "results/tables/mass_check.csv",
    f"{STUDY_DIR}/claims.csv",
    f"{STUDY_DIR}/measures_check.json",
    f"{STUDY_DIR}/scaling_law.csv",
    "results/tables/errata.csv",
    "results/tables/paper_fits.csv",
    "results/tables/table3_table4_model.csv",
    f"results/tables/timestep_{TIMESTEP_RECORD}_summary.csv",
    # Jibson (2007), recomputed on the collection: the displacements and both forms refitted
    *JIBSON_RESULTS,
    # the simplified estimates against the rigorous answers on the same records
    *ESTIMATES_RESULTS,
    # the verification against SLAMMER 1.1 (its summary says so when the reference is not here)
    *VERIFICATION_RESULTS,
    *FLEXIBLE_RESULTS,
    # the paper's question in two dimensions: station pairs in the plane (planar.smk)
    *PLANAR_RESULTS,
    # the vertical ground motion on sliders and pendulums, on the three-component stations (vertical.smk)
    *VERTICAL_RESULTS,
    # the codes' equivalent-linear displacement against the exact one (code_vs_exact.smk)
    *CODE_EXACT_RESULTS,
    # a one-story building on friction pendulums against the fixed base (isolation.smk)
    *ISOLATION_RESULTS,
    *ISOLATION_VERTICAL_RESULTS,
    # the paper's question with a structure: a friction damper on a building (damper.smk)
    *DAMPER_RESULTS,
]


rule all:
    input:
        RESULTS,
        "reports/index.html",


rule results:
    input:
        RESULTS,
