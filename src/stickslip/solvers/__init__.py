"""Solvers for a rigid sliding block on a moving base: flat friction (the paper's Eq. 1), one-way and two-way slopes.

What resists sliding is a :class:`~stickslip.solvers.resistance.Resistance`.
Each solver module registered in :data:`stickslip.solution.SOLVERS` provides
``sliding_history(acceleration, dt, resistance, **options) -> SolverHistory``;
:func:`stickslip.solve` dispatches on the method name and turns the history
into a :class:`stickslip.response.Response`.
"""
