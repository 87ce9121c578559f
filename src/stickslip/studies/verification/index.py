"""The verification's section of ``reports/index.html``: pass counts against SLAMMER 1.1's own results, and a link.

:func:`verification_section_html` reads only the summary that
:mod:`stickslip.studies.verification.slammer` wrote.  Without the reference
data it says so plainly, and how to get them.
"""

from __future__ import annotations

import html
import json
from pathlib import Path

from stickslip.reports.links import relative_href

#: How the section names each scheme.
SCHEME_NAMES = {"slammer": "SLAMMER's scheme (<code>slammer</code>)", "exact": "the exact solver (<code>exact</code>)"}


def _scheme_item(name: str, result: dict) -> str:
    polarities = ", ".join(f"{polarity} {group['passed']} of {group['analyses']} (slope {group['slope']:.5f}, "
                           f"intercept {group['intercept']:+.4f} cm, R² {group['r_squared']:.7f})"
                           for polarity, group in result["polarities"].items() if "slope" in group)
    verdict = "the group rules are met" if result["passes"] else "<b>the group rules are not met</b>"
    return (f"<li>{SCHEME_NAMES.get(name, html.escape(name))}: <b>{result['passed']} of {result['analyses']}</b> "
            f"within tolerance; {html.escape(polarities)}; {verdict}.</li>")


def flexible_html(flexible_path: Path, base: Path) -> str:
    """The flexible analyses' lines: per scheme and group the values within tolerance and the misses explained."""
    summary = json.loads(flexible_path.read_text(encoding="utf-8"))
    if summary["status"] != "ok":
        return ""
    items = []
    for scheme, groups in summary["schemes"].items():
        counts = "; ".join(f"{html.escape(name)} <b>{group['passed']:,} of {group['analyses']:,}</b>"
                           f"{' (group rules met)' if group['passes'] else ' (<b>group rules not met</b>)'}, "
                           + (f"{group['explained']} of {len(group['misses'])} misses explained" if group["misses"]
                              else "no misses")
                           for name, group in groups.items())
        items.append(f"<li>{SCHEME_NAMES.get(scheme, html.escape(scheme))}: {counts}.</li>")
    explanations = "; ".join(f"{scheme}: {html.escape(text)}" for scheme, text in summary["explanations"].items())
    return (f"<p>The flexible sliding block: SLAMMER 1.1's {summary['source']['flexible_analyses']:,} decoupled and "
            f"coupled analyses, each in both polarities, by the same rules and SLAMMER's scaling (a miss is explained "
            f"when {explanations}; "
            f'<a href="{relative_href(flexible_path, base)}">{flexible_path.name}</a>):</p><ul>'
            + "".join(items) + "</ul>")


def verification_section_html(summary_path: str | Path, page: str | Path | None, base: str | Path,
                              flexible_path: str | Path | None = None) -> str:
    """The section's HTML; ``page`` is the verification's rendered notebook (None when not rendered), ``base`` the
    index's folder, ``flexible_path`` the flexible analyses' summary."""
    summary_path, base = Path(summary_path), Path(base)
    summary = json.loads(summary_path.read_text(encoding="utf-8"))
    parts = ['<h1 id="verification">Verification against SLAMMER 1.1\'s own results</h1>']
    if summary["status"] != "ok":
        parts.append(f"<p><b>Not run: the verification data are not here</b>: {html.escape(summary['reason'])}. "
                     f"{html.escape(summary['how_to_get'])}</p>")
        return "\n".join(parts)
    source, rules = summary["source"], summary["rules"]
    parts.append(f"<p>SLAMMER 1.1's {source['rigid_analyses']} rigid analyses on pyslammer's {source['motions']} "
                 "sample motions, each in normal and inverse polarity, recomputed by both schemes and judged by "
                 f"pySLAMMER's acceptance rules (above {rules['small_displacement']:g} cm within "
                 f"{rules['relative_tolerance']:.0%} and {rules['absolute_tolerance']:g} cm, else within "
                 f"{rules['small_tolerance']:g} cm; at least {rules['pass_rate']:.0%} passing; per polarity a line of "
                 f"slope 1 ± {rules['slope_tolerance']:g}, intercept within {rules['intercept_tolerance']:g} cm, "
                 f"R² ≥ {rules['min_r_squared']:g}):</p><ul>")
    parts += [_scheme_item(name, result) for name, result in summary["schemes"].items()]
    parts.append("</ul>")
    check = summary["convergence"]
    steps = " and ".join(f"dt/{k}" for k in check["refinements"])
    if check["misses"]:
        parts.append(f"<p>The exact solver's {check['misses']} analyses beyond tolerance: <b>{check['explained']} "
                     f"of {check['misses']} explained</b> by SLAMMER's time step (SLAMMER's scheme on the record "
                     f"resampled to {steps} converges to the exact answer).</p>")
    else:
        parts.append("<p>The exact solver is within tolerance on every analysis: no miss to explain.</p>")
    if flexible_path is not None:
        parts.append(flexible_html(Path(flexible_path), base))
    links = [f'<a href="{relative_href(Path(page), base)}">the verification\'s page</a>'] if page else []
    links += [f'<a href="{relative_href(summary_path.with_name(name), base)}">{name}</a>'
              for name in ("slammer_analyses.csv", "slammer_convergence.csv", summary_path.name)]
    parts.append(f"<p>See {', '.join(links)}.</p>")
    return "\n".join(parts)
