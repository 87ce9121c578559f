"""The reports' index page (``reports/index.html``) and the paper-comparison tables as HTML.

The index links the executed notebooks and the PNG figures under ``reports/`` and
sets each paper value beside ours, from the ``*_comparison.csv`` tables the
workflow wrote (columns ``table, row, column, ours, paper, relative_difference,
tolerance, status, note``).  It opens with a status summary: which records
were found and which are missing (with how to obtain them), and what each
study could not include because of them; then the headline counts of the
comparison cells in four categories (:data:`CATEGORIES`), which add up to the
number of cells; then an account of every table and figure of the paper
(:data:`stickslip.reports.paper_items.PAPER_ITEMS`); then the errata found by the
code, the paper's own fits beside ours and the substitute scaling study.
Nothing is computed here: every number is read from a file.  ``workflow/rules/reports.smk`` calls
:func:`write_index`.
"""

from __future__ import annotations

import html
import importlib
import json
import math
from collections.abc import Mapping, Sequence
from pathlib import Path

from stickslip.measures import MEASURE_LABELS
from stickslip.plumbing.files import read_csv_rows, write_text_atomic
from stickslip.reports.design_answer import format_number
from stickslip.reports.links import relative_href, thumbnails_html
from stickslip.reports.paper_items import PAPER_ITEMS
from stickslip.units import UNITS, energy_units, readable_units

#: Status of a comparison cell within tolerance.
OK_STATUS = "ok"

#: The categories of the headline counts, in order; every comparison cell falls in exactly one.
CATEGORIES = ("within tolerance", "beyond tolerance", "not comparable", "paper erratum")

#: Tables shown on the index: (file under results/tables, heading, what it is, the columns shown).  A column is
#: (CSV column, heading in words with its units), or (CSV column, heading, CSV column of the low end, of the high
#: end) for a value shown with its interval, "value [low, high]" (:func:`rows_html`).
RESULT_TABLES = (
    ("errata.csv", "Errata found by the code",
     "One computed check per row (E1 to E4); a comparison cell that a confirmed erratum explains is counted "
     "as \"paper erratum\" above, not as ours beyond tolerance. Values are relative, dimensionless.",
     (("check", "check"), ("description", "what is checked"), ("value", "value [-]"),
      ("compared_with", "compared with [-]"), ("finding", "finding"), ("status", "status"),
      ("explains", "comparison cell it explains"))),
    ("paper_fits.csv", "The paper's μ_max lines from its own Table 6, beside ours",
     "Least-squares lines μ_max = slope·x + intercept, x in m/s², slope in 1/(m/s²): the paper's printed Table 6 "
     "on all its records and on the records we have, and ours on the same records; 95 % slope intervals "
     "(bootstrap and Student's t), Pearson r with its 95 % interval. The records of each line are in the CSV.",
     (("source", "line"), ("x", "x"), ("n", "records"), ("intercept", "intercept [-]"),
      ("slope", "slope [1/(m/s²)], bootstrap interval", "slope_low_bootstrap", "slope_high_bootstrap"),
      ("slope", "slope [1/(m/s²)], Student's t interval", "slope_low_t", "slope_high_t"),
      ("r", "Pearson r [-]", "r_low", "r_high"), ("p_value", "p-value [-]"), ("note", "note"))),
    ("table3_table4_model.csv", "Tables 3 and 4: our model beside the paper's model and test columns",
     "Residual displacement [m] (magnitude) and E_df [J] at μ = 0.10; differences are relative, (a − b) / |b|.",
     (("table", "table"), ("interface", "interface"), ("row", "row"), ("units", "units"), ("ours", "ours"),
      ("paper_model", "the paper's model"), ("paper_test", "the paper's test"),
      ("difference_from_model", "difference from the model [-]"),
      ("difference_from_test", "difference from the test [-]"), ("status", "status"))),
    ("table8_results.csv", "Substitute scaling study: Table 8 on our records",
     "The paper scaled Mendoza 1985, which we do not have; each of our records is scaled to PGA 0.6, 0.8 and "
     "1.0 g instead (PGA and RMS in m/s², E_df,max in J).",
     (("record", "record"), ("scaling", "scaling"), ("scale_factor", "scale factor [-]"), ("pga", "PGA [m/s2]"),
      ("rms_acceleration", "RMS acceleration [m/s2]"), ("energy_dissipated_max", "E_df,max [J]"),
      ("mu_max", "μ_max [-]"), ("status", "status"))),
)

