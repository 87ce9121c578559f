"""The friction-linked structure's sweep passes a hold in blocks of samples: only where it can prove the block
quiet, to the same answer as the history that steps every interval."""

from __future__ import annotations

import numpy as np
import pytest

from stickslip.solvers.events import BLOCK
from stickslip.solvers.structure import friction_linked as linked
from stickslip.solvers.structure import friction_linked_kernels as kernels
from stickslip.solvers.structure.friction_linked import (
    FrictionLinkedSystem,
    friction_linked_history,
    friction_linked_sweep,
)
from stickslip.solvers.structure.shear_building import uniform_building

G = 9.81
MU = 0.1
DT = 0.01


def building_on_a_slider() -> FrictionLinkedSystem:
    """Two stories of 4000 kg (T = 0.5 s, 5 % modal damping) on a 1000 kg base on a pendulum of R = 2 m."""
    building = uniform_building(2, 0.5, 4000.0, 0.05, "modal")
    relative = np.hstack([-np.ones((2, 1)), np.eye(2)])
    return FrictionLinkedSystem(np.diag(np.concatenate([[1000.0], building.floor_masses])),
                                relative.T @ building.damping_matrix @ relative,
                                relative.T @ building.stiffness_matrix @ relative, np.eye(3)[0], 5000.0 * G, 2.0)


def long_holds() -> np.ndarray:
    """A ground acceleration [m/s²]: 6 s that never break the hold (0.2 m/s² at 1 Hz), 4 s of a 4 m/s² pulse
    train that slides it, then 20 s at rest: long holds from rest and after a slide."""
    t = np.arange(3000) * DT
    record = 0.2 * np.sin(2 * np.pi * t) * (t < 6.0)
    strong = (t >= 6.0) & (t < 10.0)
    record[strong] = 4.0 * np.sin(2 * np.pi * 1.3 * (t[strong] - 6.0)) * np.sin(np.pi * (t[strong] - 6.0) / 4.0)
    return record


DRIFTS = np.zeros((2, 8))
DRIFTS[0, :2] = (-1.0, 1.0)
DRIFTS[1, 1:3] = (-1.0, 1.0)


@pytest.fixture(scope="module")
def blocks():
    """The history at μ = 0.1 and the sweep's arrays of its blocks (held from rest, and the case's bound)."""
    system, record = building_on_a_slider(), long_holds()
    arrays = linked._kernel_system(system, DRIFTS, [DT])
    steps = linked._dt_steps(arrays, DT)
    modes = linked._held_modes(system, np.vstack([arrays.system[2], arrays.system[3][0]]))
    step, skip = linked._skip_case(system, steps, modes, steps[1])
    slope, velocity = linked._ground(record, DT)
    held = linked._held_arrays(arrays, steps, step, record, slope, velocity, steps[1])
    history = friction_linked_history(system, record, DT, MU, tracked=DRIFTS)
    return system, record, slope, velocity, held, skip, history


def state_at(history, record, slope, velocity, i) -> np.ndarray:
    """w = (x, ẋ, u̇_g, a, ȧ, σμ) of the history at sample i, holding."""
    return np.concatenate([history.displacement[i], history.velocity[i], [velocity[i], record[i], slope[i], 0.0]])


def reached(history) -> np.ndarray:
    """The peaks the sweep tracks, in its order: |s|, then the tracked rows."""
    return np.concatenate([[history.peak_slip], history.peaks])


def passed(blocks, i, peaks):
    """_skipped_block at sample i from the history's state: (passed, w after, totals added, peaks after), ``peaks``
    those already reached (:func:`reached`)."""
    system, record, slope, velocity, held, skip, history = blocks
    w = state_at(history, record, slope, velocity, i)
    totals = np.zeros(kernels.TOTALS)
    peaks = np.array(peaks, dtype=float)
    points = held[7].shape[1]  # the search points per interval, as the force's at them
    done = kernels._skipped_block(held, skip, points, w, i, MU, system.normal_force, system.interface, totals,
                                  peaks, np.zeros((7, 10)))
    return done, w, totals, peaks


def test_a_block_held_from_rest_is_the_held_response_bit_for_bit(blocks):
    system, record, slope, velocity, held, skip, history = blocks
    assert history.n_slip_episodes > 0 and np.all(history.phase[:601] == 0)
    done, w, totals, peaks = passed(blocks, 2 * BLOCK, np.zeros(3))
    assert done
    assert np.array_equal(w[:6], state_at(history, record, slope, velocity, 3 * BLOCK)[:6])
    assert totals[kernels.VISCOUS] > 0.0
    assert peaks[1] > 0.0 and peaks[2] > 0.0


def test_a_quiet_block_after_a_slide_is_passed_to_round_off(blocks):
    system, record, slope, velocity, held, skip, history = blocks
    last_slide = np.flatnonzero(history.phase != 0).max()
    starts = [i for i in range(0, record.size - BLOCK, BLOCK) if i > last_slide]
    outcomes = [(i, passed(blocks, i, reached(history))) for i in starts]
    passed_blocks = [(i, outcome) for i, outcome in outcomes if outcome[0]]
    assert len(passed_blocks) > 0.9 * len(starts)
    scale = np.abs(history.displacement).max(), np.abs(history.velocity).max()
    for i, (_, w, totals, peaks) in passed_blocks:
        after = i + BLOCK
        assert history.slip[i] != 0.0  # off the held response's rest: the bound, not the at-rest path
        assert np.allclose(w[:3], history.displacement[after], rtol=0, atol=1e-12 * scale[0])
        assert np.allclose(w[3:6], history.velocity[after], rtol=0, atol=1e-12 * scale[1])
        for name, column in (("viscous_energy", kernels.VISCOUS), ("energy_input", kernels.INPUT)):
            energy = getattr(history, name)
            assert totals[column] == pytest.approx(energy[after] - energy[i], rel=0,
                                                   abs=1e-12 * np.abs(energy).max())
        assert np.array_equal(peaks, reached(history))


