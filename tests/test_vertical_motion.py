"""The vertical ground motion: the normal force N/m = g + a_v, the lift-off where it vanishes, and the ledger.

Oracles: no vertical motion is the flat block of the exact solver; a constant
a_v = c·g is the block without it at μ·(1 + c) (flat) and at g·(1 + c) (the
pendulum); a synthetic vertical motion crossing −g at known times lifts the
slider off exactly there, and in flight it moves as ü = −a with no energy
exchanged; the closed form and the tolerance-controlled kernel agree; every
ledger closes on the fifteen three-component PEER sets.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from stickslip.errors import StickslipError
from stickslip.records.process import integrate_linear_acceleration
from stickslip.models.rigid import exact_scheme
from stickslip.solvers.friction_law import FrictionLaw
from stickslip.models.pendulum.normal_force import liftoff_intervals
from stickslip.models.pendulum.exact import pendulum_history
from stickslip.models.pendulum.integrated import integrated_history
from stickslip.solvers.ledger import FLIGHT, SCALAR_NAMES
from stickslip.models.pendulum.vertical_exact import vertical_history, vertical_sweep

G = 9.81
COMPARED = ("energy_dissipated", "energy_input", "kinetic_energy_final", "potential_energy_final",
            "residual_displacement", "peak_relative_displacement", "sliding_path", "slip_fraction", "peak_base_shear",
            "liftoff_time")


def aligned(station):
    """The first horizontal and the vertical component of a set [m/s²], cut to their common length, and dt [s]."""
    horizontal, vertical = station["H1"], station["UP"]
    size = min(horizontal.acceleration.size, vertical.acceleration.size)
    return horizontal.acceleration[:size], vertical.acceleration[:size], horizontal.dt


def assert_scalars_close(one: dict, other: dict, rel: float) -> None:
    for name in COMPARED:
        assert one[name] == pytest.approx(other[name], rel=rel, abs=rel * 1e-3), name


def test_without_a_vertical_motion_the_block_is_the_flat_block_of_the_exact_solver(paper_records):
    for record in paper_records.values():
        for mu in (0.05, 0.15):
            flat = exact_scheme.solve_history(record.acceleration, record.dt, mu, G)
            for vertical in (None, np.zeros(record.acceleration.size)):
                result = vertical_history(record.acceleration, vertical, record.dt, mu)
                assert result["scalars"]["energy_dissipated"] == pytest.approx(flat.energy_dissipated[-1], rel=1e-12)
                assert result["scalars"]["energy_input"] == pytest.approx(flat.energy_input[-1], rel=1e-12)
                assert result["scalars"]["n_slip_episodes"] == flat.n_slip_episodes
                assert np.max(np.abs(result["relative_displacement"] - flat.relative_displacement)) <= 1e-12 * max(
                    np.max(np.abs(flat.relative_displacement)), 1e-3)
                assert result["scalars"]["liftoff_time"] == 0.0


@pytest.mark.parametrize("c", [-0.35, 0.5])
def test_a_constant_vertical_acceleration_is_gravity_scaled_by_one_plus_c(paper_records, c):
    """Flat, closed form: μ·(1 + c) without it (1e-12); the pendulum and the velocity-dependent law, integrated:
    g·(1 + c) without it (1e-9), with the potential energy g·u²/(2R) 1/(1 + c) times the heavier pendulum's
    g·(1 + c)·u²/(2R) and the vertical motion's work −c·g·u²/(2R) (:func:`heavier_by`)."""
    for record in paper_records.values():
        a, dt = record.acceleration, record.dt
        vertical = np.full(a.size, c * G)
        for mu in (0.04, 0.12):
            flat = exact_scheme.solve_history(a, dt, mu * (1 + c), G)
            result = vertical_history(a, vertical, dt, mu)
            assert result["scalars"]["energy_dissipated"] == pytest.approx(flat.energy_dissipated[-1], rel=1e-12)
            assert result["scalars"]["energy_input"] == pytest.approx(flat.energy_input[-1], rel=1e-12)
            assert result["scalars"]["sliding_path"] == pytest.approx(flat.sliding_path, rel=1e-12)
            assert result["scalars"]["peak_relative_displacement"] == pytest.approx(
                flat.peak_relative_displacement, rel=1e-12)
            assert np.max(np.abs(result["relative_displacement"] - flat.relative_displacement)) <= 1e-12 * max(
                np.max(np.abs(flat.relative_displacement)), 1e-3)
            lifted = integrated_history(a, dt, FrictionLaw.coulomb(mu), 2.0, vertical)["scalars"]
            heavier = pendulum_history(a, dt, mu, 2.0, g=G * (1 + c))["scalars"]
            # the base shear is over the weight m·g: the heavier pendulum's is over m·g·(1 + c)
            assert_scalars_close(lifted, heavier_by(heavier, c), 1e-9)
            law = FrictionLaw.velocity_dependent(mu / 2, mu, 15.0)
            lifted = integrated_history(a, dt, law, 1.0, vertical)["scalars"]
            heavier = integrated_history(a, dt, law, 1.0, None, g=G * (1 + c))["scalars"]
            assert_scalars_close(lifted, heavier_by(heavier, c), 1e-9)
            assert heavier["energy_input_vertical"] == 0.0
            assert lifted["energy_input_vertical"] == pytest.approx(-c / (1 + c) * heavier["potential_energy_final"],
                                                                    rel=1e-9)


