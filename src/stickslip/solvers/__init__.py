"""Numerical pieces that several models share: numba compilation, the Dormand–Prince tableau, the harmonic closed forms.

:mod:`~stickslip.solvers.compilation` compiles a module's kernels with numba
so that they call each other compiled; :mod:`~stickslip.solvers.dop853` holds
the tableau of the integrated kernels (the planar block's, the pendulum's);
:mod:`~stickslip.solvers.harmonic` holds the closed forms of a rigid block on
a harmonically moving base (the oracles).  Each model's own schemes and
kernels live under :mod:`stickslip.models`; nothing here imports them.
"""