#: The quantities of the comparison and result tables (CSV column names) as a reader calls them.
QUANTITY_WORDS = {**{name: MEASURE_LABELS[name] for name in (
    "pga", "rms_acceleration", "arias_intensity", "significant_duration", "significant_duration_samples", "dt",
    "duration")},
    "energy_dissipated": "E_df, energy dissipated by friction", "energy_dissipated_max": "E_df,max",
    "residual_displacement": "residual displacement |x|", "mu_max": "μ_max", "mu_low": "μ_low", "mu_high": "μ_high"}

#: Units of the compared quantities (the comparison tables are SI), UDUNITS spelling.
COLUMN_UNITS = {name: UNITS[name] for name in (
    "pga", "rms_acceleration", "energy_dissipated", "energy_dissipated_max", "mu_max", "mu_low", "mu_high",
    "arias_intensity", "significant_duration", "significant_duration_samples", "duration", "dt",
)}

#: The CSS of the pages the package writes (the index, the isolation suite's page).
STYLE = """
body { font-family: sans-serif; margin: 2em; max-width: 70em; }
table { border-collapse: collapse; margin: 0.5em 0 1.5em 0; font-size: 0.9em; }
th, td { border: 1px solid #bbb; padding: 0.2em 0.5em; text-align: right; }
th { background: #eee; text-align: center; }
td.text { text-align: left; }
tr.flagged td { background: #fde2e2; }
tr.missing td { background: #eeeeee; color: #666; }
tr.erratum td { background: #fff4c2; }
.status { border: 1px solid #bbb; background: #f7f7f7; padding: 0.5em 1em; }
.status li { margin: 0.2em 0; overflow-wrap: anywhere; }
img { max-width: 32em; border: 1px solid #ccc; margin: 0.3em; }
"""


def cell_category(status: str) -> str:
    """The headline category of a comparison cell's status (one of :data:`CATEGORIES`).

    ``ok``: within tolerance; ``beyond tolerance``; ``paper erratum: …`` (a
    confirmed erratum of the paper explains the printed value); anything else
    (``missing: …``, ``no paper value``) is not comparable.
    """
    if status == OK_STATUS:
        return CATEGORIES[0]
    if status == "beyond tolerance":
        return CATEGORIES[1]
    if status.startswith("paper erratum"):
        return CATEGORIES[3]
    return CATEGORIES[2]


def category_counts(rows: Sequence[dict[str, str]]) -> dict[str, int]:
    """How many comparison cells fall in each of :data:`CATEGORIES`."""
    counts = dict.fromkeys(CATEGORIES, 0)
    for row in rows:
        counts[cell_category(row.get("status", ""))] += 1
    return counts


def _counts_text(counts: Mapping[str, int]) -> str:
    return ", ".join(f"{counts[category]} {category}" for category in CATEGORIES)


def headline_html(tables: Mapping[str, Sequence[dict[str, str]]]) -> str:
    """The headline counts: per comparison table and in total, the cells in each category, and their sum."""
    header = ("table", *CATEGORIES, "cells")
    lines = ["<h2>Headline: our values against the paper's</h2>",
             "<p>Every comparison cell is in exactly one category: within the column's tolerance, beyond it, not "
             "comparable (the record is missing, or the paper prints no value), or a paper erratum (a confirmed "
             "erratum of the paper, found by a computed check, explains the printed value).</p>",
             "<table>", "<tr>" + "".join(f"<th>{h}</th>" for h in header) + "</tr>"]
    total = dict.fromkeys(CATEGORIES, 0)
    for name, rows in tables.items():
        counts = category_counts(rows)
        for category in CATEGORIES:
            total[category] += counts[category]
        lines.append(f'<tr><td class="text">{html.escape(name)}</td>'
                     + "".join(f"<td>{counts[c]}</td>" for c in CATEGORIES) + f"<td>{len(rows)}</td></tr>")
    lines.append('<tr><th class="text">all tables</th>' + "".join(f"<th>{total[c]}</th>" for c in CATEGORIES)
                 + f"<th>{sum(total.values())}</th></tr>")
    lines.append("</table>")
    return "\n".join(lines)


