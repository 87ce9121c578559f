"""OpenSees models of the friction-linked structures, for the oracle tests: a shear building on a sliding
bearing, and a shear building on a fixed base carrying a sliding mass.

Both are 2-D models (``ndm 2``, ``ndf 3``) whose nodes all sit at the origin
and move horizontally (global X, direction 1) under a ``UniformExcitation``
of the ground acceleration a_g [m/s²], a Path time series linear between
samples, as in stickslip.  The stories are ``zeroLength`` elements in
direction 1: an ``Elastic`` material of the story stiffness k_j [N/m], and
the building's damping matrix C_b [N·s/m] as ``Viscous`` dashpots, one
between floors i and j of coefficient −C_b[i, j] and one between floor i and
the building's base of coefficient Σ_j C_b[i, j] (any symmetric C_b is such
a set of dashpots, so the modal and the Rayleigh matrices are modelled
exactly).  Floor nodes carry their masses m_j [kg] horizontally; their
vertical and rotational degrees of freedom are fixed.

The friction interface is a ``flatSliderBearing`` (R = ∞) or a
``singleFPBearing`` of effective radius R [m], Coulomb friction μ, initial
stiffness kInit [N/m], its local x axis vertical (global Y) and its shear
direction −X (as in tests/test_pendulum_opensees.py), its axial material
elastic and 1,000 times stiffer than kInit.  The weight that the bearing
carries is a nodal load applied in one static step and held (``loadConst``):

- **the isolated building**: the bearing between the fixed ground node and
  the base node (mass m_b), which carries the whole weight (m_b + Σ m_j)·g;
  the stories stand on the base node;
- **the damper**: the stories stand on the fixed ground node, and the
  bearing joins floor j's node to the damper's node (mass m_d, weight m_d·g).

Integrator: HHT α = 0.7, KrylovNewton, a step of :data:`SUBSTEP` (the other
OpenSees oracles' settings, tests/test_opensees_oracle.py).  kInit
regularises the stick: the bearing's elastic stretch at the friction force
is μ·N/kInit [m], and OpenSees's answer approaches the exact one as kInit
grows.  A ``singleFPBearing`` also departs from the small-angle model by
terms of the order μ·u/R + (u/R)² (tests/test_pendulum_opensees.py).

What is read, at every analysis step: the floors' displacements relative to
the ground [m], their absolute accelerations [m/s²] (OpenSees's relative
acceleration plus a_g), the slip s across the bearing [m], the bearing's
shear force [N], and the first story's shear [N] (the force of the elements
between the building's base and the floors above it).  The friction work
E_df [J] is ∫(V − N·s/R)·ds over the steps (V the bearing's shear, N its
axial force, in OpenSees's own N = P + V·s/R for the pendulum), minus the
elastic energy left in the regularising spring at the end.
"""

from __future__ import annotations

import math

import numpy as np
import openseespy.opensees as ops  # a test dependency in environment-test.lock; never skipped
from test_opensees_oracle import apply_weight, transient_analysis

#: Analysis time step [s]: each record sample is split into round(dt/SUBSTEP) steps.
SUBSTEP = 5e-4
_GROUND, _BASE, _DAMPER = 1, 2, 3


def _floor(j: int) -> int:
    """The node of floor j (1 the lowest)."""
    return 10 + j


