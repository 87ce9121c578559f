"""The friction-linked structure in the plane (the integrated scheme): its oracles.

A shear building on a friction pendulum (the isolated building: d = e_0) and a
sliding mass on a building's roof (the friction tuned mass damper:
d = e_d − e_n), built from the spec's matrices, under pyslammer's sample
records as two horizontal axes and a vertical:

* a pair with one zero component is the exact one-direction solver
  (:func:`~stickslip.solvers.structure.friction_linked.friction_linked_history`);
* an interface that never slides is the linear structure on a fixed interface
  (:func:`~stickslip.solvers.structure.linear_response.linear_history` in each
  direction);
* a frictionless interface is the linear structure with the spring N₀/R across
  it (none on a flat surface: the damper's mass rides free on the bare
  building), in each direction: every event of a slip (the stops and the turns
  through zero speed in the plane) is exercised;
* turning both components turns the response;
* a constant vertical acceleration c is the normal force N₀·(1 + c/g), and in one
  direction the exact solver with g' = g + c;
* the answer does not move with the tolerance, and the ledger closes, with the
  vertical (lift-off included) and the velocity law;
* a friction law out of range, or components of different lengths, is one line.
"""

from __future__ import annotations

import dataclasses
import math
from importlib.resources import files as package_files

import numpy as np
import pytest

from stickslip.records.readers import read_record
from stickslip.errors import StickslipError
from stickslip.solvers.structure.friction_linked import FrictionLinkedSystem, friction_linked_history
from stickslip.solvers.structure.integrated import solve_structure_in_plane
from stickslip.solvers.structure.linear_response import linear_history
from stickslip.solvers.structure.shear_building import uniform_building

G = 9.81
SAMPLES = package_files("pyslammer") / "sample_ground_motions"


def isolated(stories=2, period=0.5, mass=2.0e5, mass_ratio=4.0, radius=2.0):
    """The isolated building (base first) and its fixed-base building."""
    superstructure = mass * mass_ratio / (1.0 + mass_ratio)
    building = uniform_building(stories, period, superstructure, 0.05, "modal")
    relative = np.hstack([-np.ones((stories, 1)), np.eye(stories)])
    direction = np.zeros(stories + 1)
    direction[0] = 1.0
    system = FrictionLinkedSystem(np.diag(np.r_[mass - superstructure, np.diag(building.mass_matrix)]),
                                  relative.T @ building.damping_matrix @ relative,
                                  relative.T @ building.stiffness_matrix @ relative, direction, mass * G, radius)
    return system, building


def damper(stories=2, period=1.0, mass=2.0e5, mass_ratio=0.05, radius=math.inf):
    """The building with a sliding mass on its roof (the mass last), and the bare building."""
    building = uniform_building(stories, period, mass, 0.02, "modal")
    size = stories + 1
    damping = np.zeros((size, size))
    stiffness = np.zeros((size, size))
    damping[:stories, :stories] = building.damping_matrix
    stiffness[:stories, :stories] = building.stiffness_matrix
    direction = np.zeros(size)
    direction[-1] = 1.0
    direction[-2] = -1.0
    system = FrictionLinkedSystem(np.diag(np.r_[np.diag(building.mass_matrix), mass_ratio * mass]), damping,
                                  stiffness, direction, mass_ratio * mass * G, radius)
    return system, building


@pytest.fixture(scope="module")
def motion():
    """Northridge VSP-360 and Loma Prieta HSP-000 (0.005 s) as the horizontal axes, Coalinga PVB-045 as the
    vertical (positive up), cut to 15 s."""
    first = read_record(SAMPLES / "Northridge_1994_VSP-360.csv")
    second = read_record(SAMPLES / "Loma_Prieta_1989_HSP-000.csv")
    third = read_record(SAMPLES / "Coalinga_1983_PVB-045.csv")
    assert first.dt == second.dt == third.dt
    length = 3001
    return (first.acceleration[:length], second.acceleration[:length], third.acceleration[:length], first.dt)


def ledger_closes(answer, tolerance=1e-9):
    """The ledger closes at every sample to ``tolerance`` of the input so far (horizontal and vertical)."""
    scale = np.maximum.accumulate(np.abs(answer.energy_input) + np.abs(answer.energy_input_vertical))
    return np.abs(answer.balance_residual).max() <= tolerance * scale[-1]


@pytest.mark.parametrize("build, mu", [(isolated, 0.06), (lambda: damper(radius=2.0), 0.1), (damper, 0.05)],
                         ids=["isolated", "damper-curved", "damper-flat"])
