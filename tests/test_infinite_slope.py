"""The slope engineer's slope: ``--fs F --slope-angle DEG`` gives k_y = (F − 1)·sin α (Newmark 1965's infinite slope).

In ``stickslip estimate`` and ``stickslip displacements``, instead of ``--ky``: both at once, half of the pair, or
a slope that fails statically (F ≤ 1) is one error line.
"""

from __future__ import annotations

import json
import math
from importlib.resources import files

import pytest
from conftest import assert_one_error_line

from stickslip.errors import StickslipError
from stickslip.estimates.infinite_slope import yield_coefficient

SAMPLE = files("pyslammer") / "sample_ground_motions" / "Cape_Mendocino_1992_PET-090.csv"


@pytest.mark.parametrize(("factor", "angle", "expected"), [(1.5, 30.0, 0.25), (2.0, 90.0 - 1e-12, 1.0),
                                                           (1.2, 20.0, 0.2 * math.sin(math.radians(20.0)))])
def test_yield_coefficient_is_f_minus_one_times_sin_alpha(factor, angle, expected):
    assert yield_coefficient(factor, angle) == pytest.approx(expected, rel=1e-14)


@pytest.mark.parametrize(("factor", "angle", "message"), [
    (1.0, 30.0, "factor of safety 1 <= 1: the slope fails statically"),
    (0.8, 30.0, "factor of safety 0.8 <= 1: the slope fails statically"),
    (1.5, 0.0, "slope angle 0 degrees: expected an angle above 0 and below 90 degrees"),
    (1.5, 90.0, "slope angle 90 degrees"),
    (math.nan, 30.0, "factor of safety nan: expected a finite number above 1"),
])
def test_no_yield_coefficient_is_one_clear_error(factor, angle, message):
    with pytest.raises(StickslipError, match=message):
        yield_coefficient(factor, angle)


def test_estimate_from_the_slope_is_the_estimate_at_its_k_y(run_cli):
    code, out, err = run_cli("estimate", "--fs", "1.5", "--slope-angle", "30", "--pga", "0.4", "--mw", "7", "--json")
    assert code == 0 and err == ""
    from_slope = json.loads(out)
    code, out, _ = run_cli("estimate", "--ky", "0.25", "--pga", "0.4", "--mw", "7", "--json")
    at_ky = json.loads(out)
    assert from_slope["records"][0]["ky"] == pytest.approx(0.25, rel=1e-14)
    assert from_slope["settings"]["slope"] == {"factor_of_safety": 1.5, "slope_angle": 30.0}
    for name, values in at_ky["records"][0]["methods"].items():
        assert from_slope["records"][0]["methods"][name]["median_displacement"] == pytest.approx(
            values["median_displacement"], rel=1e-12)
    code, out, _ = run_cli("estimate", "--fs", "1.5", "--slope-angle", "30deg", "--pga", "0.4")
    assert "k_y 0.25 (F 1.5, slope 30 degrees: (F - 1) sin(alpha), Newmark 1965)" in out.splitlines()[0]


def test_displacements_from_the_slope_are_those_at_its_k_y(run_cli):
    code, out, err = run_cli("displacements", SAMPLE, "--fs", "1.2", "--slope-angle", "25", "--json")
    assert code == 0 and err == ""
    document = json.loads(out)
    ky = 0.2 * math.sin(math.radians(25.0))
    assert document["settings"]["ky"] == [pytest.approx(ky, rel=1e-14)]
    assert document["settings"]["slope"] == {"factor_of_safety": 1.2, "slope_angle": 25.0}
    code, out, _ = run_cli("displacements", SAMPLE, "--ky", f"{ky!r}", "--json")
    (at_ky,), (from_slope,) = json.loads(out)["records"], document["records"]
    for column in ("newmark_displacement_normal", "newmark_displacement_inverse", "jibson2007_ratio"):
        assert from_slope[column] == pytest.approx(at_ky[column], rel=1e-9) and at_ky[column] > 0.0
    code, out, _ = run_cli("displacements", SAMPLE, "--fs", "1.2", "--slope-angle", "25")
    assert out.splitlines()[1] == ("k_y 0.08452 from F = 1.2 and alpha = 25 degrees: k_y = (F - 1) sin(alpha), the "
                                   "infinite slope of Newmark (1965)")


@pytest.mark.parametrize("command", [("estimate", "--pga", "0.3"), ("displacements", SAMPLE)])
@pytest.mark.parametrize(("options", "name", "phrase"), [
    (("--ky", "0.1", "--fs", "1.5", "--slope-angle", "30"), "--ky and --fs and --slope-angle",
     "both set the yield coefficient: give --ky, or --fs with --slope-angle"),
    (("--fs", "1.5"), "--fs needs --slope-angle", "k_y = (F - 1) sin(alpha), the infinite slope of Newmark (1965)"),
    (("--slope-angle", "30"), "--slope-angle needs --fs", "the infinite slope of Newmark (1965)"),
    (("--fs", "0.9", "--slope-angle", "30"), "--fs 0.9 --slope-angle 30", "the slope fails statically"),
    (("--fs", "1.5", "--slope-angle", "95"), "--slope-angle 95", "expected an angle above 0 and below 90 degrees"),
    (("--fs", "safe", "--slope-angle", "30"), "--fs 'safe'", "expected a factor of safety, a number above 1"),
])
def test_each_mistake_is_one_line(run_cli, command, options, name, phrase):
    assert_one_error_line(*run_cli(*command, *options), name, phrase)


def test_estimate_needs_a_yield_coefficient(run_cli):
    assert_one_error_line(*run_cli("estimate", "--pga", "0.3"), "--ky", "or --fs F with --slope-angle DEG")
