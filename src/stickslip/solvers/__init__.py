"""Numerical pieces that several models share: numba compilation, the Dormand–Prince tableau, closed forms, the plane.

:mod:`~stickslip.solvers.compilation` compiles a module's kernels with numba
so that they call each other compiled; :mod:`~stickslip.solvers.dop853` holds
the tableau of the integrated kernels (the planar block's, the pendulum's);
:mod:`~stickslip.solvers.harmonic` holds the closed forms of a rigid block on
a harmonically moving base (the oracles); :mod:`~stickslip.solvers.closed_forms`
the closed forms of one sample interval that the event-driven kernels share;
:mod:`~stickslip.solvers.plane` the solver of a block sliding in the plane,
flat or curved, with or without the vertical (the flat block's and the friction
pendulum's in the plane).  Each model's own schemes and
kernels live under :mod:`stickslip.models`; nothing here imports them.
"""
