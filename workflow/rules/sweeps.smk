# Friction-ratio sweeps: one job per (grid, record), each a cube
# results/sweeps/{grid}/{record}.nc; then one gathered cube per grid,
# results/sweeps/{grid}.nc, in the order of the grid's records.  The grids
# (common.smk): the paper's mu grid, the fine grid (with the continuous
# mu_max), the records scaled to target PGAs, and the block masses.
SWEEP_STEP = "stickslip.studies.sweeps:write_record_sweep"
GATHER_STEP = "stickslip.studies.sweeps:gather_grid"


rule sweep_record:
    input:
        record_path="results/records/{record}.nc",
        measures_path="results/measures/{record}.json",
        library=library(SWEEP_STEP),
    output:
        cube_path="results/sweeps/{grid}/{record}.nc",
    params:
        step=SWEEP_STEP,
        grid=lambda wildcards: SWEEP_GRIDS[wildcards.grid],
        name="{grid}",
        mass=config["block_mass"],
        g=config["gravity"],
    threads: config.get("sweep_threads", 1)
    log:
        "logs/sweeps/{grid}/{record}.log",
    resources:
        mem_mb=1000,
        runtime=30,
    script:
        STEP


rule gather_sweeps:
    input:
        cube_paths=lambda wildcards: expand("results/sweeps/{grid}/{record}.nc", grid=wildcards.grid,
                                            record=GRID_RECORDS[wildcards.grid]),
        library=library(GATHER_STEP),
    output:
        gathered_path="results/sweeps/{grid}.nc",
    params:
        step=GATHER_STEP,
    log:
        "logs/sweeps/{grid}.log",
    script:
        STEP
