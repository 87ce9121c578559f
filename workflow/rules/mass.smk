# E_df per unit mass across block masses (the "mass" sweep grid): the sweep's
# handling of m.  The physical check (m in the model) is the OpenSees test.
MASS_STEP = "stickslip.studies.mass:write_mass_check"


rule check_mass_scaling:
    input:
        cube_path="results/sweeps/mass.nc",
        library=library(MASS_STEP),
    output:
        check_path=report("results/tables/mass_check.csv", category="Checks", caption="../report/mass_check.rst"),
    params:
        step=MASS_STEP,
    log:
        "logs/tables/mass_check.log",
    script:
        STEP
