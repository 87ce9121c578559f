"""``stickslip displacements PATH... --ky 0.05,0.1,0.15``: Newmark's D_n table for slope engineers.

For each record and yield coefficient k_y: the permanent downslope
displacement D_n [cm] of a rigid block sliding one way, in SLAMMER's normal
and inverse polarities and their mean, with Jibson's (2007) empirical
estimates beside it; then, per k_y, the mean, median and standard deviation
over the records, the vertical components among them left out and named
(:mod:`stickslip.slope_displacements`).  As a table,
``--json`` (one object) or ``--csv FILE`` (one row per record and k_y, and the
statistics in ``FILE`` with ``_statistics`` before the suffix).  The yield
coefficients come from ``--ky`` or, for an infinite slope, from ``--fs`` and
``--slope-angle`` (:mod:`stickslip.cli.slope_options`); ``--g`` takes its
unit (``9.81m/s2``), and a bare number outside the usual gets a warning.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

from stickslip.cli.quantities import read_gravity
from stickslip.cli.record_options import add_keep_going_option, add_record_options, read_records_from_args
from stickslip.cli.slope_options import INFINITE_SLOPE, add_slope_options, yield_coefficients
from stickslip.constants import STANDARD_GRAVITY
from stickslip.plumbing.files import check_output_path, write_csv_atomic
from stickslip.records.verticals_apart import left_out_line
from stickslip.units import UNITS

#: The yield coefficients when none are given: the critical accelerations of Jibson's (2007) regressions [g].
DEFAULT_KY = "0.02,0.05,0.1,0.2,0.3,0.4"

#: The schemes this table offers: SLAMMER's own, or the exact one.
METHODS = ("exact", "slammer")


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "displacements",
        help="Newmark's permanent displacement D_n [cm] per record and k_y, both polarities, with statistics "
             "and Jibson (2007)",
        description=(
            "Solve the rigid block sliding one way (downslope, past k_y*g) on each record at each yield coefficient "
            "k_y, with the record as given (normal) and with its sign flipped (inverse), and print the permanent "
            "displacement D_n [cm] of each and their mean, as SLAMMER's results table gives them; beside each, "
            "Jibson's (2007) empirical estimates from the record's PGA (a_c/a_max form) and Arias intensity (I_a "
            "form); then the mean, median and standard deviation over the records at each k_y."
        ),
    )
    parser.add_argument("paths", type=Path, nargs="+", metavar="path", help="record files (formats may mix)")
    add_slope_options(parser, "yield coefficients k_y [-]: a comma list (0.05,0.1,0.15) or START:STOP:STEP, each a "
                              "number in g (0.15), a percentage of g (15%%) or a yield acceleration k_y*g with its unit "
                              "(1.47m/s2); the default is Jibson's (2007) critical accelerations", default_ky=DEFAULT_KY)
    parser.add_argument("--method", choices=METHODS, default="exact",
                        help="exact (default: event-driven, no time-step error) or slammer (SLAMMER 1.1's own "
                             "trapezoid stepping)")
    parser.add_argument("--g", default=STANDARD_GRAVITY,
                        help=f"gravity [m/s2]: 9.81 or 9.81m/s2 (default {STANDARD_GRAVITY}; SLAMMER's is 9.80665)")
    add_record_options(parser)
    add_keep_going_option(parser)
    output = parser.add_mutually_exclusive_group()
    output.add_argument("--json", action="store_true",
                        help="print one JSON object: settings, units, one row per record and k_y, the statistics")
    parser.add_argument("--csv", type=Path, default=None, metavar="FILE",
                        help="write one row per record and k_y to FILE, and the statistics to FILE_statistics.csv")
    parser.set_defaults(func=run)


def statistics_path(path: Path) -> Path:
    """Where ``--csv FILE`` writes the statistics: ``FILE`` with ``_statistics`` before its suffix."""
    return path.with_name(f"{path.stem}_statistics{path.suffix or '.csv'}")


def run(args) -> int:
    from stickslip.slope_displacements import ROW_COLUMNS, STATISTIC_COLUMNS, slope_displacements

    args.g = read_gravity(args.g)
    ky, slope = yield_coefficients(args, args.g)
    if args.csv is not None:
        check_output_path(args.csv, "the CSV table")
        check_output_path(statistics_path(args.csv), "the CSV table of statistics")
    records = read_records_from_args(args.paths, args)
    table = slope_displacements(records, ky, g=args.g, method=args.method)
    rows, statistics = table.rows(), table.statistic_rows()
    if args.csv is not None:
        write_csv_atomic(args.csv, [_cells(row) for row in rows], list(ROW_COLUMNS))
        write_csv_atomic(statistics_path(args.csv), [_cells(row) for row in statistics], list(STATISTIC_COLUMNS))
    if args.json:
        document = {"settings": {"ky": table.ky.tolist(), "g": table.g, "method": table.method,
                                 "direction": "down", "jibson2007_sigma_log10_cm": table.jibson_sigma,
                                 "slope": slope},
                    "units": {name: UNITS[name] for name in (*ROW_COLUMNS, *STATISTIC_COLUMNS) if name in UNITS},
                    "records": [_cells(row) for row in rows], "statistics": [_cells(row) for row in statistics],
                    "left_out_of_statistics": table.apart[1]}
        print(json.dumps(document, allow_nan=False))
    else:
        print(format_table(table, slope))
        if args.csv is not None:
            print(f"\ntables written to {args.csv} and {statistics_path(args.csv)}")
    return 0


def _cells(row: dict) -> dict:
    """``row`` with NaN as None (an empty CSV cell, JSON null)."""
    return {name: None if isinstance(value, float) and math.isnan(value) else value for name, value in row.items()}


def _number(value: float, digits: int = 4) -> str:
    return "-" if math.isnan(value) else f"{value:.{digits}g}"


def format_table(table, slope: dict | None = None) -> str:
    """The terminal output: the settings, one line per record and k_y, the statistics, the notes; ``slope`` the
    factor of safety and slope angle [degrees] that gave k_y, if they did."""
    lines = [f"Newmark displacement D_n [cm]: rigid block sliding one way (downslope past k_y*g), "
             f"{table.method} solver, g = {table.g:g} m/s2"]
    if slope is not None:
        lines.append(_slope_line(slope, float(table.ky[0])))
    lines.append("")
    width = max(len("record"), *(len(name) for name in table.records))
    header = (f"{'':<{width}}  {'ky':>6}  {'a_c/a_max':>9}  {'D_n normal':>10}  {'D_n inverse':>11}  {'D_n mean':>9}"
              f"  {'Jibson (2007)':>14}  {'Jibson (2007)':>14}")
    units = (f"{'record':<{width}}  {'[-]':>6}  {'[-]':>9}  {'[cm]':>10}  {'[cm]':>11}  {'[cm]':>9}"
             f"  {'a_c/a_max [cm]':>14}  {'I_a form [cm]':>14}")
    lines += [header, units]
    for row in table.rows():
        lines.append(f"{row['record']:<{width}}  {row['ky']:>6g}  {_number(row['critical_acceleration_ratio'], 3):>9}"
                     f"  {_number(row['newmark_displacement_normal']):>10}"
                     f"  {_number(row['newmark_displacement_inverse']):>11}"
                     f"  {_number(row['newmark_displacement_mean']):>9}"
                     f"  {_number(row['jibson2007_ratio'], 3):>14}  {_number(row['jibson2007_arias'], 3):>14}")
    found = table.statistics()
    included, apart = table.apart
    counted = int(included.sum())
    groups = (("normal", "D_n normal [cm]"), ("inverse", "D_n inverse [cm]"), ("mean", "D_n mean [cm]"))
    lines += ["", f"over the {counted} record{'s' if counted != 1 else ''}"
                  f"{' (the horizontal components)' if apart else ''}:",
              f"{'':>6}" + "".join(f"  {label:^26}" for _, label in groups),
              f"{'ky':>6}" + "".join(f"  {'mean':>8}{'median':>9}{'std':>9}" for _ in groups)]
    for j, ky in enumerate(table.ky):
        lines.append(f"{ky:>6g}" + "".join(
            f"  {_number(found['mean'][name][j]):>8}{_number(found['median'][name][j]):>9}"
            f"{_number(found['std'][name][j]):>9}" for name, _ in groups))
    lines += [line for line in (left_out_line(apart),) if line]
    sigma = table.jibson_sigma
    lines += ["", "normal: the record as given; inverse: its sign flipped (SLAMMER's polarities); std: sample standard "
                  "deviation (n - 1)",
              "Jibson (2007): median estimates of his regressions with his printed coefficients, a_c/a_max form "
              f"(sigma {sigma['critical_acceleration_ratio']:g} in log10 cm) and I_a form (sigma "
              f"{sigma['arias_intensity_and_ratio']:g}), a_max the record's PGA; '-' where a_c >= a_max (D_n = 0)"]
    return "\n".join(lines)


def _slope_line(slope: dict, ky: float) -> str:
    """``k_y 0.25 from F = 1.5 and alpha = 30 degrees: k_y = (F - 1) sin(alpha), ...``."""
    return (f"k_y {ky:.4g} from F = {slope['factor_of_safety']:g} and alpha = {slope['slope_angle']:g} degrees: "
            f"{INFINITE_SLOPE}")
