"""A bare number given to an acceleration option is in units of g; a number with a unit is in that unit.

``--ky 0.15`` is k_y = 0.15 (as SLAMMER, pySLAMMER and Jibson's tables write
it), the same as ``--ky 0.15g`` and ``--ky 1.4715m/s2`` at g = 9.81 m/s²;
``--target-pga 0.4`` is 0.4 g.  The output says the yield acceleration it used.
"""

from __future__ import annotations

import json
from importlib.resources import files

import pytest

from stickslip.cli.accelerations import acceleration, in_units_of_g
from stickslip.cli.collection_options import min_pga_in_g
from stickslip.errors import StickslipError
from stickslip.records.process import scale_to_pga
from stickslip.records.readers import read_record
from stickslip.models import solve

G = 9.81


@pytest.fixture(scope="module")
def record_file():
    """A record every installation has: pyslammer's Cape Mendocino PET-090 (time [s], acceleration [g])."""
    return files("pyslammer") / "sample_ground_motions" / "Cape_Mendocino_1992_PET-090.csv"


@pytest.mark.parametrize(("text", "expected"), [
    ("0.15", 0.15), ("0.15g", 0.15), ("0.15 G", 0.15), (".15", 0.15), ("1.5e-1", 0.15),
    ("1.4715m/s2", 0.15), ("1.4715 m/s²", 0.15), ("1.4715m/s^2", 0.15), ("1.4715 m s-2", 0.15), ("-0.3", -0.3),
    ("147.15cm/s2", 0.15), ("147.15 gal", 0.15), ("147.15cm/s/s", 0.15), ("0.15g's", 0.15),
])
def test_a_bare_number_is_in_g_and_a_unit_converts(text, expected):
    assert in_units_of_g(text, G, "--ky", "0.15") == pytest.approx(expected, rel=1e-15)
    assert acceleration(text, G, "--ky", "0.15") == pytest.approx(expected * G, rel=1e-15)


@pytest.mark.parametrize("text", ["0.102", "0.031g", "0.055 G", "0.062g's"])
def test_a_number_in_g_is_taken_exactly(text):
    """No round trip through m/s² for a number already in g: 0.102 * 9.81 / 9.81 is 0.10200000000000001."""
    number = float(text.rstrip("gG's "))
    assert number * G / G != number  # the round trip this guards against
    assert in_units_of_g(text, G, "--ky", "0.15") == number


@pytest.mark.parametrize("text", ["abc", "0.15ft", "0.15 m/s", "g", "", "0.1g0.2", "1.47m/s2/s"])
def test_anything_else_names_both_forms(text):
    with pytest.raises(StickslipError, match=r"expected a number in units of g \(0\.15, or 0\.15g\) or an "
                                             r"acceleration with its unit \(1\.47m/s2, 147cm/s2\)"):
        in_units_of_g(text, G, "--ky", "0.15")


def test_solve_ky_bare_is_the_yield_coefficient(run_cli, record_file):
    results = {}
    for text in ("0.15", "0.15g", "1.4715m/s2"):
        code, out, err = run_cli("solve", record_file, "--ky", text, "--json")
        assert code == 0, err
        results[text] = json.loads(out)
    assert results["0.15"]["ky"] == results["0.15g"]["ky"] == 0.15
    assert results["1.4715m/s2"]["ky"] == pytest.approx(0.15, rel=1e-15)
    expected = solve(read_record(record_file), ky=0.15).scalars()["downslope_displacement"]
    assert expected > 0
    for document in results.values():
        assert document["downslope_displacement"] == pytest.approx(expected, rel=1e-12)


def test_solve_says_which_yield_acceleration_it_used(run_cli, record_file):
    code, out, err = run_cli("solve", record_file, "--ky", "0.15")
    assert code == 0, err
    assert "ky = 0.15 (k_y*g = 1.472 m/s2), one-way (downslope), mass = 1 kg" in out.splitlines()[0]


def test_optimum_ky_grid_is_of_yield_coefficients(run_cli, record_file):
    code, out, err = run_cli("optimum", record_file, "--ky", "0.02:0.4:0.02", "--json")
    assert code == 0, err
    document = json.loads(out)
    asked = document["settings"]["given_ky"]
    assert asked[0] == 0.02 and asked[-1] == pytest.approx(0.4) and len(asked) == 20
    solved = document["settings"]["ky"]  # the grid asked for, extended where the near-optimal range reached its edge
    assert solved[0] <= 0.02 and solved[-1] >= 0.4 and set(asked) <= set(solved)
    row = document["records"][0]
    assert 0.0 < row["efficiency"] <= 1.0
    code, out, err = run_cli("optimum", record_file, "--ky", "0.02:0.4:0.02")
    assert code == 0, err
    assert out.startswith("yield-coefficient grid: 20 values of ky from 0.02 to 0.4, step 0.02 "
                          "(yield accelerations k_y*g from 0.1962 to 3.924 m/s2)")


def test_target_pga_bare_is_in_g(run_cli, record_file):
    energies = []
    for text in ("0.4", "0.4g", f"{0.4 * G}m/s2", f"{0.4 * G * 100}cm/s2", f"{0.4 * G * 100}gal"):
        code, out, err = run_cli("solve", record_file, "--mu", "0.1", "--target-pga", text, "--json")
        assert code == 0, err
        energies.append(json.loads(out)["energy_dissipated"])
    expected = solve(scale_to_pga(read_record(record_file), 0.4 * G), mu=0.1).energy_dissipated
    assert energies == pytest.approx([expected] * 5, rel=1e-12)


@pytest.mark.parametrize(("text", "expected"), [("0.3", 0.3), ("0.3g", 0.3), ("2.943m/s2", 0.3)])
def test_min_pga_bare_is_in_g(text, expected):
    assert min_pga_in_g(text) == pytest.approx(expected, rel=1e-15)
