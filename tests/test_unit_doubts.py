"""Units read without a doubt: a PGA, k_y or mu that only the wrong units explain gets a warning; one g per call.

A ``time,acc`` CSV written in m/s² and read as g (the format's units) gives a
PGA of several g: the warning names the PGA in the units assumed and in the
likely ones.  A bare ``--target-pga``, ``--ky`` or ``--mu`` beyond what it
can be warns the same way, as does a pendulum's ``--radius`` outside the usual
0.2 to 20 m, and ``--target-pga`` takes every unit ``--units`` takes.
``--g`` converts the records stored in g as well as k_y·g, and the
outputs state it.  ``--reference-strain`` needs its unit (pySLAMMER's
decimal strain 0.0005 is 0.05 %), and an equivalent-linear layer that
softens to below 20 % of its V_s gets a warning.
"""

from __future__ import annotations

import json
import warnings

import numpy as np
import pytest
import xarray as xr
from conftest import assert_one_error_line

import stickslip
from stickslip.errors import StickslipWarning
from stickslip.measures import intensity_measures
from stickslip.models.layer import solve_flexible
from stickslip.models.layer.layer import Layer
from stickslip.records.plausibility import PLAUSIBLE_PGA, PLAUSIBLE_PGA_UNSTATED, pga_doubt
from stickslip.records.readers import read_record

G = 9.81
SLAMMER_G = 9.80665


def broadband(pga: float, seed: int = 0, samples: int = 3000) -> np.ndarray:
    """A random motion with the peak |value| ``pga`` (in whatever units), tapered at both ends."""
    values = np.random.default_rng(seed).normal(size=samples) * np.hanning(samples)
    return pga * values / np.max(np.abs(values))


def write_time_acc(path, values, dt: float = 0.01):
    """``values`` as pySLAMMER's ``time,acc`` CSV: no units in its title, so the format's (g) are assumed."""
    np.savetxt(path, np.column_stack([np.arange(values.size) * dt, values]), delimiter=",", header="time,acc",
               comments="", fmt=["%.2f", "%.9g"])
    return path


@pytest.fixture(scope="module")
def metres_csv(tmp_path_factory):
    """A 0.472 g motion written in m/s² (peak 4.63) as a time,acc CSV."""
    return write_time_acc(tmp_path_factory.mktemp("doubts") / "site_ms2.csv", broadband(4.63))


def test_a_pga_outside_the_plausible_band_names_the_units_assumed_and_the_likely_ones():
    assert PLAUSIBLE_PGA == (0.001, 4.0)
    assert pga_doubt(4.63, "g", G) == ("PGA 4.63 g if the values are in g; 0.472 g if they are in m/s2; 0.00472 g if "
                                       "they are in cm/s2")
    assert pga_doubt(45.0, "g", G) == "PGA 45 g if the values are in g; 0.0459 g if they are in cm/s2"
    assert pga_doubt(0.3, "cm/s2", G) == ("PGA 0.000306 g if the values are in cm/s2; 0.0306 g if they are in m/s2; "
                                          "0.3 g if they are in g")
    assert pga_doubt(3.9, "g", G) is None and pga_doubt(0.0099, "m/s2", G) is None


def test_a_csv_in_metres_per_second_squared_read_as_g_gets_one_warning(metres_csv, run_cli):
    with pytest.warns(StickslipWarning, match=r"site_ms2.csv: line \d+: PGA 4.63 g if the values are in g; 0.472 g if "
                                              r"they are in m/s2; 0.00472 g if they are in cm/s2: give units=$"):
        read_record(metres_csv)
    for command in (("measures",), ("records", "validate"), ("solve", "--mu", "0.1")):
        code, out, err = run_cli(*command, metres_csv)
        assert code == 0 and err.count("\n") == 1, err
        assert err.startswith(f"stickslip: warning: {metres_csv}: line ") and err.endswith(
            "PGA 4.63 g if the values are in g; 0.472 g if they are in m/s2; 0.00472 g if they are in cm/s2: give "
            "--units\n")
    code, out, err = run_cli("measures", metres_csv, "--units", "m/s2", "--json")
    assert code == 0 and err == "" and json.loads(out)["pga"] == pytest.approx(4.63, rel=1e-8)


