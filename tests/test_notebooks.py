"""The report notebooks run with papermill, and the reports' index page links and compares."""

from __future__ import annotations

import csv
import json
import os
import re
from pathlib import Path

import numpy as np
import pytest

from stickslip.reports.index_page import cell_category, comparison_html, render_index, status_html, write_index

REPO_ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = REPO_ROOT / "notebooks"
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
#: A drawn figure with axes, labels and a curve is tens of kB; an empty canvas is ~2 kB.
MIN_FIGURE_BYTES = 8_000
#: The record report's figures (workflow/rules/reports.smk).
RECORD_FIGURES = ("energy_vs_mu", "displacement_vs_mu", "acceleration", "response")


def _assert_png(path: Path) -> None:
    assert path.is_file(), f"{path.name} was not written"
    data = path.read_bytes()
    assert data[:8] == PNG_SIGNATURE, f"{path.name} is not a PNG"
    assert len(data) > MIN_FIGURE_BYTES, f"{path.name} is only {len(data)} bytes"


def _design_answer(executed: dict) -> dict[str, tuple[str, ...]]:
    """The record report's design-answer table: quantity (in words) -> (value, units), as the notebook printed it."""
    for cell in executed["cells"]:
        for output in cell.get("outputs", []):
            html = "".join(output.get("data", {}).get("text/html", ""))
            if "μ_max on the grid" in html:
                return {quantity: (value, units) for quantity, value, units in
                        re.findall(r"<th>([^<]+)</th>\s*<td>([^<]+)</td>\s*<td>([^<]*)</td>", html)}
    raise AssertionError("no design-answer table in the report")


def _kernel_available() -> bool:
    from jupyter_client.kernelspec import KernelSpecManager

    return "python3" in KernelSpecManager().find_kernel_specs()


@pytest.mark.slow
def test_record_report_runs_with_papermill(paper_records_dir, tmp_path, monkeypatch):
    papermill = pytest.importorskip("papermill")
    if not _kernel_available():
        pytest.fail("no Jupyter kernel 'python3': run `python -m ipykernel install --sys-prefix --name python3`")
    monkeypatch.setenv("MPLBACKEND", "Agg")
    record = paper_records_dir / "SLAMMER_Coyote_Lake_1979_G06-230.txt"
    figures = tmp_path / "figures"
    output = tmp_path / "report.ipynb"
    papermill.execute_notebook(
        str(NOTEBOOKS / "record_report.ipynb"),
        str(output),
        parameters={
            "record": str(record),
            "mu_start": 0.05,
            "mu_stop": 0.20,
            "mu_step": 0.025,
            "mu_case": 0.125,
            "range_points": 0,  # the paper's grid as it is
            "output_dir": str(tmp_path),
        },
        kernel_name="python3",
        cwd=str(REPO_ROOT),
        progress_bar=False,
    )
    executed = json.loads(output.read_text())
    code_cells = [cell for cell in executed["cells"] if cell["cell_type"] == "code"]
    assert all(cell["execution_count"] is not None for cell in code_cells)
    assert not [o for cell in code_cells for o in cell.get("outputs", []) if o.get("output_type") == "error"]
    # papermill injects the given parameters after the cell tagged "parameters"
    injected = [c for c in code_cells if "injected-parameters" in c["metadata"].get("tags", [])]
    assert injected and "mu_case = 0.125" in "".join(injected[0]["source"])
    for name in RECORD_FIGURES:
        _assert_png(figures / f"coyote_g06_230_{name}.png")
    text = json.dumps(executed, ensure_ascii=False)
    # the measures table names each measure in words, with units as people write them (dimensionless: "-")
    assert "Arias intensity" in text and "m/s2" in text and "significant duration, whole samples" in text
    assert "significant_duration_samples" not in text and "m s-2" not in text
    # the design answer: mu_max on the paper grid (0.125), the continuous one near it, the range around it,
    # and the stroke and residual displacement at the grid's mu_max as the solver gives them (stickslip.optimum)
    answer = _design_answer(executed)
    assert answer["μ_max on the grid"] == ("0.125", "-")
    mu_max = float(answer["μ_max, continuous"][0])
    assert abs(mu_max - 0.125) < 0.025
    low = float(answer["near-optimal range, E_df ≥ 0.95·E_df,max: lowest"][0])
    assert low <= 0.125 <= float(answer["near-optimal range, E_df ≥ 0.95·E_df,max: highest"][0])
    import stickslip

    at_max = stickslip.solve(stickslip.read_record(record), mu=0.125)  # the stroke: any mass
    assert float(answer["stroke (peak |x|) at the grid's μ_max"][0]) == pytest.approx(
        at_max.peak_relative_displacement, rel=1e-3)
    assert answer["residual displacement x at the end, at the grid's μ_max"][1] == "m"
    efficiency = float(answer["efficiency of μ = 0.1, E_df / E_df,max (continuous)"][0])
    assert 0 < efficiency <= 1
    # headings show the parameters' values, not their names
    assert "Response at μ = 0.125 (as asked)" in text and "`mu_case`" not in text
    # the sweep the notebook computed, on the parameters' grid, is saved next to the report, and the report says where
    saved = tmp_path / "coyote_g06_230_sweep.nc"
    assert f"saved as `{saved}`" in text
    from stickslip.sweeps import read_cube

    np.testing.assert_allclose(read_cube(saved).mu.values, [0.05, 0.075, 0.1, 0.125, 0.15, 0.175, 0.2])


def _write_csv(path: Path, rows: list[dict]) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