def accounting_html(results_dir: Path, reports_dir: Path, base: Path) -> str:
    """Every table and figure of the paper: regenerated or substituted (with links), or why not reproducible."""
    folders = {"results": results_dir, "reports": reports_dir}
    header = ("paper", "what", "outcome", "our output", "reason")
    lines = ["<h2>The paper, table by table and figure by figure</h2>", "<table>",
             "<tr>" + "".join(f"<th>{h}</th>" for h in header) + "</tr>"]
    for item in PAPER_ITEMS:
        links = []
        for folder, pattern in item["outputs"]:
            for path in sorted(folders[folder].glob(pattern)):
                links.append(f'<a href="{relative_href(path, base)}">{html.escape(path.name)}</a>')
        if item["outputs"] and not links:
            links = ["not produced in this run"]
        cells = (item["item"], item["what"], item["outcome"])
        lines.append("<tr>" + "".join(f'<td class="text">{html.escape(c)}</td>' for c in cells)
                     + f'<td class="text">{"<br>".join(links)}</td>'
                     + f'<td class="text">{html.escape(item["reason"])}</td></tr>')
    lines.append("</table>")
    return "\n".join(lines)


def rows_html(rows: Sequence[dict[str, str]], columns: Sequence | None = None) -> str:
    """A CSV table's rows as an HTML table: ``columns`` (default all), numbers to four significant digits.

    A column is a CSV column name (its own heading), a (name, heading) pair, or (name, heading, low, high): the
    value with the columns ``low`` and ``high`` as its interval, ``value [low, high]``.  A column the rows do not
    have is left out.  Text is escaped, a quantity's name in words (:data:`QUANTITY_WORDS`); a ``status`` cell
    shows only its first part (``missing`` for ``missing: …``; the CSV keeps the whole explanation).
    """
    if not rows:
        return "<p>empty table</p>"
    columns = [(column, column) if isinstance(column, str) else tuple(column) for column in columns or list(rows[0])]
    columns = [column for column in columns if column[0] in rows[0]]
    lines = ["<table>", "<tr>" + "".join(f"<th>{html.escape(column[1])}</th>" for column in columns) + "</tr>"]
    for row in rows:
        cells = []
        for name, _, *interval in columns:
            value = row.get(name, "") or ""
            try:
                float(value)
            except ValueError:
                text = (value.split(":", 1)[0] if name == "status" else readable_units(value) if name == "units"
                        else QUANTITY_WORDS.get(value, value))
                cells.append(f'<td class="text">{html.escape(text)}</td>')
                continue
            bounds = f" [{_number(row.get(interval[0], ''))}, {_number(row.get(interval[1], ''))}]" if interval else ""
            cells.append(f"<td>{_number(value)}{bounds}</td>")
        lines.append("<tr>" + "".join(cells) + "</tr>")
    lines.append("</table>")
    return "\n".join(lines)


def measures_rows(measures: dict[str, float], digits: int = 6) -> list[tuple[str, str, str]]:
    """(what it is, value to ``digits`` significant digits, units as read) for each intensity measure (SI units)."""
    from stickslip.measures import MEASURE_LABELS, MEASURE_UNITS

    return [(MEASURE_LABELS[name], format_number(value, digits), readable_units(MEASURE_UNITS[name]))
            for name, value in measures.items()]


