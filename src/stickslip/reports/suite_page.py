"""What ``stickslip isolation suite`` shows: its text table, its figure and its HTML page, all read from its document.

Nothing is computed here: every number comes from the command's ``--json``
document (:func:`stickslip.cli.isolation_suite.suite_document`).  The page,
``DIR/index.html`` beside ``DIR/suite_spectra.png`` and ``DIR/suite.json``,
loads nothing from the web.
"""

from __future__ import annotations

import html
import json
from pathlib import Path

from matplotlib.figure import Figure

from stickslip.plumbing.files import write_text_atomic
from stickslip.reports.index_page import STYLE
from stickslip.reports.plots import new_figure, save_figure

#: The bounds' column headings.
BOUND_WORDS = {"upper_bound": "upper bound", "lower_bound": "lower bound"}

#: The responses as the tables name them, with their units.
RESPONSE_WORDS = {"peak_displacement": ("D", "m", ".4f"), "base_shear_coefficient": ("V_b/W", "1", ".4f")}


def summary_lines(document: dict) -> list[str]:
    """The lines above the tables: the target, the isolator, the period range, the scaling and its check."""
    (low, high), (below, above) = document["period_range"], document["range_factors"]
    periods, friction, check = document["design_period"], document["friction"], document["spectrum_check"]
    shorter, longer = sorted((periods["upper_bound"], periods["lower_bound"]))
    count, statistic = document["suite_size"], document["statistic"]
    rule = (f"the mean over {count} pairs" if statistic == "mean" else
            f"the maximum over {count} pairs (fewer than {document['minimum_pairs_for_mean']}: the maximum, not the mean)")
    return [
        f"{document['code_title']} target: {document['target']} ({document['target_source']}), 5 % damping",
        f"{document['isolator']} R = {document['radius']:.4g} m, mu = {document['mu']:g} (upper bound "
        f"{friction['upper_bound']:.4g}, lower bound {friction['lower_bound']:.4g}), g = {document['g']:g} m/s2",
        f"T_M (ELF): nominal {periods['nominal']:.3f} s, upper bound {periods['upper_bound']:.3f} s, lower bound "
        f"{periods['lower_bound']:.3f} s; period range {below:g} x {shorter:.3f} = {low:.3f} s to {above:g} x "
        f"{longer:.3f} = {high:.3f} s ({check['clause']})",
        f"scaling: {document['scaling']}; average RotD100 / target over the range: smallest {check['smallest_ratio']:.4f} "
        f"at T = {check['at_period']:.3f} s: {'pass' if check['passed'] else 'FAIL'}",
        f"statistic: {rule}",
    ]


def pair_table(document: dict) -> tuple[list[str], list[list[str]]]:
    """The pairs' table: headings, and per pair its name, vertical, scale factor and responses at both bounds."""
    headings = ["pair", "vertical", "scale factor"]
    for name, (label, unit, _) in RESPONSE_WORDS.items():
        headings += [f"{label} {BOUND_WORDS[bound]} [{unit}]" for bound in BOUND_WORDS]
    rows = []
    for pair in document["pairs"]:
        row = [pair["name"], pair["vertical"] or "-", f"{pair['scale_factor']:.4f}"]
        for name, (_, _, form) in RESPONSE_WORDS.items():
            row += [format(pair[name][bound], form) for bound in BOUND_WORDS]
        rows.append(row)
    return headings, rows


def comparison_table(document: dict) -> tuple[list[str], list[list[str]]]:
    """The statistic beside the ELF values: headings (quantity, then the bounds) and rows."""
    statistic = document["statistic"]
    rows = []
    for name, (label, unit, form) in RESPONSE_WORDS.items():
        at = {bound: document["response"][bound][name] for bound in BOUND_WORDS}
        floor = at["upper_bound"]["floor"]
        rows += [[f"{label}, response history ({statistic}) [{unit}]", *(format(at[b]["statistic"], form) for b in at)],
                 [f"{label}, ELF [{unit}]", *(format(at[b]["elf"], form) for b in at)],
                 [f"{label} ratio, limit >= {floor:.2f}",
                  *(f"{'pass' if at[b]['passed'] else 'FAIL'} {at[b]['ratio']:.3f}" for b in at)],
                 [f"{label}, design value [{unit}]", *(format(at[b]["design_value"], form) for b in at)]]
    return ["", *BOUND_WORDS.values()], rows


