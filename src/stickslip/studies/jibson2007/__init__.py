"""Study ``jibson2007`` (``workflow/rules/jibson2007.smk``): Jibson's (2007) regressions recomputed on the
collection study's records.

- :mod:`~stickslip.studies.jibson2007.displacements`: one-way Newmark displacements, per chunk, and gathered;
- :mod:`~stickslip.studies.jibson2007.fit`: his two regression forms refitted, with bootstrap intervals;
- :mod:`~stickslip.studies.jibson2007.plots`: the figures of ``notebooks/jibson2007.ipynb``;
- :mod:`~stickslip.studies.jibson2007.index`: the study's section of ``reports/index.html``.
"""
