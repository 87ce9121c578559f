"""The section of ``reports/index.html`` on the isolated building: the best pendulum per period, near-fault
against far-field, and a link.

:func:`isolation_section_html` reads only ``isolation_study.json`` (:mod:`stickslip.studies.isolation.tables`) and
the in-plane part's ``isolation_vertical_summary.csv`` (:mod:`stickslip.studies.isolation.with_vertical`).
"""

from __future__ import annotations

import html
import json
from pathlib import Path

from stickslip.plumbing.files import read_csv_rows
from stickslip.reports.links import relative_href

#: The in-plane ratios (with the vertical over without it) the index names, with their words.
VERTICAL_RATIOS = {"peak_drift_ratio": "drift", "base_shear_coefficient_ratio": "V_b/W"}
#: The quantities compared near-fault against far-field, with their words.
NEAR_FAR_WORDS = {"drift_ratio": "drift ratio", "floor_acceleration_ratio": "floor acceleration ratio",
                  "peak_isolator_displacement": "isolator displacement"}


def near_far_sentence(near_far: dict) -> str:
    """One sentence on near-fault against far-field (the study JSON's ``near_far``): per quantity, in how many of
    the (T, R, μ) cells the near-fault median is the larger and the test's p-value small, and the range of the
    ratio of the medians; "" where the groups were not compared."""
    if not near_far["compared"]:
        return ""
    parts = [f"{NEAR_FAR_WORDS[quantity]}: near-fault median the larger in {found['near_larger']} of "
             f"{found['cells']}, p &lt; {found['significance']:g} in {found['significant']}, near / far "
             f"{found['median_ratio_min']:.3g} to {found['median_ratio_max']:.3g}"
             for quantity, found in near_far["quantities"].items()]
    return ("<p>Near-fault against far-field per T, R and μ (medians over each group, two-sided Mann–Whitney U "
            "test): " + "; ".join(parts) + ".</p>")


def vertical_sentence(summary_path: Path) -> str:
    """One sentence on the in-plane part: per case (T, R) and μ, the median and 84th percentile of the drift and
    base shear ratios with the vertical over without it; "" without its rows (no three-component records)."""
    rows = [row for row in read_csv_rows(summary_path) if row["quantity"] in VERTICAL_RATIOS]
    if not rows:
        return ""
    by_case = {}
    for row in rows:
        by_case.setdefault((float(row["period"]), float(row["radius"]), float(row["mu"])), []).append(
            f"{VERTICAL_RATIOS[row['quantity']]} {float(row['median']):.2f} (84 %: {float(row['p84']):.2f})")
    one_building = len({case[:2] for case in by_case}) == 1
    cells = [(f"μ = {mu:g}" if one_building else f"T = {period:g} s, R = {radius:g} m, μ = {mu:g}")
             + f": {', '.join(ratios)}" for (period, radius, mu), ratios in by_case.items()]
    (period, radius, _), stations = next(iter(by_case)), rows[0]["stations"]
    building = f" (T = {period:g} s, R = {radius:g} m)" if one_building else ""
    return (f"<p>In the plane on the {stations} three-component stations, with the vertical over without it"
            f"{building}, median and 84th percentile: " + "; ".join(html.escape(cell) for cell in cells) + ".</p>")


def isolation_section_html(study_path: str | Path, vertical_summary_path: str | Path, page: str | Path | None,
                           base: str | Path) -> str:
    """The section's HTML; ``vertical_summary_path`` the in-plane part's summary, ``page`` the rendered notebook
    (None when not rendered), ``base`` the index's folder."""
    study_path, vertical_summary_path, base = Path(study_path), Path(vertical_summary_path), Path(base)
    document = json.loads(study_path.read_text(encoding="utf-8"))
    parts = ['<h1 id="isolation">A building on friction pendulums against the fixed base</h1>']
    statuses = [document[key] for key in ("pairs_status", "three_component_status") if document[key] != "ok"]
    if not document["available"]:
        parts.append("<p>No record: " + " ".join(html.escape(status) for status in statuses) + "</p>")
    else:
        settings = document["settings"]
        components = document["components"]
        parts.append(
            f"<p>A one-story building (m_s/m_b = {settings['mass_ratio']:g}, ζ = {settings['damping_ratio']:g}) on "
            f"friction pendulums, each horizontal component alone ({components['slammer']} components of the SLAMMER "
            f"library's station pairs, {components['three_component']} of the three-component stations). Per "
            "fixed-base period, the pendulum of the smallest median drift ratio (isolated / fixed base), with the "
            "median and 84th percentile over the records:</p><ul>")
        for cell in document["best"]:
            parts.append(
                f"<li>T = {cell['period']:g} s: R = {cell['radius']:g} m, μ = {cell['mu']:g}: drift ratio "
                f"{cell['drift_ratio_median']:.2f} (84 %: {cell['drift_ratio_p84']:.2f}), floor acceleration ratio "
                f"{cell['floor_acceleration_ratio_median']:.2f} ({cell['floor_acceleration_ratio_p84']:.2f}), "
                f"isolator displacement {cell['isolator_displacement_median']:.3f} m "
                f"({cell['isolator_displacement_p84']:.3f} m)</li>")
        parts.append("</ul>")
        parts.append(vertical_sentence(vertical_summary_path))
        parts.append(near_far_sentence(document["near_far"]))
        notes = [*statuses, document["far_field_status"]]
        parts.append("<p>" + " ".join(html.escape(note) for note in notes) + "</p>")
    links = [f'<a href="{relative_href(Path(page), base)}">the isolation page</a>'] if page else []
    links += [f'<a href="{relative_href(study_path.with_name(name), base)}">{name}</a>'
              for name in ("isolation_summary.csv", "isolation_near_far.csv", "isolation_cases.csv", "isolation.nc",
                           study_path.name)]
    links += [f'<a href="{relative_href(vertical_summary_path, base)}">{vertical_summary_path.name}</a>']
    parts.append(f"<p>See {', '.join(links)}.</p>")
    return "\n".join(parts)
