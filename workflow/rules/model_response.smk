# Single solved cases: the paper's Figs. 2, 3, 11-12 and 16, and our model of
# the shaking-table cases beside the paper's model and test (Tables 3 and 4);
# beyond the paper, the record of Figs. 11-12 under a flexible sliding mass.
MODEL_RESPONSE_STEP = "stickslip.studies.model_response.cases:write_model_responses"
FLEXIBLE_LEDGER_STEP = "stickslip.studies.model_response.flexible_ledger:write_flexible_ledgers"
SHAKING_TABLE_STEP = "stickslip.studies.model_response.shaking_table:write_shaking_table_comparison"
MODEL_CASES = ["fig2_stick_slip", "fig2_permanent_slip", "fig3_algorithm1", "fig3_exact", "harmonic_model",
               "seismic_model"]


rule solve_model_responses:
    input:
        fig3_record_path=f"results/records/{FIG3_RECORD}.nc",
        seismic_record_path=f"results/records/{SEISMIC_RECORD}.nc",
        library=library(MODEL_RESPONSE_STEP),
    output:
        expand("results/model/{case}.nc", case=MODEL_CASES),
        table_path=report("results/tables/model_responses.csv", category="Single solved cases",
                          caption="../report/model_responses.rst"),
    params:
        step=MODEL_RESPONSE_STEP,
        responses_dir=lambda wildcards, output: str(Path(output[0]).parent),
        settings=config["model_response"],
        mass=config["block_mass"],
        g=config["gravity"],
    log:
        "logs/tables/model_responses.log",
    script:
        STEP


rule solve_flexible_ledgers:
    input:
        seismic_record_path=f"results/records/{SEISMIC_RECORD}.nc",
        library=library(FLEXIBLE_LEDGER_STEP),
    output:
        decoupled_path="results/model/flexible_decoupled.nc",
        coupled_path="results/model/flexible_coupled.nc",
    params:
        step=FLEXIBLE_LEDGER_STEP,
        settings=config["model_response"],
        g=config["gravity"],
    log:
        "logs/tables/flexible_ledgers.log",
    script:
        STEP


rule compare_shaking_table:
    input:
        cases_path="results/tables/model_responses.csv",
        paper=PAPER_REFERENCE,
        library=library(SHAKING_TABLE_STEP),
    output:
        model_path=report("results/tables/table3_table4_model.csv", category="Single solved cases",
                          caption="../report/model_responses.rst"),
        table3_path=report("results/tables/table3_comparison.csv", category="Comparison with the paper",
                           caption="../report/comparison.rst"),
        table4_path=report("results/tables/table4_records_comparison.csv", category="Comparison with the paper",
                           caption="../report/comparison.rst"),
    params:
        step=SHAKING_TABLE_STEP,
        tolerances=config["comparison_tolerance"],
    log:
        "logs/tables/compare_shaking_table.log",
    script:
        STEP
