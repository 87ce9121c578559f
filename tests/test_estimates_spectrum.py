"""Sa(1.5 T_s): the oscillator's response is exact for a record linear between its samples, and so is the PSA."""

from __future__ import annotations

import math

import numpy as np
import pytest

from stickslip.errors import StickslipError
from stickslip.estimates.measures import estimate_inputs, spectral_acceleration_g
from stickslip.measures import intensity_measures
from stickslip.records.record import Record, RecordMeta
from stickslip.response_spectrum import pseudo_spectral_acceleration, relative_displacement

PERIOD, DAMPING, DT = 0.45, 0.05, 0.01
OMEGA = 2.0 * math.pi / PERIOD
DAMPED = OMEGA * math.sqrt(1.0 - DAMPING**2)
TIME = np.arange(600) * DT


def test_a_constant_acceleration_from_rest_is_exact():
    """u(t) = -(a/ω²)(1 - e^(-ξωt)(cos ω_d t + ξ/√(1-ξ²) sin ω_d t))."""
    exact = -(1.0 / OMEGA**2) * (1.0 - np.exp(-DAMPING * OMEGA * TIME) * (
        np.cos(DAMPED * TIME) + DAMPING / math.sqrt(1.0 - DAMPING**2) * np.sin(DAMPED * TIME)))
    computed = relative_displacement(np.ones_like(TIME), DT, PERIOD, DAMPING)
    assert computed[0] == 0.0
    assert np.max(np.abs(computed - exact)) < 1e-12 * np.max(np.abs(exact))


def test_a_ramp_from_rest_is_exact():
    """a = t: u = -(t - 2ξ/ω)/ω² + e^(-ξωt)(A cos ω_d t + B sin ω_d t), at rest at t = 0."""
    first = -2.0 * DAMPING / OMEGA**3
    second = (1.0 / OMEGA**2 + DAMPING * OMEGA * first) / DAMPED
    exact = (-(TIME - 2.0 * DAMPING / OMEGA) / OMEGA**2
             + np.exp(-DAMPING * OMEGA * TIME) * (first * np.cos(DAMPED * TIME) + second * np.sin(DAMPED * TIME)))
    computed = relative_displacement(TIME, DT, PERIOD, DAMPING)
    assert np.max(np.abs(computed - exact)) < 1e-12 * np.max(np.abs(exact))


def test_the_psa_is_omega_squared_times_the_largest_displacement():
    rng = np.random.default_rng(1)
    acceleration = rng.normal(0.0, 1.0, 1500)
    displacement = relative_displacement(acceleration, 0.02, 0.6)
    assert pseudo_spectral_acceleration(acceleration, 0.02, 0.6) == pytest.approx(
        (2 * math.pi / 0.6) ** 2 * np.max(np.abs(displacement)), rel=1e-15)


def test_a_stiff_oscillator_follows_the_ground():
    """At T << the record's periods the PSA is the PGA (to the quasi-static error)."""
    time = np.arange(2000) * 0.005
    acceleration = 3.0 * np.sin(2 * math.pi * 1.0 * time)
    assert pseudo_spectral_acceleration(acceleration, 0.005, 0.02) == pytest.approx(3.0, rel=2e-3)


@pytest.mark.parametrize("arguments, message", [((0.0,), "oscillator period T [s] must be a positive finite number"),
                                                ((0.5, 1.2), "damping ratio 1.2: expected a number in [0, 1)")])
def test_bad_oscillators_are_refused(arguments, message):
    with pytest.raises(StickslipError, match=message.replace("[", r"\[").replace(")", r"\)")):
        relative_displacement(np.ones(10), 0.01, *arguments)


def test_the_estimates_inputs_of_a_record_in_the_papers_units(two_tone_record):
    g = 9.80665
    inputs = estimate_inputs(two_tone_record, g=g, site_period=0.3)
    measures = intensity_measures(two_tone_record, g)
    assert inputs["pga"] == pytest.approx(measures.pga / g) and inputs["pgv"] == pytest.approx(100 * measures.pgv)
    assert inputs["arias_intensity"] == measures.arias_intensity and inputs["mean_period"] == measures.mean_period
    assert inputs["spectral_acceleration"] == spectral_acceleration_g(two_tone_record, 0.3, g)
    assert inputs["spectral_acceleration"] == pytest.approx(pseudo_spectral_acceleration(
        two_tone_record.acceleration, two_tone_record.dt, 0.45) / g)
    assert estimate_inputs(two_tone_record, g=g)["spectral_acceleration"] is None


def test_a_record_too_short_for_a_mean_period_has_none():
    """4 samples 1 ms apart: no Fourier frequency in 0.25-20 Hz."""
    short = Record(acceleration=np.array([0.0, 1.0, -1.0, 0.0]), dt=0.001, meta=RecordMeta(record_id="short"))
    assert estimate_inputs(short)["mean_period"] is None