def scalars_rows(scalars: dict[str, float], digits: int = 6,
                 attrs: Mapping[str, tuple[str, str]] | None = None,
                 mass: float | None = None) -> list[tuple[str, str, str]]:
    """(what it is, value to ``digits`` significant digits, units as read) for each scalar of a solved case (SI).

    ``attrs`` maps each scalar to its (units, long name): by default a 1-D block's
    (:data:`stickslip.models.rigid.response.SCALAR_ATTRS` and its slope's), for a block in the plane
    :data:`stickslip.models.planar.response.SCALAR_ATTRS`.  A count is written as a whole number.  With the
    block's ``mass`` [kg], energies are labelled as :func:`stickslip.units.energy_units` says (J/kg for the
    default 1 kg).
    """
    if attrs is None:
        from stickslip.models.rigid import SCALAR_ATTRS, SLOPE_SCALAR_ATTRS

        attrs = {**SCALAR_ATTRS, **SLOPE_SCALAR_ATTRS}
    return [(attrs[name][1], format_number(value, digits),
             readable_units(energy_units(mass) if attrs[name][0] == "J" and mass is not None else attrs[name][0]))
            for name, value in scalars.items()]


def _number(text: str, digits: int = 4) -> str:
    """A number string formatted to ``digits`` significant digits; empty or non-numeric text unchanged."""
    try:
        value = float(text)
    except (TypeError, ValueError):
        return html.escape(str(text or ""))
    if math.isnan(value):
        return ""
    return format_number(value, digits)


def comparison_html(rows: Sequence[dict[str, str]], max_note: int = 160) -> str:
    """An HTML table of comparison rows: ours beside the paper's, flagged rows shaded red (missing grey)."""
    header = ("row", "quantity", "units", "ours", "paper", "rel. diff.", "tolerance", "status", "note")
    lines = ["<table>", "<tr>" + "".join(f"<th>{h}</th>" for h in header) + "</tr>"]
    for row in rows:
        status = row.get("status", "")
        category = cell_category(status)
        css = {"not comparable": "missing", "beyond tolerance": "flagged", "paper erratum": "erratum"}.get(category, "")
        rel = row.get("relative_difference", "")
        rel_text = _number(rel, 3)
        if rel_text and rel_text != html.escape(rel):
            rel_text = f"{float(rel) * 100:+.2f} %"
        note = row.get("note", "") or ""
        if len(note) > max_note:
            note = note[: max_note - 1] + "…"
        status_text = status.split(":", 1)[0] if category in ("not comparable", "paper erratum") else status
        cells = [
            ("text", html.escape(row.get("row", ""))),
            ("text", html.escape(QUANTITY_WORDS.get(row.get("column", ""), row.get("column", "")))),
            ("text", readable_units(COLUMN_UNITS.get(row.get("column", ""), ""))),
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
                 status: str = "", beyond: str = "", beyond_figures: Sequence[str | Path] = (),
                 figure_alts: Mapping[str, str] | None = None) -> str:
    """The HTML text of the index page for ``reports_dir`` (links relative to ``index_path``'s folder).

    Opens with ``status`` (:func:`status_html`), then lists every executed
    notebook (rendered as HTML under ``reports_dir/html``, with the notebook
    beside it), every PNG under ``reports_dir`` (grouped by folder), and every
    ``results_dir/tables/*_comparison.csv`` as a table of our values beside the paper's.
    Ends with ``beyond``, the sections of the work beyond the paper, whose
    figures (under the folders ``beyond_figures``) they show themselves.
    ``figure_alts`` are the figures' alternative texts by path (:func:`~stickslip.reports.links.thumbnails_html`).
    """
    results_dir, reports_dir = Path(results_dir), Path(reports_dir)
    base = Path(index_path).parent if index_path is not None else reports_dir
    notebooks = sorted(path for path in reports_dir.rglob("*.ipynb") if not path.name.startswith("."))
    figures = sorted(path for path in reports_dir.rglob("*.png")
                     if not any(path.is_relative_to(Path(folder)) for folder in beyond_figures))
    comparisons = sorted((results_dir / "tables").glob("*_comparison.csv"))

    tables = {path.name.removesuffix("_comparison.csv"): read_csv_rows(path) for path in comparisons}

    parts = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8"><title>stickslip reports</title>',
        f"<style>{STYLE}</style></head><body>",
        "<h1>stickslip: reproduction of the paper</h1>",
        status,
        "<p>Every number below was read from a file the workflow wrote; the paper's values come from "
        "the reference table <code>stickslip/reference/paper.yaml</code>. Rows beyond tolerance are "
        "shaded red, rows that cannot be compared grey, paper errata yellow. Units are SI.</p>",
        headline_html(tables),
        accounting_html(results_dir, reports_dir, base),
    ]
    for name, heading, text, columns in RESULT_TABLES:
        path = results_dir / "tables" / name
        if path.is_file():
            parts += [f'<h2>{html.escape(heading)} (<a href="{relative_href(path, base)}">{html.escape(name)}</a>)</h2>',
                      f"<p>{html.escape(text)}</p>", rows_html(read_csv_rows(path), columns)]
    parts += ["<h2>Notebooks</h2>", "<ul>"]
    for notebook in notebooks:
        name = notebook.relative_to(reports_dir).with_suffix("")
        page = reports_dir / "html" / name.with_suffix(".html")
        link = (f'<a href="{relative_href(page, base)}">{html.escape(name.as_posix())}</a>' if page.is_file()
                else html.escape(name.as_posix()))
        parts.append(f'<li>{link} (<a href="{relative_href(notebook, base)}">notebook</a>)</li>')
    if not notebooks:
        parts.append("<li>none</li>")
    parts.append("</ul>")
    parts.append("<h2>Figures</h2>")
    groups: dict[Path, list[Path]] = {}
    for figure in figures:
        groups.setdefault(figure.parent, []).append(figure)
    for folder, items in groups.items():
        parts += [f"<h3>{html.escape(folder.relative_to(reports_dir).as_posix())}</h3><div>",
                  thumbnails_html(items, base, figure_alts), "</div>"]
    if not figures:
        parts.append("<p>none</p>")

    parts.append("<h2>Our values beside the paper's</h2>")
    for path in comparisons:
        name = path.name.removesuffix("_comparison.csv")
        rows = tables[name]
        parts.append(f'<h3>{html.escape(name)} (<a href="{relative_href(path, base)}">{html.escape(path.name)}</a>), '
                     f"{len(rows)} cells: {_counts_text(category_counts(rows))}</h3>")
        parts.append(comparison_html(rows))
    if not comparisons:
        parts.append("<p>no comparison tables found</p>")
    parts.append(beyond)
    parts.append("</body></html>")
    return "\n".join(parts) + "\n"


