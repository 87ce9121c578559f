# Intensity measures of the paper's records beside the paper's Table 5.
rule table5:
    input:
        config=CONFIG_FILE,
        code=PACKAGE_SOURCES,
        records="results/records",
    output:
        "results/tables/table5_records.csv",
        "results/tables/table5_comparison.csv",
    log:
        "logs/table5.log",
    shell:
        "stickslip study table5 --config {input.config} --out-dir results > {log} 2>&1"
