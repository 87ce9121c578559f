"""Response spectra of a component and of a pair: closed forms, eqsig's independent oscillator, and the command."""

from __future__ import annotations

import json
import math

import eqsig.sdof as sdof  # a test dependency in environment-test.lock; never skipped
import numpy as np
import pytest

from stickslip.errors import StickslipError
from stickslip.records.pair import RecordPair
from stickslip.records.record import Record, RecordMeta
from stickslip.response_spectrum import relative_displacement
from stickslip.spectra import component_spectra, motion_spectra, pair_spectra, rotated_peaks

DT, PERIOD, DAMPING, AMPLITUDE = 0.002, 0.5, 0.05, 2.0
TIME = np.arange(0.0, 40.0, DT)
OMEGA = 2.0 * math.pi / PERIOD
#: At resonance the steady amplitude is a0/(2 ξ ω²); after 40 s (ξωt = 25) the transient is gone.
STEADY = AMPLITUDE / (2.0 * DAMPING * OMEGA**2)


def test_a_resonant_harmonic_gives_the_steady_amplitude():
    spectra = component_spectra(AMPLITUDE * np.sin(OMEGA * TIME), DT, [PERIOD], DAMPING)
    assert spectra.displacements["psa"][0] == pytest.approx(STEADY, rel=1e-4)
    assert spectra.pseudo_acceleration("psa")[0] == pytest.approx(AMPLITUDE / (2 * DAMPING), rel=1e-4)


def test_an_undamped_oscillator_after_a_velocity_impulse_swings_v_over_omega():
    """A one-sample pulse of area v0 = a dt (the record linear between samples: a triangle of area a dt) gives the
    free vibration u = -(v0/ω) sin ωt, peak v0/ω to the pulse's finite width."""
    acceleration = np.zeros(4000)
    acceleration[1] = 100.0
    velocity = 100.0 * DT
    peak = component_spectra(acceleration, DT, [2.0], 0.0).displacements["psa"][0]
    assert peak == pytest.approx(velocity / (2 * math.pi / 2.0), rel=1e-4)


def test_a_circular_motion_has_all_azimuths_alike():
    """a = A (sin ωt, cos ωt): the resonant response turns on a circle, so RotD50 = RotD100 = the geometric mean
    = the steady amplitude, and the SRSS is √2 times it."""
    spectra = pair_spectra(AMPLITUDE * np.sin(OMEGA * TIME), AMPLITUDE * np.cos(OMEGA * TIME), DT, [PERIOD], DAMPING)
    for measure in ("rotd100", "rotd50", "geomean"):
        assert spectra.displacements[measure][0] == pytest.approx(STEADY, rel=1e-3)
    assert spectra.displacements["srss"][0] == pytest.approx(math.sqrt(2) * STEADY, rel=1e-3)


def test_a_uniaxial_pair_has_rotd50_one_over_root_two_of_rotd100():
    """Only axis 1 moves: the peak at azimuth θ is |cos θ| times the component's; the median of |cos θ| over
    0°..179° is cos 45°, the geometric mean is 0 and the SRSS the component's."""
    rng = np.random.default_rng(3)
    first = rng.normal(0.0, 1.0, 3000)
    spectra = pair_spectra(first, np.zeros_like(first), 0.01, [0.2, 1.0])
    alone = component_spectra(first, 0.01, [0.2, 1.0]).displacements["psa"]
    np.testing.assert_allclose(spectra.displacements["rotd100"], alone, rtol=1e-12)
    np.testing.assert_allclose(spectra.displacements["rotd50"], alone / math.sqrt(2), rtol=1e-12)
    np.testing.assert_allclose(spectra.displacements["srss"], alone, rtol=1e-12)
    assert np.all(spectra.displacements["geomean"] == 0.0)


def test_rotd100_is_the_largest_azimuth_peak_and_rotd50_their_median():
    rng = np.random.default_rng(5)
    first, second = rng.normal(0.0, 1.0, 2500), rng.normal(0.0, 0.6, 2500)
    spectra = pair_spectra(first, second, 0.01, [0.7])
    one, other = relative_displacement(first, 0.01, 0.7), relative_displacement(second, 0.01, 0.7)
    fine = np.array([np.max(np.abs(one * math.cos(t) + other * math.sin(t))) for t in np.radians(np.arange(0, 180, 0.05))])
    assert spectra.displacements["rotd100"][0] == pytest.approx(fine.max(), rel=1e-6)
    every = np.array([np.max(np.abs(one * math.cos(t) + other * math.sin(t))) for t in np.radians(np.arange(180))])
    np.testing.assert_allclose(rotated_peaks(one, other), every, rtol=1e-15)  # the samples it skips hold no peak
    assert spectra.displacements["rotd50"][0] == pytest.approx(np.median(every), rel=1e-15)
    assert spectra.displacements["rotd100"][0] >= rotated_peaks(one, other).max()


