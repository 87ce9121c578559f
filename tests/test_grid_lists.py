"""A grid option takes a START:STOP:STEP range or a comma list in the same option, and its error names both forms."""

from __future__ import annotations

import json
from importlib.resources import files

import pytest

from conftest import assert_one_error_line

RECORD = files("pyslammer") / "sample_ground_motions" / "Cape_Mendocino_1992_PET-090.csv"


def test_mu_comma_list_is_the_mu_list(run_cli):
    code, listed, err = run_cli("optimum", RECORD, "--mu", "0.05,0.1,0.15", "--json")
    assert code == 0, err
    code, explicit, err = run_cli("optimum", RECORD, "--mu-list", "0.05", "0.1", "0.15", "--json")
    assert code == 0, err
    assert json.loads(listed)["settings"]["given_mu"] == [0.05, 0.1, 0.15]
    assert json.loads(listed)["records"] == json.loads(explicit)["records"]


def test_ky_comma_list_with_and_without_units(run_cli):
    code, bare, err = run_cli("optimum", RECORD, "--ky", "0.05,0.1,0.2", "--json")
    assert code == 0, err
    code, united, err = run_cli("optimum", RECORD, "--ky", "0.4905m/s2,0.981m/s2,1.962m/s2", "--json")
    assert code == 0, err
    assert json.loads(united)["settings"]["given_ky"] == pytest.approx(json.loads(bare)["settings"]["given_ky"],
                                                                       rel=1e-15)


@pytest.mark.parametrize(("value", "phrase"), [
    ("0.05;0.1", "expected START:STOP:STEP, three numbers such as 0.05:0.2:0.025, or a comma list (0.05,0.1,0.15)"),
    ("0.05,x", "expected a comma list of friction ratios mu (0.05,0.1,0.15) or START:STOP:STEP"),
    ("0.1,0.05", "values must be strictly increasing"),
])
def test_a_malformed_mu_names_both_forms(run_cli, value, phrase):
    assert_one_error_line(*run_cli("optimum", RECORD, "--mu", value), f"--mu {value!r}", phrase)


def test_the_report_says_it_takes_a_range(run_cli, tmp_path):
    assert_one_error_line(*run_cli("report", RECORD, "--mu", "0.05,0.1,0.15", "--out", tmp_path / "r.html"),
                          "--mu '0.05,0.1,0.15'", "the report sweeps a START:STOP:STEP range")
