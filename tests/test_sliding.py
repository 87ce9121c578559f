"""The exact solver with two thresholds and a body force: flat unchanged, one-way and two-way (inclined) sliding."""

from __future__ import annotations

import csv
import math

import numpy as np
import pytest
from conftest import FIXTURES
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays
from scipy.optimize import brentq

from stickslip.errors import StickslipError
from stickslip.records.process import resample
from stickslip.records.record import Record
from stickslip.models import solve
from stickslip.models.rigid.exact_scheme import sliding_history
from stickslip.models.rigid.exact import SCALAR_NAMES, record_scalars, sweep_scalars, sweep_scalars_reference
from stickslip.models.rigid.resistance import Resistance

G = 9.81
SLOPE_CASES = {
    "one-way": {"ky": 0.08},
    "two-way": {"ky": 0.08, "direction": "both", "thrust_angle": 12.0},
}


# --- the flat case is unchanged -----------------------------------------------------------


def test_flat_scalars_equal_the_flat_only_kernels_bit_for_bit(paper_records):
    """Both kernels reproduce, bit for bit, what the flat-only kernels of commit 941c74a stored.

    ``tests/fixtures/flat_kernel_scalars.csv`` holds those kernels' scalars as
    hexadecimal floats; regenerating it from today's code would defeat it.
    """
    with open(FIXTURES / "flat_kernel_scalars.csv", newline="", encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    assert len(rows) == 60
    kernels = {"sweep_scalars": sweep_scalars, "sweep_scalars_reference": sweep_scalars_reference}
    for row in rows:
        record = paper_records[row["record_file"]]
        computed = kernels[row["kernel"]]([record.acceleration], record.dt, [float(row["mu"])], G)[0, 0]
        stored = np.array([float.fromhex(row[name]) for name in SCALAR_NAMES])
        np.testing.assert_array_equal(computed, stored, err_msg=f"{row['record_file']} {row['kernel']} {row['mu']}")


def test_flat_resistances_and_friction_ratios_give_identical_bits(paper_records):
    records = list(paper_records.values())
    mu = np.linspace(0.01, 0.4, 120)
    accelerations, dts = [r.acceleration for r in records], [r.dt for r in records]
    by_mu = sweep_scalars(accelerations, dts, mu, G)
    np.testing.assert_array_equal(by_mu, sweep_scalars(accelerations, dts, resistances=[Resistance.friction(m, G) for m in mu]))
    # SLAMMER's two-way block at thrust angle 0 is flat friction with mu = ky.
    np.testing.assert_array_equal(by_mu, sweep_scalars(accelerations, dts, resistances=[
        Resistance.two_way(m, G, 0.0) for m in mu]))


def test_sweep_scalars_refuses_both_or_neither_kind_of_input():
    with pytest.raises(StickslipError, match="not both"):
        sweep_scalars([np.zeros(5)], 0.01, [0.1], G, resistances=[Resistance.one_way(0.1, G)])
    with pytest.raises(StickslipError, match="or resistances"):
        sweep_scalars([np.zeros(5)], 0.01)
    with pytest.raises(StickslipError, match="at least one"):
        sweep_scalars([np.zeros(5)], 0.01, resistances=[])
    with pytest.raises(StickslipError, match="not both"):
        record_scalars(np.zeros(5), 0.01, 0.1, G, resistance=Resistance.one_way(0.1, G))


# --- one-way sliding: closed forms ----------------------------------------------------------


def test_rectangular_pulse_one_way_displacement_matches_the_closed_form():
    """ü_g = A from t = 0 to T1, a linear ramp to 0 over one dt, then rest; k = k_y·g < A.

    Downslope velocity u̇ = (A − k)t on the plateau, then
    u̇ = V1 + (A − k)τ − Aτ²/(2dt) on the ramp, then V2 − kτ until it stops:
    D = (A − k)T1²/2 + V1·dt + (A − k)dt²/2 − A·dt²/6 + V2²/(2k).
    """
    amplitude, ky, dt, n_plateau = 3.0, 0.1, 0.01, 40
    k = ky * G
    acceleration = np.zeros(400)
    acceleration[: n_plateau + 1] = amplitude
    plateau = n_plateau * dt
    v1 = (amplitude - k) * plateau
    v2 = v1 + (amplitude - k) * dt - amplitude * dt / 2
    expected = (amplitude - k) * plateau**2 / 2 + v1 * dt + (amplitude - k) * dt**2 / 2 - amplitude * dt**2 / 6
    expected += v2**2 / (2 * k)
    history = sliding_history(acceleration, dt, Resistance.one_way(ky, G))
    assert -history.relative_displacement[-1] == pytest.approx(expected, rel=1e-13)
    assert history.n_slip_episodes == 1
    assert history.slip_time == pytest.approx(plateau + dt + v2 / k, rel=1e-13)
    # E_df = k_y·g·D, and a stopped block has given all of E_I to it (its final speed is the ground's, zero).
    assert history.energy_dissipated[-1] == pytest.approx(k * expected, rel=1e-13)
    assert history.energy_input[-1] == pytest.approx(history.energy_dissipated[-1] + 0.5 * history.ground_velocity[-1] ** 2,
                                                     rel=1e-12)


def test_newmark_sine_pulse_converges_to_the_closed_form_at_second_order():
    """One cycle of A·sin(ωt): the block slides from sin(ωt1) = k/A until u̇ = 0 (Newmark 1965).

    u̇(t) = A/ω·(cos ωt1 − cos ωt) − k(t − t1); D = u(t2) at the root t2 of u̇.
    The solver is exact for the sampled (piecewise-linear) sine; the sampling
    error shrinks as dt².
    """
    amplitude, frequency, ky = 4.0, 2.0, 0.2
    omega, k = 2 * math.pi * frequency, ky * G
    t1 = math.asin(k / amplitude) / omega

    def velocity(t):
        return amplitude / omega * (math.cos(omega * t1) - math.cos(omega * t)) - k * (t - t1)

    t2 = brentq(velocity, t1 + 1e-9, 1 / frequency)
    expected = (amplitude / omega * ((t2 - t1) * math.cos(omega * t1) - (math.sin(omega * t2) - math.sin(omega * t1)) / omega)
                - k * (t2 - t1) ** 2 / 2)
    errors = []
    for dt in (1e-3, 1e-4):
        time = np.arange(0.0, 1 / frequency + 2.0, dt)
        acceleration = np.where(time <= 1 / frequency, amplitude * np.sin(omega * time), 0.0)
        history = sliding_history(acceleration, dt, Resistance.one_way(ky, G))
        errors.append(abs(-history.relative_displacement[-1] - expected) / expected)
    assert errors[1] < 2e-6
    assert 50 < errors[0] / errors[1] < 200


def test_one_way_block_never_moves_upslope(paper_records):
    record = paper_records["SLAMMER_Kobe_1995_KJM-090.txt"]
    history = sliding_history(-record.acceleration, record.dt, Resistance.one_way(0.05, G))
    assert np.all(np.diff(history.relative_displacement) <= 0.0)
    assert np.all(history.relative_velocity <= 0.0)
    assert set(np.unique(history.phase)) == {-1, 0}
    assert history.sliding_path == pytest.approx(-history.relative_displacement[-1], rel=1e-14)


def test_two_way_block_slides_upslope_only_past_ky_plus_twice_the_slope_term():
    """A square wave of ±a: upslope sliding needs a > k_y·g + 2·g·sin β."""
    ky, beta = 0.1, 10.0
    upslope_limit = ky * G + 2 * G * math.sin(math.radians(beta))
    for amplitude, slides_up in ((0.98 * upslope_limit, False), (1.02 * upslope_limit, True)):
        acceleration = np.concatenate([np.zeros(5), -amplitude * np.ones(50), np.zeros(100)])
        history = sliding_history(acceleration, 0.01, Resistance.two_way(ky, G, beta))
        assert (history.relative_displacement[-1] > 0.0) == slides_up


# --- energy balance and resampling, one-way and inclined --------------------------------------


@pytest.mark.parametrize("case", SLOPE_CASES)
def test_energy_balance_closes_to_round_off_with_the_body_force_work(paper_records, distinct_paper_file, case):
    record = paper_records[distinct_paper_file]
    response = solve(record, g=G, **SLOPE_CASES[case])
    assert response.energy_dissipated > 0.0
    assert response.balance_residual / response.energy_input < 1e-12
    if case == "two-way":
        # The body force (gravity along the slope) did work: leaving it out breaks the balance.
        assert abs(response.body_force_work) > 1e-3 * response.energy_input
        kinetic = response.kinetic_energy
        without = kinetic[-1] - kinetic[0] + response.energy_dissipated - response.energy_input
        assert abs(without - response.body_force_work) < 1e-12 * response.energy_input
    else:
        assert response.body_force_work == 0.0


@pytest.mark.parametrize("case", SLOPE_CASES)
@pytest.mark.parametrize("name", ["SLAMMER_Cape_Mendocino_1992_PET-090.txt", "SLAMMER_Coyote_Lake_1979_G06-230.txt"])
def test_resampling_to_a_twentieth_of_dt_changes_nothing(paper_records, name, case):
    record = paper_records[name]
    fine = resample(record, record.dt / 20)
    coarse, refined = solve(record, g=G, **SLOPE_CASES[case]).scalars(), solve(fine, g=G, **SLOPE_CASES[case]).scalars()
    for key in ("energy_dissipated", "energy_input", "body_force_work"):
        assert refined[key] == pytest.approx(coarse[key], rel=0, abs=1e-12 * coarse["energy_input"]), key
    for key in ("downslope_displacement", "peak_relative_displacement", "sliding_path"):
        assert refined[key] == pytest.approx(coarse[key], rel=1e-12), key
    assert refined["n_slip_episodes"] == coarse["n_slip_episodes"]


@pytest.mark.parametrize("case", SLOPE_CASES)
def test_sweep_kernels_equal_the_history_and_each_other(paper_records, case):
    records = [paper_records[name] for name in ("SLAMMER_Kobe_1995_KJM-090.txt", "CHY080-N.AT2")]
    ky = [0.02, 0.07, 0.2]
    resistances = [Resistance.from_options(G, **{**SLOPE_CASES[case], "ky": value}) for value in ky]
    accelerations, dts = [r.acceleration for r in records], [r.dt for r in records]
    fast = sweep_scalars(accelerations, dts, resistances=resistances)
    reference = sweep_scalars_reference(accelerations, dts, resistances=resistances)
    input_column = SCALAR_NAMES.index("energy_input")
    others = [k for k in range(len(SCALAR_NAMES)) if k != input_column]
    np.testing.assert_array_equal(fast[..., others], reference[..., others])
    np.testing.assert_allclose(fast[..., input_column], reference[..., input_column], rtol=1e-12)
    for i, record in enumerate(records):
        for j, resistance in enumerate(resistances):
            history = sliding_history(record.acceleration, record.dt, resistance)
            assert reference[i, j, SCALAR_NAMES.index("energy_dissipated")] == history.energy_dissipated[-1]
            assert reference[i, j, SCALAR_NAMES.index("residual_displacement")] == history.relative_displacement[-1]
            np.testing.assert_array_equal(record_scalars(record.acceleration, record.dt, resistance=resistance), fast[i, j])


@settings(max_examples=100, deadline=None)
@given(
    arrays(np.float64, st.integers(min_value=2, max_value=200),
           elements=st.floats(min_value=-10.0, max_value=10.0, allow_nan=False, allow_subnormal=False)),
    st.floats(min_value=1e-3, max_value=0.05),
    st.floats(min_value=0.01, max_value=0.8),
    st.floats(min_value=0.0, max_value=40.0),
)
def test_random_records_balance_and_both_kernels_agree(acceleration, dt, ky, thrust_angle):
    for resistance in (Resistance.one_way(ky, G), Resistance.two_way(ky, G, thrust_angle)):
        fast = sweep_scalars([acceleration], dt, resistances=[resistance])[0, 0]
        reference = sweep_scalars_reference([acceleration], dt, resistances=[resistance])[0, 0]
        np.testing.assert_array_equal(np.delete(fast, 1), np.delete(reference, 1))
        response = solve(Record(acceleration, dt), g=G, mass=1.0, **resistance.parameters)
        scale = max(response.energy_input, float(np.max(response.kinetic_energy)), 1e-30)
        assert response.balance_residual <= 1e-9 * scale


# --- polarity ---------------------------------------------------------------------------------


@pytest.mark.parametrize("case", SLOPE_CASES)
def test_inverse_polarity_is_the_negated_record(paper_records, case):
    record = paper_records["SLAMMER_Northridge_1994_NWH-090.txt"]
    inverse = solve(record, g=G, inverse=True, **SLOPE_CASES[case])
    negated = solve(Record(-record.acceleration, record.dt), g=G, **SLOPE_CASES[case])
    assert inverse.scalars() == negated.scalars()
    assert inverse.record_meta.processing[-1] == "inverse polarity"
    assert inverse.downslope_displacement != solve(record, g=G, **SLOPE_CASES[case]).downslope_displacement
