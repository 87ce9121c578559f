"""The simplified (empirical) Newmark estimates SLAMMER 1.1 offers, checked against the papers.

One module per family: :mod:`~stickslip.estimates.jibson` (Jibson 1993,
Jibson et al. 2000, Jibson 2007 eqs. 6, 7, 9, 10, and the probability of
failure), :mod:`~stickslip.estimates.ambraseys_menu`,
:mod:`~stickslip.estimates.saygili_rathje` (Saygili and Rathje 2008, Rathje
and Saygili 2009), :mod:`~stickslip.estimates.bray_travasarou` and
:mod:`~stickslip.estimates.rathje_antonakos`.  Each method returns an
:class:`~stickslip.estimates.estimate.Estimate`: the median displacement [m],
σ with the base of its logarithm, P(D = 0) where the method defines one, and
P(D > d).  :mod:`~stickslip.estimates.registry` declares them all once; the
command ``stickslip estimate`` and the library study take what applies from it,
and :mod:`~stickslip.estimates.ranking` ranks them by their error against the
rigorous answers.
The differences from SLAMMER and from other open codes: docs/estimates.md.
"""
