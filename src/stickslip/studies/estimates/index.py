"""The section of ``reports/index.html`` on the simplified estimates: which method came closest, per k_y, and a link.

:func:`estimates_section_html` reads only the summary table and the study
document that :mod:`stickslip.studies.estimates.simplified` wrote.
"""

from __future__ import annotations

import html
import json
from pathlib import Path

from stickslip.estimates.ranking import ranking_rows
from stickslip.estimates.registry import METHODS
from stickslip.plumbing.files import read_csv_rows
from stickslip.reports.links import relative_href


def estimates_section_html(summary_path: str | Path, study_path: str | Path, page: str | Path | None,
                           base: str | Path) -> str:
    """The section's HTML; ``page`` is the rendered notebook (None when not rendered), ``base`` the index's folder."""
    summary_path, study_path, base = Path(summary_path), Path(study_path), Path(base)
    document = json.loads(study_path.read_text(encoding="utf-8"))
    collection, settings = document["collection"], document["settings"]
    best = [row for row in ranking_rows(read_csv_rows(summary_path)) if row["rank"] == 1]
    parts = ['<h1 id="estimates">The simplified estimates against the rigorous answers</h1>',
             f"<p>Every simplified estimate SLAMMER 1.1 offers, on the {collection['records_solved']} records "
             f"({collection['events']} events) of the <code>{html.escape(collection['kind'])}</code> collection, "
             f"at k_y = {', '.join(f'{value:g}' for value in settings['critical_accelerations_g'])} g, against the exact "
             f"rigid D_n of both polarities and, for the flexible methods, the coupled D of layers of T_s = "
             f"{', '.join(f'{value:g}' for value in settings['site_periods'])} s. The method with the smallest RMS of "
             f"ln(D / D_est) over the rows with D ≥ {settings['displacement_floor_cm']:g} cm:</p><ul>"]
    for row in best:
        against = "rigid D_n" if row["compared_with"] == "rigid" else f"coupled D, T_s {row['site_period']:g} s"
        parts.append(f"<li>k_y {row['ky']:g} ({html.escape(against)}): {html.escape(METHODS[row['method']].label)}, "
                     f"RMS {row['rms_ln']:.2f}, bias {row['bias_ln']:+.2f}, σ {row['sigma_ln']:.2f} (ln units)</li>")
    if not best:
        parts.append("<li>none: too few rows with D at or above the floor</li>")
    parts.append("</ul>")
    links = [f'<a href="{relative_href(Path(page), base)}">the simplified estimates page</a>'] if page else []
    links += [f'<a href="{relative_href(summary_path.with_name(name), base)}">{name}</a>'
              for name in (summary_path.name, "estimates_exceedance.csv", "estimates_rows.csv")]
    parts.append(f"<p>See {', '.join(links)}.</p>")
    return "\n".join(parts)
