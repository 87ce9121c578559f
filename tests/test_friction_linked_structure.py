"""The exact friction-linked structure against what is known without it: the structure held fixed or left free,
the friction pendulum, a brute-force integration with located events, its own ledger, a resampled record."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from stickslip.errors import StickslipError
from stickslip.solvers.restoring import restoring_history
from stickslip.solvers.structure.friction_linked import (
    FrictionLinkedSystem,
    friction_linked_history,
    friction_linked_sweep,
)
from stickslip.solvers.structure.linear_response import linear_history
from stickslip.solvers.structure.shear_building import uniform_building

G = 9.81


def isolated(stories=2, period=0.5, base=1000.0, superstructure=4000.0, radius=2.0, damping_model="modal"):
    """A building of ``stories`` on a base mass: x = (u_b, u_1 … u_n), d = e₀, N the total weight."""
    building = uniform_building(stories, period, superstructure, 0.05, damping_model)
    relative = np.hstack([-np.ones((stories, 1)), np.eye(stories)])
    system = FrictionLinkedSystem(np.diag(np.concatenate([[base], building.floor_masses])),
                                  relative.T @ building.damping_matrix @ relative,
                                  relative.T @ building.stiffness_matrix @ relative, np.eye(stories + 1)[0],
                                  (base + superstructure) * G, radius)
    return system, building


def damper(radius=math.inf):
    """A mass of 5 % on the top of a two-story building: x = (u_1, u_2, u_d), d = e_d − e_2."""
    building = uniform_building(2, 1.0, 2000.0, 0.02)
    mass = np.diag(np.concatenate([building.floor_masses, [100.0]]))
    stiffness, damping = np.zeros((3, 3)), np.zeros((3, 3))
    stiffness[:2, :2], damping[:2, :2] = building.stiffness_matrix, building.damping_matrix
    return FrictionLinkedSystem(mass, damping, stiffness, [0.0, -1.0, 1.0], 100.0 * G, radius), building


def noise(samples=1500, dt=0.01, seed=3, peak=4.0):
    """A random ground acceleration [m/s²] that starts and ends at rest."""
    rng = np.random.default_rng(seed)
    values = np.convolve(rng.normal(size=samples), np.hanning(15), mode="same")
    values *= np.sin(np.pi * np.arange(samples) / (samples - 1))
    return peak * values / np.max(np.abs(values)), dt


def test_a_bearing_that_never_slides_is_the_fixed_base_building():
    system, building = isolated(stories=3)
    acceleration, dt = noise()
    held = friction_linked_history(system, acceleration, dt, 50.0)
    fixed = linear_history(building.mass_matrix, building.damping_matrix, building.stiffness_matrix, np.ones(3),
                           acceleration, dt)
    assert held.n_slip_episodes == 0 and np.all(held.phase == 0) and np.all(held.displacement[:, 0] == 0.0)
    scale = np.max(np.abs(fixed.displacement))
    assert np.max(np.abs(held.displacement[:, 1:] - fixed.displacement)) < 1e-10 * scale
    assert np.max(np.abs(held.absolute_acceleration[:, 1:] - fixed.absolute_acceleration)) < 1e-10 * np.max(
        np.abs(fixed.absolute_acceleration))


def test_a_damper_that_never_slides_is_the_building_with_the_mass_attached():
    system, building = damper()
    acceleration, dt = noise(seed=5)
    held = friction_linked_history(system, acceleration, dt, 100.0)
    attached = linear_history(np.diag(building.floor_masses + np.array([0.0, 100.0])), building.damping_matrix,
                              building.stiffness_matrix, np.ones(2), acceleration, dt)
    scale = np.max(np.abs(attached.displacement))
    assert np.max(np.abs(held.displacement[:, :2] - attached.displacement)) < 1e-10 * scale
    assert np.max(np.abs(held.displacement[:, 2] - held.displacement[:, 1])) < 1e-13 * scale


@pytest.mark.parametrize("make", [isolated, damper])
def test_no_friction_on_a_flat_surface_is_the_free_structure(make):
    system, _ = make(radius=math.inf)
    acceleration, dt = noise(seed=7)
    free = friction_linked_history(system, acceleration, dt, 0.0)
    linear = linear_history(system.mass_matrix, system.damping_matrix, system.stiffness_matrix,
                            np.ones(system.size), acceleration, dt)
    scale = np.max(np.abs(linear.displacement))
    assert np.max(np.abs(free.displacement - linear.displacement)) < 1e-10 * scale
    assert free.energy_dissipated[-1] == 0.0


def test_one_mass_on_the_surface_is_the_friction_pendulum():
    acceleration, dt = noise(seed=11)
    system = FrictionLinkedSystem([[2.0]], [[0.0]], [[0.0]], [1.0], 2.0 * G, 1.5)
    structure = friction_linked_history(system, acceleration, dt, 0.08)
    pendulum = restoring_history(acceleration, dt, 0.08 * G, G / 1.5, G)
    scale = np.max(np.abs(pendulum["relative_displacement"]))
    assert scale > 0.05
    assert np.max(np.abs(structure.displacement[:, 0] - pendulum["relative_displacement"])) < 1e-10 * scale
    assert structure.energy_dissipated[-1] == pytest.approx(2.0 * pendulum["scalars"]["energy_dissipated"], rel=1e-10)


@pytest.mark.parametrize("make, mu", [(isolated, 0.05), (damper, 0.02), (lambda: damper(radius=3.0), 0.1)])
def test_the_ledger_closes_to_round_off_on_random_records(make, mu):
    system, _ = make()
    acceleration, dt = noise(seed=13)
    history = friction_linked_history(system, acceleration, dt, mu)
    assert history.n_slip_episodes > 3 and 0.0 < history.slip_time < 15.0
    assert np.max(np.abs(history.balance_residual)) < 1e-12 * history.energy_input.max()
    for name in ("kinetic_energy", "strain_energy", "viscous_energy", "potential_energy", "energy_dissipated"):
        assert np.all(getattr(history, name) >= -1e-12 * history.energy_input.max()), name


def test_the_ledger_closes_to_round_off_on_a_real_record(paper_records):
    record = paper_records["CHY080-N.AT2"]
    system, _ = isolated(stories=2, radius=2.5)
    history = friction_linked_history(system, record.acceleration, record.dt, 0.06)
    assert history.n_slip_episodes > 10
    assert history.energy_dissipated[-1] > 0.3 * history.energy_input[-1]
    assert np.max(np.abs(history.balance_residual)) < 1e-12 * history.energy_input.max()


def brute_force(system, acceleration, dt, mu, rtol=1e-12):
    """x at the samples by DOP853 (``rtol``) per sample interval, each phase's event located by solve_ivp."""
    n, d = system.size, system.interface
    mass = np.diag(system.mass_matrix)
    stiffness = system.stiffness_matrix + system.restoring_stiffness * np.outer(d, d)
    basis = np.linalg.svd(d[None, :])[2][1:].T
    held = basis @ np.linalg.solve(basis.T @ system.mass_matrix @ basis, basis.T)
    limit = mu * system.normal_force

    def ground(t, i):
        return acceleration[i] + (acceleration[i + 1] - acceleration[i]) * (t - i * dt) / dt

    def needed(t, z, i):  # the friction force the hold needs
        x, v = z[:n], z[n:]
        load = -stiffness @ x - system.damping_matrix @ v - mass * ground(t, i)
        residual = load - system.mass_matrix @ (held @ load) + system.restoring_stiffness * d * (d @ x)
        return d @ residual / (d @ d) - system.restoring_stiffness * (d @ x)

    def rates(t, z, i, sigma):
        x, v = z[:n], z[n:]
        load = -stiffness @ x - system.damping_matrix @ v - mass * ground(t, i)
        return np.concatenate([v, held @ load if sigma == 0 else (load - d * sigma * limit) / mass])

    def settle(t, z, i, sigma):
        force = needed(t, z, i)
        return 0 if abs(force) <= limit else int(np.sign(force))

    z = np.zeros(2 * n)
    sigma = settle(0.0, z, 0, 0)
    out = [z[:n].copy()]
    for i in range(acceleration.size - 1):
        t, end = i * dt, (i + 1) * dt
        while t < end:
            if sigma == 0:
                events = [lambda t, z, i, s: needed(t, z, i) - limit, lambda t, z, i, s: needed(t, z, i) + limit]
            else:
                events = [lambda t, z, i, s: d @ z[n:]]
            for event in events:
                event.terminal = True
            solution = solve_ivp(rates, (t, end), z, method="DOP853", rtol=rtol, atol=1e-14, events=events,
                                 args=(i, sigma))
            z, t = solution.y[:, -1], solution.t[-1]
            if solution.status == 1 and t < end:
                if sigma == 0:
                    sigma = int(np.sign(needed(t, z, i)))
                else:
                    z[n:] -= d * (d @ z[n:]) / (d @ d)
                    sigma = settle(t, z, i, sigma)
                if sigma != 0:  # step off the event's root, where the new phase's own event sits at zero
                    solution = solve_ivp(rates, (t, min(t + 1e-9, end)), z, method="DOP853", rtol=rtol, atol=1e-14,
                                         args=(i, sigma))
                    z, t = solution.y[:, -1], solution.t[-1]
        out.append(z[:n].copy())
    return np.array(out)


