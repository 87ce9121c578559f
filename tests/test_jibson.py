"""Jibson (2007), recomputed: the fit recovers known coefficients, the selection counts, D_n is the one-way solve's.

The end-to-end run of the target on pyslammer's 18 motions is in
``test_workflow.py`` (the ``.test/`` workflow, run once for the suite).
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from stickslip import solve
from stickslip.collections import load_collection
from stickslip.measures import intensity_measures
from stickslip.records.process import peak_ground_acceleration
from stickslip.studies.jibson2007.index import jibson_section_html
from stickslip.studies.jibson2007.displacements import POLARITIES, displacement_rows
from stickslip.studies.jibson2007.fit import (EXCLUSIONS, FORMS, fit_form, jibson_fit, jibson_reference, predict,
                                              select)

GRID_G = [0.02, 0.05, 0.1, 0.2, 0.3, 0.4]
G = 9.81


def _synthetic_rows(form: str, truth: dict[str, float], sigma: float, n_records: int = 80, seed: int = 1) -> list[dict]:
    """Rows of ``n_records`` records, six a_c each, log10 D_n = form(truth) + N(0, sigma²)."""
    rng = np.random.default_rng(seed)
    rows = []
    for index in range(n_records):
        pga_g = rng.uniform(0.45, 1.2)
        arias = 10 ** rng.uniform(-1.0, 1.0)  # m/s
        ratio = np.array(GRID_G) / pga_g
        log_d = predict(form, truth, ratio, np.full(ratio.size, arias)) + rng.normal(0.0, sigma, ratio.size)
        for r, value in zip(ratio, log_d):
            rows.append({"record": f"r{index:03d}", "event": f"e{index % 7}", "status": "ok", "polarity": "normal",
                         "critical_acceleration_ratio": r, "arias_intensity": arias, "newmark_displacement": 10 ** value})
    return rows


@pytest.mark.parametrize("form, truth", [
    ("critical_acceleration_ratio", {"intercept": 0.3, "log_one_minus_ratio": 2.0, "log_ratio": -1.2}),
    ("arias_intensity_and_ratio", {"intercept": -1.2, "log_arias_intensity": 0.6, "log_ratio": -3.0}),
])
def test_the_fit_recovers_known_coefficients_within_its_bootstrap_interval(form, truth):
    sigma = 0.3
    fit = fit_form(form, _synthetic_rows(form, truth, sigma), n_boot=400, seed=0)
    assert fit["status"] == "ok" and fit["rows"] == 480 and fit["records"] == 80 and fit["bootstrap_resamples"] == 400
    for term in FORMS[form]:
        value = fit["coefficients"][term]
        assert value["low"] <= truth[term] <= value["high"], (term, value)
        assert value["low"] < value["value"] < value["high"]
    assert fit["sigma"]["low"] <= sigma <= fit["sigma"]["high"]
    assert abs(fit["sigma"]["value"] - sigma) < 0.03


def test_the_bootstrap_resamples_records_not_rows():
    """Rows repeated within records: a row bootstrap would be far too narrow, the record bootstrap is not."""
    form, truth = "critical_acceleration_ratio", {"intercept": 0.3, "log_one_minus_ratio": 2.0, "log_ratio": -1.2}
    rows = _synthetic_rows(form, truth, 0.3, n_records=40)
    copies = [{**row, "polarity": polarity} for row in rows for polarity in POLARITIES]  # two identical rows each
    single, doubled = fit_form(form, rows, n_boot=300, seed=0), fit_form(form, copies, n_boot=300, seed=0)
    for term in FORMS[form]:
        assert doubled["coefficients"][term]["value"] == pytest.approx(single["coefficients"][term]["value"])
        width = (single["coefficients"][term]["high"] - single["coefficients"][term]["low"])
        doubled_width = (doubled["coefficients"][term]["high"] - doubled["coefficients"][term]["low"])
        assert doubled_width == pytest.approx(width, rel=0.25)


def _row(record, ratio, displacement, status="ok"):
    return {"record": record, "event": "e", "status": status, "polarity": "normal", "ky": 0.1,
            "critical_acceleration_ratio": str(ratio), "arias_intensity": "1.0", "newmark_displacement": str(displacement)}


def test_rows_with_ac_at_or_above_pga_or_no_sliding_are_counted_and_left_out():
    rows = [_row("a", 0.5, 12.0), _row("a", 1.0, 0.0), _row("a", 1.6, 0.0), _row("b", 0.9, 0.0),
            _row("b", 0.2, 0.4), _row("b", 0.1, 3.0), {"record": "c", "event": "", "status": "not solved: missing: x"}]
    kept, excluded = select(rows, floor_cm=1.0)
    assert [row["newmark_displacement"] for row in kept] == ["12.0", "3.0"]
    assert excluded == {"not solved": 1, "a_c >= PGA": 2, "does not slide (D_n = 0)": 1,
                        "below the displacement floor": 1}
    kept, excluded = select(rows, floor_cm=None)
    assert len(kept) == 3 and excluded["below the displacement floor"] == 0 and excluded["a_c >= PGA"] == 2
    assert sum(excluded.values()) + len(kept) == len(rows) and set(excluded) == set(EXCLUSIONS)


def test_too_few_rows_say_so_and_the_document_counts_the_collection():
    rows = [_row("a", 0.5, 12.0), _row("a", 0.3, 20.0), _row("a", 1.2, 0.0)]
    document = jibson_fit(rows, GRID_G, 1.0, n_boot=50, seed=0, g=G)
    assert document["collection"] == {"records": 1, "records_solved": 1, "events": 1, "rows": 3}
    for form in FORMS:
        fit = document["selections"]["with_floor"]["forms"][form]
        assert fit["status"].startswith("too few data: 2 rows of 1 records")
    assert document["reference"]["forms"]["critical_acceleration_ratio"]["sigma"] == jibson_reference()["forms"][
        "critical_acceleration_ratio"]["sigma"]


@pytest.fixture(scope="module")
def sample_record():
    """A pyslammer sample motion whose PGA lies inside the a_c grid: some a_c below it, some above."""
    samples = load_collection("pyslammer")
    for record_id in samples.ids:
        record = samples.read(record_id)
        if GRID_G[1] * G < peak_ground_acceleration(record) < GRID_G[-1] * G:
            return record
    raise AssertionError("no pyslammer sample has a PGA between 0.05 and 0.4 g")


def test_the_tables_displacement_is_the_one_way_solve_in_both_polarities(sample_record):
    """D_n [cm] of the table equals stickslip's one-way solve (stickslip solve --ky, --inverse) at each a_c."""
    measures = intensity_measures(sample_record, g=G).as_dict()
    rows = displacement_rows([sample_record], [measures], GRID_G, G)
    assert len(rows) == len(POLARITIES) * len(GRID_G)
    pga_g = measures["pga"] / G
    for row in rows:
        expected = 100.0 * solve(sample_record, ky=row["ky"], g=G, inverse=row["polarity"] == "inverse").downslope_displacement
        np.testing.assert_allclose(row["newmark_displacement"], expected, rtol=1e-9, atol=1e-12)
        assert row["critical_acceleration_ratio"] == pytest.approx(row["ky"] / pga_g)
        assert row["newmark_displacement"] >= 0.0
        if row["ky"] >= pga_g:  # a_c >= PGA: the block cannot slide
            assert row["newmark_displacement"] == 0.0
    assert any(row["newmark_displacement"] > 0 for row in rows)
    assert any(row["critical_acceleration_ratio"] >= 1.0 for row in rows)


def test_the_index_section_sets_ours_beside_jibsons(tmp_path):
    form, truth = "critical_acceleration_ratio", {"intercept": 0.3, "log_one_minus_ratio": 2.0, "log_ratio": -1.2}
    document = jibson_fit(_synthetic_rows(form, truth, 0.3, n_records=20), GRID_G, 1.0, n_boot=50, seed=0, g=G)
    path = tmp_path / "results" / "jibson2007_fit.json"
    path.parent.mkdir()
    path.write_text(json.dumps(document), encoding="utf-8")
    section = jibson_section_html(path, tmp_path / "reports" / "html" / "jibson2007.html", tmp_path / "reports")
    assert '<h1 id="jibson2007">' in section and "(Jibson 2.341)" in section and "(Jibson 0.510)" in section
    assert 'href="html/jibson2007.html"' in section and 'href="../results/jibson2007_displacements.csv"' in section
    assert "records (7 events; Jibson: 2270 records of 30 earthquakes)" in section