def heavier_by(heavier: dict, c: float) -> dict:
    """The end results of a slider under gravity g·(1 + c) as those of one under g with a vertical a_v = c·g: the
    base shear is over the weight m·g (the heavier's is over m·g·(1 + c)) and the potential energy m·g·u²/(2R)."""
    return heavier | {"peak_base_shear": heavier["peak_base_shear"] * (1 + c),
                      "potential_energy_final": heavier["potential_energy_final"] / (1 + c)}


# --- lift-off --------------------------------------------------------------------------------------------------------

def synthetic_motion():
    """4.5 s at dt = 0.01 s: a horizontal 1.5 Hz sine of 0.4 g for two cycles, then rest; N/m falling linearly from
    g at 0.5 s to −g at 1.0 s and back to g at 1.5 s, so that it crosses zero at 0.75 s and 1.25 s exactly, and
    again from 3.5 s to 3.9 s (crossings at 3.6 s and 3.8 s), when the slider has come to rest."""
    dt = 0.01
    t = np.arange(0, 451) * dt
    normal = np.full(t.size, G)
    for start, bottom, end in ((0.5, 1.0, 1.5), (3.5, 3.7, 3.9)):
        down = (t >= start) & (t <= bottom)
        normal[down] = G - 2 * G * (t[down] - start) / (bottom - start)
        up = (t > bottom) & (t <= end)
        normal[up] = -G + 2 * G * (t[up] - bottom) / (end - bottom)
    horizontal = 0.4 * G * np.sin(2 * np.pi * 1.5 * t) * (t < 4 / 3)
    return t, horizontal, normal - G, dt


