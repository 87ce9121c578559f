"""The paper's studies and our extensions, one module per thing computed.

Each module turns the files of an earlier workflow stage into tables (CSV),
cubes (NetCDF) or JSON, atomically, and never opens a source record file:

- :mod:`~stickslip.studies.record_measures`: stored record -> its intensity measures;
- :mod:`~stickslip.studies.measures_table`: measures -> the records table (the paper's Table 5);
- :mod:`~stickslip.studies.record_sweep`: stored record -> its friction-ratio sweep on a grid; gathering;
- :mod:`~stickslip.studies.mu_max`: sweeps -> μ_max and near-optimal ranges (Tables 6 and 7);
- :mod:`~stickslip.studies.relations`: μ_max against PGA and RMS acceleration (Figs. 22 and 23);
- :mod:`~stickslip.studies.scaling`: scaled records (Table 8, Figs. 24 and 25);
- :mod:`~stickslip.studies.harmonic`: harmonic base motion (Table 4);
- :mod:`~stickslip.studies.mass`: E_df per unit mass across block masses;
- :mod:`~stickslip.studies.model_response`: single solved cases (Figs. 2, 3, 11-12, 16);
- :mod:`~stickslip.studies.shaking_table`: our model beside the paper's model and test (Tables 3 and 4);
- :mod:`~stickslip.studies.errata`: the paper's errata, each found by a computed check;
- :mod:`~stickslip.studies.paper_fits`: the paper's μ_max lines from its own Table 6, beside ours;
- :mod:`~stickslip.studies.timestep`: Algorithm 1 at two time steps (Figs. 18 to 20);
- :mod:`~stickslip.studies.compare`: our values beside the paper's, cell by cell;
- :mod:`~stickslip.studies.references`: the stored reference tables of the CI check.
- :mod:`~stickslip.studies.slammer_verification`: SLAMMER 1.1's own rigid results, recomputed by
  both schemes and judged by pySLAMMER's rules (it reads pyslammer's sample motions itself).

``workflow/rules/*.smk`` wires them together; see ``docs/studies.md``.
"""
