"""Study ``damper`` (``workflow/rules/damper.smk``): the paper's question with a structure, a flat friction
damper on a one-story building, on the paper's records and the collection study's records.

- :mod:`~stickslip.studies.damper.motions`: the records the study runs on;
- :mod:`~stickslip.studies.damper.response`: one record's bare building and its damper over μ;
- :mod:`~stickslip.studies.damper.sweep`: every record over mass ratio × T × μ, and the two optima, one cube per
  job, gathered;
- :mod:`~stickslip.studies.damper.tables`: the case table, the statistics over records and the study's JSON;
- :mod:`~stickslip.studies.damper.plots`: the figures of ``notebooks/damper_study.ipynb``;
- :mod:`~stickslip.studies.damper.index`: the study's section of ``reports/index.html``.
"""
