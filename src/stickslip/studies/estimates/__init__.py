"""Study ``estimates`` (``workflow/rules/estimates.smk``): the simplified displacement estimates measured
against the rigorous answers on every record of the collection study (``docs/estimates.md``).

- :mod:`~stickslip.studies.estimates.simplified`: the estimates and the rigorous answers, per chunk, and their ranking;
- :mod:`~stickslip.studies.estimates.plots`: the figures of ``notebooks/estimates.ipynb``;
- :mod:`~stickslip.studies.estimates.index`: the study's section of ``reports/index.html``.
"""