def test_a_vertical_motion_crossing_minus_g_lifts_off_exactly_where_it_crosses():
    t, horizontal, vertical, dt = synthetic_motion()
    intervals = liftoff_intervals(vertical, dt, G)
    assert intervals == pytest.approx(np.array([[0.75, 1.25], [3.6, 3.8]]), abs=1e-12)
    for result in (vertical_history(horizontal, vertical, dt, 0.1),
                   integrated_history(horizontal, dt, FrictionLaw.coulomb(0.1), math.inf, vertical),
                   integrated_history(horizontal, dt, FrictionLaw.velocity_dependent(0.08, 0.12, 20.0), 2.0,
                                      vertical)):
        assert result["scalars"]["liftoff_time"] == pytest.approx(0.7, rel=1e-12)
        flying = (t > 0.75 + dt / 2) & (t < 1.25 - dt)
        assert np.all(result["phase"][flying] == FLIGHT)
        assert np.all(result["phase"][(t > 1.25 + dt / 2) & (t < 1.75)] != FLIGHT)
        for name in ("energy_dissipated", "energy_input", "sliding_path"):
            assert np.ptp(result[name][flying]) <= 1e-15 * max(np.max(np.abs(result[name])), 1e-300), name
        # no normal force in flight, so no restoring force: W_v takes the change of E_p
        restoring_work = result["potential_energy"] - result["energy_input_vertical"]
        assert np.ptp(restoring_work[flying]) <= 1e-14 * max(np.max(result["potential_energy"]), 1e-300)
        x, v = result["relative_displacement"], result["relative_velocity"]
        i = np.flatnonzero(flying)[:-1]
        # in flight ü = −a exactly: the cubic of a linear acceleration between samples
        assert x[i + 1] == pytest.approx(x[i] + v[i] * dt - dt * dt * (2 * horizontal[i] + horizontal[i + 1]) / 6,
                                         rel=0, abs=1e-12)
        assert v[i + 1] == pytest.approx(v[i] - dt * (horizontal[i] + horizontal[i + 1]) / 2, rel=0, abs=1e-12)
        assert abs(v[np.searchsorted(t, 1.0)]) > 0.05  # it left sliding
        # the second lift-off comes while it is stuck on a ground at rest: it flies at rest and lands at rest
        still = t > 3.4
        assert np.all(result["phase"][(t > 3.4) & (t < 3.6)] == 0)
        assert np.ptp(x[still]) == 0.0 and np.all(v[still] == 0.0)


def test_liftoff_intervals_at_the_records_ends_and_touching_minus_g():
    dt = 0.5
    assert liftoff_intervals(np.array([-2 * G, -2 * G, 0.0, 0.0]), dt, G) == pytest.approx(np.array([[0.0, 0.75]]))
    assert liftoff_intervals(np.array([0.0, -G, 0.0, -3 * G]), dt, G) == pytest.approx(np.array([[1.0 + dt / 3, 1.5]]))
    assert liftoff_intervals(np.zeros(5), dt, G).shape == (0, 2)


def test_fifteen_stations_lift_off_only_at_el_centro_array_6_and_gazli(three_component_sets):
    """Measured: El Centro Array #6 at 2.393-2.455 s and 2.524-2.563 s (0.101 s in all), Gazli six times between
    8.02 and 9.54 s (0.0356 s in all); the kernels' time lifted off is the intervals' total."""
    totals = {}
    for name, station in three_component_sets.items():
        vertical = station["UP"]
        intervals = liftoff_intervals(vertical.acceleration, vertical.dt, G)
        totals[name] = float(np.sum(intervals[:, 1] - intervals[:, 0]))
        if totals[name]:
            a, av, dt = aligned(station)
            for result in (vertical_history(a, av, dt, 0.1),
                           integrated_history(a, dt, FrictionLaw.velocity_dependent(0.05, 0.1, 20.0), 2.0, av)):
                assert result["scalars"]["liftoff_time"] == pytest.approx(totals[name], rel=1e-12)
    assert {name for name, total in totals.items() if total} == {"ImperialValley06_ElCentroArray6", "Gazli_Karakyr"}
    assert totals["ImperialValley06_ElCentroArray6"] == pytest.approx(0.1011, abs=1e-4)
    assert totals["Gazli_Karakyr"] == pytest.approx(0.0356, abs=1e-4)


# --- the kernels against each other and the ledgers on real records --------------------------------------------------

def test_the_integrated_kernel_matches_the_closed_form_flat_block_under_the_vertical_motion(three_component_sets):
    """Measured: scalars within 8.9e-15, u at the samples within 2.9e-15 of its peak, over the fifteen sets at
    μ = 0.03 and 0.1."""
    for station in three_component_sets.values():
        a, av, dt = aligned(station)
        for mu in (0.03, 0.1):
            exact = vertical_history(a, av, dt, mu)
            integrated = integrated_history(a, dt, FrictionLaw.coulomb(mu), math.inf, av)
            assert_scalars_close(integrated["scalars"], exact["scalars"], 1e-9)
            scale = np.max(np.abs(exact["relative_displacement"]))
            assert np.max(np.abs(integrated["relative_displacement"] - exact["relative_displacement"])) <= 1e-9 * scale


