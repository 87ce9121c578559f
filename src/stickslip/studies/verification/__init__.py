"""Study ``verification`` (``workflow/rules/verification.smk``): SLAMMER 1.1's own results, recomputed by
both of our schemes and judged by pySLAMMER's rules.

- :mod:`~stickslip.studies.verification.slammer`: the rigid block;
- :mod:`~stickslip.studies.verification.flexible`: the flexible block (decoupled and coupled);
- :mod:`~stickslip.studies.verification.plots`: the figures of ``notebooks/slammer_verification.ipynb``;
- :mod:`~stickslip.studies.verification.index`: the study's section of ``reports/index.html``.
"""