def test_a_pair_with_one_zero_component_is_the_exact_one_direction_solver(motion, build, mu):
    first, _, _, dt = motion
    system = build()[0]
    exact = friction_linked_history(system, first, dt, mu)
    answer = solve_structure_in_plane(system, first, np.zeros_like(first), dt, mu_slow=mu)
    assert np.count_nonzero(np.diff(exact.phase)) >= 5  # stops, turns and breakaways to reproduce
    assert np.all(answer.displacement[..., 1] == 0.0)
    assert answer.n_slip_episodes == exact.n_slip_episodes
    scale = np.abs(exact.displacement).max()
    assert np.abs(answer.displacement[..., 0] - exact.displacement).max() <= 1e-8 * scale
    assert np.abs(answer.velocity[..., 0] - exact.velocity).max() <= 1e-8 * np.abs(exact.velocity).max()
    assert np.abs(answer.absolute_acceleration[..., 0] - exact.absolute_acceleration).max() \
        <= 1e-8 * np.abs(exact.absolute_acceleration).max()
    assert np.array_equal(answer.moving, (exact.phase != 0).astype(float))
    for name in ("energy_dissipated", "energy_input", "viscous_energy", "kinetic_energy", "sliding_path"):
        assert getattr(answer, name)[-1] == pytest.approx(getattr(exact, name)[-1], rel=1e-8), name
    assert answer.slip_time == pytest.approx(exact.slip_time, rel=1e-8)


def test_an_interface_that_never_slides_is_the_building_on_a_fixed_base(motion):
    first, second, _, dt = motion
    system, building = isolated()
    answer = solve_structure_in_plane(system, first, second, dt, mu_slow=5.0)
    assert answer.moving.max() == 0.0
    scale = np.abs(answer.displacement).max()
    assert scale > 1e-3
    assert np.abs(answer.displacement[:, 0, :]).max() <= 1e-12 * scale  # the base stays put, to round-off
    for axis, record in enumerate((first, second)):
        fixed = linear_history(building.mass_matrix, building.damping_matrix, building.stiffness_matrix,
                               np.ones(building.stories), record, dt)
        assert np.abs(answer.displacement[:, 1:, axis] - fixed.displacement).max() <= 1e-9 * scale
        assert np.abs(answer.absolute_acceleration[:, 1:, axis] - fixed.absolute_acceleration).max() \
            <= 1e-9 * np.abs(fixed.absolute_acceleration).max()
    # the force that holds the base: the whole structure's inertia, less the surface's restoring force (none here)
    holding = -np.einsum("kij,i->kj", answer.absolute_acceleration, np.diag(system.mass_matrix))
    assert np.abs(answer.interface_force - holding).max() <= 1e-9 * np.abs(holding).max()
    assert answer.energy_dissipated[-1] == 0.0
    assert ledger_closes(answer)


@pytest.mark.parametrize("build", [isolated, lambda: damper(radius=1.5), damper],
                         ids=["isolated", "damper-curved", "damper-flat"])
def test_a_frictionless_interface_is_the_linear_structure_with_its_spring(motion, build):
    first, second, _, dt = motion
    system = build()[0]
    answer = solve_structure_in_plane(system, first, second, dt, mu_slow=0.0)
    spring = system.restoring_stiffness * np.outer(system.interface, system.interface)
    scale = np.abs(answer.displacement).max()
    for axis, record in enumerate((first, second)):
        linear = linear_history(system.mass_matrix, system.damping_matrix, system.stiffness_matrix + spring,
                                np.ones(system.size), record, dt)
        assert np.abs(answer.displacement[..., axis] - linear.displacement).max() <= 1e-8 * scale
        assert np.abs(answer.velocity[..., axis] - linear.velocity).max() <= 1e-8 * np.abs(linear.velocity).max()
    assert answer.energy_dissipated[-1] == 0.0
    assert answer.n_slip_episodes >= 1


@pytest.mark.parametrize("build, mu", [(isolated, 0.06), (damper, 0.1)], ids=["isolated", "damper"])
def test_turning_both_components_turns_the_response(motion, build, mu):
    first, second, vertical, dt = motion
    system = build()[0]
    angle = 0.7
    cos, sin = np.cos(angle), np.sin(angle)
    answer = solve_structure_in_plane(system, first, second, dt, vertical=vertical, mu_slow=mu)
    turned = solve_structure_in_plane(system, cos * first - sin * second, sin * first + cos * second, dt,
                                      vertical=vertical, mu_slow=mu)
    expected = np.stack([cos * answer.displacement[..., 0] - sin * answer.displacement[..., 1],
                         sin * answer.displacement[..., 0] + cos * answer.displacement[..., 1]], axis=-1)
    assert answer.moving.sum() > 100
    assert np.abs(turned.displacement - expected).max() <= 1e-8 * np.abs(expected).max()
    for name in ("energy_dissipated", "energy_input", "energy_input_vertical", "sliding_path"):
        assert getattr(turned, name)[-1] == pytest.approx(getattr(answer, name)[-1], rel=1e-8, abs=1e-6), name


