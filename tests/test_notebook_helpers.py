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
    as_text = html_table(rows, ["value", "id"], digits=None)  # numbers as written, aligned as numbers
    assert "<td>0.123456</td>" in as_text and '<td style="text-align:left">c</td>' in as_text
    for missing in ("-", "nan", float("nan")):  # no value, in a column of numbers
        assert html_table([{"value": missing}], ["value"]) == "<table><tr><th>value</th></tr><tr><td>-</td></tr></table>"
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
                                      "vertical_study", "isolation_study", "damper_study",
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


def test_a_figure_not_drawn_is_saved_and_shown_as_one_sentence_not_an_empty_box(tmp_path, monkeypatch):
    from stickslip.reports.plots import NotDrawn, plot_not_drawn

    shown = []
    monkeypatch.setattr("stickslip.reports.notebook_helpers.display", shown.append)
    figure = plot_not_drawn("Intensity measures", "this collection publishes no intensity measures\nto check ours")
    assert isinstance(figure, NotDrawn)
    FigureFolder(tmp_path).show(figure, "measures_check")
    assert (tmp_path / "measures_check.png").read_bytes()[:4] == b"\x89PNG"  # the workflow declares the file
    (sentence,) = shown
    assert sentence.data == "<p>Not drawn: this collection publishes no intensity measures; to check ours.</p>"


def test_a_number_on_a_page_is_never_minus_zero_and_a_count_is_whole():
    import numpy as np

    from stickslip.reports.design_answer import format_number
    from stickslip.reports.index_page import scalars_rows

    assert [format_number(value) for value in (-0.0, 0.0, -1.5e-7, 1234567, np.int64(27), 27.0, float("nan"))] == [
        "0", "0", "-1.5e-07", "1234567", "27", "27", "-"]
    rows = scalars_rows({"residual_displacement": -0.0, "n_slip_episodes": 12345678})
    assert [(value, units) for _, value, units in rows] == [("0", "m"), ("12345678", "-")]
