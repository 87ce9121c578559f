"""Study ``collections`` (``workflow/rules/collections.smk``): the paper's question on every record of a
collection, one job per chunk of records (``docs/collections.md``).

- :mod:`~stickslip.studies.collections.records`: a chunk of the collection's records, read, checked, stored;
- :mod:`~stickslip.studies.collections.measures`: the chunk's intensity measures;
- :mod:`~stickslip.studies.collections.sweep`: the chunk's friction sweeps, and the study gathered;
- :mod:`~stickslip.studies.collections.measures_check`: our measures against the collection's published ones;
- :mod:`~stickslip.studies.collections.relations`: μ_max against the records' measures and metadata;
- :mod:`~stickslip.studies.collections.friction_design`: coverage of a fixed μ, the paper's claims, the design chart;
- :mod:`~stickslip.studies.collections.analysis`: the findings, written in one step;
- :mod:`~stickslip.studies.collections.scaling_law`: E_df(k·μ; k·a) = k²·E_df(μ; a), checked on records;
- :mod:`~stickslip.studies.collections.tables` and :mod:`~stickslip.studies.collections.plots`: the tables
  and figures of ``notebooks/collection_study.ipynb``;
- :mod:`~stickslip.studies.collections.index`: the study's section of ``reports/index.html``.
"""
