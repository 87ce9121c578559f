"""The index of a folder of report pages: each page linked, their design answers side by side.

``stickslip report A B ... --out pages/`` renders one page per record (or
pair) and then writes ``pages/index.html``.  Each page's notebook writes
its design answer, as its own table shows it, to the file its
``answer_path`` parameter names (:func:`write_answer`); :func:`index_html`
sets the answers side by side, one column per page, one row per quantity
(the rows of every page, in the order the first page that has each gives
them; a page without one shows ``-``).  Nothing is computed here.  The page
is self-contained and links the pages by relative paths, so the folder can
be moved or served as is.
"""

from __future__ import annotations

import html
import json
import re
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from stickslip.plumbing.files import write_text_atomic
from stickslip.reports.links import relative_href

#: The index page's name in the folder of pages.
INDEX_NAME = "index.html"

_STYLE = """
body { font-family: sans-serif; margin: 2em; max-width: 100%; }
table { border-collapse: collapse; font-size: 0.9em; }
th, td { border: 1px solid #ccc; padding: 0.25em 0.6em; text-align: right; }
th:first-child, td:first-child { text-align: left; }
th { background: #f3f3f3; }
"""


def write_answer(path: str | Path | None, rows: Sequence[tuple[str, str, str]], note: str | None = None) -> None:
    """Write a page's design answer to ``path`` (JSON; nothing when ``path`` is None): ``rows`` of (quantity, value
    as the page writes it, units), and a ``note`` for a page without an answer (why: the block never slides, the
    record is missing)."""
    if path is not None:
        write_text_atomic(path, json.dumps({"rows": [list(row) for row in rows], "note": note}) + "\n")


@dataclass(frozen=True)
class IndexedPage:
    """One page of the index: its file, the name its column shows, and its answer file (:func:`write_answer`)."""

    page: Path
    name: str
    answer: Path


def index_html(pages: Sequence[IndexedPage], folder: str | Path, title: str) -> str:
    """The index of ``pages`` (in ``folder``, where the index goes) under the heading ``title``, as one HTML page."""
    answers = [json.loads(Path(page.answer).read_text(encoding="utf-8")) for page in pages]
    quantities: dict[str, str] = {}
    for answer in answers:
        for quantity, _, units in answer["rows"]:
            quantities.setdefault(quantity, units)
    values = [{quantity: value for quantity, value, _ in answer["rows"]} for answer in answers]
    head = "".join(f'<th><a href="{html.escape(relative_href(page.page, folder))}">{html.escape(page.name)}</a></th>'
                   for page in pages)
    body = "".join(
        f"<tr><td>{html.escape(quantity)}{'' if units in ('', '-') else f' [{html.escape(units)}]'}</td>"
        + "".join(f"<td>{html.escape(found.get(quantity, '-'))}</td>" for found in values) + "</tr>"
        for quantity, units in quantities.items())
    notes = "".join(f"<li><b>{html.escape(page.name)}</b>: {html.escape(answer['note'])}</li>"
                    for page, answer in zip(pages, answers) if answer.get("note"))
    links = "".join(f'<li><a href="{html.escape(relative_href(page.page, folder))}">{html.escape(page.name)}</a>'
                    f"{_described(page.page)}</li>" for page in pages)
    return (f"<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>{html.escape(title)}</title>"
            f"<style>{_STYLE}</style></head><body>\n<h1>{html.escape(title)}</h1>\n"
            f"<p>{len(pages)} pages, each linked; their design answers side by side, as each page's own table gives "
            "them (a quantity a page does not give: -).</p>\n"
            f"<ul>{links}</ul>\n"
            + (f"<table><tr><th>quantity</th>{head}</tr>{body}</table>\n" if quantities else "")
            + (f"<p>Without a design answer:</p><ul>{notes}</ul>\n" if notes else "")
            + "</body></html>\n")


def _described(page: Path) -> str:
    """``: <the page's title>``, escaped, from its ``<title>`` (empty when it has none)."""
    found = re.search(r"<title>(.*?)</title>", Path(page).read_text(encoding="utf-8"), re.S)
    return f": {found.group(1).strip()}" if found else ""  # the page's title is escaped HTML already


def write_index(pages: Sequence[IndexedPage], folder: str | Path, title: str) -> Path:
    """Write :func:`index_html` as ``folder/index.html`` (atomically); return its path."""
    path = Path(folder) / INDEX_NAME
    write_text_atomic(path, index_html(pages, folder, title))
    return path