@pytest.mark.parametrize("build, mu", [(isolated, 0.06), (lambda: damper(radius=2.0), 0.1)],
                         ids=["isolated", "damper"])
def test_a_constant_vertical_acceleration_scales_the_normal_force(motion, build, mu):
    first, second, _, dt = motion
    system = build()[0]
    lifted = 0.3 * G
    heavier = dataclasses.replace(system, normal_force=system.normal_force * (1.0 + lifted / G))
    constant = np.full(first.size, lifted)
    with_vertical = solve_structure_in_plane(system, first, second, dt, vertical=constant, mu_slow=mu)
    scaled = solve_structure_in_plane(heavier, first, second, dt, mu_slow=mu)
    scale = np.abs(scaled.displacement).max()
    assert np.abs(with_vertical.displacement - scaled.displacement).max() <= 1e-9 * scale
    assert with_vertical.energy_dissipated[-1] == pytest.approx(scaled.energy_dissipated[-1], rel=1e-9)
    # the work of the vertical through the curved surface, −∫(ΔN/R)·s·ds: less the extra potential energy the
    # heavier N stores (the ledger keeps E_p at the static N₀)
    assert with_vertical.energy_input_vertical[-1] == pytest.approx(
        with_vertical.potential_energy[-1] - scaled.potential_energy[-1], rel=1e-8)
    # and in one direction, the exact solver with g' = g + a_v
    along = solve_structure_in_plane(system, first, np.zeros_like(first), dt, vertical=constant, mu_slow=mu)
    exact = friction_linked_history(heavier, first, dt, mu)
    assert np.abs(along.displacement[..., 0] - exact.displacement).max() <= 1e-8 * np.abs(exact.displacement).max()


@pytest.mark.parametrize("build, mu, law", [
    (isolated, 0.06, {}),
    (isolated, 0.04, {"mu_fast": 0.08, "rate": 30.0}),
    (lambda: damper(radius=2.0), 0.1, {}),
    (damper, 0.05, {"mu_fast": 0.1, "rate": 20.0}),
], ids=["isolated", "isolated-velocity-law", "damper-curved", "damper-velocity-law"])
def test_the_answer_holds_to_the_tolerance_and_the_ledger_closes(motion, build, mu, law):
    first, second, vertical, dt = motion
    system = build()[0]
    answer = solve_structure_in_plane(system, first, second, dt, vertical=vertical, mu_slow=mu, **law)
    finer = solve_structure_in_plane(system, first, second, dt, vertical=vertical, mu_slow=mu, rtol=1e-12, **law)
    assert answer.n_slip_episodes >= 1
    assert np.abs(answer.displacement - finer.displacement).max() <= 1e-9 * np.abs(finer.displacement).max()
    assert answer.energy_dissipated[-1] == pytest.approx(finer.energy_dissipated[-1], rel=1e-9)
    assert ledger_closes(answer)


def test_the_interface_flies_where_the_normal_force_vanishes_and_the_ledger_closes(motion):
    first, second, vertical, dt = motion
    system = isolated()[0]
    downwards = -3.0 * vertical  # up to 1.1 g downwards
    answer = solve_structure_in_plane(system, first, second, dt, vertical=downwards, mu_slow=0.06)
    flying = answer.normal_force == 0.0
    assert answer.flight_time > 0.0
    assert flying.any()
    assert np.all(answer.friction_force[flying] == 0.0)
    assert np.all(answer.moving[flying] == 1.0)
    assert ledger_closes(answer)


def test_a_friction_law_out_of_range_is_one_clear_error(motion):
    first, second, _, dt = motion
    with pytest.raises(StickslipError, match=r"^friction law mu_fast must be a finite number >= 0, got -0.1$"):
        solve_structure_in_plane(isolated()[0], first, second, dt, mu_slow=0.05, mu_fast=-0.1)
    with pytest.raises(StickslipError, match=r"^the components must have as many samples as the first \(3001\)$"):
        solve_structure_in_plane(isolated()[0], first, second[:-1], dt, mu_slow=0.05)
