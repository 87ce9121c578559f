"""SLAMMER's rigid-block scheme: hand-stepped samples, zero samples, convergence to exact, SLAMMER's signs."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import require_shared_verification

from stickslip.errors import StickslipError
from stickslip.records.process import resample
from stickslip.records.record import Record
from stickslip.models import solve
from stickslip.models.rigid import exact_scheme
from stickslip.models.rigid import slammer
from stickslip.models.rigid.resistance import Resistance
from stickslip.studies.verification.slammer import (
    POLARITIES,
    PYSLAMMER_RULES,
    read_rigid_analyses,
    sample_motions,
    scaled_records,
    scheme_displacement,
)

G = 9.81


def test_one_way_steps_follow_the_trapezoid_rule_by_hand():
    """k_y·g = 1 m/s², dt = 0.1 s, a = 3, 3, 0, −1 m/s².

    Sample 0: stuck and |a| > 1, so y = 3 − 1 = 2, v = 0.05·2 = 0.1, u = 0.05·0.1 = 0.005.
    Sample 1: sliding, y = 2, v = 0.1 + 0.05·4 = 0.3, u = 0.005 + 0.05·0.4 = 0.025.
    Sample 2 (a = 0) is skipped.  Sample 3: y = −2, v = 0.3 + 0.05·0 = 0.3, u = 0.025 + 0.05·0.6 = 0.055.
    Integrated instead (inverse polarity's rule), sample 2: y = −1, v = 0.35, u = 0.0575; sample 3:
    y = −2, v = 0.35 − 0.15 = 0.2, u = 0.0575 + 0.0275 = 0.085.
    """
    resistance = Resistance.one_way(1.0 / G, G)
    acceleration = np.array([3.0, 3.0, 0.0, -1.0])
    skipped = slammer.sliding_history(acceleration, 0.1, resistance)
    np.testing.assert_allclose(-skipped.relative_displacement, [0.005, 0.025, 0.025, 0.055], rtol=1e-13)
    np.testing.assert_allclose(-skipped.relative_velocity, [0.1, 0.3, 0.3, 0.3], rtol=1e-13)
    integrated = slammer.sliding_history(acceleration, 0.1, resistance, skip_zero_samples=False)
    np.testing.assert_allclose(-integrated.relative_displacement, [0.005, 0.025, 0.0575, 0.085], rtol=1e-13)
    np.testing.assert_allclose(-integrated.relative_velocity, [0.1, 0.3, 0.35, 0.2], rtol=1e-13)
    assert list(integrated.phase) == [-1, -1, -1, -1]


def test_velocity_reset_step_still_adds_half_a_step_of_displacement():
    """a = 2, 0.5 (k = 1): v = 0.05, then 0.05 + 0.05·(−0.5 + 1) = 0.075 > 0; a = −3: v ≤ 0, reset, u += dt·v_prev/2."""
    resistance = Resistance.one_way(1.0 / G, G)
    history = slammer.sliding_history(np.array([2.0, 0.5, -3.0, -3.0]), 0.1, resistance)
    u = -history.relative_displacement
    np.testing.assert_allclose(u, [0.0025, 0.0025 + 0.05 * 0.125, 0.0025 + 0.05 * 0.2, 0.0025 + 0.05 * 0.2], rtol=1e-13)
    assert list(history.relative_velocity[2:]) == [0.0, 0.0]
    assert history.n_slip_episodes == 1


def test_a_skipped_zero_sample_is_as_if_it_were_not_there(paper_records):
    """Normal polarity drops samples of exactly zero; inverse polarity integrates them."""
    record = paper_records["SLAMMER_Cape_Mendocino_1992_PET-090.txt"]
    acceleration = record.acceleration.copy()
    zeros = np.arange(400, 1400, 97)
    acceleration[zeros] = 0.0
    resistance = Resistance.one_way(0.05, G)
    with_zeros = slammer.sliding_history(acceleration, record.dt, resistance)
    without = slammer.sliding_history(np.delete(acceleration, zeros), record.dt, resistance)
    assert with_zeros.relative_displacement[-1] == without.relative_displacement[-1]
    integrated = slammer.sliding_history(acceleration, record.dt, resistance, skip_zero_samples=False)
    assert integrated.relative_displacement[-1] != with_zeros.relative_displacement[-1]
    # stickslip.solve applies SLAMMER's rule: skip in normal polarity, integrate in inverse polarity.
    zeroed = Record(acceleration, record.dt)
    assert solve(zeroed, ky=0.05, method="slammer").residual_displacement == with_zeros.relative_displacement[-1]
    inverse = solve(zeroed, ky=0.05, method="slammer", inverse=True)
    assert inverse.residual_displacement == slammer.sliding_history(
        -acceleration, record.dt, resistance, skip_zero_samples=False).relative_displacement[-1]


@pytest.mark.parametrize(
    ("options", "gain", "bound"),
    [({"ky": 0.08}, 30, 1e-5), ({"ky": 0.08, "direction": "both", "thrust_angle": 12.0}, 10, 1e-5),
     ({"mu": 0.1}, 5, 5e-3)],
)
@pytest.mark.parametrize("name", ["SLAMMER_Cape_Mendocino_1992_PET-090.txt", "SLAMMER_Kobe_1995_KJM-090.txt"])
def test_scheme_converges_to_exact_on_finer_resampled_records(paper_records, name, options, gain, bound):
    """Resampled linearly to dt/10 and dt/100 (the exact answer does not change), SLAMMER's error shrinks.

    One-way the error falls about 100-fold per decade of dt (second order); a
    reversal without sticking (two-way; flat friction is SLAMMER's two-way block
    at thrust angle 0) is resolved by a velocity reset at a sample, first order:
    about 10-fold per decade where reversals dominate.
    """
    record = paper_records[name]
    exact = solve(record, **options)
    errors = []
    for factor in (1, 10, 100):
        finer = resample(record, record.dt / factor) if factor > 1 else record
        scheme = solve(finer, method="slammer", **options)
        assert solve(finer, **options).residual_displacement == pytest.approx(exact.residual_displacement, rel=1e-11)
        errors.append(abs(scheme.residual_displacement - exact.residual_displacement) / abs(exact.residual_displacement))
    assert errors[0] > gain * errors[1] and errors[1] > gain * errors[2]
    assert errors[2] < bound


def test_python_and_compiled_steps_agree(paper_records, monkeypatch):
    record = paper_records["CHY080-N.AT2"]
    resistance = Resistance.two_way(0.1, G, 8.0)
    as_python = slammer.sliding_history(record.acceleration, record.dt, resistance)
    monkeypatch.setattr(slammer, "PYTHON_SAMPLES", record.npts - 1)
    as_compiled = slammer.sliding_history(record.acceleration, record.dt, resistance)
    assert slammer._compiled_steps.cache_info().currsize == 1
    for name in ("relative_displacement", "relative_velocity", "relative_acceleration", "energy_input"):
        np.testing.assert_array_equal(getattr(as_python, name), getattr(as_compiled, name))


def test_scheme_refuses_thresholds_slammer_does_not_have():
    with pytest.raises(StickslipError, match="SLAMMER's cases only"):
        slammer.sliding_history(np.zeros(4), 0.01, Resistance(2.0, 1.0, 0.0))


def test_scheme_is_a_method_of_solve_and_names_its_options():
    record = Record(np.array([0.0, 3.0, 0.0]), 0.1)
    with pytest.raises(StickslipError, match="accepts: skip_zero_samples"):
        solve(record, ky=0.1, method="slammer", time_step=0.01)
    assert exact_scheme.sliding_history(record.acceleration, 0.1, Resistance.one_way(0.1, G)).sliding_path > 0.0


# --- the sign convention, against SLAMMER's own results --------------------------------------

#: pyslammer sample motions whose normal and inverse SLAMMER displacements tell the polarities apart.
SIGN_MOTIONS = ("Cape_Mendocino_1992_PET-090.csv", "Northridge_1994_PAC-175.csv")


def test_positive_ground_acceleration_drives_downslope_as_in_slammer():
    """SLAMMER's normal polarity is ours: a positive acceleration drives the block downslope (−x)."""
    analyses = [a for a in read_rigid_analyses(require_shared_verification()) if a["motion_file"] in SIGN_MOTIONS]
    assert len(analyses) == 10
    records = scaled_records(analyses, sample_motions(analyses), slammer.SLAMMER_GRAVITY)
    swapped_fails = 0
    for analysis in analyses:
        computed = {polarity: scheme_displacement("slammer", records[analysis["analysis_id"]], analysis["ky"],
                                                  slammer.SLAMMER_GRAVITY, polarity) for polarity in POLARITIES}
        expected = analysis["reference"]
        assert PYSLAMMER_RULES.passes(computed["normal"], expected["normal"]), analysis
        assert PYSLAMMER_RULES.passes(computed["inverse"], expected["inverse"]), analysis
        swapped_fails += not PYSLAMMER_RULES.passes(computed["inverse"], expected["normal"])
    assert swapped_fails == len(analyses)  # the other sign convention misses every one
