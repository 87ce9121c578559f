"""The reports' index page (``reports/index.html``) and the paper-comparison tables as HTML.

The index links the executed notebooks and the PNG figures under ``reports/`` and
sets each paper value beside ours, from the ``*_comparison.csv`` tables the
workflow wrote (columns ``table, row, column, ours, paper, relative_difference,
tolerance, status, note``).  It opens with a status summary: which records
were found and which are missing (with how to obtain them), and what each
study could not include because of them.  Nothing is computed here: every
number is read from a file.  ``workflow/rules/reports.smk`` calls
:func:`write_index`.
"""

from __future__ import annotations

import html
import json
import math
import os
from collections.abc import Mapping, Sequence
from pathlib import Path

from stickslip.io import read_csv_rows, write_text_atomic
from stickslip.units import UNITS

#: Status of a comparison cell within tolerance.
OK_STATUS = "ok"

#: Units of the compared quantities (the comparison tables are SI), UDUNITS spelling.
COLUMN_UNITS = {name: UNITS[name] for name in (
    "pga", "rms_acceleration", "energy_dissipated", "energy_dissipated_max", "mu_max", "mu_low", "mu_high",
    "arias_intensity", "significant_duration", "significant_duration_samples", "duration", "dt",
)}

_STYLE = """
body { font-family: sans-serif; margin: 2em; max-width: 70em; }
table { border-collapse: collapse; margin: 0.5em 0 1.5em 0; font-size: 0.9em; }
th, td { border: 1px solid #bbb; padding: 0.2em 0.5em; text-align: right; }
th { background: #eee; }
td.text { text-align: left; }
tr.flagged td { background: #fde2e2; }
tr.missing td { background: #eeeeee; color: #666; }
.status { border: 1px solid #bbb; background: #f7f7f7; padding: 0.5em 1em; }
.status li { margin: 0.2em 0; overflow-wrap: anywhere; }
img { max-width: 32em; border: 1px solid #ccc; margin: 0.3em; }
"""


def is_flagged(row: dict[str, str]) -> bool:
    """Whether a comparison cell is beyond tolerance or missing (status other than ``ok``)."""
    return row.get("status", OK_STATUS) != OK_STATUS


#: Units of a solved case's scalars (:meth:`stickslip.response.Response.scalars`) not in the sweep cube.
def measures_rows(measures: dict[str, float], digits: int = 6) -> list[tuple[str, str, str]]:
    """(name, value to ``digits`` significant digits, units) for each intensity measure (SI units)."""
    from stickslip.measures import MEASURE_UNITS

    return [(name, f"{value:.{digits}g}", MEASURE_UNITS.get(name, "")) for name, value in measures.items()]


def scalars_rows(scalars: dict[str, float], digits: int = 6) -> list[tuple[str, str, str]]:
    """(name, value to ``digits`` significant digits, units) for each scalar of a solved case (SI units)."""
    from stickslip.response import SCALAR_ATTRS

    return [(name, f"{value:.{digits}g}", SCALAR_ATTRS.get(name, ("",))[0]) for name, value in scalars.items()]


def _number(text: str, digits: int = 4) -> str:
    """A number string formatted to ``digits`` significant digits; empty or non-numeric text unchanged."""
    try:
        value = float(text)
    except (TypeError, ValueError):
        return html.escape(str(text or ""))
    if math.isnan(value):
        return ""
    return f"{value:.{digits}g}"


def comparison_html(rows: Sequence[dict[str, str]], max_note: int = 160) -> str:
    """An HTML table of comparison rows: ours beside the paper's, flagged rows shaded red (missing grey)."""
    header = ("row", "quantity", "units", "ours", "paper", "rel. diff.", "tolerance", "status", "note")
    lines = ["<table>", "<tr>" + "".join(f"<th>{h}</th>" for h in header) + "</tr>"]
    for row in rows:
        status = row.get("status", "")
        css = "missing" if status.startswith("missing") else "flagged" if is_flagged(row) else ""
        rel = row.get("relative_difference", "")
        rel_text = _number(rel, 3)
        if rel_text and rel_text != html.escape(rel):
            rel_text = f"{float(rel) * 100:+.2f} %"
        note = row.get("note", "") or ""
        if len(note) > max_note:
            note = note[: max_note - 1] + "…"
        status_text = "missing" if status.startswith("missing") else status
        cells = [
            ("text", html.escape(row.get("row", ""))),
            ("text", html.escape(row.get("column", ""))),
            ("text", COLUMN_UNITS.get(row.get("column", ""), "")),
            ("", _number(row.get("ours", ""))),
            ("", _number(row.get("paper", ""))),
            ("", rel_text),
            ("", _number(row.get("tolerance", ""), 3)),
            ("text", html.escape(status_text)),
            ("text", html.escape(note)),
        ]
        tds = "".join(f'<td class="{c}">{v}</td>' if c else f"<td>{v}</td>" for c, v in cells)
        lines.append(f'<tr class="{css}">{tds}</tr>' if css else f"<tr>{tds}</tr>")
    lines.append("</table>")
    return "\n".join(lines)


def _relative(path: Path, start: Path) -> str:
    """``path`` relative to the folder ``start``, with forward slashes (for an href)."""
    return Path(os.path.relpath(path, start)).as_posix()


