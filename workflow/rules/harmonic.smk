# Harmonic base motion: E_df of the shaking-table cases under each reading of
# the paper's "u_g0 = 30 mm" (Table 4, model column), then beside the paper's.
HARMONIC_STEP = "stickslip.studies.harmonic:write_harmonic_energies"
HARMONIC_COMPARISON_STEP = "stickslip.studies.harmonic:write_harmonic_comparison"


rule solve_harmonic_cases:
    input:
        library=library(HARMONIC_STEP),
    output:
        energy_path="results/tables/harmonic_energy.csv",
    params:
        step=HARMONIC_STEP,
        settings=config["harmonic"],
        mass=config["block_mass"],
        g=config["gravity"],
    log:
        "logs/tables/harmonic.log",
    script:
        STEP


rule compare_harmonic:
    input:
        energy_path="results/tables/harmonic_energy.csv",
        paper=PAPER_REFERENCE,
        library=library(HARMONIC_COMPARISON_STEP),
    output:
        readings_path=report("results/tables/table4_readings.csv", category="Harmonic base motion",
                             caption="../report/table4_readings.rst"),
        comparison_path=report("results/tables/table4_comparison.csv", category="Comparison with the paper",
                               caption="../report/comparison.rst"),
    params:
        step=HARMONIC_COMPARISON_STEP,
        tolerances=config["comparison_tolerance"],
    log:
        "logs/tables/compare_harmonic.log",
    script:
        STEP
