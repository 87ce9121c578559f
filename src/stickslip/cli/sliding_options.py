"""The options of ``solve`` and ``sweep`` that say how the block slides besides ``--mu``.

``--ky`` gives the yield coefficient k_y [1] instead of a friction ratio:
a bare number is k_y itself (``0.15``, as SLAMMER, pySLAMMER and Jibson's
tables write it), ``0.15g`` is the same; a number with an acceleration unit
(``1.47m/s2``, any spelling :func:`stickslip.units.normalise_units` knows) is
the yield acceleration k_y·g, divided by the command's g.  The block then slides
downslope only (``--direction down``, the default: Newmark's and SLAMMER's
rigid block) or both ways (``--direction both``, with ``--thrust-angle``
[degrees], SLAMMER's "downslope and upslope").  ``--inverse`` solves the
record with its sign flipped (SLAMMER's inverse polarity).

``--ky-table`` (``solve``) gives k_y as a function of the block's accumulated
downslope displacement (:class:`stickslip.solvers.yield_table.YieldTable`):
a text file of lines ``D_m ky``, or the pairs inline, ``0:0.15,0.1:0.10``.
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

from stickslip.cli.accelerations import in_units_of_g
from stickslip.errors import StickslipError
from stickslip.solvers.resistance import DIRECTIONS
from stickslip.solvers.yield_table import YieldTable

#: Help of ``--ky``, for one value.
KY_HELP = ("yield coefficient k_y [-] (0.15, the same as 0.15g), or a yield acceleration k_y*g with its unit "
           "(1.47m/s2): the block slides downslope when the ground acceleration exceeds k_y*g (one-way unless "
           "--direction both); instead of --mu")

#: Help of ``--ky-table``.
KY_TABLE_HELP = ("yield coefficient varying with the block's accumulated downslope displacement D (SLAMMER's "
                 "'varies with displacement', D in m, not cm): a text file of lines 'D ky' (D [m], k_y [-]; blanks "
                 "or a comma between, # comments) or the pairs inline, D:KY,D:KY (0:0.15,0.1:0.10); the first D is "
                 "0 and D increases, k_y > 0; linear between pairs, constant past the last; one-way, --method "
                 "slammer (a single pair is a constant k_y, any method); instead of --mu or --ky")


def add_sliding_options(parser: argparse.ArgumentParser) -> None:
    """Add ``--direction``, ``--thrust-angle`` and ``--inverse`` to ``parser`` (``--ky`` is the command's own)."""
    parser.add_argument(
        "--direction", choices=DIRECTIONS, default=None,
        help="with --ky: down (default: slides downslope only) or both (also upslope, past k_y*g + 2 g sin(thrust angle))",
    )
    parser.add_argument(
        "--thrust-angle", type=float, default=None, metavar="DEG",
        help="with --direction both: SLAMMER's thrust angle [degrees, 0 to 90] (default 0)",
    )
    parser.add_argument(
        "--inverse", action="store_true",
        help="solve the record with its sign flipped (SLAMMER's inverse polarity)",
    )


def sliding_options(args: argparse.Namespace, has_ky: bool) -> dict:
    """``direction`` and ``thrust_angle`` for the library, checked against ``--ky``; one-line errors."""
    if not has_ky and args.direction is not None:
        raise StickslipError("--direction applies with --ky only (a friction ratio --mu slides both ways on a flat surface)")
    if args.thrust_angle is not None and args.direction != "both":
        raise StickslipError("--thrust-angle applies to --direction both only (one-way sliding has no thrust angle)")
    if args.thrust_angle is not None and not 0.0 <= args.thrust_angle <= 90.0:
        raise StickslipError(f"--thrust-angle {args.thrust_angle:g}: expected an angle from 0 to 90 degrees")
    return {key: value for key, value in (("direction", args.direction), ("thrust_angle", args.thrust_angle))
            if value is not None}


def parse_yield_coefficient(text: str, g: float, option: str = "--ky") -> float:
    """k_y [1] from ``"0.15"`` or ``"0.15g"`` (k_y itself) or ``"1.47m/s2"`` (k_y·g [m/s²], divided by ``g`` [m/s²]).

    A bare number above 1 gives a warning (a yield acceleration above 1 g; the
    number may be in other units: :func:`~stickslip.cli.accelerations.in_units_of_g`).
    """
    value = in_units_of_g(text, g, option, "0.15", largest=1.0)
    if not (math.isfinite(value) and value > 0.0):
        raise StickslipError(f"{option} {text!r}: the yield coefficient must be a positive finite number")
    return value


def parse_yield_table(text: str) -> YieldTable:
    """The ``--ky-table`` of a file, or of pairs ``D:KY,D:KY`` inline when no such file exists; one-line errors."""
    if ":" in text and not Path(text).exists():
        return YieldTable.parse(text, f"--ky-table {text!r}")
    return YieldTable.read(text)
