"""``stickslip estimate``: on a record and on given measures, its JSON keys, and one line for each mistake."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from importlib.resources import files

import pytest

import stickslip
from conftest import assert_one_error_line
from stickslip.estimates.measures import estimate_inputs
from stickslip.estimates.registry import estimates
from stickslip.records.readers import read_record
from test_estimates_papers import METHOD_NAMES, WITH_P_ZERO

SAMPLE = files("pyslammer") / "sample_ground_motions" / "Cape_Mendocino_1992_PET-090.csv"
KEYS = {"median_displacement", "sigma", "log_base", "p_zero"}


def _stickslip(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "stickslip", *map(str, args)], capture_output=True, text=True,
                          timeout=300, env={**os.environ, "PYTHONDONTWRITEBYTECODE": "1"})


@pytest.fixture(scope="module")
def on_a_record() -> dict:
    """The JSON of ``stickslip estimate SAMPLE --ky 0.1 --mw 7.0 --ts 0.3 --vs 300 --vs-base 760 --exceed 5cm --json``."""
    result = _stickslip("estimate", SAMPLE, "--ky", "0.1", "--mw", "7.0", "--ts", "0.3", "--vs", "300", "--vs-base",
                        "760", "--exceed", "5cm", "--json")
    assert result.returncode == 0, result.stderr
    assert result.stderr == ""
    return json.loads(result.stdout)


def test_on_a_record_every_method_applies_with_exactly_its_four_keys(on_a_record):
    (case,) = on_a_record["records"]
    assert tuple(case["methods"]) == METHOD_NAMES
    for name, values in case["methods"].items():
        assert set(values) == KEYS, name
        assert values["log_base"] in ("10", "e") and values["median_displacement"] > 0.0, name
        assert (values["p_zero"] is None) == (name not in WITH_P_ZERO), name
    assert case["not_applicable"] == {} and case["no_sliding"] == {}
    assert on_a_record["units"]["median_displacement"] == "m"


def test_on_a_record_the_estimates_are_the_library_s_from_its_measures(on_a_record):
    record = read_record(SAMPLE)
    (case,) = on_a_record["records"]
    inputs = estimate_inputs(record, g=9.81, site_period=0.3)
    assert case["measures"] == pytest.approx(inputs)
    found, _ = estimates({**inputs, "ky": 0.1, "magnitude": 7.0, "site_period": 0.3})
    for name, estimate in found.items():
        assert case["methods"][name]["median_displacement"] == pytest.approx(estimate.median_displacement, rel=1e-12)
        assert case["exceedance"][name] == pytest.approx(estimate.probability_of_exceeding(0.05), rel=1e-12)


def test_on_a_record_the_rigorous_displacements_are_the_solvers(on_a_record):
    record = read_record(SAMPLE)
    (case,) = on_a_record["records"]
    for polarity in ("normal", "inverse"):
        inverse = polarity == "inverse"
        assert case["rigid_displacement"][polarity] == pytest.approx(
            stickslip.solve(record, ky=0.1, g=9.81, inverse=inverse).downslope_displacement, rel=1e-12)
        layer = stickslip.Layer(height=300 * 0.3 / 4, vs=300.0, vs_base=760.0)
        assert case["coupled_displacement"][polarity] == pytest.approx(stickslip.solve_flexible(
            record, 0.1, layer, model_name="coupled", g=9.81, inverse=inverse, ledger=False).displacement, rel=1e-12)
    assert on_a_record["settings"]["layer"]["period"] == pytest.approx(0.3)
    assert set(case["failure_probability"]) == {"jibson_2000", "rigid_normal", "rigid_inverse"}


def test_given_measures_print_the_methods_they_allow_and_name_what_the_others_need(run_cli):
    code, out, err = run_cli("estimate", "--ky", "0.1", "--pga", "0.3g", "--pgv", "0.4m/s", "--json")
    assert code == 0 and err == ""
    (case,) = json.loads(out)["records"]
    assert case["measures"]["pgv"] == pytest.approx(40.0) and case["measures"]["pga"] == 0.3
    assert set(case["methods"]) == {"jibson_2007_pga", "ambraseys_menu_1988", "saygili_rathje_2008_pga",
                                    "saygili_rathje_2008_pga_pgv"}
    assert case["not_applicable"]["bray_travasarou_2007"] == ["--ts", "--mw"]
    assert case["rigid_displacement"] is None and case["record"] is None
    assert case["methods"]["ambraseys_menu_1988"]["median_displacement"] == pytest.approx(
        0.01 * 10 ** (0.90 + 2.53 * __import__("math").log10(2 / 3) - 1.09 * __import__("math").log10(1 / 3)))


def test_the_table_shows_centimetres_and_the_rigorous_answer():
    result = _stickslip("estimate", SAMPLE, "--ky", "0.1")
    assert result.returncode == 0, result.stderr
    record = read_record(SAMPLE)
    normal = 100 * stickslip.solve(record, ky=0.1, g=9.81).downslope_displacement
    assert f"rigorous rigid D_n [cm] (exact, one-way): normal {normal:.3g}," in result.stdout
    assert "median D [cm]" in result.stdout and "Jibson (2007) eq. 6" in result.stdout
    assert "--mw for Jibson (2007) eq. 7" in result.stdout


def test_k_y_at_the_pga_gives_zero_with_the_reason(run_cli):
    code, out, _ = run_cli("estimate", "--ky", "0.35", "--pga", "0.3", "--json")
    (case,) = json.loads(out)["records"]
    assert code == 0 and case["methods"]["jibson_2007_pga"]["median_displacement"] == 0.0
    assert case["no_sliding"]["jibson_2007_pga"] == "k_y = 0.35 >= PGA = 0.3 g: the block never slides"


def test_a_mistake_is_one_line_and_exit_2_from_the_shell():
    result = _stickslip("estimate", "--ky", "0.1", "--pgv", "40")
    assert_one_error_line(result.returncode, result.stdout, result.stderr, "--pgv '40'",
                          "expected a number with its unit, such as 40cm/s or 0.4m/s")


@pytest.mark.parametrize("args, name, phrase", [
    (("--ky", "0.1"), "give record files", "or the measures to estimate from"),
    ((SAMPLE, "--ky", "0.1", "--pga", "0.3"), "--pga", "is for estimates without a record"),
    (("--ky", "-0.1", "--pga", "0.3"), "--ky", "every value must be a positive finite number"),
    (("--ky", "0.1", "--pga", "0.3", "--ts", "-1"), "--ts -1", "expected a period >= 0 s"),
    ((SAMPLE, "--ky", "0.1", "--vs", "300", "--vs-base", "760", "--ts", "0.3", "--height", "20"), "--height and --ts",
     "give one of them"),
    ((SAMPLE, "--ky", "0.1", "--vs", "300"), "--vs", "the layer needs --vs-base"),
    (("--ky", "0.1", "--pga", "0.3", "--vs", "300", "--vs-base", "760", "--ts", "0.3"), "layer options",
     "give record files"),
    (("--ky", "0.1", "--pga", "0.3", "--exceed", "5 furlongs"), "--exceed", "such as 5cm or 0.05m"),
    (("--ky", "0.1", "--arias", "0"), "--arias", "expected a positive number [m/s]"),
    (("--ky", "0.1", "--pga", "fast"), "--pga 'fast'", "expected a number in units of g"),
])
def test_each_mistake_is_one_line(run_cli, args, name, phrase):
    assert_one_error_line(*run_cli("estimate", *args), name, phrase)


def test_a_list_of_k_y_gives_one_row_each_equal_to_its_own_call(run_cli):
    code, out, err = run_cli("estimate", SAMPLE, "--ky", "0.05,0.1,0.2", "--mw", "7", "--json")
    assert code == 0 and err == ""
    document = json.loads(out)
    assert document["settings"]["ky"] == [0.05, 0.1, 0.2]
    assert [row["ky"] for row in document["records"]] == [0.05, 0.1, 0.2]
    assert len({row["record"] for row in document["records"]}) == 1
    for row in document["records"]:
        code, single, _ = run_cli("estimate", SAMPLE, "--ky", str(row["ky"]), "--mw", "7", "--json")
        (alone,) = json.loads(single)["records"]
        assert row["methods"] == alone["methods"] and row["rigid_displacement"] == alone["rigid_displacement"]
    medians = [row["methods"]["jibson_2007_pga"]["median_displacement"] for row in document["records"]]
    assert medians[0] > medians[1] > medians[2] > 0.0
    code, out, _ = run_cli("estimate", "--ky", "0.1,0.2", "--pga", "0.3")
    blocks = out.split("\n\ngiven measures: ")
    assert len(blocks) == 2 and "; k_y 0.1, g = 9.81 m/s2" in blocks[0] and blocks[1].startswith("PGA 0.3 g; k_y 0.2,")