def limits_note(document: dict) -> str:
    """What the limits under the comparison are, with their fractions of the ELF values."""
    floors = {name: document["response"]["upper_bound"][name]["floor"] for name in RESPONSE_WORDS}
    return (f"limits (ASCE 7-22 §17.6 as coded): the response history's D not less than "
            f"{floors['peak_displacement']:.2f} of the ELF D, its V_b not less than "
            f"{floors['base_shear_coefficient']:.2f} of the ELF V_b; the design value is the greater of the statistic "
            "and the limit; the runs have no torsion, so D is set against D_M")


def _aligned(headings: list[str], rows: list[list[str]]) -> list[str]:
    widths = [max(len(cell) for cell in column) for column in zip(headings, *rows)]
    return ["  ".join(cell.ljust(width) if index == 0 else cell.rjust(width)
                      for index, (cell, width) in enumerate(zip(line, widths))) for line in (headings, *rows)]


def suite_text(document: dict) -> str:
    """The command's text output: the summary, the pairs' table, and the statistic beside the ELF values."""
    return "\n".join([*summary_lines(document), "", *_aligned(*pair_table(document)), "",
                      *_aligned(*comparison_table(document)), limits_note(document)])


def plot_suite_spectra(document: dict) -> Figure:
    """Each pair's scaled RotD100 [g], their average and the target over T [s] (log axes), the range shaded."""
    figure, ax = new_figure(figsize=(7.5, 5.0))
    spectra = document["spectra"]
    for index, (pair, values) in enumerate(zip(document["pairs"], spectra["scaled_rotd100"])):
        ax.plot(spectra["periods"], values, color="0.6", lw=0.8, label="scaled pairs' RotD100" if index == 0 else None)
    ax.plot(spectra["periods"], spectra["average"], color="C0", lw=2.0, label=f"average of {len(document['pairs'])}")
    ax.plot(spectra["periods"], spectra["target"], color="k", lw=1.6, ls="--", label="target")
    ax.axvspan(*document["period_range"], color="C1", alpha=0.15, label="period range")
    ax.set(xscale="log", yscale="log", xlabel="period T [s]", ylabel="pseudo-spectral acceleration [g]",
           title=f"{document['code_title']}: suite scaled ({document['scaling']}), 5 % damping")
    ax.grid(True, which="both", linewidth=0.3)
    ax.legend(fontsize="small")
    return figure


#: The class of a table's first column, left-aligned text (the reports' style).
TEXT_CELL = ' class="text"'


def _html_table(headings: list[str], rows: list[list[str]]) -> str:
    head = "".join(f"<th>{html.escape(cell)}</th>" for cell in headings)
    body = "".join("<tr>" + "".join(f"<td{TEXT_CELL if index == 0 else ''}>{html.escape(cell)}</td>"
                                    for index, cell in enumerate(row)) + "</tr>" for row in rows)
    return f"<table><tr>{head}</tr>{body}</table>"


def suite_html(document: dict, figure: str, data: str) -> str:
    """The page: the summary, the figure (``figure``, a file beside the page), both tables and a link to ``data``."""
    title = f"{document['code_title']}: a suite of {document['suite_size']} pairs against the ELF design"
    return "\n".join([
        "<!DOCTYPE html>",
        f'<html lang="en"><head><meta charset="utf-8"><title>{html.escape(title)}</title>',
        f"<style>{STYLE}</style></head><body>",
        f"<h1>{html.escape(title)}</h1>",
        "<ul>" + "".join(f"<li>{html.escape(line)}</li>" for line in summary_lines(document)) + "</ul>",
        f'<p><img src="{html.escape(figure)}" alt="each pair\'s scaled RotD100, their average and the target, the '
        'period range shaded"></p>',
        "<h2>The statistic beside the ELF design</h2>", _html_table(*comparison_table(document)),
        f"<p>{html.escape(limits_note(document))}.</p>",
        "<h2>The pairs</h2>", _html_table(*pair_table(document)),
        f'<p>Every number on this page: <a href="{html.escape(data)}">{html.escape(data)}</a>.</p>',
        "</body></html>"])


def write_suite_page(document: dict, folder: str | Path, files: dict[str, str]) -> Path:
    """Write the figure, the document and the page (``files``: ``page``, ``figure``, ``document`` names) under
    ``folder``, each atomically; return the page's path."""
    folder = Path(folder)
    save_figure(plot_suite_spectra(document), folder / files["figure"])
    write_text_atomic(folder / files["document"], json.dumps(document, allow_nan=False, indent=1))
    write_text_atomic(folder / files["page"], suite_html(document, files["figure"], files["document"]))
    return folder / files["page"]
