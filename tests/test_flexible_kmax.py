"""k_max of the flexible layer: the exact scheme's peak between the samples, and the peak at the samples beside it.

SLAMMER reports k_max, the largest |k| of the layer's average acceleration
k(t)·g, at the record's samples.  The exact scheme knows k(t) between them
(a closed form per step), and its block starts to slide there: ``kmax`` is
that continuous peak, ``kmax_samples`` SLAMMER's, which the verification
compares.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
import xarray as xr

from stickslip.models.layer import exact as layer_exact
from stickslip.models.layer import flexible_sweep, solve_flexible
from stickslip.models.layer.layer import Layer
from stickslip.records.process import resample
from stickslip.records.record import Record, RecordMeta
from stickslip.studies.verification import flexible as flexible_verification
from stickslip.studies.verification.slammer import PYSLAMMER_RULES
from stickslip.units import UNITS

G = 9.80665

#: A layer whose period T = 4H/V_s = 0.08 s is eight samples of the record below.
LAYER = Layer(6.0, 300.0, 600.0, 0.05)


@pytest.fixture(scope="module")
def resonant_record() -> Record:
    """A decaying 1.1 Hz wave with a 13 Hz tone near the layer's frequency, 0.5 g peak, 8 s every 0.01 s."""
    time = np.arange(0.0, 8.0, 0.01)
    wave = (np.sin(2 * np.pi * 1.1 * time) + 0.5 * np.sin(2 * np.pi * 13.0 * time)) * np.exp(-0.3 * time)
    return Record(0.5 * G * wave / np.max(np.abs(wave)), 0.01, RecordMeta(record_id="resonant wave"))


@pytest.mark.parametrize("model", ["decoupled", "coupled"])
def test_the_exact_kmax_is_the_peak_between_the_samples(resonant_record, model):
    """Above the samples' peak, unchanged by resampling, and the limit of the samples' peak as they get denser."""
    result = solve_flexible(resonant_record, 0.1, LAYER, model, g=G)
    assert result.kmax_samples == pytest.approx(np.max(np.abs(result.average_acceleration)) / G, rel=1e-15)
    assert result.kmax > 1.01 * result.kmax_samples
    finer = solve_flexible(resample(resonant_record, resonant_record.dt / 7), 0.1, LAYER, model, g=G)
    assert finer.kmax == pytest.approx(result.kmax, rel=1e-12)
    densest = solve_flexible(resample(resonant_record, resonant_record.dt / 64), 0.1, LAYER, model, g=G)
    assert result.kmax * (1 - 1e-5) < densest.kmax_samples <= result.kmax * (1 + 1e-12)


def test_both_models_share_the_layer_s_kmax_and_slammer_s_scheme_knows_the_samples_only(resonant_record):
    decoupled = solve_flexible(resonant_record, 0.1, LAYER, "decoupled", g=G)
    coupled = solve_flexible(resonant_record, 0.1, LAYER, "coupled", g=G)
    assert coupled.kmax == pytest.approx(decoupled.kmax, rel=1e-14)
    assert coupled.kmax_samples == pytest.approx(decoupled.kmax_samples, rel=1e-14)
    slammer = solve_flexible(resonant_record, 0.1, LAYER, "decoupled", "slammer", g=G)
    assert slammer.kmax == slammer.kmax_samples


@pytest.mark.parametrize("model", ["decoupled", "coupled"])
def test_a_yield_coefficient_between_the_two_peaks_slides_and_one_above_kmax_does_not(resonant_record, model):
    """The block starts to slide where k·g exceeds k_y·g between the samples: the printed k_max is where it cannot."""
    result = solve_flexible(resonant_record, 0.1, LAYER, model, g=G)
    assert np.max(result.average_acceleration) / G == pytest.approx(result.kmax_samples)  # the peak is downslope
    between = solve_flexible(resonant_record, 0.5 * (result.kmax + result.kmax_samples), LAYER, model, g=G)
    above = solve_flexible(resonant_record, result.kmax * (1 + 1e-9), LAYER, model, g=G)
    assert between.displacement > 0.0 and above.displacement == 0.0


