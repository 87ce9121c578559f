# Errata of the paper found by computed checks (results/tables/errata.csv); the
# comparison tables mark the cells a confirmed erratum explains.
ERRATA_STEP = "stickslip.studies.errata:write_errata"


rule check_errata:
    input:
        seismic_path="results/model/seismic_model.nc",
        harmonic_path="results/model/harmonic_model.nc",
        readings_path="results/tables/table4_readings.csv",
        paper=PAPER_REFERENCE,
        library=library(ERRATA_STEP),
    output:
        errata_path=report("results/tables/errata.csv", category="Comparison with the paper",
                           caption="../report/errata.rst"),
    params:
        step=ERRATA_STEP,
        g=config["gravity"],
    log:
        "logs/tables/errata.log",
    script:
        STEP
