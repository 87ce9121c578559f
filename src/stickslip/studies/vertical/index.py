"""The section of ``reports/index.html`` on the vertical ground motion: what it changes, per radius, and a link.

:func:`vertical_section_html` reads only the summary table and the study
document that :mod:`stickslip.studies.vertical.effect` wrote.
"""

from __future__ import annotations

import html
import json
from pathlib import Path

from stickslip.plumbing.files import read_csv_rows
from stickslip.reports.links import relative_href

#: The changes the section shows, as it names them.
SHOWN = {"energy_ratio": "E_df,max with / without", "base_shear_ratio_at_reference": "V/W at the reference μ",
         "peak_displacement_ratio_at_reference": "displacement demand at the reference μ"}


def vertical_section_html(summary_path: str | Path, study_path: str | Path, page: str | Path | None,
                          base: str | Path) -> str:
    """The section's HTML; ``page`` is the rendered notebook (None when not rendered), ``base`` the index's folder."""
    summary_path, study_path, base = Path(summary_path), Path(study_path), Path(base)
    document = json.loads(study_path.read_text(encoding="utf-8"))
    parts = ['<h1 id="vertical">The vertical ground motion on sliders and pendulums</h1>']
    if not document["available"]:
        parts.append(f"<p>{html.escape(document['message'])}</p>")
    else:
        pooled = "all" if len(document["directions"]) > 1 else document["directions"][0]
        parts.append(f"<p>{document['stations']} near-fault stations with their vertical, directions "
                     f"{html.escape(', '.join(document['directions']))}; ratios with / without the vertical as "
                     f"recorded (reversed in brackets), median and range over the stations, at μ = "
                     f"{document['reference_mu']:g} for the demands:</p><ul>")
        rows = {(row["radius"], row["vertical"], row["quantity"]): row for row in read_csv_rows(summary_path)
                if row["direction"] == pooled}
        for radius in document["radii_m"]:
            cells = []
            for quantity, label in SHOWN.items():
                found = [rows.get((radius, variant, quantity)) for variant in ("recorded", "reversed")]
                text = [f"{float(row['median']):.2f} ({float(row['min']):.2f} to {float(row['max']):.2f})"
                        for row in found if row is not None and row["median"] not in ("", "nan")]
                cells.append(f"{label} {text[0]}" + (f" [{text[1]}]" if len(text) > 1 else "") if text else
                             f"{label}: no value")
            name = "flat slider" if radius == "inf" else f"R = {radius} m"
            parts.append(f"<li>{html.escape(name)}: {html.escape('; '.join(cells))}</li>")
        parts.append("</ul>")
    links = [f'<a href="{relative_href(Path(page), base)}">the vertical ground motion page</a>'] if page else []
    links += [f'<a href="{relative_href(summary_path.with_name(name), base)}">{name}</a>'
              for name in (summary_path.name, "vertical_changes.csv", "vertical_cases.csv", "vertical_liftoff.csv")]
    parts.append(f"<p>See {', '.join(links)}.</p>")
    return "\n".join(parts)
