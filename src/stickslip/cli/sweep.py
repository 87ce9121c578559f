"""``stickslip sweep PATH... --mu START:STOP:STEP --out cube.nc``: a friction-ratio (or yield-acceleration) sweep into a NetCDF cube."""

from __future__ import annotations

from pathlib import Path

from stickslip.cli.grid_options import (
    add_grid_options,
    check_optimum_options,
    grid_from_args,
    note_never_slides,
    target_pgas,
)
from stickslip.cli.record_options import add_record_options, read_records_from_args
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
            "and the efficiency of the reference mu (or ky): see 'stickslip optimum'."
        ),
    )
    parser.add_argument("paths", type=Path, nargs="+", metavar="PATH", help="record files (formats may be mixed)")
    add_grid_options(parser, yield_grid=True)
    add_scheme_options(parser, "; the cube records it")
    add_record_options(parser)
    parser.add_argument("--out", type=Path, required=True, help="the NetCDF cube to write")
    parser.set_defaults(func=run)


def run(args) -> int:
    from stickslip.optimum import with_optimum
    from stickslip.sweeps import sweep, write_cube

    check_output_path(args.out, "the NetCDF cube")
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
