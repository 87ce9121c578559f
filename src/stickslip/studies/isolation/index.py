"""The section of ``reports/index.html`` on the isolated building: the best pendulum per period, near-fault
against far-field, the plane against each component alone, and a link.

:func:`isolation_section_html` reads only ``isolation_study.json`` (:mod:`stickslip.studies.isolation.tables`), the
in-plane part's ``isolation_vertical_summary.csv`` (:mod:`stickslip.studies.isolation.with_vertical`) and the
library pairs' ``isolation_plane_pairs_summary.csv`` (:mod:`stickslip.studies.isolation.plane_pairs`).
"""

from __future__ import annotations

import html
import json
from pathlib import Path

from stickslip.plumbing.files import read_csv_rows
from stickslip.reports.links import relative_href

#: The in-plane ratios (with the vertical over without it) the index names, with their words.
VERTICAL_RATIOS = {"peak_drift_ratio": "drift", "base_shear_coefficient_ratio": "V_b/W"}
#: The library pairs' ratios (in the plane over the larger component alone) the index names, with their words.
PLANE_PAIR_RATIOS = {"peak_isolator_displacement_ratio": "isolator displacement", "peak_drift_ratio": "drift"}
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


def ratio_sentence(rows: list[dict], words: dict, lead: str) -> str:
    """One paragraph of ratios: per case (T, R) and μ, the median and 84th percentile of each of ``rows``'
    quantities named in ``words``, after ``lead`` (HTML) and the building where there is one; "" without rows."""
    if not rows:
        return ""
    by_case = {}
    for row in rows:
        by_case.setdefault((float(row["period"]), float(row["radius"]), float(row["mu"])), []).append(
            f"{words[row['quantity']]} {float(row['median']):.2f} (84 %: {float(row['p84']):.2f})")
    one_building = len({case[:2] for case in by_case}) == 1
    cells = [(f"μ = {mu:g}" if one_building else f"T = {period:g} s, R = {radius:g} m, μ = {mu:g}")
             + f": {', '.join(ratios)}" for (period, radius, mu), ratios in by_case.items()]
    period, radius, _ = next(iter(by_case))
    building = f" (T = {period:g} s, R = {radius:g} m)" if one_building else ""
    return (f"<p>{lead}{building}, median and 84th percentile: "
            + "; ".join(html.escape(cell) for cell in cells) + ".</p>")


def vertical_sentence(summary_path: Path) -> str:
    """One sentence on the in-plane part: per case (T, R) and μ, the median and 84th percentile of the drift and
    base shear ratios with the vertical over without it; "" without its rows (no three-component records)."""
    rows = [row for row in read_csv_rows(summary_path) if row["quantity"] in VERTICAL_RATIOS]
    stations = rows[0]["stations"] if rows else 0
    return ratio_sentence(rows, VERTICAL_RATIOS,
                          f"In the plane on the {stations} three-component stations, with the vertical over without it")


def plane_pairs_sentence(summary_path: Path) -> str:
    """One sentence on the library's station pairs in the plane: per case (T, R) and μ, over all pairs, the median
    and 84th percentile of the isolator displacement and drift in the plane over the larger component alone; ""
    without its rows (no library)."""
    rows = [row for row in read_csv_rows(summary_path)
            if row["group"] == "all" and row["quantity"] in PLANE_PAIR_RATIOS and int(row["pairs"])]
    pairs = max((int(row["pairs"]) for row in rows), default=0)
    return ratio_sentence(rows, PLANE_PAIR_RATIOS,
                          f"In the plane on {pairs} station pairs of the SLAMMER library, over the larger component "
                          "alone")


def isolation_section_html(study_path: str | Path, vertical_summary_path: str | Path, page: str | Path | None,
                           base: str | Path, plane_pairs_summary_path: str | Path | None = None) -> str:
    """The section's HTML; ``vertical_summary_path`` the in-plane part's summary, ``page`` the rendered notebook
    (None when not rendered), ``base`` the index's folder, ``plane_pairs_summary_path`` the library pairs' summary
    in the plane (None: not named)."""
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
        if plane_pairs_summary_path is not None:
            parts.append(plane_pairs_sentence(Path(plane_pairs_summary_path)))
        parts.append(near_far_sentence(document["near_far"]))
        notes = [*statuses, document["far_field_status"]]
        parts.append("<p>" + " ".join(html.escape(note) for note in notes) + "</p>")
    links = [f'<a href="{relative_href(Path(page), base)}">the isolation page</a>'] if page else []
    links += [f'<a href="{relative_href(study_path.with_name(name), base)}">{name}</a>'
              for name in ("isolation_summary.csv", "isolation_near_far.csv", "isolation_cases.csv", "isolation.nc",
                           study_path.name)]
    links += [f'<a href="{relative_href(Path(path), base)}">{Path(path).name}</a>'
              for path in (vertical_summary_path, plane_pairs_summary_path) if path is not None]
    parts.append(f"<p>See {', '.join(links)}.</p>")
    return "\n".join(parts)
