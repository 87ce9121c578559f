# The units of every column of results/tables/*.csv and of every NetCDF
# variable, UDUNITS spelling (stickslip.units.UNITS): results/tables/units.csv.
UNITS_STEP = "stickslip.studies.units:write_units_table"


rule write_units_table:
    input:
        library=library(UNITS_STEP),
    output:
        units_path="results/tables/units.csv",
    params:
        step=UNITS_STEP,
    log:
        "logs/tables/units.log",
    script:
        STEP