@pytest.mark.parametrize("make, mu", [(isolated, 0.05), (damper, 0.15)])
def test_the_closed_form_agrees_with_a_brute_force_integration(make, mu):
    system, _ = make()
    acceleration, dt = noise(samples=200, seed=17, peak=5.0)
    exact = friction_linked_history(system, acceleration, dt, mu)
    assert exact.n_slip_episodes >= 2 and np.any(exact.phase == 0) and np.any(exact.phase != 0)
    reference = brute_force(system, acceleration, dt, mu)
    assert np.max(np.abs(exact.displacement - reference)) < 1e-8 * np.max(np.abs(reference))


def test_a_record_resampled_linearly_gives_the_same_answer():
    system, _ = isolated(stories=2)
    acceleration, dt = noise(samples=800, seed=19)
    fine = np.interp(np.arange(0.0, (acceleration.size - 1) * dt + 1e-9, dt / 4), np.arange(acceleration.size) * dt,
                     acceleration)
    coarse = friction_linked_history(system, acceleration, dt, 0.05)
    resampled = friction_linked_history(system, fine, dt / 4, 0.05)
    scale = np.max(np.abs(coarse.displacement))
    assert np.max(np.abs(resampled.displacement[::4] - coarse.displacement)) < 1e-10 * scale
    assert resampled.energy_dissipated[-1] == pytest.approx(coarse.energy_dissipated[-1], rel=1e-10)
    assert resampled.peak_slip == pytest.approx(coarse.peak_slip, rel=1e-3)


