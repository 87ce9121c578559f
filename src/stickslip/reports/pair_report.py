"""The pair report notebook: a block sliding in the plane under two components of one station, as one page.

``stickslip report X Y --pair --out page.html`` renders
``stickslip/reports/notebooks/pair_report.ipynb`` (``notebooks/pair_report.ipynb``
of a checkout links to it) with :func:`stickslip.reports.record_report.render_report`:
E_df and the stroke against μ in the plane beside each component alone and
the turned axes, μ_max of each, the path of the block in the plane, the
ground acceleration's orbit against the friction circle, and the energy
ledger at one μ.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from pathlib import Path

from stickslip.constants import STANDARD_GRAVITY
from stickslip.records.components import component_label
from stickslip.records.pair import RecordPair
from stickslip.reports.planar_plots import axis_names
from stickslip.reports.record_report import ParameterError, check_positive, read_report_record, render_report

#: The notebook, shipped as package data.
NOTEBOOK = Path(__file__).resolve().parent / "notebooks" / "pair_report.ipynb"

#: The report's figures, ``{pair}_{name}.png``, and their alternative texts ({pair}: the pair's file-name stem).
FIGURES = {
    "energy_vs_mu": "{pair}: energy dissipated by friction against the friction ratio, in the plane and each "
                    "component alone",
    "stroke_vs_mu": "{pair}: largest distance of the block from its start against the friction ratio, in the plane "
                    "and each component alone",
    "path": "{pair}: path of the block in the plane relative to its base",
    "orbit": "{pair}: orbit of the ground acceleration and the friction circle",
    "ledger": "{pair}: energy input, dissipated and kinetic against time",
}


def figure_alts(pair: str) -> dict[str, str]:
    """The report's figure file names for ``pair`` (its name) and their alternative texts."""
    return {f"{pair}_{name}.png": alt.format(pair=pair) for name, alt in FIGURES.items()}


def turned_axis(pair: RecordPair, angle: float) -> str:
    """Where the axis turned by ``angle`` [degrees] from the first component towards the second points, in words.

    With the components' azimuths known (their names end with them: ``228``,
    ``TAK-090``, ``CHY080-N``; azimuths grow clockwise, as on a compass):
    "160° clockwise from 228 (azimuth 28°)"; without: "75° from L1 towards T1".
    """
    first, second = axis_names(pair)  # without azimuths the components are taken as a right angle apart
    if pair.azimuths is None:
        return f"{angle:g}° from {first} towards {second}"
    turn = "clockwise" if pair.separation > 0 else "counterclockwise"
    azimuth = (pair.azimuths[0] + math.copysign(angle, pair.separation)) % 360.0 + 0.0
    return f"{angle:g}° {turn} from {first} (azimuth {azimuth:g}°)"


def resolution_sentence(pair: RecordPair) -> str:
    """How a pair whose components are not a right angle apart is put on the plane's axes, as a sentence ('' if they are)."""
    if pair.orthogonal:
        return ""
    _, second = axis_names(pair)
    return (f" The components are {abs(pair.separation):g}° apart: the second axis of the plane, {second}, carries "
            "the acceleration resolved onto it, (a₂ − a₁·cos Δ)/sin Δ.")


def pair_label(pair: RecordPair) -> str:
    """``0° + 90°``, ``TAK-000 + TAK-090``: the pair's components as its page names them (else their record ids)."""
    return " + ".join(component_label(record.meta.component or record.meta.record_id)
                      for record in (pair.first, pair.second))


def pair_report_title(pair: RecordPair) -> str:
    """The page's title: ``Pair report: 0° + 90° (Gazli USSR, Karakyr)``, the components and, where they are known,
    the event and station."""
    where = ", ".join(filter(None, (pair.first.meta.event, pair.first.meta.station or pair.second.meta.station)))
    return f"Pair report: {pair_label(pair)}" + (f" ({where})" if where else "")


def read_report_pair(first, second, pad: bool = False, format=None, dt=None, units=None, g: float = STANDARD_GRAVITY,
                     any_pair: bool = False) -> RecordPair:
    """The pair of the files ``first`` and ``second`` (``pad``: the shorter padded; values in g converted with ``g``
    [m/s²]; ``any_pair``: not checked to be one station's two horizontal components); a mistake names ``-p``."""
    records = []
    for path in (first, second):
        if path is None:
            raise ParameterError("pass both components: -p first PATH -p second PATH")
        record, missing = read_report_record(path, format, dt, units, g, accept_zero=True)
        if missing:
            raise ParameterError(f"{path}: {missing}")
        records.append(record)
    return RecordPair.padded(*records, any_pair) if pad else RecordPair(*records, any_pair=any_pair)


def render_pair_report(parameters: Mapping) -> str:
    """The pair report for the notebook's ``parameters`` (``first``, ``second``, ``mu_start``, ...) as one HTML page."""
    for name in ("mu_case", "mass", "g"):
        if parameters.get(name) is not None:
            check_positive(parameters[name], f"-p {name}")
    return render_report(NOTEBOOK, parameters)
