# Acquisition: one job per record.  Each record is read from the records
# folder, the pyslammer sample motions or a checked download, validated, and
# stored as results/records/{record}.nc, values in g converted with the
# config's gravity; a record no source has is stored as "missing", with how to
# obtain it, and every later stage names it so.
ACQUIRE_STEP = "stickslip.records.acquire:store_record"


rule acquire_record:
    input:
        local_record_files,
        manifest=config["records_manifest"],
        library=library(ACQUIRE_STEP),
    output:
        path="results/records/{record}.nc",
    params:
        step=ACQUIRE_STEP,
        record_id="{record}",
        records_dir=RECORDS_DIR,
        accept_unknown=config.get("accept_unknown_versions", False),
        download=config.get("download_records", True),
        g=config["gravity"],
    log:
        "logs/records/{record}.log",
    resources:
        mem_mb=500,
        runtime=10,
    script:
        STEP
