"""The section of ``reports/index.html`` on the codes' equivalent-linear displacement against the exact one.

:func:`code_exact_section_html` reads only ``bias.csv`` and
``code_vs_exact.json`` (:mod:`stickslip.studies.code_vs_exact.analysis`).
"""

from __future__ import annotations

import html
import json
from pathlib import Path

from stickslip.plumbing.files import read_csv_rows
from stickslip.studies.code_vs_exact.plots import CODE_STYLE
from stickslip.reports.links import relative_href


def code_exact_section_html(bias_path: str | Path, summary_path: str | Path, page: str | Path | None,
                            base: str | Path) -> str:
    """The section's HTML; ``page`` is the rendered notebook (None when not rendered), ``base`` the index's folder."""
    bias_path, summary_path, base = Path(bias_path), Path(summary_path), Path(base)
    document = json.loads(summary_path.read_text(encoding="utf-8"))
    parts = ['<h1 id="code-vs-exact">The codes\' equivalent-linear displacement against the exact one</h1>']
    if not document["available"]:
        parts.append("<p>No case: no station pair of the collection and no three-component station was read. "
                     f"{html.escape(document['three_component_status'])}</p>")
    else:
        parts.append(f"<p>{document['pairs']} station pairs of the collection and "
                     f"{document['three_component_stations']} three-component stations, R = "
                     f"{', '.join(f'{r:g}' for r in document['radii_m'])} m, μ = "
                     f"{', '.join(f'{m:g}' for m in document['mu'])}; each code's D from the record's own 5 % "
                     "spectrum (a component's in one direction, RotD100 in the plane) against the pendulum's exact "
                     "peak displacement, every case without a vertical:</p><ul>")
        by_row = {(row["grouping"], row["code"]): row for row in read_csv_rows(bias_path) if row["grouping"] == "all"}
        factor = document["unconservative_factor"]
        for code, (label, _) in CODE_STYLE.items():
            row = by_row.get(("all", code))
            if row is None or not int(row["n"]):
                parts.append(f"<li>{html.escape(label)}: no case</li>")
                continue
            share = float(row["unconservative_share"])
            parts.append(f"<li>{html.escape(label)}: bias of ln(D_exact/D_code) {float(row['bias']):+.2f}, σ "
                         f"{float(row['sigma']):.2f} over {row['n']} cases; D_exact &gt; {factor:g}·D_code in "
                         f"{100 * share:.0f} %</li>")
        parts.append("</ul>")
        closest = document["closest_code"]
        if closest:
            parts.append(f"<p>Closest (smallest root mean square of the log ratio): "
                         f"{html.escape(CODE_STYLE[closest][0])}.</p>")
        notes = [document["far_field_status"] if document["far_field_status"] != "ok" else "",
                 f"Pulse-like records: {document['pulse_status']}.",
                 document["three_component_status"] if document["three_component_status"] != "ok" else ""]
        parts.append("<p>" + " ".join(html.escape(note) for note in notes if note) + "</p>")
    links = [f'<a href="{relative_href(Path(page), base)}">the page</a>'] if page else []
    links += [f'<a href="{relative_href(path, base)}">{path.name}</a>'
              for path in (bias_path, bias_path.with_name("cases.csv"), summary_path)]
    parts.append(f"<p>See {', '.join(links)}.</p>")
    return "\n".join(parts)

