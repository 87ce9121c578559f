"""The section of ``reports/index.html`` on Jibson (2007), recomputed: our coefficients beside his, and a link.

:func:`jibson_section_html` reads only the fit document that
:mod:`stickslip.studies.jibson2007.fit` wrote.
"""

from __future__ import annotations

import html
import json
from collections.abc import Mapping
from pathlib import Path

from stickslip.estimates.jibson import FORM_TERMS
from stickslip.reports.links import relative_href

#: How the section names each form.
FORM_NAMES = {"critical_acceleration_ratio": "form 1, log D_n on a_c/a_max",
              "arias_intensity_and_ratio": "form 2, log D_n on I_a and a_c/a_max"}


def _value(value: Mapping) -> str:
    if value["low"] is None:
        return f"{value['value']:.3f}"
    return f"{value['value']:.3f} [{value['low']:.3f}, {value['high']:.3f}]"


def _form_item(form: str, fit: Mapping, printed: Mapping) -> str:
    if fit["status"] != "ok":
        return f"<li>{FORM_NAMES[form]}: no fit: {html.escape(fit['status'])}.</li>"
    terms = ", ".join(f"{term} {_value(fit['coefficients'][term])} (Jibson {printed['coefficients'][term]:.3f})"
                      for term in FORM_TERMS[form])
    return (f"<li>{FORM_NAMES[form]}: {html.escape(terms)}; σ {_value(fit['sigma'])} (Jibson {printed['sigma']:.3f}); "
            f"R² {fit['r_squared']:.3f}; {fit['rows']} rows of {fit['records']} records.</li>")


def jibson_section_html(fit_path: str | Path, page: str | Path | None, base: str | Path) -> str:
    """The section's HTML; ``page`` is the rendered notebook (None when not rendered), ``base`` the index's folder."""
    fit_path, base = Path(fit_path), Path(base)
    document = json.loads(fit_path.read_text(encoding="utf-8"))
    reference, collection, settings = document["reference"], document["collection"], document["settings"]
    grid = ", ".join(f"{value:g}" for value in settings["critical_accelerations_g"])
    parts = ['<h1 id="jibson2007">Jibson (2007), recomputed</h1>',
             f"<p>Jibson's two regression forms refitted on one-way displacements D_n [cm] of the collection's "
             f"{collection['records_solved']} records ({collection['events']} events; Jibson: "
             f"{reference['data']['records']} records of {reference['data']['earthquakes']} earthquakes), a_c = {grid} g "
             f"where a_c &lt; PGA, both polarities, exact solver. Coefficients with 95 % bootstrap intervals over "
             f"records ({settings['n_boot']} resamples), Jibson's printed values in brackets after ours.</p>"]
    for selection, result in document["selections"].items():
        floor = result["displacement_floor_cm"]
        excluded = "; ".join(f"{count} {html.escape(reason)}" for reason, count in result["excluded_rows"].items() if count)
        parts.append(f"<h3>{'D_n ≥ %g cm (our floor)' % floor if floor is not None else 'Every D_n &gt; 0'}: "
                     f"{result['rows']} rows enter; left out: {excluded or 'none'}</h3><ul>")
        parts += [_form_item(form, fit, reference["forms"][form]) for form, fit in result["forms"].items()]
        parts.append("</ul>")
    links = [f'<a href="{relative_href(Path(page), base)}">the Jibson (2007) page</a>'] if page else []
    links += [f'<a href="{relative_href(fit_path.with_name(name), base)}">{name}</a>'
              for name in ("jibson2007_displacements.csv", fit_path.name)]
    parts.append(f"<p>See {', '.join(links)}.</p>")
    return "\n".join(parts)
