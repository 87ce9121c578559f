# Intensity measures: one job per record (results/measures/{record}.json),
# then the records table beside the paper's Table 5.
MEASURES_STEP = "stickslip.studies.measures.record_measures:write_record_measures"
RECORDS_TABLE_STEP = "stickslip.studies.measures.records_table:write_records_table"


rule compute_measures:
    input:
        record_path="results/records/{record}.nc",
        library=library(MEASURES_STEP),
    output:
        measures_path="results/measures/{record}.json",
    params:
        step=MEASURES_STEP,
        g=config["gravity"],
    log:
        "logs/measures/{record}.log",
    resources:
        mem_mb=500,
        runtime=10,
    script:
        STEP


rule write_records_table:
    input:
        measures_paths=expand("results/measures/{record}.json", record=PAPER_RECORDS),
        paper=PAPER_REFERENCE,
        library=library(RECORDS_TABLE_STEP),
    output:
        table_path=report("results/tables/table5_records.csv", category="Records",
                          caption="../report/table5_records.rst"),
        comparison_path=report("results/tables/table5_comparison.csv", category="Comparison with the paper",
                               caption="../report/comparison.rst"),
    params:
        step=RECORDS_TABLE_STEP,
        tolerances=config["comparison_tolerance"],
    log:
        "logs/tables/records_table.log",
    script:
        STEP
