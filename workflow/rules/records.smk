# Acquire and validate the paper's records (local folder, pyslammer samples,
# checksummed download) and store each as results/records/{id}.nc.  Records no
# source can provide are listed as missing, with how to obtain them.
rule fetch_records:
    input:
        config=CONFIG_FILE,
        code=PACKAGE_SOURCES,
        manifest=config["records_manifest"],
    output:
        directory("results/records"),
    log:
        "logs/fetch_records.log",
    shell:
        "stickslip records fetch --out-dir {output} > {log} 2>&1 && cat {log}"