def _comparison_row(row: str, column: str, ours: str, paper: str, status: str) -> dict:
    return {"table": "table6", "row": row, "column": column, "ours": ours, "paper": paper,
            "relative_difference": "", "tolerance": "0.05", "status": status, "note": ""}


@pytest.fixture
def tiny_results(tmp_path) -> tuple[Path, Path]:
    """A results folder with one comparison table and a reports folder with a notebook and a figure."""
    results, reports = tmp_path / "results", tmp_path / "reports"
    _write_csv(results / "tables" / "table6_comparison.csv", [
        _comparison_row("rec_a", "mu_max", "0.125", "0.125", "ok"),
        _comparison_row("rec_a", "energy_dissipated_max", "3.1244", "3.386", "beyond tolerance"),
        _comparison_row("rec_b", "mu_max", "", "0.075", "missing: record rec_b not found"),
    ])
    (reports / "figures" / "records").mkdir(parents=True)
    (reports / "figures" / "fig21_energy_vs_mu.png").write_bytes(PNG_SIGNATURE)
    (reports / "figures" / "records" / "rec_a_response.png").write_bytes(PNG_SIGNATURE)
    (reports / "records").mkdir()
    (reports / "paper_figures.ipynb").write_text("{}")
    (reports / "records" / "rec_a.ipynb").write_text("{}")
    return results, reports


def _measures(tmp_path: Path) -> list[Path]:
    paths = [tmp_path / "rec_a.json", tmp_path / "rec_b.json"]
    paths[0].write_text(json.dumps({"record": "rec_a", "status": "ok"}))
    paths[1].write_text(json.dumps({"record": "rec_b", "status": "missing: record rec_b not found. How to obtain it: ask"}))
    return paths


def test_report_index_links_and_compares(tiny_results, tmp_path):
    results, reports = tiny_results
    (reports / "html").mkdir()
    (reports / "html" / "paper_figures.html").write_text("<html></html>")
    index = write_index(_measures(tmp_path), reports / "index.html", {"Table 6": ["rec_a", "rec_b"]},
                        results_dir=results, reports_dir=reports)
    text = index.read_text(encoding="utf-8")
    for href in ("html/paper_figures.html", "paper_figures.ipynb", "records/rec_a.ipynb",
                 "figures/fig21_energy_vs_mu.png",
                 "figures/records/rec_a_response.png", "../results/tables/table6_comparison.csv"):
        assert f'href="{href}"' in text, href
    # the paper's value is set beside ours, the flagged and missing rows are marked
    assert "<td>3.386</td>" in text and "<td>3.124</td>" in text
    assert text.count('<tr class="flagged">') == 1
    assert text.count('<tr class="missing">') == 1
    assert "3 cells: 1 within tolerance, 1 beyond tolerance, 1 not comparable, 0 paper erratum" in text
    # no leftover temporary file from the atomic write
    assert sorted(p.name for p in reports.iterdir() if p.is_file()) == ["index.html", "paper_figures.ipynb"]


def test_status_summary_names_missing_records_and_what_they_left_out():
    documents = [{"record": "rec_a", "status": "ok"},
                 {"record": "rec_b", "status": "missing: record rec_b not found. How to obtain it: ask"}]
    text = status_html(documents, {"Table 6": ["rec_a", "rec_b"], "Time step": ["rec_b"], "Mass": ["rec_a"]})
    assert "1 of 2 records found</b>: rec_a" in text and "1 missing" in text
    assert "<b>rec_b</b>: record rec_b not found. How to obtain it: ask" in text
    assert "Table 6: 1 of 2 records; without rec_b" in text
    assert "Time step: nothing computed: every record is missing" in text
    assert "Mass: all 1 record(s) included" in text


def test_record_report_of_a_missing_record_says_so(tmp_path, monkeypatch):
    papermill = pytest.importorskip("papermill")
    from stickslip.records.netcdf import write_missing_record

    monkeypatch.setenv("MPLBACKEND", "Agg")
    record = write_missing_record("mendoza_1985", "record mendoza_1985 not found. How to obtain it: ask INPRES",
                                  tmp_path / "mendoza_1985.nc")
    output = tmp_path / "report.ipynb"
    papermill.execute_notebook(str(NOTEBOOKS / "record_report.ipynb"), str(output),
                               parameters={"record": str(record), "figures_dir": str(tmp_path / "figures")},
                               kernel_name="python3", cwd=str(REPO_ROOT), progress_bar=False)
    text = output.read_text(encoding="utf-8")
    assert "mendoza_1985 is missing" in text and "How to obtain it: ask INPRES" in text
    for name in RECORD_FIGURES:
        assert (tmp_path / "figures" / f"mendoza_1985_{name}.png").read_bytes()[:8] == PNG_SIGNATURE


def test_report_index_links_are_relative_to_the_index(tiny_results, tmp_path):
    results, reports = tiny_results
    text = render_index(results, reports, tmp_path / "elsewhere" / "index.html")
    assert 'href="../reports/paper_figures.ipynb"' in text
    assert os.sep + "tmp" not in text.replace(str(tmp_path), "")


def test_comparison_html_flags_and_escapes():
    rows = [_comparison_row("a<b", "pga", "6.5", "6.49", "ok"),
            _comparison_row("c", "pga", "1", "2", "beyond tolerance")]
    html = comparison_html(rows)
    assert "a&lt;b" in html and '<td class="text">m/s2</td>' in html  # units and quantities as people write them
    assert '<td class="text">peak ground acceleration</td>' in html and ">pga<" not in html
    assert [cell_category(r["status"]) for r in rows] == ["within tolerance", "beyond tolerance"]
    assert html.count('class="flagged"') == 1
