"""Harmonic base motion: the closed forms of §2.2.1 as oracles for the exact solver."""

from __future__ import annotations

import math

import numpy as np
import pytest

from stickslip.errors import StickslipError
from stickslip.solvers import harmonic
from stickslip.models.rigid.exact import SCALAR_NAMES, sweep_scalars
from stickslip.models.rigid.exact_scheme import solve_history

G = 9.81
AMPLITUDE = 0.030  # m, the paper's shaking-table amplitude
FREQUENCY = 2.0  # Hz
DT = 0.0005  # s, 1000 samples per cycle
SAMPLES_PER_CYCLE = round(1.0 / (FREQUENCY * DT))


def friction_ratio(f_f: float) -> float:
    """μ giving normalized friction f_f for the test's base motion."""
    return f_f * AMPLITUDE * (2 * math.pi * FREQUENCY) ** 2 / G


@pytest.fixture(scope="module")
def long_record():
    """20 s = 40 cycles of harmonic base motion."""
    return harmonic.harmonic_record(AMPLITUDE, FREQUENCY, 20.0, DT)


def test_constants_of_equations_4_and_5():
    assert harmonic.PERMANENT_SLIP_THRESHOLD == pytest.approx(0.5370, abs=5e-5)
    assert harmonic.F_F_MAX == pytest.approx(0.4502, abs=5e-5)


def test_normalized_friction_and_mu_max_are_eq_3_and_6():
    omega_squared = (2 * math.pi * FREQUENCY) ** 2
    assert harmonic.normalized_friction(0.1, AMPLITUDE, FREQUENCY, G) == pytest.approx(0.1 * G / (AMPLITUDE * omega_squared))
    mu_max = harmonic.mu_max(AMPLITUDE, FREQUENCY, G)
    assert mu_max == pytest.approx(0.2174, abs=1e-4)  # √2/π · 0.03 · (4π)² / 9.81
    assert harmonic.normalized_friction(mu_max, AMPLITUDE, FREQUENCY, G) == pytest.approx(harmonic.F_F_MAX, rel=1e-14)


@pytest.mark.parametrize(
    ("f_f", "expected"),
    [(1.5, "no_slip"), (1.0, "no_slip"), (0.999, "stick_slip"), (0.5371, "stick_slip"), (0.5369, "permanent_slip"), (0.1, "permanent_slip")],
)
def test_regime_boundaries(f_f, expected):
    assert harmonic.regime(f_f) == expected


def test_energy_per_cycle_peaks_at_f_f_max():
    f_f = np.linspace(0.01, 0.53, 5201)
    mu = [friction_ratio(value) for value in f_f]
    energy = [harmonic.energy_per_cycle(m, AMPLITUDE, FREQUENCY, 1.0, G) for m in mu]
    assert f_f[int(np.argmax(energy))] == pytest.approx(harmonic.F_F_MAX, abs=1e-4)


def test_energy_per_cycle_outside_permanent_slip_is_an_error():
    with pytest.raises(StickslipError, match="outside the permanent-slip range"):
        harmonic.energy_per_cycle(friction_ratio(0.6), AMPLITUDE, FREQUENCY, 5.1, G)


@pytest.mark.parametrize("f_f", [0.2, 0.3, 0.45, 0.5])
def test_dissipated_energy_per_steady_cycle_matches_closed_form(long_record, f_f):
    mu = friction_ratio(f_f)
    mass = 5.1
    history = solve_history(long_record.acceleration, long_record.dt, mu, G)
    dissipated = mass * history.energy_dissipated
    closed_form = harmonic.energy_per_cycle(mu, AMPLITUDE, FREQUENCY, mass, G)
    for cycle in range(1, 4):  # the last three whole cycles
        end = dissipated.size - 1 - (cycle - 1) * SAMPLES_PER_CYCLE
        per_cycle = dissipated[end] - dissipated[end - SAMPLES_PER_CYCLE]
        assert per_cycle == pytest.approx(closed_form, rel=1e-3)


def test_regimes_in_steady_state(long_record):
    last_cycles = slice(-4 * SAMPLES_PER_CYCLE, None)
    permanent = solve_history(long_record.acceleration, long_record.dt, friction_ratio(0.52), G)
    assert np.all(permanent.phase[last_cycles] != 0)
    assert permanent.n_slip_episodes == 1
    stick_slip = solve_history(long_record.acceleration, long_record.dt, friction_ratio(0.55), G)
    assert np.count_nonzero(stick_slip.phase[last_cycles] == 0) > 0
    assert np.count_nonzero(stick_slip.phase[last_cycles] != 0) > 0
    for f_f in (1.001, 1.5):
        none = solve_history(long_record.acceleration, long_record.dt, friction_ratio(f_f), G)
        assert none.n_slip_episodes == 0
        assert none.sliding_path == 0.0


def test_fine_mu_sweep_peaks_at_mu_max(long_record):
    mu_max = harmonic.mu_max(AMPLITUDE, FREQUENCY, G)
    mu = np.linspace(0.7 * mu_max, 1.3 * mu_max, 601)
    dissipated = sweep_scalars([long_record.acceleration], long_record.dt, mu, G)[0, :, SCALAR_NAMES.index("energy_dissipated")]
    assert mu[int(np.argmax(dissipated))] == pytest.approx(mu_max, rel=1e-2)


def test_harmonic_record_samples_and_id():
    record = harmonic.harmonic_record(AMPLITUDE, FREQUENCY, 5.0, 0.001)
    assert record.meta.record_id == "harmonic_30mm_2Hz_5s"
    assert record.npts == 5001
    assert record.duration == pytest.approx(5.0)
    omega = 2 * math.pi * FREQUENCY
    np.testing.assert_allclose(record.acceleration, -AMPLITUDE * omega**2 * np.sin(omega * record.time), atol=1e-12)


def test_harmonic_record_ramp_is_a_sine_squared_envelope():
    record = harmonic.harmonic_record(AMPLITUDE, FREQUENCY, 5.0, 0.001, ramp_cycles=2.0)
    omega = 2 * math.pi * FREQUENCY
    steady = -AMPLITUDE * omega**2 * np.sin(omega * record.time)
    ramp_end = round(1.0 / 0.001)  # 2 cycles at 2 Hz = 1 s
    np.testing.assert_allclose(record.acceleration[ramp_end:], steady[ramp_end:], atol=1e-12)
    envelope = np.sin(0.5 * math.pi * record.time[:ramp_end] / 1.0) ** 2
    np.testing.assert_allclose(record.acceleration[:ramp_end], envelope * steady[:ramp_end], atol=1e-12)
    assert abs(record.acceleration[250]) < abs(steady[250])


def test_harmonic_record_rejects_bad_arguments():
    with pytest.raises(StickslipError, match="frequency"):
        harmonic.harmonic_record(AMPLITUDE, 0.0, 5.0, 0.001)
    with pytest.raises(StickslipError, match="ramp_cycles"):
        harmonic.harmonic_record(AMPLITUDE, FREQUENCY, 5.0, 0.001, ramp_cycles=-1.0)
