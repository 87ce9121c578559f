"""Numerical pieces that several models share: the planar kernel, numba compilation, the harmonic closed forms.

:mod:`~stickslip.solvers.planar_kernel` integrates a block sliding in the plane
(the planar model's solver; its Dormand–Prince tableau also serves the
pendulum's integrated scheme); :mod:`~stickslip.solvers.compilation` compiles a
module's kernels with numba so that they call each other compiled;
:mod:`~stickslip.solvers.harmonic` holds the closed forms of a rigid block on a
harmonically moving base (the oracles).  Each model's own schemes live under
:mod:`stickslip.models`.
"""
