"""The collection study's section of ``reports/index.html``, separate from the reproduction of the paper.

:func:`collection_section_html` reads only what the workflow wrote in
``results/collections/{study}/`` and ``reports/`` and says, at a glance: how
many records were studied (and which were left out: not read, or never
sliding on the grid; which files of a folder were skipped, not being record files), the paper's claims with their verdicts, the numbers an engineer would design with, the check of our
intensity measures against the collection's published values, the figures,
and links to every table.
"""

from __future__ import annotations

import html
import json
from collections.abc import Mapping
from pathlib import Path

import numpy as np

from stickslip.plumbing.files import read_csv_rows
from stickslip.reports.links import relative_href, thumbnails_html
from stickslip.collections.members import GROUPS, left_out, studied

#: Tables of the study linked from the section.
TABLES = ("records.csv", "skipped.csv", "relations.csv", "coverage.csv", "claims.csv", "near_far.csv", "measures_check.csv",
          "scaling_law.csv", "design.json")


def collection_section_html(study_dir: str | Path, figures_dir: str | Path, page: str | Path, base: str | Path,
                            min_records: int, not_here: int = 0, figure_alts: Mapping[str, str] | None = None) -> str:
    """The section's HTML; ``page`` is the study's rendered notebook, ``base`` the index's folder.

    ``figure_alts``: the figures' alternative texts by path (:func:`~stickslip.reports.links.thumbnails_html`).

    Quartiles of fewer than ``min_records`` records studied are not given.
    """
    study_dir, figures_dir, page, base = Path(study_dir), Path(figures_dir), Path(page), Path(base)
    rows = read_csv_rows(study_dir / "records.csv")
    ok = studied(rows)
    out = left_out(rows)
    kind = study_dir.name
    parts = [f'<h1 id="collection">Beyond the paper: the {html.escape(kind)} collection study</h1>',
             f"<p><b>{len(ok)} records</b> from {len({row['event'] for row in ok})} earthquakes were studied "
             f'(<a href="{relative_href(page, base)}">the study\'s page</a>).']
    for group, words in GROUPS.items():
        members = [row for row in out if row["group"] == group]
        if members:
            parts.append(f" <b>{len(members)} record{'s' if len(members) != 1 else ''} {words}</b>, left out of every "
                         "fit: " + "; ".join(
                f"{html.escape(row['id'])} ({html.escape(row['reason'])})" for row in members) + ".")
    skipped = read_csv_rows(study_dir / "skipped.csv")
    if skipped:
        parts.append(f" {len(skipped)} other file{'s' if len(skipped) != 1 else ''} of the folder, not record "
                     f"files, skipped: {html.escape(', '.join(row['file'] for row in skipped))}.")
    if not_here:
        parts.append(f" {not_here} more records of the collection are not on this machine: "
                     f"<code>stickslip records fetch --collection {html.escape(kind)} --out-dir FOLDER</code> "
                     "downloads and checks them (docs/collections.md).")
    if kind == "pyslammer":
        parts.append(" These are pyslammer's sample motions, the study that needs no download: point "
                     "<code>STICKSLIP_SLAMMER_DIR</code> (or <code>collection_study.folder</code>) at a copy of the "
                     "SLAMMER library to study its records instead (docs/collections.md).")
    parts.append("</p>")
    parts.append("<h2>The paper's claims, tested</h2><table><tr><th>claim</th><th>the paper</th><th>ours</th>"
                 "<th>verdict</th></tr>")
    for claim in read_csv_rows(study_dir / "claims.csv"):
        parts.append("<tr>" + "".join(f'<td style="text-align:left">{html.escape(claim[key])}</td>'
                                      for key in ("claim", "paper", "ours", "verdict")) + "</tr>")
    parts.append("</table>")
    coverage = read_csv_rows(study_dir / "coverage.csv")
    parts.append("<h2>Numbers to design with</h2><ul>")
    ratio = np.array([float(row["mu_max_g_over_pga"]) for row in ok])
    if ratio.size >= min_records:
        quartiles = np.quantile(ratio, [0.25, 0.5, 0.75])
        parts.append(f"<li>μ_max·g/PGA: median {quartiles[1]:.3f}, quartiles {quartiles[0]:.3f} to "
                     f"{quartiles[2]:.3f}</li>")
    parts += [f"<li>E_df(μ = {float(band['reference_mu']):g})/E_df,max: median "
              f"{float(band['median_efficiency_reference']):.2f}</li>"
              for band in coverage if band["pga_band"] == "all records" and band["status"] == "ok"]
    for band in coverage:
        if band["status"] != "ok":
            parts.append(f"<li>{html.escape(band['pga_band'])}: {html.escape(band['status'])}</li>")
            continue
        meets = "meets" if band["design_meets_target"] == "True" else "does not meet"
        parts.append(f"<li>{html.escape(band['pga_band'])} ({band['n']} records): μ = {float(band['design_mu']):g} "
                     f"reaches 90 % of E_df,max for {float(band['share_design_mu']):.0%} of them ({meets} the 80 % "
                     f"target); μ = {float(band['reference_mu']):g} lies in the near-optimal range of "
                     f"{float(band['share_reference_in_range']):.0%}"
                     "</li>")
    parts.append("</ul>")
    summary_path = study_dir / "measures_check.json"
    summary = json.loads(summary_path.read_text(encoding="utf-8"))
    if summary["checked"]:
        met = "met" if summary["passes"] else "<b>not met</b>"
        parts.append(f"<h2>Our measures against the collection's published values</h2><p>{summary['within']} of "
                     f"{summary['checked']} values ({summary['records']} records × PGA, Arias intensity, 5-95 % "
                     f"duration, mean period) within the database's rounding: {summary['pass_rate']:.2%}; the "
                     f"threshold {summary['threshold']:.0%} is {met}. "
                     + (f"{len(summary['beyond'])} beyond, each with its explanation in measures_check.csv.</p>"
                        if summary["beyond"] else "None beyond.</p>"))
    else:
        parts.append("<h2>Our measures against the collection's published values</h2><p>Not checked: this "
                     "collection publishes no intensity measures.</p>")
    figures = sorted(figures_dir.glob("*.png"))
    if figures:
        parts.append("<h2>Figures</h2><div>")
        parts.append(thumbnails_html(figures, base, figure_alts))
        parts.append("</div>")
    links = [f'<a href="{relative_href(study_dir / name, base)}">{name}</a>' for name in TABLES if (study_dir / name).is_file()]
    parts.append(f"<p>Tables: {', '.join(links)}.</p>")
    return "\n".join(parts)
