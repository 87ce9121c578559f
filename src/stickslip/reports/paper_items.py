"""Every table and figure of the paper, and what stands for it in our outputs (the index page's account).

:data:`PAPER_ITEMS` lists each item of the paper in order with an outcome:

- ``regenerated``: computed again from the paper's records and settings;
- ``substituted``: computed on something else, because what the paper used
  is missing (the reason says what and why);
- ``test data not published``: the item shows shaking-table measurements,
  which the paper does not publish;
- ``not reproducible``: a drawing or photograph, with nothing to compute.

``outputs`` are glob patterns under the ``results`` or ``reports`` folder
(``("reports", "figures/fig2_*.png")``); the index links every file they match
and says when none was produced in the run.
"""

from __future__ import annotations

REGENERATED = "regenerated"
SUBSTITUTED = "substituted"
TEST_DATA = "test data not published"
NOT_REPRODUCIBLE = "not reproducible"

_PHOTO = "a photograph or drawing of the test set-up or model: nothing to compute"
_TESTS = "shaking-table measurements; the paper publishes no test data"

#: (paper item, outcome, outputs, reason), in the paper's order.
PAPER_ITEMS: tuple[dict, ...] = (
    {"item": "Table 1", "what": "contact interfaces", "outcome": NOT_REPRODUCIBLE, "outputs": (),
     "reason": "a description of the test materials: nothing to compute"},
    {"item": "Table 2", "what": "unit weights of the ANSYS model", "outcome": NOT_REPRODUCIBLE, "outputs": (),
     "reason": "material data of the paper's ANSYS model; our rigid-block model needs only m = 5.10 kg"},
    {"item": "Table 3, model column", "what": "residual displacements", "outcome": REGENERATED,
     "outputs": (("results", "tables/table3_comparison.csv"), ("results", "tables/table3_table4_model.csv")),
     "reason": "harmonic and Kobe rows; the Mendoza rows are not comparable (record missing)"},
    {"item": "Table 3, test column", "what": "residual displacements", "outcome": TEST_DATA, "outputs": (),
     "reason": "the printed test values are shown beside ours in table3_table4_model.csv"},
    {"item": "Table 4, model column", "what": "E_df of the shaking-table cases", "outcome": REGENERATED,
     "outputs": (("results", "tables/table4_comparison.csv"), ("results", "tables/table4_records_comparison.csv"),
                 ("results", "tables/table4_readings.csv")),
     "reason": "harmonic and Kobe rows; the Mendoza rows are not comparable (record missing)"},
    {"item": "Table 4, test column", "what": "E_df measured", "outcome": TEST_DATA, "outputs": (),
     "reason": "the printed test values are shown beside ours in table3_table4_model.csv"},
    {"item": "Table 5", "what": "the records", "outcome": REGENERATED,
     "outputs": (("results", "tables/table5_comparison.csv"),), "reason": "six of eight records"},
    {"item": "Table 6", "what": "E_df,max and μ_max per record", "outcome": REGENERATED,
     "outputs": (("results", "tables/table6_comparison.csv"), ("results", "tables/paper_fits.csv")),
     "reason": "six of eight records; the printed RMS column is an erratum (errata.csv)"},
    {"item": "Table 7", "what": "near-optimal μ ranges", "outcome": REGENERATED,
     "outputs": (("results", "tables/table7_comparison.csv"),), "reason": "six of eight records"},
    {"item": "Table 8", "what": "scaling study", "outcome": SUBSTITUTED,
     "outputs": (("results", "tables/table8_results.csv"), ("results", "tables/table8_comparison.csv")),
     "reason": "the paper scaled Mendoza 1985, which is missing: every record we have is scaled instead"},
    {"item": "Fig. 1", "what": "problem formulation", "outcome": NOT_REPRODUCIBLE, "outputs": (),
     "reason": "a schematic drawing"},
    {"item": "Fig. 2", "what": "harmonic base motion, stick-slip and permanent slip", "outcome": REGENERATED,
     "outputs": (("reports", "figures/fig2_harmonic_regimes.png"),), "reason": "exact solver, closed forms marked"},
    {"item": "Fig. 3", "what": "Algorithm 1 at Δt = 0.003 s, μ = 0.10", "outcome": SUBSTITUTED,
     "outputs": (("reports", "figures/fig3_algorithm1_substitute.png"),),
     "reason": "Mendoza 1985 is missing; drawn on the substitute record named in the figure, with the exact solution"},
    {"item": "Figs. 4, 5, 7, 13", "what": "test set-up, blocks, ANSYS model", "outcome": NOT_REPRODUCIBLE,
     "outputs": (), "reason": _PHOTO},
    {"item": "Figs. 6, 8, 9, 10", "what": "measured block and table accelerations", "outcome": TEST_DATA,
     "outputs": (), "reason": _TESTS},
    {"item": "Figs. 11-12, tests", "what": "energies from the test measurements", "outcome": TEST_DATA,
     "outputs": (), "reason": _TESTS},
    {"item": "Figs. 11-12, model", "what": "E_k, E_df, E_I against time", "outcome": SUBSTITUTED,
     "outputs": (("reports", "figures/fig11_12_energy_*.png"),),
     "reason": "the model's energies for the harmonic and Kobe cases, in place of the unpublished test energies "
               "(the Mendoza case is missing)"},
    {"item": "Figs. 14, 15", "what": "block acceleration, test against ANSYS model", "outcome": TEST_DATA,
     "outputs": (), "reason": _TESTS},
    {"item": "Fig. 16", "what": "relative displacement, friction force, friction loops", "outcome": REGENERATED,
     "outputs": (("reports", "figures/fig16_friction_*.png"),), "reason": "Kobe KJMA 090 × 0.65 and the harmonic case"},
    {"item": "Fig. 17", "what": "the records", "outcome": REGENERATED,
     "outputs": (("reports", "figures/fig17_records.png"),), "reason": "six of eight records"},
    {"item": "Figs. 18-20", "what": "effect of the time step", "outcome": REGENERATED,
     "outputs": (("reports", "figures/fig1[89]_timestep.png"), ("reports", "figures/fig20_timestep.png")),
     "reason": "Algorithm 1 at two time steps beside the exact solver"},
    {"item": "Fig. 21", "what": "E_df against μ", "outcome": REGENERATED,
     "outputs": (("reports", "figures/fig21_energy_vs_mu.png"),), "reason": "six of eight records"},
    {"item": "Figs. 22, 23", "what": "μ_max against PGA and RMS", "outcome": REGENERATED,
     "outputs": (("reports", "figures/fig22_mu_max_vs_pga.png"), ("reports", "figures/fig23_mu_max_vs_rms.png"),
                 ("results", "tables/paper_fits.csv")),
     "reason": "six of eight records; the paper's own lines recomputed from its Table 6 in paper_fits.csv"},
    {"item": "Figs. 24, 25", "what": "scaling study", "outcome": SUBSTITUTED,
     "outputs": (("reports", "figures/fig24_scaling_mu_max_vs_pga.png"),
                 ("reports", "figures/fig25_scaling_mu_max_vs_rms.png")),
     "reason": "Mendoza 1985 is missing: every record we have is scaled instead"},
)
