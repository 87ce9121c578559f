"""Solvers for a rigid sliding block on a moving base: flat friction (the paper's Eq. 1), one-way and two-way slopes.

What resists sliding is a :class:`~stickslip.models.rigid.resistance.Resistance`.
Each scheme is one module with ``sliding_history(acceleration, dt,
resistance, **options) -> SolverHistory`` and its ``SCHEME`` entry, named in
:data:`stickslip.models.rigid.scheme.SCHEME_MODULES`: ``exact``
(:mod:`~stickslip.models.rigid.exact_scheme`, on the event kernel of
:mod:`~stickslip.models.rigid.events` compiled by :mod:`~stickslip.models.rigid.exact`),
``newmark`` and ``slammer``.  :func:`stickslip.solve` asks the entry what the
scheme accepts and turns the history into a :class:`stickslip.models.rigid.response.Response`.
"""
