"""``stickslip isolation design``'s quantities take their units, and a bare number far from its usual range is doubted.

The isolator's radius, friction and the structure's lengths read as every quantity option does
(``--radius 200cm``, ``--mu 6%``), the spectra's accelerations in units of g or with an acceleration unit
(``--sms 14.71m/s2`` is 1.5 g at g = 9.806 65 m/s²), and ``--g`` as gravity everywhere.
"""

from __future__ import annotations

import json

import pytest

from tests.conftest import assert_one_error_line

SPECTRUM = ("--sm1", "1.0", "--tl", "8")
#: A design's options, each bare.
BARE = {"--sms": "1.5", "--sm1": "1.0", "--tl": "8", "--radius": "2", "--mu": "0.06"}


def design_with(run_cli, option: str, value: str) -> tuple[int, str, str]:
    """``isolation design`` on :data:`BARE` with ``option`` given as ``value``: (exit code, stdout, stderr)."""
    options = {**BARE, option: value}
    return run_cli("isolation", "design", *[part for pair in options.items() for part in pair])


def design_json(run_cli, *options: str) -> tuple[dict, str]:
    code, out, err = run_cli("isolation", "design", *options, "--json")
    assert code == 0, err
    return json.loads(out), err


def test_a_radius_in_cm_and_a_friction_in_percent_give_the_design_of_the_bare_numbers(run_cli):
    bare, _ = design_json(run_cli, "--sms", "1.5", *SPECTRUM, "--radius", "2", "--mu", "0.06")
    with_units, err = design_json(run_cli, "--sms", "1.5", *SPECTRUM, "--radius", "200cm", "--mu", "6%")
    assert err == ""
    assert with_units["radius"] == 2.0 and with_units["mu"] == 0.06
    assert with_units["asce7_22"] == bare["asce7_22"] and with_units["en1998_2"] == bare["en1998_2"]


def test_a_spectral_acceleration_with_an_acceleration_unit_is_divided_by_g(run_cli):
    in_g, _ = design_json(run_cli, "--sms", "1.5g", *SPECTRUM, "--radius", "2", "--mu", "0.06", "--g", "9.80665")
    in_si, _ = design_json(run_cli, "--sms", "14.709975m/s2", *SPECTRUM, "--radius", "2", "--mu", "0.06",
                           "--g", "980.665cm/s2")
    assert in_g["spectra_given"]["sms"] == 1.5
    assert in_si["spectra_given"]["sms"] == pytest.approx(1.5, rel=1e-12)
    assert in_si["g"] == pytest.approx(9.80665, rel=1e-15)
    assert in_si["asce7_22"]["nominal"]["design_displacement"] == pytest.approx(
        in_g["asce7_22"]["nominal"]["design_displacement"], rel=1e-9)


@pytest.mark.parametrize(("option", "value", "named"), [
    ("--radius", "2000", "2 m if it is in mm"),
    ("--mu", "6", "0.06 if it is in % (write the unit: 6%)"),
    ("--g", "981", "9.81 m/s2 if it is in cm/s2"),
])
def test_a_bare_number_outside_its_usual_range_gets_one_warning_naming_its_readings(run_cli, option, value, named):
    code, _, err = design_with(run_cli, option, value)
    warnings = [line for line in err.splitlines() if "warning" in line]
    assert len(warnings) == 1, err
    assert f"{option} {value}:" in warnings[0] and named in warnings[0]
    assert "  " not in warnings[0].split("warning: ")[1]


@pytest.mark.parametrize(("option", "value", "phrase"), [
    ("--sms", "1.5x", "expected a number in units of g"),
    ("--radius", "2m/s", "expected a number with its unit"),
    ("--mu", "six", "expected a number with its unit"),
])
def test_a_quantity_in_no_unit_of_its_kind_is_refused_in_one_line(run_cli, option, value, phrase):
    code, out, err = design_with(run_cli, option, value)
    assert_one_error_line(code, out, err, option, phrase)
