"""``stickslip sweep PATH... --mu START:STOP:STEP --out cube.nc``: a friction-ratio (or yield-acceleration) sweep into a NetCDF cube."""

from __future__ import annotations

import json
from pathlib import Path

from stickslip.cli.grid_options import (
    add_grid_options,
    check_optimum_options,
    grid_from_args,
    note_never_slides,
    parse_heights,
    target_pgas,
)
from stickslip.cli.layer_options import (
    add_layer_options,
    check_flexible_args,
    checked_layer,
    layer_settings_from_args,
    warn_softened_layer,
)
from stickslip.cli.pair_options import (
    add_angle_option,
    add_pair_options,
    angles_from_args,
    check_pair_args,
    pairs_from_args,
    planar_requested,
)
from stickslip.cli.record_options import add_record_options, read_records_from_args
from stickslip.errors import StickslipError
from stickslip.plumbing.files import check_output_path
from stickslip.records.process import scaled_versions
from stickslip.cli.scheme_options import add_scheme_options, scheme_options_from_args


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "sweep",
        help="solve record files over a range of friction ratios or yield accelerations and write a NetCDF cube",
        description=(
            "Solve every record for every friction ratio (or yield acceleration, --ky; optionally scaled) and "
            "write the response scalars (energies in J, lengths in m; with --ky also the permanent downslope "
            "displacement in m) as a compressed NetCDF cube, atomically. The cube also holds each record's "
            "mu_max (ky_max for a yield grid), near-optimal range, stroke and residual (and downslope) displacement, "
            "and the efficiency of the reference mu (or ky): see 'stickslip optimum'. With --model decoupled or "
            "coupled, the sliding mass is a soil layer: the cube has dimensions record x ky x height (--height "
            "a list or range) and holds the permanent displacement [m] and the layer's k_max, final V_s and damping. "
            "With --pair, the files are taken two by two as the components of one station: the cube has dimensions "
            "pair x direction (plane, first, second: both components at once, each alone) x mu, and with --angles "
            "the largest and median 1-D response over the turned axes."
        ),
    )
    parser.add_argument("paths", type=Path, nargs="+", metavar="PATH", help="record files (formats may be mixed)")
    add_grid_options(parser, yield_grid=True)
    add_scheme_options(parser, "; the cube records it")
    add_layer_options(parser, several_heights=True)
    add_pair_options(parser)
    add_angle_option(parser)
    add_record_options(parser)
    parser.add_argument("--out", type=Path, required=True, help="the NetCDF cube to write")
    parser.set_defaults(func=run)


def run(args) -> int:
    from stickslip.optimum import with_optimum
    from stickslip.sweeps import sweep, write_cube

    check_output_path(args.out, "the NetCDF cube")
    check_pair_args(args)
    if planar_requested(args):
        return run_planar(args)
    angles_from_args(args)  # refuses --angles without --pair
    settings = layer_settings_from_args(args)
    if settings is not None:
        return run_flexible(args, settings)
    options = scheme_options_from_args(args)
    grid = grid_from_args(args)
    reference = check_optimum_options(args, grid.name)
    target_pga = target_pgas(args)
    records = read_records_from_args(args.paths, args)
    cube = sweep(
        records,
        scale=args.scale,
        target_pga=target_pga,
        mass=args.mass,
        method=args.method,
        g=args.g,
        progress=True,
        config={"command": "stickslip sweep", "paths": [str(p) for p in args.paths],
                grid.name: list(map(float, grid.values)), **grid.options, "inverse": args.inverse},
        options=options,
        inverse=args.inverse,
        **{grid.name: grid.values},
        **grid.options,
    )
    note_never_slides([v for record in records for v in scaled_versions(record, args.scale, target_pga)], grid)
    cube = with_optimum(cube, records, args.q, reference, options)
    print(write_cube(cube, args.out))
    return 0


def run_flexible(args, settings: dict) -> int:
    """``sweep --model decoupled|coupled``: records × k_y × layer heights into one cube."""
    from stickslip.flexible_sweeps import flexible_sweep
    from stickslip.records.process import scale, scale_to_pga
    from stickslip.sweeps import write_cube

    check_flexible_args(args)
    scheme_options_from_args(args)  # refuses --time-step: both schemes follow the record's samples
    grid = grid_from_args(args)
    if grid.name != "ky":
        raise StickslipError(f"--model {args.model} sweeps yield coefficients: give --ky or --ky-list, not a friction grid")
    heights = parse_heights(args.height)
    checked_layer(float(heights[0]), settings)  # the damping, before any record is read
    targets = target_pgas(args)
    for option, values in (("--scale", args.scale), ("--target-pga", targets)):
        if values is not None and len(values) > 1:
            raise StickslipError(f"{option}: --model {args.model} takes one value (the cube's dimensions are record, "
                                 "ky and height); sweep the others one at a time")
    records = read_records_from_args(args.paths, args)
    if args.scale is not None:
        records = [scale(record, args.scale[0]) for record in records]
    elif targets is not None:
        records = [scale_to_pga(record, targets[0]) for record in records]
    cube = flexible_sweep(records, grid.values, heights, model_name=args.model, method=args.method, g=args.g,
                          inverse=args.inverse, progress=True, **settings)
    layer = checked_layer(float(heights[0]), settings)
    for record, vs_final in zip(records, cube["vs_final"].min("height").values):
        warn_softened_layer(record, layer, vs_final)
    print(write_cube(cube, args.out))
    return 0


def run_planar(args) -> int:
    """``sweep --pair``: record pairs × direction (plane, each component alone) × mu into one cube."""
    from stickslip.planar_sweeps import planar_sweep
    from stickslip.sweeps import write_cube

    grid = grid_from_args(args)
    if grid.name != "mu":
        raise StickslipError("--pair sweeps friction ratios of a flat surface: give --mu or --mu-list")
    if args.scale is not None and len(args.scale) > 1:
        raise StickslipError("--scale: --pair takes one factor (the cube's dimensions are pair, direction and mu)")
    angles = angles_from_args(args)
    pairs = pairs_from_args(args, None if args.scale is None else args.scale[0])
    cube = planar_sweep(pairs, grid.values, mass=args.mass, g=args.g, angles=angles, progress=True)
    cube.attrs["config"] = json.dumps({"command": "stickslip sweep --pair", "paths": [str(p) for p in args.paths],
                                       "mu": list(map(float, grid.values)), "pad": args.pad,
                                       "any_pair": args.any_pair,
                                       "angles": None if angles is None else angles.tolist()})
    print(write_cube(cube, args.out))
    return 0
