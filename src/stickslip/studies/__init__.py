"""The paper's studies and our extensions, one package per study.

A study's package holds its computation, its figures and its section of ``reports/index.html``, and is
wired by the workflow file of the same name, ``workflow/rules/<study>.smk``. Its computing modules turn
the files of an earlier workflow stage into tables (CSV), cubes (NetCDF) or JSON, atomically, and never
open a source record file; its figures only draw what those wrote (``docs/studies.md``).

- :mod:`~stickslip.studies.measures`: stored records -> their intensity measures and the records table
  (the paper's Table 5);
- :mod:`~stickslip.studies.sweeps`: stored record -> its friction-ratio sweep on a grid; gathering;
- :mod:`~stickslip.studies.mu_max`: sweeps -> μ_max and near-optimal ranges (Tables 6 and 7);
- :mod:`~stickslip.studies.relations`: μ_max against PGA and RMS acceleration (Figs. 22 and 23);
- :mod:`~stickslip.studies.scaling`: scaled records (Table 8, Figs. 24 and 25);
- :mod:`~stickslip.studies.harmonic`: harmonic base motion (Table 4);
- :mod:`~stickslip.studies.timestep`: Algorithm 1 at two time steps (Figs. 18 to 20);
- :mod:`~stickslip.studies.mass`: E_df per unit mass across block masses;
- :mod:`~stickslip.studies.model_response`: single solved cases (Figs. 2, 3, 11-12, 16) and the
  shaking-table comparison (Tables 3 and 4);
- :mod:`~stickslip.studies.errata`: the paper's errata, each found by a computed check;
- :mod:`~stickslip.studies.paper_fits`: the paper's μ_max lines from its own Table 6, beside ours;
- :mod:`~stickslip.studies.units`: every table column and NetCDF variable with its units;
- :mod:`~stickslip.studies.verification`: SLAMMER 1.1's own rigid and flexible results, recomputed by
  both schemes and judged by pySLAMMER's rules;
- :mod:`~stickslip.studies.collections`: the paper's question on every record of a collection;
- :mod:`~stickslip.studies.jibson2007`: Jibson's (2007) regressions recomputed on the collection;
- :mod:`~stickslip.studies.estimates`: the simplified estimates against the rigorous answers;
- :mod:`~stickslip.studies.planar`: the collection's station pairs sliding in the plane;
- :mod:`~stickslip.studies.vertical`: the vertical ground motion on sliders and pendulums;
- :mod:`~stickslip.studies.code_vs_exact`: the codes' equivalent-linear displacement against the exact one;
- :mod:`~stickslip.studies.isolation`: a building on friction pendulums against the same building on a fixed base;
- :mod:`~stickslip.studies.damper`: the paper's question with a structure, a friction damper on a building.

Shared by several studies:

- :mod:`~stickslip.studies.compare`: our values beside the paper's, cell by cell;
- :mod:`~stickslip.studies.references`: the stored reference tables of the CI check.

``workflow/rules/records.smk`` (acquisition), ``common.smk`` (configuration) and ``reports.smk`` (pages
and the index) serve every study and have no package here.
"""
