"""Solvers for a rigid block with Coulomb friction on a moving base (the paper's Eq. 1).

Each solver module provides ``solve_history(acceleration, dt, mu, g, **options)
-> SolverHistory``; :func:`stickslip.solve` dispatches on the method name and
turns the history into a :class:`stickslip.response.Response`.
"""
