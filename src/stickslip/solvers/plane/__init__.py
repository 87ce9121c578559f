"""The solver of a block sliding in the plane: flat or on a spherical dish, with or without the vertical.

Per unit mass and relative to the ground, with u, v ∈ ℝ² the block's
displacement and velocity, a(t) ∈ ℝ² the horizontal ground acceleration and
a_v(t) the vertical one (positive up), both linear between samples, the normal
force per unit mass is n(t) = g + a_v(t) and the block, on a surface of
curvature κ = 1/R (κ = 0: flat; small-angle geometry),

* sticks (v = 0) while the force needed to hold it, |b| with
  b = a + κ·n·u, stays within μ(0)·n;
* slides with v̇ = −b − μ(|v|)·n·v/|v|: the restoring force −κ·n·u and one
  friction force opposite to the sliding velocity (the friction circle), of
  coefficient μ(s) = μ_fast − (μ_fast − μ_slow)·e^{−rate·s} (Coulomb:
  μ_fast = μ_slow);
* breaks away when |b| rises past μ(0)·n, along −b/|b|, and stops when |v|
  reaches zero; it then sticks if |b| ≤ μ(0)·n and breaks away again otherwise;
* flies where n ≤ 0 (it lifts off the surface: no friction, no restoring
  force, v̇ = −a) and lands where n rises past 0, with its velocity.

A model composes what it slides on (:mod:`~stickslip.solvers.plane.resistance`:
the friction law, the curvature, the normal force from the vertical) and
calls :func:`solve_pair_on_surface` or :func:`sweep_pairs_on_surface`: the
flat block (:mod:`stickslip.models.planar`) Coulomb's μ·g with n = 1 and κ = 0,
the friction pendulum in the plane (:mod:`stickslip.models.pendulum.pair`) its
friction law, 1/R, g and the vertical.

Between the events the slip equation has no closed form in general: it is
integrated with DOP853 to a relative tolerance ``rtol`` on the velocity
(:mod:`~stickslip.solvers.plane.stepping`).  With the speed scale
S = 2·(max|a| + μ·max n)·dt, the regimes of the speed s = |v|, one module
each, keep the integration non-stiff and the events exact:

* **fast** (s ≥ ``s_switch`` = :data:`~stickslip.solvers.plane.record.SWITCH_RATIO`·S,
  :mod:`~stickslip.solvers.plane.sliding`): the time t is the
  independent variable and the steps end on the samples, where a(t) has its
  kinks; a step that would carry v past zero is refused and shortened;
* **settled** (on the slow manifold of the direction,
  :mod:`~stickslip.solvers.plane.settled`, its series in
  :mod:`~stickslip.solvers.plane.manifold`): only s, u and the energies are
  integrated, in time, while the series holds; a stop (s = 0) and the speed
  where the series ends are located by Newton's method on the step, and a
  decelerating step goes no further than the stop at its present
  deceleration.  The manifold depends on the rate of a, which jumps at the
  samples: there the velocity goes on from the manifold of the interval that
  ends;
* **slow** (below ``s_switch``, off the manifold,
  :mod:`~stickslip.solvers.plane.sliding`): the independent variable
  becomes σ with dt = s·dσ (a Sundman transformation); a step that would pass
  a sample is brought onto it by Newton's method;
* **stopping** (s < ``s_lock`` = ``lock_ratio``·S off the manifold,
  |b| < μ(0)·n, :mod:`~stickslip.solvers.plane.stopping`): the rest of the
  slip in closed form, where its estimated error is below the tolerance;
* **flight** (n ≤ 0, :mod:`~stickslip.solvers.plane.flight`): in closed form.

A stick (:mod:`~stickslip.solvers.plane.stick`) costs almost nothing: whole
blocks of samples are proven stuck from their bounds.  The events of one sample
interval are :mod:`~stickslip.solvers.plane.interval`'s, the record's and the
sweep's :mod:`~stickslip.solvers.plane.record`'s.

The ledger per unit mass, each term integrated as a state of its own so that
the balance E_k − E_k(0) + E_p − E_p(0) + E_df − E_I − W_v = 0 is a genuine
check: E_df/m = ∫μ·n·s dt (friction), W_v/m = −∫κ·(n − g)·u·v dt (the work of
the vertical motion through the normal force on the curved surface: zero where
n = g, and ½·g·κ·(|u|² − |u₀|²) over a flight, where n is 0), E_I/m = ∫ü·u̇_g dt
with ü = a in stick, −κ·n·u − μ·n·v/|v| in slip and 0 in flight,
E_k/m = ½·|u̇_g + v|², and the potential energy E_p/m = ½·g·κ·|u|², a state
(the restoring force's work ∫κ·n·u·v dt is E_p − E_p(0) − W_v).

All functions are numba kernels over plain arrays, compiled with
``cache=True``.  The kernels that allocate nothing are compiled without
numba's reference counting of arrays (``_nrt=False``): counting the arrays
passed between them cost a third of the time.  numba renews a kernel's cache
when the kernel's own file changes, not when a module it calls does: after
editing one module of this package, delete the package's cached kernels
(``*.nbi`` and ``*.nbc`` in its ``__pycache__``, or under ``NUMBA_CACHE_DIR``)
before running it again.
"""

from stickslip.solvers.plane.interval import MAX_PASSES
from stickslip.solvers.plane.record import (
    HISTORY_NAMES, LOCK_RATIO, PLANAR_SCALAR_NAMES, RTOL, SURFACE_SCALAR_NAMES, check_progress, solve_pair_on_surface,
    sweep_pairs_on_surface)

__all__ = ["HISTORY_NAMES", "LOCK_RATIO", "MAX_PASSES", "PLANAR_SCALAR_NAMES", "RTOL", "SURFACE_SCALAR_NAMES",
           "check_progress", "solve_pair_on_surface", "sweep_pairs_on_surface"]