def test_values_whose_units_nobody_states_are_doubted_from_2_g(run_cli, tmp_path):
    """A 0.36 g motion written in m/s² reads as 3.5 g: inside the 4 g band, outside the unstated units' 2 g."""
    assert PLAUSIBLE_PGA_UNSTATED == (0.001, 2.0)
    unstated = write_time_acc(tmp_path / "tolmezzo_ms2.csv", broadband(3.5))
    with pytest.warns(StickslipWarning, match=r"tolmezzo_ms2.csv: line \d+: PGA 3.5 g if the values are in g; 0.357 g "
                                              r"if they are in m/s2; 0.00357 g if they are in cm/s2: give units=$"):
        read_record(unstated)
    code, out, err = run_cli("solve", unstated, "--mu", "0.1")
    assert code == 0 and err.startswith("stickslip: warning: ") and err.endswith("give --units\n"), err
    stated = write_time_acc(tmp_path / "stated.csv", broadband(3.5))
    stated.write_text(stated.read_text().replace("time,acc", "time (s),acceleration (g)", 1))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        read_record(stated)  # the file says g: 3.5 g is in the 4 g band
        read_record(unstated, units="g")  # the user says g
        read_record(write_time_acc(tmp_path / "strong.csv", broadband(1.3)))  # pySLAMMER's strongest sample: 1.30 g


def test_units_the_file_states_or_given_units_advise_otherwise(tmp_path):
    path = tmp_path / "weak.txt"
    np.savetxt(path, np.column_stack([np.arange(3000) * 0.01, broadband(0.3)]), fmt=["%.2f", "%.9g"])
    with pytest.warns(StickslipWarning, match="PGA 0.000306 g if the values are in cm/s2; 0.0306 g if they are in m/s2; "
                                              "0.3 g if they are in g: check units=$"):
        read_record(path, units="cm/s2")
    titled = write_time_acc(tmp_path / "titled.csv", broadband(6.0))
    titled.write_text(titled.read_text().replace("time,acc", "time (s),acceleration (g)", 1))
    with pytest.warns(StickslipWarning, match="PGA 6 g if the values are in g; 0.612 g if they are in m/s2; 0.00612 g "
                                              "if they are in cm/s2: the file says g: check its values$"):
        read_record(titled)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        read_record(path, units="g")  # 0.3 g: no doubt


def test_target_pga_takes_every_unit_units_takes_and_doubts_a_bare_number_beyond_4_g(run_cli, tmp_path):
    path = write_time_acc(tmp_path / "site.csv", broadband(0.3))
    expected = read_record(path)
    for text in ("981cm/s2", "981 gal", "9.81m/s^2", "1g"):
        code, out, err = run_cli("solve", path, "--mu", "0.1", "--target-pga", text, "--json")
        assert code == 0 and err == "", (text, err)
        assert json.loads(out)["processing"] == [f"scale {9.81 / np.max(np.abs(expected.acceleration)):g} to PGA "
                                                 "9.81 m/s2"]
    code, out, err = run_cli("solve", path, "--mu", "0.1", "--target-pga", "5")
    assert code == 0
    assert err == ("stickslip: warning: --target-pga 5: 5 g if the number is in g, more than 4 g; 0.51 g if it is in "
                   "m/s2; 0.0051 g if it is in cm/s2 (write the unit: 5m/s2)\n")
    assert_one_error_line(*run_cli("solve", path, "--mu", "0.1", "--target-pga", "400"), "--target-pga 400",
                          "400 g if the number is in g, more than 100 g, which no ground motion comes near; 0.408 g if "
                          "it is in cm/s2 (write the unit: 400cm/s2)")


@pytest.mark.parametrize(("arguments", "warning"), [
    (("--ky", "15"), "--ky 15: 15 g if the number is in g, more than 1 g; 0.0153 g if it is in cm/s2 (write the unit: "
                     "15cm/s2)"),
    (("--mu", "15"), "--mu 15: a friction ratio of 15: the block slides only where the ground acceleration passes 15 "
                     "g, which no ground motion reaches; a friction ratio is written as a fraction (0.15 for 15 %)"),
])
def test_a_yield_coefficient_or_friction_ratio_above_one_gets_a_warning(run_cli, tmp_path, arguments, warning):
    path = write_time_acc(tmp_path / "site.csv", broadband(0.3))
    code, out, err = run_cli("solve", path, *arguments)
    assert code == 0 and err.splitlines()[0] == f"stickslip: warning: {warning}"
    code, out, err = run_cli("optimum", path, "--mu", "0.5:3:0.5", "--json")
    warned = [line for line in err.splitlines() if line.startswith("stickslip: warning: ")]
    assert code == 0 and [line.split(": ")[3] for line in warned] == [
        f"a friction ratio of {value}" for value in ("1.5", "2", "2.5", "3")]  # one warning for each value above 1
    code, out, err = run_cli("solve", path, arguments[0], "0.15")
    assert code == 0 and err == ""


