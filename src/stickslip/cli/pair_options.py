"""``--pair``, ``--pad`` and ``--any-pair``: record files taken two by two as the horizontal components of one station.

``stickslip solve X.AT2 Y.AT2 --pair --mu 0.1`` slides the block in the plane
under both components (``--model planar`` says the same); several pairs are
given one after another (X1 Y1 X2 Y2 ...).  The two files of a pair must have
the same time step and, unless ``--pad`` pads the shorter with zeros at its end,
the same number of samples.  They must be one station's two horizontal
components: a vertical component, or two files whose headers, names or
manifests give different events or stations (:func:`stickslip.records.pair.pair_doubt`),
are refused in one line, unless ``--any-pair`` pairs them all the same; the
command then says so (a note on stderr, and its output).  One component may
be zero throughout (a uniaxial test), not both.  Options that mean nothing in
the plane (``--ky``, ``--inverse``, a soil layer, ``--target-pga``, another
scheme than exact) are one-line errors.
"""

from __future__ import annotations

import argparse
import math
import sys

import numpy as np

from stickslip.cli.record_options import read_records_from_args
from stickslip.errors import StickslipError
from stickslip.records.pair import RecordPair
from stickslip.records.process import record_name


def add_pair_options(parser: argparse.ArgumentParser) -> None:
    """Add ``--pair``, ``--pad`` and ``--any-pair`` to ``parser``."""
    group = parser.add_argument_group("sliding in the plane (--pair, or --model planar)")
    group.add_argument("--pair", action="store_true",
                       help="take the files two by two as the two horizontal components of one station (X Y [X Y ...]) "
                            "and slide the block in the plane under both: one friction force mu*m*g opposing the "
                            "sliding velocity; needs --mu")
    group.add_argument("--pad", action="store_true",
                       help="with --pair: pad the shorter component of a pair with zeros at its end (components of "
                            "library records are often trimmed to slightly different lengths)")
    group.add_argument("--any-pair", action="store_true",
                       help="with --pair: pair the files although their headers, names or manifests say they are not "
                            "one station's two horizontal components (a vertical component, two events or two "
                            "stations); the output says so")


def add_angle_option(parser: argparse.ArgumentParser) -> None:
    """Add ``--angles STEP`` (the azimuth sweep of ``sweep --pair``)."""
    parser.add_argument("--angles", type=float, metavar="STEP",
                        help="with --pair: also turn each pair's axes every STEP degrees through 0-180 (and always 90) "
                             "and solve the 1-D block on the turned axis (the RotD idea applied to the block; 5 gives "
                             "36 azimuths)")


def angles_from_args(args: argparse.Namespace) -> np.ndarray | None:
    """The azimuths [degrees] of ``--angles STEP`` (:func:`stickslip.planar_sweeps.azimuths`), or None; one-line errors."""
    if args.angles is None:
        return None
    if not planar_requested(args):
        raise StickslipError("--angles applies with --pair (it turns the two components of a pair)")
    if not (math.isfinite(args.angles) and 0.0 < args.angles <= 90.0):
        raise StickslipError(f"--angles {args.angles:g}: expected a step in degrees, 0 < STEP <= 90")
    from stickslip.planar_sweeps import azimuths

    return azimuths(args.angles)


def planar_requested(args: argparse.Namespace) -> bool:
    """Whether the command is to slide the block in the plane (``--pair`` or ``--model planar``)."""
    return bool(getattr(args, "pair", False)) or getattr(args, "model", None) == "planar"


def check_pair_args(args: argparse.Namespace) -> None:
    """Refuse options that mean nothing for a block sliding in the plane; one line each."""
    for option in ("pad", "any_pair"):
        if getattr(args, option, False) and not planar_requested(args):
            raise StickslipError(f"--{option.replace('_', '-')} applies with --pair (two components of one station)")
    if not planar_requested(args):
        return
    if getattr(args, "model", "rigid") not in ("rigid", "planar"):
        raise StickslipError(f"--pair slides a rigid block in the plane; --model {args.model} is a soil layer on a "
                             "slope, driven by one component")
    refused = {"--ky": "ky", "--ky-table": "ky_table", "--ky-list": "ky_list", "--direction": "direction",
               "--thrust-angle": "thrust_angle", "--inverse": "inverse", "--target-pga": "target_pga",
               "--height": "height", "--vs": "vs", "--vs-base": "vs_base", "--time-step": "time_step"}
    for option, name in refused.items():
        if getattr(args, name, None) not in (None, False):
            raise StickslipError(f"{option} does not apply to sliding in the plane (--pair): the block is rigid, on a "
                                 "flat surface, with a friction ratio --mu")
    if getattr(args, "method", "exact") != "exact":
        raise StickslipError(f"--method {args.method}: sliding in the plane is solved by the exact method only")


def pairs_from_args(args: argparse.Namespace, factor: float | None = None) -> list[RecordPair]:
    """The record pairs of ``args.paths`` taken two by two (``--pad``: the shorter component padded; ``--any-pair``:
    not checked to be one station's two horizontal components, with a note), each multiplied by ``factor`` [1] when
    given (``--scale``); one-line errors."""
    records = read_records_from_args(args.paths, args, alone=False)
    if len(records) % 2:
        raise StickslipError(f"--pair takes the record files two by two (X Y [X Y ...]), but {len(records)} "
                             f"{'was' if len(records) == 1 else 'were'} given")
    any_pair = getattr(args, "any_pair", False)
    pairs = []
    for first, second in zip(records[::2], records[1::2]):
        if not (first.acceleration.any() or second.acceleration.any()):
            raise StickslipError(f"{record_name(first)} and {record_name(second)}: both components are zero "
                                 "throughout: the pair holds no ground motion (one of them may be zero, a uniaxial test)")
        pair = (RecordPair.padded(first, second, any_pair) if args.pad else RecordPair(first, second, any_pair=any_pair))
        if any_pair:
            print(f"stickslip: note: {record_name(first)} and {record_name(second)}: paired with --any-pair, "
                  f"{any_pair_note(pair)}", file=sys.stderr)
        pairs.append(pair)
    return pairs if factor is None else [pair.scaled(factor) for pair in pairs]


def any_pair_note(pair: RecordPair) -> str:
    """What the output says of a pair made with ``--any-pair``: what its names say against it, or that they say nothing."""
    doubt = pair.doubt
    return (f"although {doubt}" if doubt is not None else
            "not needed: nothing in their headers, names or manifests says they are not one station's two horizontal "
            "components")
