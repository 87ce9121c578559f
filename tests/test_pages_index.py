"""The index of a folder of report pages links every page and sets their design answers side by side."""

from __future__ import annotations

import html
import re

from stickslip.reports.pages_index import INDEX_NAME, IndexedPage, write_answer, write_index


def _page(folder, name: str, title: str):
    page = folder / f"{name}.html"
    page.write_text(f"<html><head><title>{html.escape(title)}</title></head><body></body></html>", encoding="utf-8")
    return page


def test_the_index_links_every_page_and_sets_the_answers_side_by_side(tmp_path):
    folder = tmp_path / "pages"
    folder.mkdir()
    answers = tmp_path / "answers"
    answers.mkdir()
    pages = []
    for name, title, rows, note in (
            ("RSN181", "Record report: RSN181 (Imperial Valley-06)",
             [("μ_max on the grid", "0.0775", "-"), ("E_df,max on the grid", "0.9236", "J/kg")], None),
            ("kobe", "Record report: kobe <KJMA>",
             [("μ_max on the grid", "0.125", "-"), ("stroke at μ_max", "0.2929", "m")], None),
            ("QUIET", "Record report: QUIET", [], "the block never slides at any μ of the grid")):
        write_answer(answers / f"{name}.json", rows, note)
        pages.append(IndexedPage(_page(folder, name, title), name, answers / f"{name}.json"))
    index = write_index(pages, folder, "stickslip report: 3 records")
    assert index == folder / INDEX_NAME
    text = index.read_text(encoding="utf-8")
    for name in ("RSN181", "kobe", "QUIET"):
        assert text.count(f'href="{name}.html"') == 2  # in the list and heading its column
    assert "Record report: kobe &lt;KJMA&gt;" in text and "<KJMA>" not in text
    rows = {cells[0]: cells[1:] for cells in (re.findall(r"<td>(.*?)</td>", row)
                                              for row in re.findall(r"<tr>(.*?)</tr>", text)) if cells}
    assert rows == {"μ_max on the grid": ["0.0775", "0.125", "-"],
                    "E_df,max on the grid [J/kg]": ["0.9236", "-", "-"],
                    "stroke at μ_max [m]": ["-", "0.2929", "-"]}
    assert "<li><b>QUIET</b>: the block never slides at any μ of the grid</li>" in text


def test_no_answer_file_is_written_without_a_path(tmp_path):
    write_answer(None, [("μ_max on the grid", "0.1", "-")])
    assert list(tmp_path.iterdir()) == []