def write_index(measures_paths: Sequence[str | Path], index_path: str | Path, studies: Mapping[str, Sequence[str]],
                results_dir: str | Path = "results", reports_dir: str | Path = "reports",
                sections: Sequence[tuple[str, Mapping]] = (), figure_alts: Mapping[str, str] | None = None) -> Path:
    """Write the index page (see :func:`render_index`) to ``index_path`` atomically; return the path.

    ``measures_paths`` are the records' measures files, for the status summary
    (:func:`status_html`, with ``studies``).  ``sections`` are the report
    pages' own sections, in order: each a ``"module:function"`` that returns
    the section's HTML and its keyword arguments (``base``, the index's
    folder, is added); a section given a ``figures_dir`` shows the figures
    there itself, with ``figure_alts``.  The workflow passes each declared
    page's ``index_section`` and every declared figure's alternative text, by
    path (``report_page`` in ``workflow/rules/common.smk``).
    """
    index_path = Path(index_path)
    documents = [json.loads(Path(path).read_text(encoding="utf-8")) for path in measures_paths]
    parts, own_figures = [], []
    for function_name, arguments in sections:
        module, function = function_name.split(":")
        shows_figures = "figures_dir" in arguments
        extra = {"figure_alts": figure_alts} if shows_figures else {}
        parts.append(getattr(importlib.import_module(module), function)(base=index_path.parent, **arguments, **extra))
        if shows_figures:
            own_figures.append(arguments["figures_dir"])
    page = render_index(results_dir, reports_dir, index_path, status_html(documents, studies), "\n".join(parts),
                        own_figures, figure_alts)
    write_text_atomic(index_path, page)
    return index_path