def test_a_block_where_the_hold_breaks_is_stepped(blocks):
    system, record, slope, velocity, held, skip, history = blocks
    breaks = [i for i in range(0, record.size - BLOCK, BLOCK)
              if history.phase[i] == 0 and np.any(history.phase[i:i + BLOCK + 1] != 0)]
    assert breaks
    for i in breaks:
        assert not passed(blocks, i, reached(history))[0]


def test_a_block_that_could_set_a_peak_takes_it_at_its_points(blocks):
    system, record, slope, velocity, held, skip, history = blocks
    last_slide = np.flatnonzero(history.phase != 0).max()
    i = next(i for i in range(last_slide // BLOCK * BLOCK + BLOCK, record.size - BLOCK, BLOCK)
             if passed(blocks, i, reached(history))[0])
    done, _, _, peaks = passed(blocks, i, [history.peak_slip, 0.0, 0.0])
    assert done
    assert peaks[0] == history.peak_slip
    # the block's points are its intervals' search points, its samples after the first among them
    at_samples = np.abs(history.displacement[i + 1:i + BLOCK + 1] @ DRIFTS[:, :3].T).max(axis=0)
    assert np.all(at_samples > 0.0)
    assert np.all(peaks[1:] >= at_samples * (1.0 - 1e-12))
    assert np.all(peaks[1:] <= history.peaks * (1.0 + 1e-12))


def test_the_sweep_with_long_holds_equals_the_histories():
    system, record = building_on_a_slider(), long_holds()
    mus = [0.05, MU, 0.3]
    sweep = friction_linked_sweep(system, [record], DT, mus, tracked=DRIFTS)
    for c, mu in enumerate(mus):
        history = friction_linked_history(system, record, DT, mu, tracked=DRIFTS)
        assert sweep.residual_slip[0, c] == pytest.approx(history.slip[-1], rel=1e-12, abs=1e-15)
        assert sweep.peak_slip[0, c] == pytest.approx(history.peak_slip, rel=1e-12)
        assert np.allclose(sweep.peaks[0, c], history.peaks, rtol=1e-12, atol=0)
        for name in ("viscous_energy", "energy_input", "energy_dissipated"):
            assert getattr(sweep, name)[0, c] == pytest.approx(getattr(history, name)[-1], rel=1e-12)
        assert sweep.n_slip_episodes[0, c] == history.n_slip_episodes


def test_a_block_the_modal_bound_cannot_pass_is_passed_by_its_points(blocks):
    system, record, slope, velocity, held, skip, history = blocks
    static, left_real, left_imag, gains, static_values = skip[3:8]
    starts, block_force = held[0], held[1]
    limit = MU * system.normal_force
    last_slide = np.flatnonzero(history.phase != 0).max()
    by_points = []
    for i in range(last_slide // BLOCK * BLOCK + BLOCK, record.size - BLOCK, BLOCK):
        z = state_at(history, record, slope, velocity, i) - starts[i // BLOCK]
        slip = system.interface @ z[:3]
        delta = z - slip * static
        amplitudes = np.hypot(left_real @ delta, left_imag @ delta)
        bound = block_force[i // BLOCK] + abs(slip * static_values[0]) + gains[0] @ amplitudes
        done, w, _, _ = passed(blocks, i, reached(history))
        if bound >= limit and done:
            by_points.append(i)
            assert np.allclose(w[:3], history.displacement[i + BLOCK], rtol=0,
                               atol=1e-12 * np.abs(history.displacement).max())
    assert by_points
    assert np.abs(history.friction_force[by_points[0]:by_points[0] + BLOCK + 1]).max() < limit


def test_modes_that_are_not_a_sound_basis_bound_nothing():
    undamped = building_on_a_slider()
    critical = FrictionLinkedSystem(undamped.mass_matrix, np.zeros((3, 3)), np.zeros((3, 3)), undamped.interface,
                                    undamped.normal_force, undamped.radius)
    rows = np.vstack([np.ones(10), np.ones(10)])
    static, left_real, left_imag, gains, static_values, force_gains, values = linked._held_modes(critical, rows)
    assert np.all(np.isnan(gains)) and np.all(np.isnan(force_gains))
    record = long_holds()
    sweep = friction_linked_sweep(critical, [record], DT, [0.05])  # the base alone: 1000 kg × 4 m/s² > 0.05 N
    history = friction_linked_history(critical, record, DT, 0.05)
    assert history.n_slip_episodes > 0
    assert sweep.residual_slip[0, 0] == pytest.approx(history.slip[-1], rel=1e-12)
    assert sweep.energy_input[0, 0] == pytest.approx(history.energy_input[-1], rel=1e-12)