USUAL_RADII = "outside the 0.2 to 20 m usual for the surfaces of friction pendulums (T = 0.9 to 9 s)"


@pytest.mark.parametrize(("arguments", "warnings_expected"), [
    (("--radius", "200"), [f"--radius 200: 200 m if the number is in m, {USUAL_RADII}; 2 m if it is in cm; 0.2 m if "
                           "it is in mm (write the unit: 200cm)"]),
    (("--radius", "0.05"), [f"--radius 0.05: 0.05 m if the number is in m, {USUAL_RADII}"]),
    (("--radius", "200m"), []),  # written with its unit: taken as written
    (("--radius", "2", "--chart-radii", "100,200,300"), [
        f"--chart-radii 100,200,300: {value} m if the number is in m, {USUAL_RADII}; {value / 100:g} m if it is in cm"
        + ("" if value < 200 else f"; {value / 1000:g} m if it is in mm") + f" (write the unit: {value}cm)"
        for value in (100, 200, 300)]),
])
def test_a_pendulum_radius_outside_the_usual_gets_a_warning_for_each_value(run_cli, tmp_path, arguments,
                                                                           warnings_expected):
    """A radius given in cm (200 for 2 m) is a nearly flat surface, T = 28 s: answered, with a warning naming the
    likely unit; each radius of a list gets its own."""
    path = write_time_acc(tmp_path / "site.csv", broadband(0.3))
    code, out, err = run_cli("optimum", path, *arguments, "--mu", "0.02:0.2:0.02",
                             *(("--chart", tmp_path / "chart.png") if "--chart-radii" in arguments else ()))
    assert code == 0 and err.splitlines() == [f"stickslip: warning: {warning}" for warning in warnings_expected]
    for radius in ("2", "inf"):
        code, out, err = run_cli("solve", path, "--mu", "0.05", "--radius", radius)
        assert code == 0 and err == ""


def test_one_g_converts_the_records_in_g_and_the_yield_level_and_every_output_states_it(run_cli, tmp_path):
    """pySLAMMER's g (9.80665 m/s²) everywhere: the command is the library read and solved with that g."""
    path = write_time_acc(tmp_path / "site.csv", broadband(0.45, seed=3))
    record = read_record(path, g=SLAMMER_G)
    assert record.meta.gravity == SLAMMER_G
    np.testing.assert_array_equal(record.acceleration,
                                  np.loadtxt(path, delimiter=",", skiprows=1)[:, 1] * SLAMMER_G)
    expected = stickslip.solve(record, ky=0.1, g=SLAMMER_G).scalars()["downslope_displacement"]
    with_default_conversion = stickslip.solve(read_record(path), ky=0.1, g=SLAMMER_G).scalars()
    assert abs(with_default_conversion["downslope_displacement"] / expected - 1) > 1e-4  # two g's: off by about 0.1 %
    code, out, err = run_cli("solve", path, "--ky", "0.1", "--g", str(SLAMMER_G), "--json")
    assert code == 0 and err == ""
    document = json.loads(out)
    assert document["g"] == SLAMMER_G and document["downslope_displacement"] == pytest.approx(expected, rel=1e-12)
    code, out, _ = run_cli("solve", path, "--ky", "0.1", "--g", str(SLAMMER_G))
    assert "g = 9.80665 m/s2" in out.splitlines()[0]
    code, out, _ = run_cli("measures", path, "--g", str(SLAMMER_G), "--json")
    measures = intensity_measures(record, g=SLAMMER_G).as_dict()
    document = json.loads(out)
    assert document["g"] == SLAMMER_G and document["pga"] == pytest.approx(measures["pga"], rel=1e-12)
    assert document["arias_intensity"] == pytest.approx(measures["arias_intensity"], rel=1e-12)
    code, out, _ = run_cli("measures", path, "--g", str(SLAMMER_G))
    assert "g = 9.80665 m/s2" in out.splitlines()[0]
    code, out, _ = run_cli("records", "validate", path, "--g", str(SLAMMER_G))
    assert "g = 9.80665 m/s2" in out.splitlines()[0]


