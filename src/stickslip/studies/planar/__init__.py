"""Study ``planar`` (``workflow/rules/planar.smk``): the paper's question in two dimensions, on the station
pairs of the collection study's records (``docs/planar.md``).

- :mod:`~stickslip.studies.planar.pairs`: which two horizontal components of one station make a pair;
- :mod:`~stickslip.studies.planar.sweep`: the pairs listed, each chunk of pairs swept, the chunks gathered;
- :mod:`~stickslip.studies.planar.ratios`: per pair, the optimum in the plane beside the 1-D ones, and R;
- :mod:`~stickslip.studies.planar.design`: the relations with PGA and RMS, the design chart, near against far;
- :mod:`~stickslip.studies.planar.analysis`: the findings, written in one step;
- :mod:`~stickslip.studies.planar.plots`: the figures of ``notebooks/planar_study.ipynb``;
- :mod:`~stickslip.studies.planar.index`: the study's section of ``reports/index.html``.
"""
