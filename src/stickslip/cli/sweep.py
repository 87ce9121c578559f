"""``stickslip sweep PATH... --mu START:STOP:STEP --out cube.nc``: a friction-ratio sweep into a NetCDF cube."""

from __future__ import annotations

from pathlib import Path

from stickslip.cli.grid_options import (
    add_grid_options,
    check_optimum_options,
    friction_ratios,
    note_never_slides,
    target_pgas,
)
from stickslip.cli.record_options import add_record_options, read_records_from_args
from stickslip.errors import StickslipError
from stickslip.io import check_output_path
from stickslip.records.process import scaled_versions
from stickslip.solution import SOLVERS


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "sweep",
        help="solve record files over a range of friction ratios and write a NetCDF cube",
        description=(
            "Solve every record for every friction ratio (optionally scaled) and write the response "
            "scalars (energies in J, lengths in m) as a compressed NetCDF cube, atomically, with each "
            "record's mu_max, near-optimal range, stroke and residual displacement there, and the "
            "efficiency of the reference mu (see 'stickslip optimum')."
        ),
    )
    parser.add_argument("paths", type=Path, nargs="+", metavar="PATH", help="record files (formats may be mixed)")
    add_grid_options(parser)
    parser.add_argument("--method", choices=tuple(SOLVERS), default="exact", help="solver (default exact)")
    parser.add_argument("--time-step", type=float, default=None,
                        help="newmark integration step [s] (default 0.001); the cube records it")
    add_record_options(parser)
    parser.add_argument("--out", type=Path, required=True, help="the NetCDF cube to write")
    parser.set_defaults(func=run)


def run(args) -> int:
    from stickslip.optimum import with_optimum
    from stickslip.sweeps import sweep, write_cube

    check_output_path(args.out, "the NetCDF cube")
    check_optimum_options(args)
    options = {}
    if args.time_step is not None:
        if args.method != "newmark":
            raise StickslipError("--time-step applies to --method newmark only (exact has no time step of its own)")
        options["time_step"] = args.time_step
    mu = friction_ratios(args)
    target_pga = target_pgas(args)
    records = read_records_from_args(args.paths, args)
    cube = sweep(
        records,
        mu,
        scale=args.scale,
        target_pga=target_pga,
        mass=args.mass,
        method=args.method,
        g=args.g,
        progress=True,
        config={"command": "stickslip sweep", "paths": [str(p) for p in args.paths], "mu": list(map(float, mu))},
        options=options,
    )
    note_never_slides([v for record in records for v in scaled_versions(record, args.scale, target_pga)], mu, args.g)
    print(write_cube(with_optimum(cube, records, args.q, args.reference_mu, options), args.out))
    return 0
