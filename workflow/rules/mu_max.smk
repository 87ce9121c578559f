# mu_max of every paper record on the paper's grid, the fine grid and
# continuous, with the near-optimal ranges (Tables 6 and 7); then the same
# beside the paper's printed values.
MU_MAX_STEP = "stickslip.studies.mu_max:write_mu_max_tables"
MU_MAX_COMPARISON_STEP = "stickslip.studies.mu_max:write_mu_max_comparisons"


rule find_mu_max:
    input:
        grid_path="results/sweeps/paper.nc",
        fine_path="results/sweeps/fine.nc",
        library=library(MU_MAX_STEP),
    output:
        results_path=report("results/tables/table6_results.csv", category="mu_max",
                            caption="../report/table6_results.rst"),
        ranges_path=report("results/tables/table7_ranges.csv", category="mu_max",
                           caption="../report/table7_ranges.rst"),
    params:
        step=MU_MAX_STEP,
        q=config["mu_max"]["near_optimal_fraction"],
    log:
        "logs/tables/mu_max.log",
    script:
        STEP


rule compare_mu_max:
    input:
        results_path="results/tables/table6_results.csv",
        ranges_path="results/tables/table7_ranges.csv",
        grid_path="results/sweeps/paper.nc",
        errata_path="results/tables/errata.csv",
        paper=PAPER_REFERENCE,
        library=library(MU_MAX_COMPARISON_STEP),
    output:
        table6_path=report("results/tables/table6_comparison.csv", category="Comparison with the paper",
                           caption="../report/comparison.rst"),
        table7_path=report("results/tables/table7_comparison.csv", category="Comparison with the paper",
                           caption="../report/comparison.rst"),
        q_path="results/tables/table7_q_intervals.csv",
    params:
        step=MU_MAX_COMPARISON_STEP,
        tolerances=config["comparison_tolerance"],
    log:
        "logs/tables/compare_mu_max.log",
    script:
        STEP