def _stories(building, base: int) -> list[int]:
    """The floors' nodes and the ``building``'s stories and dashpots standing on node ``base``; returns the tags of
    the elements touching ``base`` (whose forces sum to the first story's shear)."""
    n = building.stories
    damping_matrix = building.damping_matrix
    for j in range(1, n + 1):
        ops.node(_floor(j), 0.0, 0.0)
        ops.fix(_floor(j), 0, 1, 1)
        ops.mass(_floor(j), float(building.floor_masses[j - 1]), 0.0, 0.0)
    below = [base] + [_floor(j) for j in range(1, n)]
    on_base = []
    tag = 100

    def link(lower: int, upper: int, material: tuple) -> None:
        nonlocal tag
        tag += 1
        ops.uniaxialMaterial(*material[:1], tag, *material[1:])
        ops.element("zeroLength", tag, lower, upper, "-mat", tag, "-dir", 1)
        if lower == base:
            on_base.append(tag)

    for j in range(1, n + 1):
        link(below[j - 1], _floor(j), ("Elastic", float(building.story_stiffnesses[j - 1])))
        grounded = float(damping_matrix[j - 1].sum())
        if grounded != 0.0:
            link(base, _floor(j), ("Viscous", grounded, 1.0))
        for i in range(j + 1, n + 1):
            if damping_matrix[j - 1, i - 1] != 0.0:
                link(_floor(j), _floor(i), ("Viscous", -float(damping_matrix[j - 1, i - 1]), 1.0))
    return on_base


def _bearing(lower: int, upper: int, mu: float, radius: float, initial_stiffness: float) -> None:
    """Element 1: a Coulomb bearing from ``lower`` to ``upper`` (module docstring)."""
    ops.frictionModel("Coulomb", 1, mu)
    ops.uniaxialMaterial("Elastic", 1, 1e3 * initial_stiffness)
    ops.uniaxialMaterial("Elastic", 2, 1e3 * initial_stiffness)
    orient = ("-orient", 0.0, 1.0, 0.0, -1.0, 0.0, 0.0)
    if math.isinf(radius):
        ops.element("flatSliderBearing", 1, lower, upper, 1, initial_stiffness, "-P", 1, "-Mz", 2, *orient)
    else:
        ops.element("singleFPBearing", 1, lower, upper, 1, radius, initial_stiffness, "-P", 1, "-Mz", 2, *orient)


def _run(acceleration: np.ndarray, dt: float, building, base: int, slip_nodes: tuple[int, int],
         on_base: list[int], radius: float, initial_stiffness: float) -> dict:
    """Drive the model built so far, the ``building`` standing on node ``base``, with ``acceleration`` [m/s²]
    sampled every ``dt`` [s]; read every step."""
    n = building.stories
    ops.timeSeries("Path", 2, "-dt", dt, "-values", *np.asarray(acceleration, dtype=float).tolist())
    ops.pattern("UniformExcitation", 2, 1, "-accel", 2)
    transient_analysis()
    substeps = max(1, round(dt / SUBSTEP))
    step = dt / substeps
    n_steps = (acceleration.size - 1) * substeps
    floors = [_floor(j) for j in range(1, n + 1)]
    displacement, velocity = np.zeros((n_steps + 1, n)), np.zeros((n_steps + 1, n))
    base_displacement, base_velocity = np.zeros(n_steps + 1), np.zeros(n_steps + 1)
    slip, shear, axial, story_shear = (np.zeros(n_steps + 1) for _ in range(4))
    axial[0] = ops.basicForce(1)[0]
    lower, upper = slip_nodes
    for i in range(1, n_steps + 1):
        if ops.analyze(1, step) != 0 and ops.analyze(10, step / 10) != 0:
            raise AssertionError(f"OpenSees failed to converge at step {i}")
        displacement[i] = [ops.nodeDisp(node, 1) for node in floors]
        velocity[i] = [ops.nodeVel(node, 1) for node in floors]
        if base != _GROUND:
            base_displacement[i], base_velocity[i] = ops.nodeDisp(base, 1), ops.nodeVel(base, 1)
        slip[i] = ops.nodeDisp(upper, 1) - (ops.nodeDisp(lower, 1) if lower != _GROUND else 0.0)
        axial[i], shear[i] = ops.basicForce(1)[:2]
        story_shear[i] = sum(ops.basicForce(tag)[0] for tag in on_base)
    ops.wipe()
    # the bearing's shear acts along −X: s = −(shear deformation), and its shear force along +X is −shear
    force = -shear
    normal = -axial + (0.0 if math.isinf(radius) else shear * (-slip) / radius)  # SingleFPSimple2d's N
    friction = force - (0.0 if math.isinf(radius) else normal * slip / radius)
    work = float(np.sum(0.5 * (friction[1:] + friction[:-1]) * np.diff(slip)))
    restoring = 0.0 if math.isinf(radius) else normal[-1] / radius
    elastic = friction[-1] ** 2 / (2 * (initial_stiffness - restoring))
    # each floor's absolute acceleration from the forces on it at the step (HHT's own acceleration satisfies
    # the equations of motion between steps, not at them)
    stories = ((displacement - base_displacement[:, None]) @ building.stiffness_matrix
               + (velocity - base_velocity[:, None]) @ building.damping_matrix)
    carried = np.zeros((n_steps + 1, n))
    if lower != _GROUND:
        carried[:, floors.index(lower)] = force
    return {"time": np.arange(n_steps + 1) * step, "substeps": substeps, "floor_displacement": displacement,
            "floor_acceleration": (carried - stories) / building.floor_masses, "slip": slip,
            "bearing_force": force, "normal_force": -axial, "story_shear": story_shear,
            "energy_dissipated": work - elastic}


