"""Study ``vertical`` (``workflow/rules/vertical.smk``): the vertical ground motion on sliders and
pendulums, on the three-component stations.

- :mod:`~stickslip.studies.vertical.records`: the three-component records, acquired from a folder and checked;
- :mod:`~stickslip.studies.vertical.sweep`: every station, radius and vertical variant swept over μ;
- :mod:`~stickslip.studies.vertical.effect`: what the vertical motion changes: the study's tables;
- :mod:`~stickslip.studies.vertical.plots`: the figures of ``notebooks/vertical_study.ipynb``;
- :mod:`~stickslip.studies.vertical.index`: the study's section of ``reports/index.html``.
"""
