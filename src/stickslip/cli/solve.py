"""``stickslip solve PATH... --mu MU`` (or ``--ky KY``, a layer, ``--pair``): each record's case, its end results.

The model is ``--model``, or the one that the motion (one component, or
``--pair``) and the parameters given choose (:mod:`stickslip.cli.model_options`);
every model is solved, printed and written the same way, through its entry
(:func:`stickslip.solve`) and its result (:class:`stickslip.models.result.Result`).
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

from stickslip.cli.model_options import (
    add_model_options,
    model_from_args,
    parameters_from_args,
    scheme_options_from_args,
)
from stickslip.cli.pair_options import (
    add_pair_options,
    add_vertical_options,
    motion_kind_from_args,
    motion_notes,
    motions_from_args,
    pair_fields,
    vertical_fields,
)
from stickslip.cli.record_options import add_keep_going_option, add_record_options, record_files
from stickslip.errors import StickslipError
from stickslip.plumbing.files import atomic_path, check_output_path
from stickslip.records.process import record_name
from stickslip.units import UNITS, energy_units, per_unit_mass


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "solve",
        help="solve a sliding block on records for one friction ratio or yield acceleration",
        description=(
            "Read ground-motion records (formats may mix) and solve, for each, one case of a sliding-block model: "
            "the rigid block with Coulomb friction (the paper's Eq. 1, --mu) or a yield acceleration (Newmark's "
            "block on a slope, --ky, or --ky-table for a k_y that varies with displacement); with --model "
            "decoupled or coupled and --ky a soil layer over the sliding surface (SLAMMER's flexible analyses: "
            "the permanent displacement D [m], k_max [g], the final V_s [m/s] and damping [-]); with --pair the "
            "files taken two by two as the horizontal components of one station and the block sliding in the "
            "plane (--mu), beside each component alone. Print the end results (energies in J or J/kg, "
            "displacements in m), or write every time history to a NetCDF file."
        ),
    )
    parser.add_argument("paths", type=Path, nargs="+", metavar="path", help="record files")
    add_model_options(parser)
    add_pair_options(parser)
    add_vertical_options(parser)
    scaling = parser.add_mutually_exclusive_group()
    scaling.add_argument("--scale", type=float, default=None, help="multiply the record by this factor [-]")
    scaling.add_argument(
        "--target-pga", default=None, metavar="PGA",
        help="scale the record to this PGA [g] (0.4, the same as 0.4g), or with its unit (3.92m/s2)",
    )
    add_record_options(parser)
    add_keep_going_option(parser)
    parser.add_argument(
        "--json", action="store_true",
        help="print one JSON object per file (or pair) and line: the motion, the case solved (model, method, "
             "parameters), the end results and the units of each, UDUNITS spelling",
    )
    parser.add_argument("--out", type=Path, default=None,
                        help="write all time histories to this NetCDF file (one record file, or one pair, only)")
    parser.set_defaults(func=run)


def format_table(scalars: dict[str, float | int], units: dict[str, str]) -> str:
    """The scalars as an aligned table: name, value, units (``1``, dimensionless, left blank)."""
    width = max(len(name) for name in scalars)
    lines = []
    for name, value in scalars.items():
        shown = f"{value:d}" if isinstance(value, int) else f"{value:.6g}"
        lines.append(f"{name:<{width}}  {shown:>14}  {'' if units[name] == '1' else units[name]}".rstrip())
    return "\n".join(lines)


def motion_document(motion) -> tuple[dict, dict]:
    """What the ``--json`` object says of the motion solved, and the units of its numbers.

    A record says whether it is a vertical component (``vertical``: what says
    so, or None); a pair whether ``--any-pair`` made it (:func:`~stickslip.cli.pair_options.pair_fields`); a
    vertical its file, sense and whether ``--any-vertical`` took it
    (:func:`~stickslip.cli.pair_options.vertical_fields`).
    """
    from stickslip.records.components import vertical_component
    from stickslip.records.pair import RecordPair
    from stickslip.records.vertical import WithVertical

    if isinstance(motion, WithVertical):
        document, units = motion_document(motion.horizontal)
        return {**document, "vertical_source": motion.vertical.meta.source, "vertical_sense": motion.sense,
                **vertical_fields(motion)}, units

    if isinstance(motion, RecordPair):
        document = {"pair": motion.name, "sources": [motion.first.meta.source, motion.second.meta.source],
                    "event": motion.first.meta.event, "dt": motion.dt, "npts": motion.npts,
                    "processing": [list(motion.first.meta.processing), list(motion.second.meta.processing)],
                    "separation": motion.separation, **pair_fields(motion)}
        return document, {"dt": UNITS["dt"], "npts": "1", "separation": "degree"}
    meta = motion.meta
    document = {"record": meta.record_id, "source": meta.source, "event": meta.event, "station": meta.station,
                "component": meta.component, "vertical": vertical_component(meta), "format": meta.format,
                "dt": motion.dt, "dt_source": meta.dt_source, "npts": motion.npts, "processing": list(meta.processing)}
    return document, {"dt": UNITS["dt"], "npts": "1"}


def motion_label(motion) -> str:
    """The motion as the text output names it: its file, or both files of a pair (and how they were resolved)."""
    from stickslip.records.pair import RecordPair
    from stickslip.records.vertical import WithVertical

    if isinstance(motion, WithVertical):
        return f"{motion_label(motion.horizontal)} + {record_name(motion.vertical)} (vertical)"

    if not isinstance(motion, RecordPair):
        return record_name(motion)
    turned = "" if motion.orthogonal else (f" (components {abs(motion.separation):g} deg apart, resolved onto "
                                           "orthogonal axes)")
    return f"{record_name(motion.first)} + {record_name(motion.second)}{turned}"


def run(args) -> int:
    kind = motion_kind_from_args(args)
    entry = model_from_args(args, kind)
    parameters = parameters_from_args(args, entry)
    options = scheme_options_from_args(args, entry)
    if args.scale == 0:
        raise StickslipError(f"--scale {args.scale:g}: a scale factor of zero leaves no ground motion; "
                             "give a non-zero factor (a negative one flips the sign)")
    if args.out is not None:
        files = len(record_files(args.paths))
        if files > (2 if kind == "pair" else 1):  # checked before any file is read
            raise StickslipError(f"--out writes the time histories of one {'pair' if kind == 'pair' else 'record'}, "
                                 f"but {files} files were given: solve them one at a time, or use stickslip sweep for "
                                 "one cube of all")
        check_output_path(args.out, "the NetCDF file")
    motions = motions_from_args(args, kind, args.scale, args.target_pga)
    for number, motion in enumerate(motions):
        result = entry.solve(motion, args.method, **parameters, **options)
        label = motion_label(motion)
        for notice in result.notices():
            print(f"stickslip: note: {label}: {notice}", file=sys.stderr)
        if args.out is not None:
            write_dataset(result.to_xarray(), args.out)
        scalars = result.scalars()
        if args.json:
            described, units = motion_document(motion)
            document = {**described, **result.case(), **scalars, **result.extras(),
                        "units": {**units, **result.case_units(), **result.scalar_units()}}
            print(json.dumps(document, allow_nan=False))  # no Infinity or NaN
            continue
        print(("\n" if number else "") + f"{label}  {result.describe()}")
        for line in motion_notes(motion):
            print(line)
        mass = result.case().get("mass")  # None for a model whose energies are per kg already (a layer's)
        units = {name: energy_units(mass) if unit == "J" and mass is not None else unit
                 for name, unit in result.scalar_units().items()}
        print(format_table(scalars, units))
        for text in (*result.notes(), *("\n" + table for table in result.tables())):
            print(text if mass is None else per_unit_mass(text, mass))
        if args.out is not None:
            print(f"time histories written to {args.out}")
    return 0


def write_dataset(dataset, path: Path) -> None:
    """Write ``dataset`` to the NetCDF file ``path``, whole or not at all."""
    try:
        with atomic_path(path) as tmp:
            dataset.to_netcdf(tmp, engine="netcdf4")
    except OSError as error:
        raise StickslipError(f"{path}: cannot write the NetCDF file ({error.strerror or error})") from None