def test_the_sweep_equals_the_histories():
    system, _ = isolated(stories=2)
    first, dt = noise(seed=23)
    second = noise(samples=700, seed=29)[0]
    mus = [0.0, 0.03, 0.08, 5.0]
    drift_rows = np.zeros((2, 2 * 3 + 2))
    drift_rows[0, :2] = (-1.0, 1.0)
    drift_rows[1, 1:3] = (-1.0, 1.0)
    sweep = friction_linked_sweep(system, [first, second], [dt, 0.02], mus, tracked=drift_rows)
    for r, (record, step) in enumerate(((first, dt), (second, 0.02))):
        for c, mu in enumerate(mus):
            history = friction_linked_history(system, record, step, mu, tracked=drift_rows)
            drifts = np.abs(np.diff(history.displacement, axis=1)).max(axis=0)
            assert sweep.residual_slip[r, c] == pytest.approx(history.slip[-1], rel=1e-12, abs=1e-15)
            assert sweep.energy_dissipated[r, c] == pytest.approx(history.energy_dissipated[-1], rel=1e-12, abs=1e-12)
            assert sweep.energy_input[r, c] == pytest.approx(history.energy_input[-1], rel=1e-12)
            assert sweep.peak_slip[r, c] == pytest.approx(history.peak_slip, rel=1e-12, abs=1e-15)
            assert sweep.n_slip_episodes[r, c] == history.n_slip_episodes
            assert np.allclose(sweep.peaks[r, c], history.peaks, rtol=1e-12)
            assert np.all(history.peaks >= drifts * (1 - 1e-12)) and np.all(history.peaks <= drifts * 1.03)
            assert abs(sweep.balance_residual[r, c]) < 1e-11 * history.energy_input.max()


def test_a_bad_system_is_one_clear_line():
    with pytest.raises(StickslipError, match=r"interface d: expected 2 entries with one \+1"):
        FrictionLinkedSystem(np.eye(2), np.zeros((2, 2)), np.zeros((2, 2)), [1.0, 1.0], 10.0)
    with pytest.raises(StickslipError, match=r"normal force N \[N\] must be a positive finite number"):
        FrictionLinkedSystem(np.eye(2), np.zeros((2, 2)), np.zeros((2, 2)), [1.0, 0.0], 0.0)
    system, _ = isolated()
    with pytest.raises(StickslipError, match="friction ratio mu must be a finite number >= 0"):
        friction_linked_history(system, np.zeros(10), 0.01, -0.1)
