"""Numerical pieces that several models share: the event engine, the resistances it composes, compilation, the plane.

:mod:`~stickslip.solvers.events` is the event engine, the stick → slip → stop
loop over a record and the lanes of a sweep, written once and driven by a
model's phase functions, with the pieces of the event loop inside an interval;
:mod:`~stickslip.solvers.closed_forms` the closed forms of one sample interval
that the event-driven kernels share; :mod:`~stickslip.solvers.restoring` is
Coulomb friction with a restoring stiffness on the engine (the friction
pendulum's and the spring's); :mod:`~stickslip.solvers.ledger` is the layout of
what the one-direction sliders return; :mod:`~stickslip.solvers.compilation`
compiles kernels with numba, the engine on a model's phase functions among
them; :mod:`~stickslip.solvers.dop853` holds the tableau of the integrated
kernels (the planar block's, the pendulum's); :mod:`~stickslip.solvers.harmonic`
holds the closed forms of a rigid block on a harmonically moving base (the
oracles); :mod:`~stickslip.solvers.plane` the solver of a block sliding in the
plane, flat or curved, with or without the vertical (the flat block's and the
friction pendulum's in the plane).  Nothing here imports a model.
"""
