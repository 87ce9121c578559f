# Friction-ratio sweeps (NetCDF cubes) and the tables derived from them.

rule table6:
    """Paper grid and fine grid sweeps; Tables 6 and 7; mu_max fits (Figs. 21-23)."""
    input:
        config=CONFIG_FILE,
        code=PACKAGE_SOURCES,
        records="results/records",
    output:
        "results/sweeps/paper_grid.nc",
        "results/sweeps/paper_fine.nc",
        "results/tables/table6_results.csv",
        "results/tables/table7_ranges.csv",
        "results/tables/table6_comparison.csv",
        "results/tables/table7_comparison.csv",
        "results/fits.json",
    log:
        "logs/table6.log",
    shell:
        "stickslip study table6 --config {input.config} --out-dir results > {log} 2>&1"


rule table8:
    """Scaling study at target PGAs (the paper's Table 8, Figs. 24-25)."""
    input:
        config=CONFIG_FILE,
        code=PACKAGE_SOURCES,
        records="results/records",
    output:
        "results/sweeps/table8_scaling.nc",
        "results/tables/table8_results.csv",
        "results/tables/table8_comparison.csv",
    log:
        "logs/table8.log",
    shell:
        "stickslip study table8 --config {input.config} --out-dir results > {log} 2>&1"


rule mass_study:
    """E_df / m against mu for several block masses."""
    input:
        config=CONFIG_FILE,
        code=PACKAGE_SOURCES,
        records="results/records",
    output:
        "results/sweeps/mass.nc",
        "results/tables/mass_check.csv",
    log:
        "logs/mass_study.log",
    shell:
        "stickslip study mass --config {input.config} --out-dir results > {log} 2>&1"


rule timestep_study:
    """Newmark at two time steps beside the exact solver (the paper's Figs. 18-20)."""
    input:
        config=CONFIG_FILE,
        code=PACKAGE_SOURCES,
        records="results/records",
    output:
        f"results/sweeps/timestep_{TIMESTEP_RECORD}.nc",
        f"results/tables/timestep_{TIMESTEP_RECORD}_summary.csv",
    log:
        "logs/timestep_study.log",
    shell:
        "stickslip study timestep --config {input.config} --out-dir results > {log} 2>&1"
