"""``stickslip estimate`` and ``stickslip displacements`` take every quantity with its unit; a bare number outside its
usual range gets a warning naming the units it is likely in.

A slope engineer's ``--pga 3.63`` (m/s²), ``--arias 97`` (cm/s), ``--ky 15`` (%) and ``--g 981`` (cm/s²) used to be
taken at face value; now each is answered as written, with one warning line naming the likely reading, and the same
number written with its unit is taken without a doubt.
"""

from __future__ import annotations

import json
import warnings
from importlib.resources import files

import pytest

from stickslip.cli.quantities import GRAVITY, Quantity, doubt, read_gravity, read_quantity
from stickslip.errors import StickslipError, StickslipWarning

SAMPLE = files("pyslammer") / "sample_ground_motions" / "Cape_Mendocino_1992_PET-090.csv"
ARIAS = Quantity("m/s", {None: 1.0, "m/s": 1.0, "cm/s": 0.01}, "1.2 or 1.2m/s", usual=(0.0, 30.0))


def _warnings(err: str) -> list[str]:
    return [line.removeprefix("stickslip: warning: ") for line in err.splitlines() if "warning:" in line]


@pytest.mark.parametrize(("text", "expected"), [("0.97", 0.97), ("97cm/s", 0.97), ("0.97 m/s", 0.97),
                                                ("97 cm s-1", 0.97), ("0.97m s^-1", 0.97), ("5e-5", 5e-5)])
def test_a_quantity_takes_its_units_in_any_spelling(text, expected):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert read_quantity(text, "--arias", ARIAS) == pytest.approx(expected, rel=1e-15)


@pytest.mark.parametrize("text", ["97 furlongs", "fast", "97m/s2", ""])
def test_anything_else_is_one_error_naming_the_forms(text):
    with pytest.raises(StickslipError, match=r"--arias .*: expected a number with its unit, such as 1.2 or 1.2m/s"):
        read_quantity(text, "--arias", ARIAS)


def test_a_bare_number_outside_the_usual_names_its_likely_units():
    with pytest.warns(StickslipWarning) as caught:
        assert read_quantity("97", "--arias", ARIAS) == 97.0
    assert str(caught[0].message) == ("--arias 97: 97 m/s if the number is in m/s, more than 30 m/s; 0.97 m/s if it is "
                                      "in cm/s (write the unit: 97cm/s)")
    with pytest.warns(StickslipWarning, match=r"--g 981: 981 m/s2 if the number is in m/s2, more than 9.9 m/s2; 9.81 "
                                              r"m/s2 if it is in cm/s2 \(write the unit: 981cm/s2\)"):
        assert read_gravity("981") == 981.0
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert read_gravity("981cm/s2") == pytest.approx(9.81, rel=1e-15)
        assert read_gravity("9.80665") == 9.80665 and read_gravity("9.81 m/s²") == 9.81
    assert GRAVITY.usual == (9.7, 9.9)
    assert doubt("--x 5", 5.0, "m", "more than 2 m", []) == "--x 5: 5 m if the number is in m, more than 2 m"


def test_estimate_doubts_a_bare_pga_arias_and_g_and_takes_them_with_their_units(run_cli):
    code, out, err = run_cli("estimate", "--ky", "0.1", "--pga", "0.3", "--g", "981")
    assert code == 0 and _warnings(err) == [
        "--g 981: 981 m/s2 if the number is in m/s2, more than 9.9 m/s2; 9.81 m/s2 if it is in cm/s2 (write the unit: "
        "981cm/s2)"]
    code, out, err = run_cli("estimate", "--ky", "0.1", "--pga", "3.63", "--arias", "97", "--json")
    assert code == 0
    assert _warnings(err) == [
        "--pga 3.63: 3.63 g if the number is in g, more than 2 g; 0.37 g if it is in m/s2; 0.0037 g if it is in cm/s2 "
        "(write the unit: 3.63m/s2)",
        "--arias 97: 97 m/s if the number is in m/s, more than 30 m/s; 0.97 m/s if it is in cm/s (write the unit: "
        "97cm/s)"]
    code, out, err = run_cli("estimate", "--ky", "0.1", "--pga", "3.63m/s2", "--arias", "97cm/s", "--g", "9.81m/s2",
                             "--json")
    assert code == 0 and err == ""
    document = json.loads(out)
    (case,) = document["records"]
    assert case["measures"]["pga"] == pytest.approx(0.37003, rel=1e-4)
    assert case["measures"]["arias_intensity"] == pytest.approx(0.97, rel=1e-15)
    assert document["settings"]["g"] == 9.81


