"""Tests of stickslip.records.process: resampling, scaling, padding, integration, baseline."""

from __future__ import annotations

import numpy as np
import pytest

from stickslip.errors import RecordError, StickslipError
from stickslip.records.process import (
    ground_motion,
    integrate_linear_acceleration,
    pad_to_duration,
    peak_ground_acceleration,
    resample,
    scale,
    scale_to_pga,
)
from stickslip.records.record import Record, RecordMeta


def make_record(acceleration, dt=0.01, source="synthetic.txt") -> Record:
    return Record(np.asarray(acceleration, dtype=float), dt, RecordMeta(record_id="synthetic", source=source))


@pytest.fixture
def noisy_record() -> Record:
    """A reproducible random acceleration [m/s²], 401 samples at 0.02 s."""
    rng = np.random.default_rng(20240521)
    return make_record(rng.normal(0.0, 2.0, 401), dt=0.02)


# --- resample -----------------------------------------------------------------


def test_resample_to_a_divisor_keeps_the_original_samples_and_pga(noisy_record):
    fine = resample(noisy_record, noisy_record.dt / 7)
    assert fine.npts == (noisy_record.npts - 1) * 7 + 1
    assert fine.duration == pytest.approx(noisy_record.duration, rel=1e-12)
    np.testing.assert_allclose(fine.acceleration[::7], noisy_record.acceleration, rtol=0, atol=1e-12)
    assert peak_ground_acceleration(fine) == pytest.approx(peak_ground_acceleration(noisy_record), rel=1e-12)
    assert fine.meta.processing == (f"resample linear dt={noisy_record.dt / 7:g} s",)
    assert fine.meta.source == noisy_record.meta.source


def test_resample_values_lie_on_the_piecewise_linear_history(noisy_record):
    fine = resample(noisy_record, 0.0013)
    expected = np.interp(fine.time, noisy_record.time, noisy_record.acceleration)
    np.testing.assert_allclose(fine.acceleration, expected, rtol=0, atol=1e-12)


def test_resample_drops_a_tail_shorter_than_the_new_step():
    record = make_record(np.arange(11.0), dt=0.1)  # lasts 1.0 s
    coarse = resample(record, 0.3)  # grid 0, 0.3, 0.6, 0.9; the 0.1 s tail is dropped
    assert coarse.npts == 4
    np.testing.assert_allclose(coarse.acceleration, [0.0, 3.0, 6.0, 9.0], atol=1e-12)


def test_resample_keeps_the_last_sample_despite_round_off():
    record = make_record(np.linspace(0.0, 1.0, 1800), dt=0.02)  # 35.98 s
    fine = resample(record, 0.001)
    assert fine.npts == 35981
    assert fine.acceleration[-1] == record.acceleration[-1]


@pytest.mark.parametrize("bad_dt", [0.0, -0.01, float("nan"), float("inf")])
def test_resample_rejects_a_bad_step(noisy_record, bad_dt):
    with pytest.raises(StickslipError, match="resampling time step dt"):
        resample(noisy_record, bad_dt)


# --- scale and pad ---------------------------------------------------------------


def test_scale_multiplies_and_records_the_step(noisy_record):
    scaled = scale(noisy_record, 1.26)
    np.testing.assert_array_equal(scaled.acceleration, noisy_record.acceleration * 1.26)
    assert scaled.meta.processing == ("scale 1.26",)


@pytest.mark.parametrize("bad_factor", [float("nan"), float("inf")])
def test_scale_rejects_a_factor_that_is_not_finite(noisy_record, bad_factor):
    with pytest.raises(StickslipError, match="scale factor must be a finite number"):
        scale(noisy_record, bad_factor)


def test_scale_to_pga_reaches_the_target(noisy_record):
    scaled = scale_to_pga(noisy_record, 9.81)
    assert peak_ground_acceleration(scaled) == pytest.approx(9.81, rel=1e-14)


def test_scale_to_pga_of_a_silent_record_names_the_file():
    with pytest.raises(RecordError, match=r"^silent\.txt: cannot scale to a PGA"):
        scale_to_pga(make_record(np.zeros(10), source="silent.txt"), 3.0)


def test_scale_to_pga_rejects_a_negative_target(noisy_record):
    with pytest.raises(StickslipError, match="target PGA"):
        scale_to_pga(noisy_record, -1.0)


def test_pad_to_duration_appends_zeros_to_the_first_grid_time_reached():
    record = make_record([1.0, 2.0, 3.0], dt=0.5)  # lasts 1.0 s
    padded = pad_to_duration(record, 2.2)  # the grid reaches 2.2 s at 2.5 s
    np.testing.assert_array_equal(padded.acceleration, [1.0, 2.0, 3.0, 0.0, 0.0, 0.0])
    assert padded.duration == 2.5
    assert pad_to_duration(record, 2.0).duration == 2.0


