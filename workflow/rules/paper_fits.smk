# The paper's mu_max lines recomputed from its own Table 6 (all its records and
# the ones we have), beside ours on the records we have, with r and intervals.
PAPER_FITS_STEP = "stickslip.studies.paper_fits:write_paper_fits"


rule refit_paper_lines:
    input:
        results_path="results/tables/table6_results.csv",
        paper=PAPER_REFERENCE,
        library=library(PAPER_FITS_STEP),
    output:
        fits_path=report("results/tables/paper_fits.csv", category="Relations",
                         caption="../report/paper_fits.rst"),
    params:
        step=PAPER_FITS_STEP,
        n_boot=config["relations"]["n_boot"],
        seed=config["relations"]["seed"],
    log:
        "logs/tables/paper_fits.log",
    script:
        STEP
