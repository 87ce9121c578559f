"""The index page's headline counts add up, and it accounts for every table and figure of the paper."""

from __future__ import annotations

import csv
import re
from pathlib import Path

from stickslip.reports.paper_items import PAPER_ITEMS, REGENERATED, SUBSTITUTED, TEST_DATA
from stickslip.reports.index_page import CATEGORIES, cell_category, render_index

STATUSES = ["ok", "beyond tolerance", "missing: record x not found", "paper erratum: E1 (results/tables/errata.csv)",
            "ok", "no paper value"]


def _write(path: Path, rows: list[dict]) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


def _cells(statuses):
    return [{"table": "t", "row": f"r{k}", "column": "pga", "ours": "1", "paper": "1", "relative_difference": "0",
             "tolerance": "0.05", "status": status, "note": ""} for k, status in enumerate(statuses)]


def test_each_status_falls_in_one_category():
    assert [cell_category(s) for s in STATUSES] == ["within tolerance", "beyond tolerance", "not comparable",
                                                    "paper erratum", "within tolerance", "not comparable"]


def test_headline_counts_add_up_and_errata_and_missing_records_are_not_failures(tmp_path):
    results, reports = tmp_path / "results", tmp_path / "reports"
    _write(results / "tables" / "table6_comparison.csv", _cells(STATUSES))
    _write(results / "tables" / "table8_comparison.csv", _cells(["missing: record mendoza_1985 not found"] * 4))
    (reports / "figures").mkdir(parents=True)
    (reports / "figures" / "fig2_harmonic_regimes.png").write_bytes(b"\x89PNG\r\n\x1a\n")
    text = render_index(results, reports, reports / "index.html")
    total = re.search(r"<th class=\"text\">all tables</th>((?:<th>\d+</th>)+)", text).group(1)
    counts = [int(n) for n in re.findall(r"<th>(\d+)</th>", total)]
    assert counts == [2, 1, 6, 1, 10]  # within, beyond, not comparable, paper erratum, cells
    assert sum(counts[:-1]) == counts[-1]
    assert "table8_comparison.csv</a>), 4 cells: 0 within tolerance, 0 beyond tolerance, 4 not comparable" in text
    # the paper's account: a produced figure is linked, a missing one is said to be missing
    assert 'href="figures/fig2_harmonic_regimes.png"' in text
    # (Fig. 2 and Tables 6 and 8 have a file here, every other item with outputs has none)
    assert text.count("not produced in this run") == sum(1 for item in PAPER_ITEMS if item["outputs"]) - 3
    assert text.count(TEST_DATA) >= 4


def test_every_table_and_figure_of_the_paper_is_accounted_for():
    covered = " ".join(item["item"] for item in PAPER_ITEMS)
    numbers = {int(n) for n in re.findall(r"\d+", covered)}
    ranges = {int(a) + k for a, b in re.findall(r"(\d+)-(\d+)", covered) for k in range(int(b) - int(a) + 1)}
    assert set(range(1, 26)) <= numbers | ranges  # Figs. 1 to 25 (and Tables 1 to 8)
    assert {f"Table {k}" for k in range(1, 9)} <= {item["item"].split(",")[0] for item in PAPER_ITEMS}
    for item in PAPER_ITEMS:
        assert item["reason"]
        assert bool(item["outputs"]) == (item["outcome"] in (REGENERATED, SUBSTITUTED)), item["item"]
    assert set(CATEGORIES) == {"within tolerance", "beyond tolerance", "not comparable", "paper erratum"}