def test_the_two_peaks_are_scalars_with_units_and_names_in_the_histories_and_the_cube(resonant_record):
    result = solve_flexible(resonant_record, 0.1, LAYER, "decoupled", g=G)
    scalars = result.scalars()
    assert list(scalars)[:3] == ["displacement", "kmax", "kmax_samples"]
    assert (scalars["kmax"], scalars["kmax_samples"]) == (result.kmax, result.kmax_samples)
    assert UNITS["kmax"] == UNITS["kmax_samples"] == "1"
    dataset = result.to_xarray()
    assert dataset.kmax.item() == result.kmax and dataset.kmax_samples.item() == result.kmax_samples
    assert "between the samples" in dataset.kmax.attrs["long_name"]
    assert "SLAMMER's Kmax" in dataset.kmax_samples.attrs["long_name"]
    cube = flexible_sweep([resonant_record], [0.1, 0.2], [6.0], vs=300.0, vs_base=600.0, g=G)
    assert cube.kmax.item() == pytest.approx(result.kmax, rel=1e-14)
    assert cube.kmax_samples.item() == pytest.approx(result.kmax_samples, rel=1e-14)
    assert cube.kmax.attrs["units"] == cube.kmax_samples.attrs["units"] == "1"


def test_the_command_line_prints_both_peaks(resonant_record, run_cli, tmp_path):
    path = tmp_path / "resonant.csv"
    np.savetxt(path, np.column_stack([resonant_record.time, resonant_record.acceleration]), delimiter=",",
               header="time,acc", comments="")
    expected = solve_flexible(resonant_record, 0.1, LAYER, "coupled", g=G)
    arguments = ("solve", path, "--units", "m/s2", "--g", str(G), "--ky", "0.1", "--model", "coupled", "--height", "6",
                 "--vs", "300", "--vs-base", "600")
    code, stdout, stderr = run_cli(*arguments, "--json", "--out", tmp_path / "histories.nc")
    assert code == 0, stderr
    document = json.loads(stdout.splitlines()[0])
    assert document["kmax"] == pytest.approx(expected.kmax, rel=1e-12)
    assert document["kmax_samples"] == pytest.approx(expected.kmax_samples, rel=1e-12)
    assert document["units"]["kmax"] == document["units"]["kmax_samples"] == "1"
    with xr.open_dataset(tmp_path / "histories.nc") as histories:
        assert histories.kmax_samples.item() == pytest.approx(expected.kmax_samples, rel=1e-12)
    code, stdout, stderr = run_cli(*arguments)
    rows = {fields[0]: fields[1] for fields in map(str.split, stdout.splitlines()[1:]) if len(fields) == 2}
    assert (rows["kmax"], rows["kmax_samples"]) == (f"{expected.kmax:.6g}", f"{expected.kmax_samples:.6g}")
    assert "kmax_samples is k_max at the record's samples, as SLAMMER prints it" in stdout


def test_the_verification_compares_slammer_s_kmax_with_ours_at_the_samples(resonant_record):
    """SLAMMER's k_max is at the samples: the verification's computed_kmax is ours there, not between them."""
    result = solve_flexible(resonant_record, 0.1, LAYER, "decoupled", g=G, ledger=False)
    analysis = {"analysis_id": "1", "earthquake": "wave", "station": "none", "motion_file": "wave.csv",
                "target_pga_g": 0.5, "model": "decoupled", "soil_model": "linear", "height": 6.0, "vs": 300.0,
                "vs_base": 600.0, "damping": 0.05, "reference_strain": None, "ky": 0.1, "dt": 0.01,
                "reference": {"normal": 100.0 * result.displacement}, "properties": {"kmax": result.kmax_samples}}
    row = flexible_verification.analysis_row(analysis, "normal", "exact", result, None, PYSLAMMER_RULES)
    assert row["computed_kmax"] == result.kmax_samples != result.kmax
    assert flexible_verification.property_agreement([row])["kmax"]["largest_relative_difference"] == 0.0


