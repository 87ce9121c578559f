# Harmonic rows of the paper's Table 4, and the target that builds everything.

rule table4:
    """Harmonic base motion, both readings of the paper's u_g0 = 30 mm."""
    input:
        config=CONFIG_FILE,
        code=PACKAGE_SOURCES,
    output:
        "results/tables/table4_readings.csv",
        "results/tables/table4_comparison.csv",
    log:
        "logs/table4.log",
    shell:
        "stickslip study table4 --config {input.config} --out-dir results > {log} 2>&1"
