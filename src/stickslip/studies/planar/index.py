"""The planar study's section of ``reports/index.html``, and the sentences its page shares with it.

:func:`planar_section_html` reads only what the workflow wrote in
``results/collections/{study}/planar/`` (``summary.json`` above all) and says,
at a glance: how many station pairs were swept and what was left unpaired,
how non-orthogonal and longitudinal/transverse components were taken, the
headline numbers (:func:`headline_items`), the figures, and links to the tables.
"""

from __future__ import annotations

import html
import json
from collections.abc import Mapping
from pathlib import Path

from stickslip.reports.links import relative_href, thumbnails_html

#: Tables of the study linked from the section.
TABLES = ("pairs.csv", "unpaired.csv", "pair_results.csv", "ratio_by_mu.csv", "relations.csv", "near_far.csv",
          "design.json", "summary.json")


def _spread(values: Mapping, digits: int = 2) -> str:
    """``median m (10-90 %: a-b)`` of a quantiles mapping (q10, q50, q90)."""
    return f"median {values['q50']:.{digits}f} (10-90 %: {values['q10']:.{digits}f} to {values['q90']:.{digits}f})"


def _keyed(quantiles: Mapping) -> dict:
    """design.json's quantiles (``"0.1"``, ``"0.5"``, ``"0.9"``) keyed as summary.json's (``q10``, ``q50``, ``q90``)."""
    return {f"q{round(float(key) * 100):02d}": value for key, value in quantiles.items()}


def pairing_sentences(summary: Mapping, study: str) -> list[str]:
    """What was paired and how (HTML, one sentence group per item)."""
    unpaired = summary["unpaired"]
    lines = [f"<b>{summary['pairs_formed']} station pairs</b> formed from the {summary['members']} records of the "
             f"{html.escape(study)} collection study (same event, same station, exactly two horizontal components, "
             f"one time step); {summary['pairs_studied']} slide in the plane on the grid and are studied"
             + (f", from {summary['events']} earthquakes." if summary["pairs_studied"] else ".")]
    if unpaired:
        lines.append(f"<b>{sum(unpaired.values())} records left unpaired</b>: " + "; ".join(
            f"{count} {html.escape(group)} ({html.escape(summary['unpaired_reasons'][group])})"
            for group, count in unpaired.items()) + " (each named in unpaired.csv).")
    for item in summary["pairs_not_read"]:
        lines.append(f"Not swept: {html.escape(item['pair'])} ({html.escape(item['reason'])}).")
    if summary["pairs_never_sliding"]:
        lines.append(f"{len(summary['pairs_never_sliding'])} pairs never slide in the plane on the grid: "
                     + ", ".join(html.escape(name) for name in summary["pairs_never_sliding"]) + ".")
    for item in summary["not_orthogonal"]:
        lines.append(f"{html.escape(item['pair'])}: components {item['separation']:g}° apart, not orthogonal; "
                     "resolved onto orthogonal axes (axis 1 along the first component, axis 2 = (a₂ − a₁·cos Δ)/sin Δ, "
                     "since each instrument records the projection of the horizontal acceleration on its own "
                     "direction).")
    if summary["taken_as_orthogonal"]:
        lines.append(f"{len(summary['taken_as_orthogonal'])} pairs are named longitudinal/transverse (L/T) with no "
                     "azimuth and are taken as orthogonal: " + ", ".join(html.escape(name) for name in
                                                                         summary["taken_as_orthogonal"]) + ".")
    padded = summary["padded"]
    if padded["pairs"]:
        lines.append(f"{padded['pairs']} pairs have components of different lengths: both are taken to start "
                     f"together and the shorter is padded with zeros at its end (ground at rest; at most "
                     f"{padded['largest_samples']:,} samples).")
    if summary["status"] != "ok":
        lines.append(f"<b>{html.escape(summary['status'][:1].upper() + summary['status'][1:])}.</b>")
    return lines


def _relation(summary: Mapping, key: str) -> str:
    fit = summary["relations"].get(key, {})
    if fit.get("status") != "ok":
        return f"no fit ({html.escape(str(fit.get('status')))})"
    return (f"μ_max = {fit['slope']:.4f}·x {fit['intercept']:+.4f} (x in m/s²; slope 95 % interval "
            f"{fit['slope_low']:.4f} to {fit['slope_high']:.4f}), Pearson r = {fit['pearson_r']:.2f} "
            f"[{fit['pearson_r_low']:.2f}, {fit['pearson_r_high']:.2f}], {fit['n']} points")