def test_every_extremum_between_two_samples_is_found():
    """Random states of the layer, random ramps of the ground: the located peak |k·g| of an interval against a
    dense evaluation of its closed form (4,001 points, whose own error is at most max|(k·g)''|·spacing²/8)."""
    kernels = layer_exact._compiled()
    rng = np.random.default_rng(20240611)
    ratio, participation = 2.0 / np.pi, 4.0 / np.pi
    for _ in range(2000):
        omega, xi = rng.uniform(5.0, 300.0), rng.uniform(0.0, 0.6)
        decay, damped = xi * omega, omega * np.sqrt(1.0 - xi * xi)
        pieces = int(rng.integers(1, 6))
        length = pieces * rng.uniform(0.2, 1.0) * 2.0 * np.pi / omega / layer_exact.SUBSTEPS_PER_PERIOD
        a0, slope = rng.normal(0.0, 3.0), rng.normal(0.0, 3.0) / length
        p0, p1 = -participation * a0, -participation * slope
        u0, v0 = rng.normal(0.0, 3.0) / omega ** 2, rng.normal(0.0, 3.0) / omega
        c0, c1, a, b = layer_exact._coefficients(u0, v0, omega, decay, damped, p0, p1)
        found = kernels["_interval_average_peak"](length, pieces, c0, c1, a, b, damped, decay, omega, p0, p1, a0,
                                                  slope, ratio, 0.0)
        # the layer's transient e^{−ξωτ}(A cos ω_dτ + B sin ω_dτ) differentiated twice: ü; k·g = a + (L/M_tot)·ü
        tau = np.linspace(0.0, length, 4001)
        first = (-decay * a + damped * b, -decay * b - damped * a)
        second = (-decay * first[0] + damped * first[1], -decay * first[1] - damped * first[0])
        acceleration = np.exp(-decay * tau) * (second[0] * np.cos(damped * tau) + second[1] * np.sin(damped * tau))
        dense = np.max(np.abs(a0 + slope * tau + ratio * acceleration))
        spacing_error = ratio * omega ** 4 * np.hypot(a, b) * (tau[1] - tau[0]) ** 2 / 8.0
        assert dense - 1e-12 * dense <= found <= dense + spacing_error + 1e-12 * dense


def test_a_slope_that_changes_sign_twice_inside_a_piece_has_its_peak_found():
    """(k·g)' = s + (L/M_tot)·u⃛ dips below zero and back inside one piece (same sign at both ends): the peak is the
    first of the two extrema, above both ends, found only through the zero of (k·g)''."""
    kernels = layer_exact._compiled()
    ratio, participation = 2.0 / np.pi, 4.0 / np.pi
    omega = 2.0 * np.pi * 10.0  # undamped: u's transient is R cos(ωτ − θ), u⃛ = Rω³ sin(ωτ − θ)
    length = 2.0 * np.pi / omega / layer_exact.SUBSTEPS_PER_PERIOD
    amplitude, theta = 1e-3, omega * 0.85 * length + 0.5 * np.pi  # u⃛ least at 0.85 of the piece
    slope = ratio * amplitude * omega ** 3 * (1.0 - 1e-3)  # (k·g)' at least −1e-3·(L/M_tot)Rω³
    a0 = 5.0  # k·g stays positive: its peak is its maximum
    p0, p1 = -participation * a0, -participation * slope
    c0, c1, _, _ = layer_exact._coefficients(0.0, 0.0, omega, 0.0, omega, p0, p1)
    a, b = amplitude * np.cos(theta), amplitude * np.sin(theta)
    tau = np.linspace(0.0, length, 20001)
    average = a0 + slope * tau - ratio * omega ** 2 * amplitude * np.cos(omega * tau - theta)
    inside = int(np.argmax(average))
    assert 0 < inside < tau.size - 1 and average[inside] > average[-1] + 1e-6  # an interior maximum, above the ends
    found = kernels["_interval_average_peak"](length, 1, c0, c1, a, b, omega, 0.0, omega, p0, p1, a0, slope, ratio,
                                              0.0)
    assert found == pytest.approx(average[inside], rel=1e-12, abs=1e-12)
