# mu_max against PGA and RMS acceleration across records: lines, r,
# bootstrap bands (the paper's Figs. 22 and 23).
RELATIONS_STEP = "stickslip.studies.relations:write_relations"


rule fit_relations:
    input:
        results_path="results/tables/table6_results.csv",
        library=library(RELATIONS_STEP),
    output:
        fits_path="results/fits.json",
    params:
        step=RELATIONS_STEP,
        n_boot=config["relations"]["n_boot"],
        seed=config["relations"]["seed"],
        min_records=config["relations"]["min_records"],
    log:
        "logs/tables/relations.log",
    script:
        STEP
