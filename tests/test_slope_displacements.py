"""``stickslip displacements``: D_n per record and k_y in both polarities, their statistics, Jibson's (2007) estimates."""

from __future__ import annotations

import csv
import json
import math
from importlib.resources import files

import numpy as np
import pytest

from conftest import assert_one_error_line
from stickslip.records.readers import read_record
from stickslip.slope_displacements import ROW_COLUMNS, STATISTIC_COLUMNS, slope_displacements
from stickslip.models import solve
from stickslip.studies.jibson2007.fit import jibson_reference

SAMPLES = files("pyslammer") / "sample_ground_motions"
NAMES = ("Northridge_1994_PAC-175.csv", "Cape_Mendocino_1992_PET-090.csv", "Coalinga_1983_PVB-045.csv")
KY = (0.05, 0.1, 0.2)


@pytest.fixture(scope="module")
def paths():
    return [SAMPLES / name for name in NAMES]


@pytest.fixture(scope="module")
def document(paths):
    from stickslip.cli import main
    import contextlib
    import io

    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        assert main(["displacements", *map(str, paths), "--ky", ",".join(map(str, KY)), "--json"]) == 0
    return json.loads(out.getvalue())


def test_each_value_is_the_one_way_solve_in_its_polarity(document, paths):
    rows = document["records"]
    assert len(rows) == len(NAMES) * len(KY)
    for index, path in enumerate(paths):
        record = read_record(path)
        for column, ky in enumerate(KY):
            row = rows[index * len(KY) + column]
            assert row["ky"] == ky and row["source"] == str(path)
            normal = solve(record, ky=ky).scalars()["downslope_displacement"] * 100.0
            inverse = solve(record, ky=ky, inverse=True).scalars()["downslope_displacement"] * 100.0
            assert row["newmark_displacement_normal"] == pytest.approx(normal, rel=1e-12, abs=1e-12)
            assert row["newmark_displacement_inverse"] == pytest.approx(inverse, rel=1e-12, abs=1e-12)
            assert row["newmark_displacement_mean"] == pytest.approx((normal + inverse) / 2, rel=1e-12, abs=1e-12)
    assert document["units"]["newmark_displacement_mean"] == "cm" and document["units"]["ky"] == "1"


def test_statistics_over_the_records(document):
    rows = document["records"]
    for statistic in document["statistics"]:
        values = np.array([row["newmark_displacement_mean"] for row in rows if row["ky"] == statistic["ky"]])
        expected = {"mean": values.mean(), "median": np.median(values), "std": values.std(ddof=1)}
        assert statistic["records"] == len(NAMES)
        assert statistic["newmark_displacement_mean"] == pytest.approx(expected[statistic["statistic"]], rel=1e-12)
    assert [row["statistic"] for row in document["statistics"]] == ["mean"] * 3 + ["median"] * 3 + ["std"] * 3


def test_jibson_estimates_follow_his_printed_equations(document):
    forms = jibson_reference()["forms"]
    ratio_form = forms["critical_acceleration_ratio"]["coefficients"]
    arias_form = forms["arias_intensity_and_ratio"]["coefficients"]
    for row in document["records"]:
        ratio = row["critical_acceleration_ratio"]
        assert ratio == pytest.approx(row["ky"] * 9.81 / row["pga"], rel=1e-14)
        log_ratio_form = (ratio_form["intercept"] + ratio_form["log_one_minus_ratio"] * math.log10(1 - ratio)
                          + ratio_form["log_ratio"] * math.log10(ratio))
        log_arias_form = (arias_form["intercept"] + arias_form["log_arias_intensity"] * math.log10(row["arias_intensity"])
                          + arias_form["log_ratio"] * math.log10(ratio))
        assert row["jibson2007_ratio"] == pytest.approx(10 ** log_ratio_form, rel=1e-12)
        assert row["jibson2007_arias"] == pytest.approx(10 ** log_arias_form, rel=1e-12)


def test_a_yield_acceleration_above_the_pga_slides_nothing_and_has_no_estimate(paths):
    record = read_record(paths[0])
    table = slope_displacements([record], [0.1, 5.0])
    row = table.rows()[1]
    assert row["newmark_displacement_normal"] == row["newmark_displacement_inverse"] == 0.0
    assert math.isnan(row["jibson2007_ratio"]) and math.isnan(row["jibson2007_arias"])
    assert math.isnan(table.statistics()["std"]["mean"][0])  # one record: no sample standard deviation


def test_table_csv_and_slammer_scheme(run_cli, paths, tmp_path):
    out = tmp_path / "tables" / "dn.csv"
    code, text, err = run_cli("displacements", paths[0], paths[1], "--ky", "0.05:0.15:0.05", "--method", "slammer",
                              "--csv", out)
    assert code == 0, err
    assert text.startswith("Newmark displacement D_n [cm]: rigid block sliding one way (downslope past k_y*g), "
                           "slammer solver, g = 9.81 m/s2")
    assert "over the 2 records:" in text and "Jibson (2007)" in text
    with open(out, newline="", encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    assert tuple(rows[0]) == ROW_COLUMNS and len(rows) == 6
    with open(tmp_path / "tables" / "dn_statistics.csv", newline="", encoding="utf-8") as handle:
        assert tuple(next(csv.DictReader(handle))) == STATISTIC_COLUMNS
    expected = solve(read_record(paths[1]), ky=0.1, method="slammer", inverse=True).scalars()["downslope_displacement"]
    assert float(rows[4]["newmark_displacement_inverse"]) == pytest.approx(expected * 100, rel=1e-12)


@pytest.mark.parametrize(("arguments", "name", "phrase"), [
    (("--ky", "0.1,abc"), "--ky 'abc'", "expected a number in units of g"),
    (("--ky", "0.2,0.1"), "--ky '0.2,0.1'", "strictly increasing"),
    (("--method", "newmark"), "--method", "invalid choice"),
])
def test_bad_options_are_one_line(run_cli, paths, arguments, name, phrase):
    assert_one_error_line(*run_cli("displacements", paths[0], *arguments), name, phrase)
