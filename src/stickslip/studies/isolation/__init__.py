"""Study ``isolation`` (``workflow/rules/isolation.smk``): a one-story building on friction pendulums against
the same building on a fixed base, on near-fault station pairs and three-component stations.

- :mod:`~stickslip.studies.isolation.motions`: the horizontal components the study runs on;
- :mod:`~stickslip.studies.isolation.response`: one component's peaks, on a fixed base and isolated;
- :mod:`~stickslip.studies.isolation.sweep`: every component over T × R × μ, one cube per job, gathered;
- :mod:`~stickslip.studies.isolation.tables`: the case table, the statistics over records and the study's JSON;
- :mod:`~stickslip.studies.isolation.near_far`: near-fault against far-field components per T, R and μ;
- :mod:`~stickslip.studies.isolation.with_vertical`: the three-component stations in the plane, with and without
  the vertical (integrated scheme both times), their cube and the ratios;
- :mod:`~stickslip.studies.isolation.plots`: the figures of ``notebooks/isolation_study.ipynb``;
- :mod:`~stickslip.studies.isolation.index`: the study's section of ``reports/index.html``.
"""