def status_html(documents: Sequence[Mapping], studies: Mapping[str, Sequence[str]]) -> str:
    """The status summary: records found and missing, and what each study left out.

    ``documents`` are the records' measures documents (``results/measures/{id}.json``);
    ``studies`` maps a study's name to the ids of the records it uses.
    """
    status = {document["record"]: document["status"] for document in documents}
    found = [record for record, text in status.items() if text == "ok"]
    missing = {record: text for record, text in status.items() if text != "ok"}
    parts = ['<div class="status"><h2>Status</h2>',
             f"<p><b>{len(found)} of {len(status)} records found</b>: {html.escape(', '.join(found)) or 'none'}.</p>"]
    if missing:
        parts.append(f"<p><b>{len(missing)} missing</b> (each named as missing in every table that needs it):</p><ul>")
        parts += [f"<li><b>{html.escape(record)}</b>: {html.escape(text.removeprefix('missing: '))}</li>"
                  for record, text in missing.items()]
        parts.append("</ul>")
    parts.append("<p>What that left out:</p><ul>")
    for study, records in studies.items():
        absent = [record for record in records if status.get(record, "missing") != "ok"]
        if not absent:
            outcome = f"all {len(records)} record(s) included"
        elif len(absent) == len(records):
            outcome = "nothing computed: every record is missing"
        else:
            outcome = f"{len(records) - len(absent)} of {len(records)} records; without {', '.join(absent)}"
        parts.append(f"<li>{html.escape(study)}: {html.escape(outcome)}</li>")
    parts.append("</ul></div>")
    return "\n".join(parts)


def render_index(results_dir: str | Path, reports_dir: str | Path, index_path: str | Path | None = None,
                 status: str = "") -> str:
    """The HTML text of the index page for ``reports_dir`` (links relative to ``index_path``'s folder).

    Opens with ``status`` (:func:`status_html`), then lists every executed
    notebook (rendered as HTML under ``reports_dir/html``, with the notebook
    beside it), every PNG under ``reports_dir`` (grouped by folder), and every
    ``results_dir/tables/*_comparison.csv`` as a table of our values beside the paper's.
    """
    results_dir, reports_dir = Path(results_dir), Path(reports_dir)
    base = Path(index_path).parent if index_path is not None else reports_dir
    notebooks = sorted(path for path in reports_dir.rglob("*.ipynb") if not path.name.startswith("."))
    figures = sorted(reports_dir.rglob("*.png"))
    comparisons = sorted((results_dir / "tables").glob("*_comparison.csv"))

    parts = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8"><title>stickslip reports</title>',
        f"<style>{_STYLE}</style></head><body>",
        "<h1>stickslip: reproduction of the paper</h1>",
        status,
        "<p>Every number below was read from a file the workflow wrote; the paper's values come from "
        "the reference table <code>stickslip/reference/paper.yaml</code>. Rows beyond tolerance are "
        "shaded red, missing records grey. Units are SI.</p>",
        "<h2>Notebooks</h2>",
        "<ul>",
    ]
    for notebook in notebooks:
        name = notebook.relative_to(reports_dir).with_suffix("")
        page = reports_dir / "html" / name.with_suffix(".html")
        link = (f'<a href="{_relative(page, base)}">{html.escape(name.as_posix())}</a>' if page.is_file()
                else html.escape(name.as_posix()))
        parts.append(f'<li>{link} (<a href="{_relative(notebook, base)}">notebook</a>)</li>')
    if not notebooks:
        parts.append("<li>none</li>")
    parts.append("</ul>")
    parts.append("<h2>Figures</h2>")
    groups: dict[Path, list[Path]] = {}
    for figure in figures:
        groups.setdefault(figure.parent, []).append(figure)
    for folder, items in groups.items():
        parts.append(f"<h3>{html.escape(folder.relative_to(reports_dir).as_posix())}</h3><div>")
        for item in items:
            href = _relative(item, base)
            parts.append(f'<a href="{href}"><img src="{href}" alt="{html.escape(item.stem)}" '
                         f'title="{html.escape(item.name)}"></a>')
        parts.append("</div>")
    if not figures:
        parts.append("<p>none</p>")

    parts.append("<h2>Our values beside the paper's</h2>")
    for path in comparisons:
        rows = read_csv_rows(path)
        flagged = sum(is_flagged(r) for r in rows)
        name = path.name.removesuffix("_comparison.csv")
        parts.append(f'<h3>{html.escape(name)} (<a href="{_relative(path, base)}">{html.escape(path.name)}</a>): '
                     f"{len(rows) - flagged} of {len(rows)} cells within tolerance</h3>")
        parts.append(comparison_html(rows))
    if not comparisons:
        parts.append("<p>no comparison tables found</p>")
    parts.append("</body></html>")
    return "\n".join(parts) + "\n"


def write_index(measures_paths: Sequence[str | Path], index_path: str | Path, studies: Mapping[str, Sequence[str]],
                results_dir: str | Path = "results", reports_dir: str | Path = "reports") -> Path:
    """Write the index page (see :func:`render_index`) to ``index_path`` atomically; return the path.

    ``measures_paths`` are the records' measures files, for the status summary
    (:func:`status_html`, with ``studies``).
    """
    index_path = Path(index_path)
    documents = [json.loads(Path(path).read_text(encoding="utf-8")) for path in measures_paths]
    page = render_index(results_dir, reports_dir, index_path, status_html(documents, studies))
    write_text_atomic(index_path, page)
    return index_path
