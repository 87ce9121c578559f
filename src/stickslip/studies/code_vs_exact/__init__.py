"""Study ``code_vs_exact`` (``workflow/rules/code_vs_exact.smk``): the codes' equivalent-linear displacement
of a friction pendulum against the exact one, on the station pairs and the three-component stations.

- :mod:`~stickslip.studies.code_vs_exact.displacement`: one record's code displacement from its own spectrum;
- :mod:`~stickslip.studies.code_vs_exact.cases`: per station, direction, R, μ and code (one job per chunk);
- :mod:`~stickslip.studies.code_vs_exact.analysis`: bias, scatter and unconservative share over the library;
- :mod:`~stickslip.studies.code_vs_exact.plots`: the figures of ``notebooks/code_vs_exact.ipynb``;
- :mod:`~stickslip.studies.code_vs_exact.index`: the study's section of ``reports/index.html``.
"""