def headline_items(summary: Mapping, g: float) -> list[str]:
    """The headline numbers as HTML list items (none without a study)."""
    if summary.get("status") != "ok":
        return []
    items = [
        f"<b>R over the two components</b> at the plane's μ_max: {_spread(summary['ratio_components_at_mu_max_plane'])}"
        f"; R &gt; 1 for {summary['share_ratio_components_above_1']:.0%} of the pairs.",
        f"<b>R over every azimuth</b> (0-180° in steps of {summary['settings']['angles'][1] - summary['settings']['angles'][0]:g}°): "
        f"{_spread(summary['ratio_azimuths_at_mu_max_plane'])}; R &gt; 1 for "
        f"{summary['share_ratio_azimuths_above_1']:.0%}.",
    ]
    for mu, values in summary["ratio_by_mu"].items():
        if float(mu) == summary["settings"]["reference_mu"] and values["ratio_components_q50"] is not None:
            items.append(f"At μ = {mu} (the paper's recommendation): R over the components median "
                         f"{values['ratio_components_q50']:.2f}, 90th percentile {values['ratio_components_q90']:.2f}; "
                         f"over every azimuth median {values['ratio_azimuths_q50']:.2f}, 90th percentile "
                         f"{values['ratio_azimuths_q90']:.2f}.")
    ratio = summary["design"].get("components", {}).get("ratio_quantiles")
    items += [
        f"<b>μ_max in the plane / the larger of the components' μ_max</b>: "
        f"{_spread(summary['mu_max_plane_over_larger_component'])}; / the worst azimuth's: "
        f"{_spread(summary['mu_max_plane_over_worst_azimuth'])}. μ_max in the plane "
        f"{_spread(summary['mu_max_plane'], 4)}; worst azimuth {_spread(summary['mu_max_worst_azimuth'], 4)}.",
        f"<b>E_df,max in the plane / E_df,max of the worst azimuth</b>: "
        f"{_spread(summary['energy_ratio_plane_to_worst_azimuth'])}. The worst azimuth is neither component for "
        f"{summary['share_worst_azimuth_not_a_component']:.0%} of the pairs.",
        f"<b>μ_max against PGA in 2-D</b> (PGA of the vector, max |a(t)|): "
        f"{_relation(summary, 'mu_max_plane_vs_pga_plane')}; in 1-D on the same records (each component against its "
        f"own PGA): {_relation(summary, 'mu_max_components_vs_pga')}.",
        f"<b>μ_max against RMS in 2-D</b> (RMS of |a(t)| over the vector's 5-95 % duration): "
        f"{_relation(summary, 'mu_max_plane_vs_rms_plane')}; in 1-D: {_relation(summary, 'mu_max_components_vs_rms')}.",
        f"μ_max·g/PGA in 2-D: {_spread(summary['mu_max_plane_g_over_pga_plane'], 3)}"
        + (f"; in 1-D, each component against its own PGA: {_spread(_keyed(ratio), 3)}" if ratio else "") + ".",
    ]
    design = summary["design"].get("plane", {})
    overall = next((band for band in design.get("coverage", []) if band["pga_band"] == "all records"), None)
    if overall and overall["status"] == "ok":
        other = next((band for band in summary["design"].get("components", {}).get("coverage", [])
                      if band["pga_band"] == "all records" and band["status"] == "ok"), None)
        items.append(f"<b>One μ for all stations</b>: in the plane μ = {overall['design_mu']:g} reaches 90 % of "
                     f"E_df,max for {overall['share_design_mu']:.0%} of the pairs"
                     + (f" (1-D, components: μ = {other['design_mu']:g} for {other['share_design_mu']:.0%})"
                        if other else "") + f"; μ = {summary['settings']['reference_mu']:g} lies in the plane's "
                     f"near-optimal range for {overall['share_reference_in_range']:.0%}.")
    distance = summary["ratio_components_vs_rupture_distance"]
    pga = summary["ratio_components_vs_pga_plane"]
    if "rho" in pga:
        items.append(f"R against the vector's PGA: Spearman ρ = {pga['rho']:.2f} (p = {pga['p_value']:.2f}); against "
                     f"the rupture distance: ρ = {distance.get('rho', float('nan')):.2f} "
                     f"(p = {distance.get('p_value', float('nan')):.2f}). Near-fault against farther: "
                     + ("compared in near_far.csv." if summary["near_far_status"] == "ok" else
                        html.escape(summary["near_far_status"]) + "."))
    return items


def planar_section_html(planar_dir: str | Path, figures_dir: str | Path, page: str | Path, base: str | Path,
                        figure_alts: Mapping[str, str] | None = None) -> str:
    """The section's HTML; ``page`` is the study's rendered notebook, ``base`` the index's folder."""
    planar_dir, figures_dir, page, base = Path(planar_dir), Path(figures_dir), Path(page), Path(base)
    summary = json.loads((planar_dir / "summary.json").read_text(encoding="utf-8"))
    study = planar_dir.parent.name
    parts = ['<h1 id="planar">Beyond the paper: the block sliding in the plane</h1>',
             "<p>The paper's question in two dimensions: both horizontal components of each station at once, one "
             "friction force μ·m·g opposing the sliding velocity, beside each component alone and the pair turned "
             f'through every azimuth (<a href="{relative_href(page, base)}">the study\'s page</a>; assumptions in '
             "docs/planar.md).</p>"]
    parts += [f"<p>{line}</p>" for line in pairing_sentences(summary, study)]
    items = headline_items(summary, summary["settings"]["g"])
    if items:
        parts.append("<ul>" + "".join(f"<li>{item}</li>" for item in items) + "</ul>")
    figures = sorted(figures_dir.glob("*.png"))
    if figures:
        parts.append("<h2>Figures</h2><div>")
        parts.append(thumbnails_html(figures, base, figure_alts))
        parts.append("</div>")
    links = [f'<a href="{relative_href(planar_dir / name, base)}">{name}</a>' for name in TABLES
             if (planar_dir / name).is_file()]
    parts.append(f"<p>Tables: {', '.join(links)}.</p>")
    return "\n".join(parts)
