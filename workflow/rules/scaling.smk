# Records scaled to target PGAs (the paper's Table 8, Figs. 24 and 25): the
# unscaled sweep is the paper grid's, the scaled one the "scaled" grid's.
SCALING_STEP = "stickslip.studies.scaling:write_scaling_table"
SCALING_COMPARISON_STEP = "stickslip.studies.scaling:write_scaling_comparison"


rule compute_scaling:
    input:
        unscaled_path="results/sweeps/paper.nc",
        scaled_path="results/sweeps/scaled.nc",
        library=library(SCALING_STEP),
    output:
        table_path=report("results/tables/table8_results.csv", category="Scaling",
                          caption="../report/table8_results.rst"),
    params:
        step=SCALING_STEP,
    log:
        "logs/tables/scaling.log",
    script:
        STEP


rule compare_scaling:
    input:
        table_path="results/tables/table8_results.csv",
        paper=PAPER_REFERENCE,
        library=library(SCALING_COMPARISON_STEP),
    output:
        comparison_path=report("results/tables/table8_comparison.csv", category="Comparison with the paper",
                               caption="../report/comparison.rst"),
    params:
        step=SCALING_COMPARISON_STEP,
        tolerances=config["comparison_tolerance"],
    log:
        "logs/tables/compare_scaling.log",
    script:
        STEP