def test_pad_to_a_shorter_duration_is_an_error():
    record = make_record(np.ones(101), dt=0.01, source="short.at2")
    with pytest.raises(RecordError, match=r"^short\.at2: cannot pad to 0\.5 s: the record already lasts 1 s"):
        pad_to_duration(record, 0.5)


# --- integration -----------------------------------------------------------------


def test_constant_acceleration_integrates_exactly():
    dt, acceleration = 0.01, 2.5
    motion = ground_motion(make_record(np.full(1001, acceleration), dt=dt))
    time = np.arange(1001) * dt
    np.testing.assert_allclose(motion.velocity, acceleration * time, rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(motion.displacement, acceleration * time**2 / 2, rtol=1e-12, atol=1e-14)
    assert motion.baseline == "none"


def test_a_ramp_integrates_to_the_exact_cubic():
    dt, slope = 0.05, 3.0  # a = slope·t is linear everywhere, so the cubic rule is exact
    time = np.arange(201) * dt
    velocity, displacement = integrate_linear_acceleration(slope * time, dt)
    np.testing.assert_allclose(velocity, slope * time**2 / 2, rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(displacement, slope * time**3 / 6, rtol=1e-12, atol=1e-14)


def test_integration_is_independent_of_linear_resampling(noisy_record):
    """Exact integration of a piecewise-linear signal: refining the grid changes nothing at shared samples."""
    coarse = ground_motion(noisy_record)
    fine = ground_motion(resample(noisy_record, noisy_record.dt / 4))
    np.testing.assert_allclose(fine.velocity[::4], coarse.velocity, rtol=0, atol=1e-11)
    np.testing.assert_allclose(fine.displacement[::4], coarse.displacement, rtol=0, atol=1e-11)


# --- baseline correction ------------------------------------------------------------


@pytest.mark.parametrize("degree", [3, 5, 7])
def test_polynomial_baseline_starts_and_ends_at_rest(noisy_record, degree):
    motion = ground_motion(noisy_record, baseline="polynomial", degree=degree)
    uncorrected = ground_motion(noisy_record)
    assert abs(uncorrected.displacement[-1]) > 1e-3  # the raw record drifts
    scale_v = np.max(np.abs(uncorrected.velocity))
    scale_u = np.max(np.abs(uncorrected.displacement))
    assert motion.velocity[0] == 0.0 and motion.displacement[0] == 0.0
    assert abs(motion.velocity[-1]) < 1e-12 * scale_v
    assert abs(motion.displacement[-1]) < 1e-12 * scale_u
    assert motion.baseline == f"polynomial degree {degree}"


def test_cubic_baseline_acceleration_reintegrates_to_the_corrected_motion(noisy_record):
    """For degree 3 the correction to the acceleration is linear in t, so the exact integral agrees."""
    motion = ground_motion(noisy_record, baseline="polynomial", degree=3)
    velocity, displacement = integrate_linear_acceleration(motion.acceleration, noisy_record.dt)
    np.testing.assert_allclose(velocity, motion.velocity, rtol=0, atol=1e-12)
    np.testing.assert_allclose(displacement, motion.displacement, rtol=0, atol=1e-12)


def test_polynomial_correction_is_idempotent():
    """A sine acceleration from rest drifts; once corrected, a second correction changes nothing."""
    dt = 0.001
    time = np.arange(2001) * dt
    record = make_record(np.sin(np.pi * time), dt=dt)  # v ends at 0, u drifts by 2/π m
    raw = ground_motion(record)
    corrected = ground_motion(record, baseline="polynomial")
    again = ground_motion(make_record(corrected.acceleration, dt=dt), baseline="polynomial")
    assert raw.displacement[-1] == pytest.approx(2 / np.pi, rel=1e-5)
    np.testing.assert_allclose(again.acceleration, corrected.acceleration, rtol=0, atol=1e-12)


def test_unknown_baseline_and_bad_degree_are_errors(noisy_record):
    with pytest.raises(StickslipError, match="unknown baseline correction 'spline'; known: none, polynomial"):
        ground_motion(noisy_record, baseline="spline")
    with pytest.raises(StickslipError, match="degree must be an integer from 3 to 9"):
        ground_motion(noisy_record, baseline="polynomial", degree=2)


@pytest.mark.parametrize("zero", [0.0, -0.0, 0])
def test_scale_rejects_zero(noisy_record, zero):
    with pytest.raises(StickslipError, match="scale factor must not be zero"):
        scale(noisy_record, zero)


def test_scale_allows_a_sign_flip(noisy_record):
    np.testing.assert_array_equal(scale(noisy_record, -1.0).acceleration, -noisy_record.acceleration)