def test_the_spectrum_agrees_with_eqsigs_nigam_jennings_oscillator(two_tone_record):
    """eqsig 1.2.17 (PyPI) steps the same exact recursion its own way; measured difference 2e-9 on real records."""
    periods = np.geomspace(0.05, 5.0, 25)
    theirs = sdof.pseudo_response_spectra(two_tone_record.acceleration, two_tone_record.dt, periods, 0.05)[0]
    ours = motion_spectra(two_tone_record, periods).displacements["psa"]
    np.testing.assert_allclose(ours, theirs, rtol=1e-7)


def test_a_pairs_rotd_uses_eqsigs_responses_alike(two_tone_record):
    second = np.roll(two_tone_record.acceleration, 37) * 0.7
    periods = np.array([0.3, 1.0, 2.5])
    spectra = pair_spectra(two_tone_record.acceleration, second, 0.01, periods)
    for index, period in enumerate(periods):
        one = sdof.response_series(two_tone_record.acceleration, 0.01, np.array([period]), 0.05)[0][0]
        other = sdof.response_series(second, 0.01, np.array([period]), 0.05)[0][0]
        assert spectra.displacements["rotd50"][index] == pytest.approx(np.median(rotated_peaks(one, other)), rel=1e-6)
        assert spectra.displacements["rotd100"][index] == pytest.approx(np.max(np.hypot(one, other)), rel=1e-6)


@pytest.mark.parametrize("periods, message", [([0.5, 0.2], "expected strictly increasing periods"),
                                              ([0.0, 1.0], "each must be a positive finite number")])
def test_bad_periods_are_refused(periods, message):
    with pytest.raises(StickslipError, match=message):
        component_spectra(np.ones(10), 0.01, periods)


def _write(folder, name, acceleration):
    path = folder / name
    time = np.arange(acceleration.size) * 0.01
    np.savetxt(path, np.column_stack([time, acceleration]), delimiter=",", header="time,acc", comments="")
    return path


def test_the_command_gives_a_pairs_spectra_in_g(tmp_path, run_cli, two_tone_record):
    first = _write(tmp_path, "st-000.csv", two_tone_record.acceleration)
    second = _write(tmp_path, "st-090.csv", np.zeros(two_tone_record.npts))
    code, out, err = run_cli("spectrum", first, second, "--pair", "--units", "m/s2", "--periods", "0.2,1",
                             "--json", "--csv", tmp_path / "s.csv", "--plot", tmp_path / "s.png")
    assert code == 0, err
    document = json.loads(out)
    alone = component_spectra(two_tone_record.acceleration, 0.01, [0.2, 1.0])
    assert document["periods"] == [0.2, 1.0]
    np.testing.assert_allclose(document["rotd100"], alone.pseudo_acceleration("psa") / 9.81, rtol=1e-12)
    np.testing.assert_allclose(document["sd_rotd50"], alone.displacements["psa"] / math.sqrt(2), rtol=1e-12)
    assert document["units"]["rotd50"] == "g" and document["units"]["periods"] == "s"
    assert (tmp_path / "s.csv").read_text().splitlines()[0].startswith("periods [s],rotd100 [g],rotd50 [g]")
    assert (tmp_path / "s.png").read_bytes()[:4] == b"\x89PNG"


def test_the_command_gives_one_components_psa(tmp_path, run_cli, two_tone_record):
    path = _write(tmp_path, "wave.csv", two_tone_record.acceleration)
    code, out, _ = run_cli("spectrum", path, "--units", "m/s2", "--periods", "0.5", "--damping", "10%")
    assert code == 0
    expected = component_spectra(two_tone_record.acceleration, 0.01, [0.5], 0.1).pseudo_acceleration("psa")[0] / 9.81
    assert out.splitlines()[1].split() == ["periods", "[s]", "psa", "[g]", "sd", "[m]"]
    assert float(out.splitlines()[2].split()[1]) == pytest.approx(expected, rel=1e-4)


@pytest.mark.parametrize("options, message", [
    (("--damping", "1.5"), "--damping 1.5: expected a damping ratio 0 <= xi < 1 (0.05 or 5%)"),
    (("--damping", "5 s"), "--damping '5 s': expected a number with its unit, such as 0.05 or 5%"),
    (("--periods", "1,x"), "--periods 1,x: expected periods [s] separated by commas, e.g. 0.1,0.5,1,2"),
    (("--periods", "2,1"), "--periods: 2, 1: expected strictly increasing periods [s]"),
])
def test_the_command_refuses_bad_options_in_one_line(tmp_path, run_cli, two_tone_record, options, message):
    path = _write(tmp_path, "wave.csv", two_tone_record.acceleration)
    code, _, err = run_cli("spectrum", path, "--units", "m/s2", *options)
    assert code == 2
    assert err.strip() == f"stickslip: error: {message}"
