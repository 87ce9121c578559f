"""``stickslip spectrum RECORD [--pair]``: the elastic response spectra of one component, or of a pair.

One record gives its pseudo-spectral acceleration PSA [g] and spectral
displacement SD [m]; two files with ``--pair`` (one station's two horizontal
components) give RotD100, RotD50, the geometric mean and the SRSS of the
pair (:mod:`stickslip.spectra`).  ``--damping`` is the oscillators' damping
ratio (0.05 unless given), ``--periods`` their periods [s].  A table on the
terminal, or ``--json`` (one object: ``periods`` [s], one list per measure
in g, the displacements in m, and their ``units``); ``--csv FILE`` writes the
same columns, ``--plot PNG`` the figure.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from stickslip.cli.pair_options import add_pair_options, motion_config, motion_kind_from_args, motions_from_args
from stickslip.cli.record_options import add_gravity_option, add_record_options
from stickslip.constants import DEFAULT_DAMPING
from stickslip.errors import StickslipError
from stickslip.plumbing.files import check_output_path


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "spectrum",
        help="elastic response spectra of a record (PSA, SD) or of a pair (RotD100, RotD50, geometric mean, SRSS)",
        description=(
            "The damped oscillator's pseudo-spectral acceleration [g] and spectral displacement [m] over its period, "
            "exact for the record taken linear between its samples; with --pair, the two horizontal components' "
            "RotD100, RotD50 (Boore 2010), geometric mean and SRSS. Definitions: docs/spectra.md."
        ),
    )
    parser.add_argument("paths", type=Path, nargs="+", metavar="RECORD",
                        help="a record file (with --pair: the station's two horizontal components)")
    add_record_options(parser)
    add_gravity_option(parser)
    add_pair_options(parser, "and give the pair's RotD100, RotD50, geometric mean and SRSS spectra")
    parser.add_argument("--damping", default=None, metavar="XI",
                        help=f"damping ratio of the oscillators [-], 0 <= xi < 1: 0.05 or 5%% (default {DEFAULT_DAMPING})")
    parser.add_argument("--periods", default=None, metavar="T1,T2,...",
                        help="oscillator periods [s], increasing, comma-separated (default: 100 from 0.01 s to 10 s, "
                             "evenly spaced in log T)")
    parser.add_argument("--json", action="store_true",
                        help="print one JSON object: the record(s), g [m/s2], damping, 'periods' [s], one list per "
                             "measure in g ('psa', or 'rotd100', 'rotd50', 'geomean', 'srss') and the spectral "
                             "displacements in m ('sd', or 'sd_rotd100', ...), named in its 'units' object")
    parser.add_argument("--csv", type=Path, default=None, metavar="FILE",
                        help="write the spectra to FILE, one row per period (the --json lists as columns)")
    parser.add_argument("--plot", type=Path, default=None, metavar="PNG",
                        help="draw the spectra (PSA [g] and SD [m] over T [s]) to the PNG file")
    parser.set_defaults(func=run)


def damping_from_text(text: str | None) -> float:
    """The damping ratio [-] of ``--damping`` (0.05 or 5%; :data:`~stickslip.constants.DEFAULT_DAMPING` without it)."""
    from stickslip.cli.quantities import DAMPING_RATIO, read_quantity

    if text is None:
        return DEFAULT_DAMPING
    damping = read_quantity(text, "--damping", DAMPING_RATIO)
    if not 0.0 <= damping < 1.0:
        raise StickslipError(f"--damping {text}: expected a damping ratio 0 <= xi < 1 (0.05 or 5%)")
    return damping


def periods_from_text(text: str | None) -> np.ndarray:
    """The periods [s] of ``--periods T1,T2,...`` (:data:`~stickslip.spectra.DEFAULT_PERIODS` without it)."""
    from stickslip.spectra import DEFAULT_PERIODS, checked_periods

    if text is None:
        return DEFAULT_PERIODS
    try:
        values = [float(item) for item in text.split(",")]
    except ValueError:
        raise StickslipError(f"--periods {text}: expected periods [s] separated by commas, e.g. 0.1,0.5,1,2") from None
    try:
        return checked_periods(values)
    except StickslipError as error:
        raise StickslipError(f"--{error}") from None


def displacement_key(measure: str) -> str:
    """The output's name of ``measure``'s spectral displacement: ``sd`` for one component's ``psa``, else
    ``sd_<measure>``."""
    from stickslip.spectra import COMPONENT_MEASURE

    return "sd" if measure == COMPONENT_MEASURE else f"sd_{measure}"


def columns(spectra, g: float) -> dict[str, list[float]]:
    """The output's lists: ``periods`` [s], each measure's PSA [g], then each measure's SD [m]."""
    lists = {"periods": spectra.periods.tolist()}
    lists.update({measure: (spectra.pseudo_acceleration(measure) / g).tolist() for measure in spectra.measures})
    lists.update({displacement_key(measure): spectra.displacements[measure].tolist() for measure in spectra.measures})
    return lists


