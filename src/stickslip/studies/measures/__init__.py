"""Study ``measures`` (``workflow/rules/measures.smk``): the intensity measures of the paper's records.

- :mod:`~stickslip.studies.measures.record_measures`: one stored record -> its intensity measures;
- :mod:`~stickslip.studies.measures.records_table`: the measures -> the records table beside the paper's Table 5.
"""
