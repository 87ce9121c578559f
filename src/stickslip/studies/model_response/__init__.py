"""Study ``model_response`` (``workflow/rules/model_response.smk``): single solved cases of the paper's model.

- :mod:`~stickslip.studies.model_response.cases`: the cases behind Figs. 2, 3, 11-12 and 16 (drawn by
  :mod:`stickslip.reports.model_plots`, which the paper's other figures share);
- :mod:`~stickslip.studies.model_response.flexible_ledger`: the energy figures under a flexible sliding mass;
- :mod:`~stickslip.studies.model_response.shaking_table`: our model beside the paper's model and test
  (Tables 3 and 4).
"""
