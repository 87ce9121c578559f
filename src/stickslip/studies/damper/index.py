"""The section of ``reports/index.html`` on the damper on a structure: how far apart the two optima are, and a link.

:func:`damper_section_html` reads only ``damper_study.json`` (:mod:`stickslip.studies.damper.tables`).
"""

from __future__ import annotations

import html
import json
from pathlib import Path

from stickslip.reports.links import relative_href


def damper_section_html(study_path: str | Path, page: str | Path | None, base: str | Path) -> str:
    """The section's HTML; ``page`` is the rendered notebook (None when not rendered), ``base`` the index's folder."""
    study_path, base = Path(study_path), Path(base)
    document = json.loads(study_path.read_text(encoding="utf-8"))
    parts = ['<h1 id="damper">The paper\'s question with a structure: a friction damper on a building</h1>']
    if not document["available"]:
        parts.append("<p>No record was available: " + html.escape(document["left_out"] or "none was stored") + "</p>")
    else:
        counts = ", ".join(f"{count} {library}" for library, count in document["records"].items())
        parts.append(
            f"<p>A flat friction damper on a one-story building, on {html.escape(counts)} records: the μ of the most "
            "energy dissipated E_df (the paper's μ_max) against the μ of the smallest peak drift. Per mass ratio and "
            "period, the median (84th percentile) over the records of μ_Edf/μ_drift and of the drift reduction the "
            "paper's μ gives up:</p><ul>")
        for cell in document["cells"]:
            ratio, given_up = cell["mu_ratio"], cell["reduction_given_up"]
            parts.append(f"<li>m_d/m_s = {cell['mass_ratio']:g}, T = {cell['period']:g} s: μ_Edf/μ_drift "
                         f"{ratio['median']:.2f} ({ratio['p84']:.2f}); reduction given up {given_up['median']:.3f} "
                         f"({given_up['p84']:.3f})</li>")
        parts.append("</ul>")
    links = [f'<a href="{relative_href(Path(page), base)}">the damper page</a>'] if page else []
    links += [f'<a href="{relative_href(study_path.with_name(name), base)}">{name}</a>'
              for name in ("damper_summary.csv", "damper_cases.csv", "damper.nc", study_path.name)]
    parts.append(f"<p>See {', '.join(links)}.</p>")
    return "\n".join(parts)