def units(spectra) -> dict[str, str]:
    """The units of :func:`columns` and of ``g`` and ``damping``."""
    return {"g": "m s-2", "damping": "1", "periods": "s", **{measure: "g" for measure in spectra.measures},
            **{displacement_key(measure): "m" for measure in spectra.measures}}


def describe(motion) -> dict:
    """The record, or the pair's two records, as the output names them (id and source file)."""
    from stickslip.records.pair import RecordPair

    records = (motion.first, motion.second) if isinstance(motion, RecordPair) else (motion,)
    return {"records": [{"record": record.meta.record_id, "source": record.meta.source} for record in records]}


def format_table(lists: dict[str, list[float]], units_of: dict[str, str]) -> str:
    """The spectra as an aligned table, one row per period, each column titled with its units."""
    titles = [f"{name} [{units_of[name]}]" for name in lists]
    width = max(12, *map(len, titles))
    rows = ["  ".join(f"{title:>{width}}" for title in titles)]
    for row in zip(*lists.values()):
        rows.append("  ".join(f"{value:>{width}.5g}" for value in row))
    return "\n".join(rows)


def run(args) -> int:
    from stickslip.plumbing.files import write_csv_atomic
    from stickslip.records.process import record_name
    from stickslip.spectra import motion_spectra

    for path, what in ((args.csv, "the CSV table"), (args.plot, "the spectra's figure")):
        if path is not None:
            check_output_path(path, what)
    damping = damping_from_text(args.damping)
    periods = periods_from_text(args.periods)
    kind = motion_kind_from_args(args)
    motions = motions_from_args(args, kind)
    if len(motions) != 1:
        raise StickslipError(f"spectrum takes one record (or one pair with --pair), not {len(args.paths)} files")
    motion = motions[0]
    spectra = motion_spectra(motion, periods, damping)
    lists, units_of = columns(spectra, args.g), units(spectra)
    name = motion.name if kind == "pair" else record_name(motion)
    if args.csv is not None:
        titles = {key: f"{key} [{units_of[key]}]" for key in lists}
        write_csv_atomic(args.csv, [{titles[key]: value for key, value in zip(lists, row)} for row in zip(*lists.values())])
    if args.plot is not None:
        from stickslip.reports.plots import save_figure
        from stickslip.reports.spectrum_plots import plot_spectra

        save_figure(plot_spectra(spectra, args.g, f"{name}, damping {100 * damping:g} %"), args.plot)
    if args.json:
        print(json.dumps({**describe(motion), "g": args.g, "damping": damping, "read": motion_config(args), **lists,
                          "units": units_of},
                         allow_nan=False))
        return 0
    print(f"{name}  (damping {100 * damping:g} %, g = {args.g:g} m/s2)")
    print(format_table(lists, {key: units_of[key] for key in lists}))
    for path, what in ((args.csv, "spectra"), (args.plot, "figure")):
        if path is not None:
            print(f"{what} written to {path}")
    return 0
