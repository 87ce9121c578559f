"""The report notebooks' one copy of ``show`` and ``table`` (stickslip.reports.notebook_helpers)."""

from __future__ import annotations

import pytest
from conftest import REPO_ROOT

from stickslip.reports.notebook_helpers import FigureFolder, html_table
from stickslip.reports.plots import new_figure


def test_a_table_writes_numbers_to_its_digits_booleans_as_words_and_escapes_text():
    rows = [{"id": "a<b", "value": "0.123456", "count": "12.0", "passes": True},
            {"id": "c", "value": "", "count": "3", "passes": "False"}]
    page = html_table(rows, ["id", ("value", "value [m]"), "count", "passes"])
    assert "<th>value [m]</th>" in page and '<td style="text-align:left">a&lt;b</td>' in page
    assert "<td>0.123</td>" in page and "<td>12</td>" in page and "<td>yes</td>" in page and "<b>no</b>" in page
    assert "<td>0.123456</td>" not in page
    as_text = html_table(rows, ["value"], digits=None)
    assert '<td style="text-align:left">0.123456</td>' in as_text
    folded = html_table(rows * 30, ["id"], fold_beyond=40, what="records")
    assert folded.startswith("<details><summary>60 records (click to show)</summary>")


def test_a_figure_folder_names_its_pngs_and_gives_each_its_alternative_text(tmp_path, monkeypatch):
    shown = []
    monkeypatch.setattr("stickslip.reports.notebook_helpers.display", shown.append)
    folder = FigureFolder(tmp_path / "figures", prefix="rec_", alts={"rec_energy.png": "E_df against mu"})
    figure, ax = new_figure()
    ax.plot([0, 1], [0, 1])
    assert folder.show(figure, "energy") is None  # a cell ending with it shows no path
    folder.show(figure, "other.png")
    assert shown[0].metadata == {"alt": "E_df against mu"} and not shown[1].metadata
    for name in ("rec_energy.png", "rec_other.png"):
        assert (tmp_path / "figures" / name).read_bytes()[:4] == b"\x89PNG"


@pytest.mark.parametrize("notebook", ["collection_study", "planar_study", "jibson2007", "slammer_verification", "paper_figures",
                                      "model_figures", "record_report"])
def test_no_notebook_defines_its_own_show_or_table(notebook):
    text = (REPO_ROOT / "notebooks" / f"{notebook}.ipynb").read_text(encoding="utf-8")
    assert "def show(" not in text and "def table(" not in text


def test_a_figure_not_drawn_says_why_in_lines_that_fit_its_width():
    from stickslip.reports.plots import plot_not_drawn

    address = "https://example.org/" + "a" * 150  # a long address, no space to wrap at
    figure = plot_not_drawn("Energy", f"missing: record x not found; download {address} failed")
    (text,) = [t for t in figure.axes[0].texts if t.get_text().startswith("Not drawn: missing")]
    lines = text.get_text().split("\n")
    assert len(lines) >= 3 and max(map(len, lines)) <= 95
    assert "".join(lines).replace(" ", "") == f"Notdrawn:missing:recordxnotfound;download{address}failed"
