"""The motion a command solves: each file alone, with ``--pair`` the files two by two, with ``--vertical`` its vertical.

``stickslip solve X.AT2 Y.AT2 --pair --mu 0.1`` slides the block in the plane
under both components; several pairs are given one after another (X1 Y1 X2
Y2 ...).  The two files of a pair must have the same time step and, unless
``--pad`` pads the shorter with zeros at its end, the same number of
samples; where their metadata name events or stations (SLAMMER's
``TAK-000`` and ``TAK-090``), those must agree.  A pair is scaled by a factor
(``--scale``), not to a PGA: its two components have one PGA each.

``--vertical FILE`` gives the vertical component of the station of one
record (or one pair): the normal force on a slider is then m·(g + a_v)
(:class:`~stickslip.records.vertical.WithVertical`).  Which way the file's
positive axis points is read from its component label (``UP``, ``DWN``), or
given with ``--vertical-positive up|down``; ``--pad`` pads it too.
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np

from stickslip.cli.grid_values import parse_pga
from stickslip.cli.model_options import gravity
from stickslip.cli.record_options import read_records_from_args
from stickslip.errors import StickslipError
from stickslip.records.pair import RecordPair
from stickslip.records.process import scale, scale_to_pga


def add_pair_options(parser: argparse.ArgumentParser) -> None:
    """Add ``--pair`` and ``--pad`` to ``parser``."""
    group = parser.add_argument_group("two components of one station (--pair)")
    group.add_argument("--pair", action="store_true",
                       help="take the files two by two as the two horizontal components of one station (X Y [X Y ...]) "
                            "and slide the block in the plane under both: one friction force mu*m*g opposing the "
                            "sliding velocity")
    group.add_argument("--pad", action="store_true",
                       help="with --pair: pad the shorter component of a pair with zeros at its end (components of "
                            "library records are often trimmed to slightly different lengths)")


def add_vertical_options(parser: argparse.ArgumentParser) -> None:
    """Add ``--vertical FILE`` and ``--vertical-positive up|down`` to ``parser``."""
    group = parser.add_argument_group("the vertical ground motion (--vertical)")
    group.add_argument("--vertical", type=Path, default=None, metavar="FILE",
                       help="the vertical component of the same station (one record, or one pair with --pair): the "
                            "normal force is m (g + a_v), and where g + a_v <= 0 the slider lifts off; same dt and "
                            "length as the horizontal record(s), or --pad")
    group.add_argument("--vertical-positive", choices=("up", "down"), default=None,
                       help="which way the vertical file's positive axis points (default: read from its component "
                            "label, UP or DWN; a file whose label does not tell needs it)")


def add_angle_option(parser: argparse.ArgumentParser) -> None:
    """Add ``--angles STEP`` (the azimuth sweep of ``sweep --pair``)."""
    parser.add_argument("--angles", type=float, metavar="STEP",
                        help="with --pair: also turn each pair's axes every STEP degrees through 0-180 (and always 90) "
                             "and solve the 1-D block on the turned axis (the RotD idea applied to the block; 5 gives "
                             "36 azimuths)")


def angles_from_args(args: argparse.Namespace) -> np.ndarray | None:
    """The azimuths [degrees] of ``--angles STEP`` (:func:`stickslip.models.planar.sweep.azimuths`), or None; one-line errors."""
    if args.angles is None:
        return None
    if not args.pair:
        raise StickslipError("--angles applies with --pair (it turns the two components of a pair)")
    if not (math.isfinite(args.angles) and 0.0 < args.angles <= 90.0):
        raise StickslipError(f"--angles {args.angles:g}: expected a step in degrees, 0 < STEP <= 90")
    from stickslip.models.planar.sweep import azimuths

    return azimuths(args.angles)


def motion_kind_from_args(args: argparse.Namespace) -> str:
    """``"pair"`` with ``--pair``, else ``"component"`` (:data:`stickslip.models.MOTIONS`); ``--pad`` alone is refused."""
    if getattr(args, "pad", False) and not (args.pair or getattr(args, "vertical", None) is not None):
        raise StickslipError("--pad applies with --pair (two components of one station) or --vertical")
    if getattr(args, "vertical_positive", None) is not None and getattr(args, "vertical", None) is None:
        raise StickslipError("--vertical-positive applies with --vertical only")
    return "pair" if args.pair else "component"


def has_vertical(args: argparse.Namespace) -> bool:
    """Whether the command was given a vertical component (``--vertical``)."""
    return getattr(args, "vertical", None) is not None


def pairs_from_args(args: argparse.Namespace, factor: float | None = None) -> list[RecordPair]:
    """The record pairs of ``args.paths`` taken two by two (``--pad``: the shorter component padded), each
    multiplied by ``factor`` [1] when given (``--scale``); one-line errors."""
    records = read_records_from_args(args.paths, args)
    if len(records) % 2:
        raise StickslipError(f"--pair takes the record files two by two (X Y [X Y ...]), but {len(records)} "
                             f"{'was' if len(records) == 1 else 'were'} given")
    build = RecordPair.padded if args.pad else RecordPair
    pairs = [build(records[index], records[index + 1]) for index in range(0, len(records), 2)]
    return pairs if factor is None else [pair.scaled(factor) for pair in pairs]


def motions_from_args(args: argparse.Namespace, kind: str, factor: float | None = None,
                      target_pga: str | None = None) -> list:
    """The records, or the pairs, of ``args.paths``, multiplied by ``factor`` [1] or scaled to ``target_pga``
    (text: in units of g, or with its unit); one-line errors."""
    if has_vertical(args):
        return [with_vertical(args, kind, factor, target_pga)]
    if kind == "pair":
        if target_pga is not None:
            raise StickslipError("--target-pga scales one component to a PGA; scale a pair (--pair) with --scale")
        return pairs_from_args(args, factor)
    records = read_records_from_args(args.paths, args)
    if factor is not None:
        return [scale(record, factor) for record in records]
    if target_pga is not None:
        pga = parse_pga(target_pga, gravity(args))
        return [scale_to_pga(record, pga) for record in records]
    return records


def with_vertical(args: argparse.Namespace, kind: str, factor: float | None, target_pga: str | None):
    """The one record (or pair) of ``args.paths`` with the vertical of ``--vertical``, each scaled by ``factor`` [1]."""
    from stickslip.cli.record_options import read_record_from_args, record_files
    from stickslip.records.vertical import WithVertical

    files = record_files(args.paths)
    if len(files) != (2 if kind == "pair" else 1):
        raise StickslipError(f"--vertical {args.vertical} is the vertical of one station: give one record "
                             f"(or one pair with --pair), not {len(files)} files")
    if target_pga is not None:
        raise StickslipError("--target-pga scales one component to a PGA; scale a motion with its vertical with --scale")
    horizontal = pairs_from_args(args)[0] if kind == "pair" else read_record_from_args(files[0], args)
    vertical = read_record_from_args(args.vertical, args)
    if factor is not None:
        horizontal = horizontal.scaled(factor) if kind == "pair" else scale(horizontal, factor)
        vertical = scale(vertical, factor)
    return WithVertical.of(horizontal, vertical, args.vertical_positive, pad=args.pad)
