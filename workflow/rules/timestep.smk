# The paper's time-step study (section 5.2.1, Figs. 18-20): Algorithm 1 at
# two integration steps beside the exact solver, on one record.
TIMESTEP_STEP = "stickslip.studies.timestep:write_timestep_study"


rule compare_time_steps:
    input:
        record_path=f"results/records/{TIMESTEP_RECORD}.nc",
        library=library(TIMESTEP_STEP),
    output:
        cube_path=f"results/sweeps/timestep_{TIMESTEP_RECORD}.nc",
        summary_path=report(f"results/tables/timestep_{TIMESTEP_RECORD}_summary.csv", category="Time step",
                            caption="../report/timestep_summary.rst"),
    params:
        step=TIMESTEP_STEP,
        mus=config["timestep_study"]["mus"],
        time_steps=config["timestep_study"]["time_steps"],
        mass=config["block_mass"],
        g=config["gravity"],
    log:
        "logs/tables/timestep.log",
    script:
        STEP