def test_a_bare_sa_beyond_4_g_is_doubted(run_cli):
    code, _, err = run_cli("estimate", "--ky", "0.1", "--sa", "5", "--sa13", "4.5", "--ts", "0.3", "--mw", "7")
    assert code == 0 and _warnings(err) == [
        "--sa 5: 5 g if the number is in g, more than 4 g; 0.51 g if it is in m/s2; 0.0051 g if it is in cm/s2 (write "
        "the unit: 5m/s2)",
        "--sa13 4.5: 4.5 g if the number is in g, more than 4 g; 0.459 g if it is in m/s2; 0.00459 g if it is in cm/s2 "
        "(write the unit: 4.5m/s2)"]


def test_estimate_ky_15_names_15_percent_first_and_takes_15_percent(run_cli):
    code, out, err = run_cli("estimate", "--ky", "15", "--pga", "0.3", "--json")
    assert code == 0 and _warnings(err) == ["--ky 15: 15 g if the number is in g, more than 1 g; 0.15 g if it is in %; "
                                            "0.0153 g if it is in cm/s2 (write the unit: 15%)"]
    code, out, err = run_cli("estimate", "--ky", "15%", "--pga", "0.3", "--json")
    assert code == 0 and err == ""
    assert json.loads(out)["records"][0]["ky"] == 0.15


def test_the_other_options_take_their_units(run_cli):
    bare = run_cli("estimate", SAMPLE, "--ky", "0.1", "--mw", "7", "--ts", "0.3", "--vs", "300", "--vs-base", "760",
                   "--damping", "0.05", "--exceed", "5", "--json")
    with_units = run_cli("estimate", SAMPLE, "--ky", "10%", "--mw", "7", "--ts", "0.3s", "--vs", "300m/s",
                         "--vs-base", "760 m/s", "--damping", "5%", "--exceed", "0.05m", "--json")
    assert bare[0] == with_units[0] == 0 and bare[2] == with_units[2] == ""
    first, second = json.loads(bare[1]), json.loads(with_units[1])
    assert first["settings"]["layer"] == pytest.approx(second["settings"]["layer"], rel=1e-15)
    assert first["records"][0]["methods"] == second["records"][0]["methods"]
    given = run_cli("estimate", "--ky", "0.1", "--pga", "0.3", "--tm", "0.4s", "--pgv", "0.4m/s", "--json")
    assert json.loads(given[1])["records"][0]["measures"]["mean_period"] == 0.4
    height = run_cli("estimate", SAMPLE, "--ky", "0.1", "--vs", "300", "--vs-base", "760", "--height", "22.5m",
                     "--json")
    assert json.loads(height[1])["settings"]["layer"]["height"] == 22.5


def test_displacements_warns_for_each_bare_ky_and_prints_no_negative_zero(run_cli):
    code, out, err = run_cli("displacements", SAMPLE, "--ky", "5,10,15")
    assert code == 0
    assert _warnings(err) == [
        "--ky 5: 5 g if the number is in g, more than 1 g; 0.05 g if it is in %; 0.51 g if it is in m/s2; 0.0051 g if "
        "it is in cm/s2 (write the unit: 5%)",
        "--ky 10: 10 g if the number is in g, more than 1 g; 0.1 g if it is in %; 0.0102 g if it is in cm/s2 (write "
        "the unit: 10%)",
        "--ky 15: 15 g if the number is in g, more than 1 g; 0.15 g if it is in %; 0.0153 g if it is in cm/s2 (write "
        "the unit: 15%)"]
    assert "-0" not in out
    row = next(line for line in out.splitlines() if line.split()[1:2] == ["5"])
    assert row.split()[3:6] == ["0", "0", "0"]
    code, out, err = run_cli("displacements", SAMPLE, "--ky", "5,10,15", "--json")
    assert all(str(row["newmark_displacement_normal"]) == "0.0" for row in json.loads(out)["records"])


def test_displacements_takes_percent_and_gravity_with_units(run_cli):
    code, out, err = run_cli("displacements", SAMPLE, "--ky", "5%,10%", "--g", "980.665cm/s2", "--json")
    assert code == 0 and err == ""
    document = json.loads(out)
    assert document["settings"]["ky"] == [0.05, 0.1] and document["settings"]["g"] == pytest.approx(9.80665)
    code, _, err = run_cli("displacements", SAMPLE, "--ky", "0.1", "--g", "981")
    assert code == 0 and _warnings(err)[0].startswith("--g 981: 981 m/s2 if the number is in m/s2, more than 9.9 m/s2")