def test_ledgers_close_on_the_three_component_records(three_component_sets):
    """E_k − E_k(0) + E_p − E_p(0) + E_df − E_I − W_v over the largest |E_I|; measured: at most 8.6e-15 in closed
    form, 4.4e-12 integrated (μ(v) from μ/2 to μ at 20 s/m, flat and R = 2 m, with the vertical)."""
    for station in three_component_sets.values():
        a, av, dt = aligned(station)
        for mu in (0.03, 0.1):
            closed = vertical_history(a, av, dt, mu)
            assert np.max(np.abs(closed["balance_residual"])) <= 1e-12 * np.max(np.abs(closed["energy_input"]))
            for radius in (math.inf, 2.0):
                result = integrated_history(a, dt, FrictionLaw.velocity_dependent(mu / 2, mu, 20.0), radius, av)
                assert np.max(np.abs(result["balance_residual"])) <= 1e-9 * np.max(np.abs(result["energy_input"]))
                assert np.all(np.diff(result["sliding_path"]) >= 0)
                assert np.all(np.diff(result["energy_dissipated"]) >= 0)


def test_the_ground_velocity_of_the_ledger_is_the_records_exact_integral():
    t, horizontal, vertical, dt = synthetic_motion()
    result = vertical_history(horizontal, vertical, dt, 0.1)
    assert np.array_equal(result["ground_velocity"], integrate_linear_acceleration(horizontal, dt)[0])
    assert np.array_equal(result["time"], np.arange(t.size) * dt)


def test_the_sweep_equals_the_histories(three_component_sets):
    names = ("ImperialValley06_ElCentroArray6", "Gazli_Karakyr", "Tabas_Tabas")
    motions = [aligned(three_component_sets[name]) for name in names]
    mus = np.array([0.02, 0.08, 0.3])
    swept = vertical_sweep([m[0] for m in motions], [m[1] for m in motions], [m[2] for m in motions], mus)
    for i, (a, av, dt) in enumerate(motions):
        for j, mu in enumerate(mus):
            history = vertical_history(a, av, dt, mu)["scalars"]
            assert swept[i, j] == pytest.approx([history[name] for name in SCALAR_NAMES], rel=1e-12, abs=1e-15)


def test_a_vertical_record_of_another_length_is_one_clear_error():
    with pytest.raises(StickslipError, match=r"^vertical acceleration: 4 samples, but the horizontal record has 5; "):
        vertical_history(np.zeros(5), np.zeros(4), 0.01, 0.1)
    with pytest.raises(StickslipError, match=r"^vertical acceleration: acceleration contains NaN"):
        integrated_history(np.zeros(3), 0.01, FrictionLaw.coulomb(0.1), 1.0, np.array([0.0, np.nan, 0.0]))


def test_a_vertical_file_sampled_otherwise_says_what_mends_it():
    """Another length is mended by padding (--pad); another time step only by resampling, which --pad cannot do."""
    from stickslip.records.record import Record, RecordMeta
    from stickslip.records.vertical import WithVertical

    motion = np.sin(np.arange(500) * 0.05)
    horizontal = Record(motion, 0.01, RecordMeta(source="STA-000.txt"))
    with pytest.raises(StickslipError, match=r"STA-UP.txt: the vertical component has 400 samples at dt = 0.01 s, "
                                             r"the horizontal motion 500 at 0.01 s: .* \(pad the shorter"):
        WithVertical.of(horizontal, Record(motion[:400], 0.01, RecordMeta(source="STA-UP.txt")))
    assert WithVertical.of(horizontal, Record(motion[:400], 0.01, RecordMeta(source="STA-UP.txt")), pad=True).npts == 500
    with pytest.raises(StickslipError, match=r"at dt = 0.005 s, the horizontal motion 500 at 0.01 s: they must be "
                                             r"sampled alike \(resample one of them first\)$"):
        WithVertical.of(horizontal, Record(motion, 0.005, RecordMeta(source="STA-UP.txt")), pad=True)
