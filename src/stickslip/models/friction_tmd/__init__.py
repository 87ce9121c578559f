"""The friction tuned mass damper: a mass sliding with friction on a floor of a shear building on a fixed base.

:mod:`~stickslip.models.friction_tmd.case` is the building with its damper;
:mod:`~stickslip.models.friction_tmd.references` the building's answers and
the two linear buildings the damper is judged against (bare, and with the
damper's mass attached).
"""
