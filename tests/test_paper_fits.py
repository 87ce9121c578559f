"""The paper's μ_max lines recomputed from its Table 6, beside ours (stickslip.studies.paper_fits)."""

from __future__ import annotations

import numpy as np
import pytest

from stickslip.reference import paper_tables
from stickslip.studies.paper_fits import fit_rows

PRINTED = paper_tables()["table6_results"]["rows"]
HAVE = ["cape_mendocino", "chichi_chy080n", "coyote_g06_230", "coyote_g06_320", "kobe_kjm090", "northridge_nwh090"]


def _results(values):
    """table6_results.csv rows: the records we have (ok) and the two we miss."""
    rows = [{"record": record, "status": "ok", **{k: str(v) for k, v in values[record].items()}} for record in HAVE]
    return rows + [{"record": "mendoza_1985", "status": "missing: x"}, {"record": "parkfield_c02_360", "status": "missing: y"}]


def test_the_paper_line_on_all_eight_records_is_the_least_squares_line_of_its_table6():
    rows = {(r["source"], r["x"]): r for r in fit_rows(_results(PRINTED), n_boot=200, seed=0)}
    line = rows["paper (all its records)", "pga"]
    x = [row["pga"] for row in PRINTED.values()]
    y = [row["mu_max"] for row in PRINTED.values()]
    slope, intercept = np.polyfit(x, y, 1)
    assert line["n"] == 8 and line["slope"] == pytest.approx(slope) and line["intercept"] == pytest.approx(intercept)
    assert line["r"] == pytest.approx(np.corrcoef(x, y)[0, 1])
    assert line["r_low"] < line["r"] < line["r_high"]
    assert line["slope_low_t"] < line["slope"] < line["slope_high_t"]
    assert line["slope_low_bootstrap"] <= line["slope"] <= line["slope_high_bootstrap"]
    assert "erratum E1" in rows["paper (all its records)", "rms_acceleration"]["note"]


def test_ours_on_the_paper_values_equals_the_paper_line_on_the_same_six():
    rows = {(r["source"], r["x"]): r for r in fit_rows(_results(PRINTED), n_boot=200, seed=0)}
    for x in ("pga", "rms_acceleration"):
        paper, ours = rows["paper (the records we have)", x], rows["ours (the records we have)", x]
        assert paper["n"] == ours["n"] == 6 and paper["records"] == ours["records"]
        for key in ("slope", "intercept", "r", "r_low", "r_high", "slope_low_t", "slope_high_t"):
            assert ours[key] == pytest.approx(paper[key])


def test_too_few_records_give_no_line_of_ours():
    rows = _results(PRINTED)
    for row in rows[2:6]:
        row["status"] = "missing: z"
    sources = {r["source"] for r in fit_rows(rows, n_boot=100, seed=0)}
    assert sources == {"paper (all its records)"}