def opensees_isolated(building, base_mass: float, mu: float, radius: float, initial_stiffness: float,
                      acceleration: np.ndarray, dt: float, g: float) -> dict:
    """A shear ``building`` (a :class:`~stickslip.solvers.structure.shear_building.ShearBuilding`) on a base of
    ``base_mass`` [kg] sliding on a bearing of friction ratio ``mu`` and radius ``radius`` [m] (inf: flat) with
    ``initial_stiffness`` kInit [N/m], under ``acceleration`` [m/s²] sampled every ``dt`` [s]; ``g`` [m/s²].
    Returns the histories at the analysis steps (module docstring); ``slip`` is the base's displacement relative
    to the ground, ``story_shear`` the superstructure's base shear V_s [N]."""
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.node(_GROUND, 0.0, 0.0)
    ops.fix(_GROUND, 1, 1, 1)
    ops.node(_BASE, 0.0, 0.0)
    ops.fix(_BASE, 0, 0, 1)
    ops.mass(_BASE, base_mass, 0.0, 0.0)
    on_base = _stories(building, _BASE)
    _bearing(_GROUND, _BASE, mu, radius, initial_stiffness)
    weight = (base_mass + building.total_mass) * g
    apply_weight(_BASE, (0.0, -weight, 0.0), "the building's weight")
    return _run(acceleration, dt, building, _BASE, (_GROUND, _BASE), on_base, radius, initial_stiffness)


def opensees_damper(building, damper_mass: float, story: int, mu: float, radius: float, initial_stiffness: float,
                    acceleration: np.ndarray, dt: float, g: float) -> dict:
    """A shear ``building`` on a fixed base carrying on floor ``story`` (1 the lowest) a mass ``damper_mass`` [kg]
    that slides on a bearing of friction ratio ``mu``, radius ``radius`` [m] (inf: flat) and ``initial_stiffness``
    kInit [N/m].  Returns the histories at the analysis steps (module docstring); ``slip`` is the damper's stroke
    (its displacement relative to floor ``story``), ``story_shear`` the building's base shear V_b [N]."""
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.node(_GROUND, 0.0, 0.0)
    ops.fix(_GROUND, 1, 1, 1)
    on_base = _stories(building, _GROUND)
    ops.node(_DAMPER, 0.0, 0.0)
    ops.fix(_DAMPER, 0, 0, 1)
    ops.mass(_DAMPER, damper_mass, 0.0, 0.0)
    _bearing(_floor(story), _DAMPER, mu, radius, initial_stiffness)
    apply_weight(_DAMPER, (0.0, -damper_mass * g, 0.0), "the damper's weight")
    return _run(acceleration, dt, building, _GROUND, (_floor(story), _DAMPER), on_base, radius,
                initial_stiffness)


def at_samples(history: dict, name: str) -> np.ndarray:
    """The history ``name`` of an OpenSees run at the record's samples (every ``substeps``-th analysis step)."""
    return history[name][::history["substeps"]]