def test_estimate_converts_with_its_g_states_it_and_doubts_a_bare_ky_above_one(run_cli, tmp_path):
    path = write_time_acc(tmp_path / "site.csv", broadband(0.45, seed=3))
    peak = np.max(np.abs(np.loadtxt(path, delimiter=",", skiprows=1)[:, 1]))  # in g, as written
    code, out, err = run_cli("estimate", path, "--ky", "0.1", "--g", str(SLAMMER_G), "--json")
    assert code == 0 and err == "", err
    document = json.loads(out)
    assert document["settings"]["g"] == SLAMMER_G
    assert document["records"][0]["measures"]["pga"] == pytest.approx(peak, rel=1e-12)  # one g: the file's own PGA
    code, out, _ = run_cli("estimate", path, "--ky", "0.1", "--g", str(SLAMMER_G))
    assert code == 0 and out.splitlines()[0].endswith("; k_y 0.1, g = 9.80665 m/s2")
    code, out, err = run_cli("estimate", "--ky", "15", "--pga", "0.3")
    assert code == 0 and err.splitlines()[0] == ("stickslip: warning: --ky 15: 15 g if the number is in g, more than 1 "
                                                 "g; 0.15 g if it is in %; 0.0153 g if it is in cm/s2 (write the unit: "
                                                 "15%)")


def test_the_workflows_gravity_converts_the_records_it_stores(tmp_path):
    from stickslip.records.acquire import acquire, store_record
    from stickslip.records.netcdf import read_record_netcdf

    stored = tmp_path / "tak.nc"
    store_record("pyslammer_kobe_1995_tak_090", stored, download=False, g=SLAMMER_G)
    record = read_record_netcdf(stored)
    at_default = acquire("pyslammer_kobe_1995_tak_090", download=False)
    assert record.meta.gravity == SLAMMER_G and at_default.meta.gravity == G
    np.testing.assert_allclose(record.acceleration, at_default.acceleration / G * SLAMMER_G, rtol=1e-15)
    with xr.open_dataset(stored) as dataset:
        assert dataset.attrs["gravity"] == SLAMMER_G and dataset.attrs["gravity_units"] == "m s-2"


def test_the_reference_strain_needs_its_unit(run_cli, tmp_path):
    path = write_time_acc(tmp_path / "site.csv", broadband(0.45))
    layer = ["--ky", "0.1", "--model", "decoupled", "--height", "20", "--vs", "300", "--vs-base", "760",
             "--equivalent-linear"]
    assert_one_error_line(*run_cli("solve", path, *layer, "--reference-strain", "0.0005"), "--reference-strain '0.0005'",
                          "give the strain with its unit, in percent (0.05%); pySLAMMER's decimal strain 0.0005 is "
                          "0.05%")
    code, out, err = run_cli("solve", path, *layer, "--reference-strain", "0.05%", "--json")
    assert code == 0 and err == "", err
    assert json.loads(out)["reference_strain"] == 0.05


def test_an_equivalent_linear_layer_that_softens_below_a_fifth_of_its_vs_gets_a_warning(run_cli, tmp_path):
    path = write_time_acc(tmp_path / "site.csv", broadband(0.45))
    layer = ["--ky", "0.1", "--model", "decoupled", "--height", "20", "--vs", "300", "--vs-base", "760",
             "--equivalent-linear"]
    record = read_record(path)
    with pytest.warns(StickslipWarning, match=r"the equivalent-linear layer's V_s ends at .*; check reference_strain= "):
        soft = solve_flexible(record, 0.1, Layer(20.0, 300.0, 760.0, soil_model="equivalent-linear",
                                                 reference_strain=0.0005), "decoupled")
    assert soft.vs_final < 0.2 * 300.0
    code, out, err = run_cli("solve", path, *layer, "--reference-strain", "0.0005%", "--json")
    assert code == 0
    document = json.loads(out)
    assert document["vs_final"] == pytest.approx(soft.vs_final, rel=1e-12) and "damping_final" in document
    warning, *notes = err.splitlines()
    assert warning == (f"stickslip: warning: {path}: the equivalent-linear layer's V_s ends at {soft.vs_final:.4g} m/s, "
                       "below 20% of its initial 300 m/s (reference strain 0.0005 %): a soil this soft is far outside "
                       "what the equivalent-linear model describes well; check --reference-strain (pySLAMMER's 0.0005 "
                       "is 0.05%)")
    assert all(note.startswith(f"stickslip: note: {path}: the block never slides") for note in notes)
    code, out, err = run_cli("solve", path, *layer, "--reference-strain", "0.05%")
    assert code == 0 and err == "" and "vs_final" in out and "damping_final" in out
    code, _, err = run_cli("sweep", path, "--ky", "0.1,0.2", "--model", "decoupled", "--height", "20,30", "--vs", "300",
                           "--vs-base", "760", "--equivalent-linear", "--reference-strain", "0.0005%",
                           "--out", tmp_path / "soft.nc")
    assert code == 0 and "the equivalent-linear layer's V_s ends at" in err
