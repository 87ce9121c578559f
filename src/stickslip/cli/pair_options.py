"""The motion a command solves: each file alone, with ``--pair`` the files two by two, with ``--vertical`` its vertical.

``stickslip solve X.AT2 Y.AT2 --pair --mu 0.1`` slides the block in the plane
under both components; several pairs are given one after another (X1 Y1 X2
Y2 ...).  The two files of a pair must have the same time step and, unless
``--pad`` pads the shorter with zeros at its end, the same number of
samples.  They must be one station's two horizontal components: a vertical
component, or two files whose headers, names or manifests give different
events or stations (:func:`stickslip.records.pair.pair_doubt`), are refused
in one line, unless ``--any-pair`` pairs them all the same; the command then
says so (a note on stderr, and in its output: :func:`pair_fields`,
:func:`motion_notes`).  One component may be zero throughout (a uniaxial
test), not both.  A pair is scaled by a factor (``--scale``), not to a PGA:
its two components have one PGA each.

``--vertical FILE`` gives the vertical component of the station of one
record (or one pair): the normal force on a slider is then m·(g + a_v)
(:class:`~stickslip.records.vertical.WithVertical`).  Which way the file's
positive axis points is read from its component label (``UP``, ``DWN``), or
given with ``--vertical-positive up|down``; ``--pad`` pads it too.  A file
that is not the same station's vertical (a horizontal direction, another
event or station: :func:`stickslip.records.vertical.vertical_doubt`) is
refused in one line, unless ``--any-vertical`` takes it all the same, and
then the output says so.
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

import numpy as np

from stickslip.cli.grid_values import parse_pga
from stickslip.cli.model_options import gravity
from stickslip.cli.quantities import of_unit, quantity_type
from stickslip.cli.record_options import (
    read_records_from_args,
    read_settings,
    unread_files,
)
from stickslip.errors import StickslipError
from stickslip.records.pair import RecordPair
from stickslip.records.process import record_name, scale, scale_to_pga


#: What ``--pair`` does in the commands that solve a model.
SLIDE_PAIR = ("and slide the block in the plane under both: one friction force mu*m*g opposing the sliding "
              "velocity")


def add_pair_options(parser: argparse.ArgumentParser, use: str = SLIDE_PAIR) -> None:
    """Add ``--pair``, ``--pad`` and ``--any-pair`` to ``parser``; ``use`` says in ``--pair``'s help what the command
    does with a pair."""
    group = parser.add_argument_group("two components of one station (--pair)")
    group.add_argument("--pair", action="store_true",
                       help="take the files two by two as the two horizontal components of one station (X Y [X Y ...]) "
                            f"{use}")
    group.add_argument("--pad", action="store_true",
                       help="with --pair: pad the shorter component of a pair with zeros at its end (components of "
                            "library records are often trimmed to slightly different lengths)")
    group.add_argument("--any-pair", action="store_true",
                       help="with --pair: pair the files although their headers, names or manifests say they are not "
                            "one station's two horizontal components (a vertical component, two events or two "
                            "stations); the output says so")


def add_vertical_options(parser: argparse.ArgumentParser, several: bool = False) -> None:
    """Add ``--vertical FILE``, ``--vertical-positive up|down`` and ``--any-vertical`` to ``parser``; with ``several``,
    ``--vertical`` takes one file per pair (``--vertical V1 V2 ...``)."""
    group = parser.add_argument_group("the vertical ground motion (--vertical)")
    whose = ("one file per pair, in the pairs' order" if several else
             "one record, or one pair with --pair")
    group.add_argument("--vertical", type=Path, default=None, metavar="FILE", nargs="+" if several else None,
                       help=f"the vertical component of the same station ({whose}): the "
                            "normal force is m (g + a_v), and where g + a_v <= 0 the slider lifts off; same dt and "
                            "length as the horizontal record(s), or --pad")
    told = ("which way the positive axis points in the vertical files whose component labels do not tell (a label "
            "UP or DWN is read as it says)" if several else
            "which way the vertical file's positive axis points (default: read from its component label, UP or DWN; "
            "a file whose label does not tell needs it)")
    group.add_argument("--vertical-positive", choices=("up", "down"), default=None, help=told)
    group.add_argument("--any-vertical", action="store_true",
                       help="with --vertical: take the file although its header, name or manifest says it is not the "
                            "vertical of the same station (a horizontal direction, another event or station); the "
                            "output says so")


def add_angle_option(parser: argparse.ArgumentParser) -> None:
    """Add ``--angles STEP`` (the azimuth sweep of ``sweep --pair``)."""
    parser.add_argument("--angles", type=quantity_type(of_unit("degree"), "--angles"), metavar="STEP",
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
    from stickslip.models.planar import azimuths

    return azimuths(args.angles)


def motion_kind_from_args(args: argparse.Namespace) -> str:
    """``"pair"`` with ``--pair``, else ``"component"`` (:data:`stickslip.models.MOTIONS`); ``--pad`` alone,
    ``--any-pair`` without ``--pair``, and ``--vertical-positive`` or ``--any-vertical`` without ``--vertical`` are
    refused."""
    if getattr(args, "pad", False) and not (args.pair or getattr(args, "vertical", None) is not None):
        raise StickslipError("--pad applies with --pair (two components of one station) or --vertical")
    if getattr(args, "any_pair", False) and not args.pair:
        raise StickslipError("--any-pair applies with --pair (two components of one station)")
    for option in ("vertical_positive", "any_vertical"):
        if getattr(args, option, None) not in (None, False) and getattr(args, "vertical", None) is None:
            raise StickslipError(f"--{option.replace('_', '-')} applies with --vertical only")
    return "pair" if args.pair else "component"


def has_vertical(args: argparse.Namespace) -> bool:
    """Whether the command was given a vertical component (``--vertical``)."""
    return getattr(args, "vertical", None) is not None


def pairs_from_args(args: argparse.Namespace, factor: float | None = None) -> list[RecordPair]:
    """The record pairs of ``args.paths`` taken two by two (``--pad``: the shorter component padded; ``--any-pair``:
    not checked to be one station's two horizontal components, with a note), each multiplied by ``factor`` [1] when
    given (``--scale``); one-line errors."""
    records = read_records_from_args(args.paths, args, alone=False, places=True)
    if len(records) % 2:
        raise StickslipError(f"--pair takes the record files two by two (X Y [X Y ...]), but {len(records)} "
                             f"{'was' if len(records) == 1 else 'were'} given")
    any_pair = getattr(args, "any_pair", False)
    pairs = []
    for first, second in zip(records[::2], records[1::2]):
        if first is None or second is None:  # left out by --keep-going: so is its pair
            partner = first or second
            if partner is not None:
                unread_files(args).append(f"{partner.meta.source}: not computed: the other file of its pair could "
                                          "not be read")
            continue
        if not (first.acceleration.any() or second.acceleration.any()):
            raise StickslipError(f"{record_name(first)} and {record_name(second)}: both components are zero "
                                 "throughout: the pair holds no ground motion (one of them may be zero, a uniaxial test)")
        pair = (RecordPair.padded(first, second, any_pair) if args.pad else RecordPair(first, second, any_pair=any_pair))
        if any_pair:
            print(f"stickslip: note: {record_name(first)} and {record_name(second)}: paired with --any-pair, "
                  f"{any_pair_note(pair)}", file=sys.stderr)
        pairs.append(pair)
    if not pairs:
        raise StickslipError("--keep-going: no pair could be read whole")
    return pairs if factor is None else [pair.scaled(factor) for pair in pairs]


def any_pair_note(pair: RecordPair) -> str:
    """What the output says of a pair made with ``--any-pair``: what its names say against it, or that they say nothing."""
    doubt = pair.doubt
    return (f"although {doubt}" if doubt is not None else
            "not needed: nothing in their headers, names or manifests says they are not one station's two horizontal "
            "components")


def pair_fields(pair: RecordPair) -> dict:
    """What an output says of how ``pair`` was made, JSON-ready: ``any_pair`` (whether ``--any-pair`` made it) and
    ``any_pair_note`` (:func:`any_pair_note`; None without ``--any-pair``)."""
    return {"any_pair": pair.any_pair, "any_pair_note": any_pair_note(pair) if pair.any_pair else None}


def motion_config(args: argparse.Namespace) -> dict:
    """How the motions were read, as given, JSON-ready (a cube's configuration, the ``read`` of a ``--json``
    output): the ``format``, ``dt`` [s] and ``units`` given (:func:`~stickslip.cli.record_options.read_settings`);
    for pairs (``pair``), whether ``--pad`` padded them and ``--any-pair`` made them; with ``--vertical``, its
    file and how it was taken (``vertical``, ``vertical_positive``, ``any_vertical``, ``pad``)."""
    config = read_settings(args)
    if getattr(args, "pair", False):
        config.update(pair=True, pad=args.pad, any_pair=args.any_pair)
    if has_vertical(args):
        config.update(vertical=str(args.vertical), vertical_positive=args.vertical_positive,
                      any_vertical=args.any_vertical, pad=args.pad)
    return config


def any_vertical_note(motion) -> str:
    """What the output says of a vertical taken with ``--any-vertical``: what its names say against it, and the
    label its sense was read against (``--vertical-positive``), or that they say nothing."""
    doubt, against = motion.doubt, motion.against_label
    reasons = ([f"although {doubt}"] if doubt is not None else []) + (
        [f"read positive {motion.positive} (--vertical-positive) against {against}"] if against is not None else [])
    return ", ".join(reasons) or ("not needed: nothing in its header, name or manifest says it is not the same "
                                  "station's vertical")


def vertical_fields(motion) -> dict:
    """What an output says of how a motion's vertical was taken, JSON-ready: ``vertical_positive`` (which way the
    file's positive axis was taken to point, up or down) and ``vertical_sense_from`` (``label``: the file's component
    label or name; ``option``: ``--vertical-positive``), ``any_vertical`` (whether ``--any-vertical`` took it) and
    ``any_vertical_note`` (:func:`any_vertical_note`; None without it)."""
    return {"vertical_positive": motion.positive, "vertical_sense_from": motion.sense_from,
            "any_vertical": motion.any_vertical,
            "any_vertical_note": any_vertical_note(motion) if motion.any_vertical else None}


def motion_notes(motion) -> list[str]:
    """What a text output says of how ``motion`` was made, under its heading: a pair made with ``--any-pair``, a
    vertical taken with ``--any-vertical``."""
    from stickslip.records.vertical import WithVertical

    notes = []
    if isinstance(motion, WithVertical):
        if motion.any_vertical:
            notes.append(f"vertical taken with --any-vertical, {any_vertical_note(motion)}")
        motion = motion.horizontal
    if isinstance(motion, RecordPair) and motion.any_pair:
        notes.insert(0, f"paired with --any-pair, {any_pair_note(motion)}")
    return notes


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
    horizontal = pairs_from_args(args)[0] if kind == "pair" else read_records_from_args(files, args)[0]
    vertical = read_record_from_args(args.vertical, args)
    if factor is not None:
        horizontal = horizontal.scaled(factor) if kind == "pair" else scale(horizontal, factor)
        vertical = scale(vertical, factor)
    motion = WithVertical.of(horizontal, vertical, args.vertical_positive, pad=args.pad, any_vertical=args.any_vertical)
    if args.any_vertical:
        print(f"stickslip: note: {record_name(motion.vertical)}: taken as the vertical with --any-vertical, "
              f"{any_vertical_note(motion)}", file=sys.stderr)
    return motion
