"""``stickslip sweep PATH... --mu START:STOP:STEP --out cube.nc``: a model over grids of its parameters, one NetCDF cube.

The model is ``--model``, or the one that the motion (``--pair``) and the
parameters given choose (:mod:`stickslip.cli.model_options`); its entry's
``sweep`` (:func:`stickslip.sweep`) solves every motion over the grids of its
swept parameters.  A model with a design answer over its grid (the rigid
block: μ_max or k_y,max, the near-optimal range …, :mod:`stickslip.optimum`)
adds it to the cube.
"""

from __future__ import annotations

from pathlib import Path

from stickslip.cli.grid_options import (
    add_optimum_options,
    add_scaling_options,
    check_optimum_options,
    note_never_slides,
    target_pgas,
)
from stickslip.cli.model_options import (
    add_model_options,
    model_from_args,
    parameters_from_args,
    scheme_options_from_args,
)
from stickslip.cli.pair_options import (
    add_angle_option,
    add_pair_options,
    add_vertical_options,
    angles_from_args,
    motion_config,
    motion_kind_from_args,
    motions_from_args,
)
from stickslip.cli.record_options import add_keep_going_option, add_record_options
from stickslip.errors import StickslipError
from stickslip.grids import COEFFICIENTS, Grid
from stickslip.plumbing.files import check_output_path


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
    add_model_options(parser, grids=True)
    add_pair_options(parser)
    add_vertical_options(parser)
    add_angle_option(parser)
    add_scaling_options(parser)
    add_optimum_options(parser)
    add_record_options(parser)
    add_keep_going_option(parser)
    parser.add_argument("--out", type=Path, required=True, help="the NetCDF cube to write")
    parser.set_defaults(func=run)


def swept_grid(parameters: dict) -> Grid | None:
    """The grid of the swept coefficient among ``parameters`` (:data:`stickslip.grids.COEFFICIENTS`), if one is."""
    named = [name for name in COEFFICIENTS if name in parameters]
    return Grid(named[0], parameters[named[0]]) if len(named) == 1 else None


def scaled_motions(args, entry, kind: str) -> tuple[list, list, dict]:
    """The motions as read, the versions the model solves, and the scaling its sweep takes as a dimension.

    A model whose sweep scales along a dimension of its cube (:attr:`~stickslip.models.entry.Model.scaled_sweeps`)
    takes ``scale`` or ``target_pga``; another takes one factor or PGA, applied here.
    """
    targets = target_pgas(args)
    if entry.scaled_sweeps:
        motions = motions_from_args(args, kind)
        return motions, motions, {"scale": args.scale, "target_pga": targets}
    for option, values in (("--scale", args.scale), ("--target-pga", args.target_pga)):
        if values is not None and len(values) > 1:
            raise StickslipError(f"{option}: the {entry.name} model's sweep takes one value (its cube has no scaling "
                                 "dimension); sweep the others one at a time")
    factor = None if args.scale is None else args.scale[0]
    target = None if args.target_pga is None else args.target_pga[0]
    motions = motions_from_args(args, kind, factor, target)
    return motions, motions, {}


def run(args) -> int:
    from stickslip.records.process import scaled_versions
    from stickslip.sweeps import write_cube

    check_output_path(args.out, "the NetCDF cube")
    kind = motion_kind_from_args(args)
    entry = model_from_args(args, kind)
    parameters = parameters_from_args(args, entry, grids=True)
    options = scheme_options_from_args(args, entry)
    angles = angles_from_args(args)
    grid = swept_grid(parameters)
    reference = check_optimum_options(args, entry, grid.name) if entry.designs and grid is not None else None
    motions, solved, scaling = scaled_motions(args, entry, kind)
    config = {"command": "stickslip sweep", "model": entry.name, "paths": [str(p) for p in args.paths],
              **motion_config(args),
              **{name: (list(map(float, value)) if hasattr(value, "tolist") else value)
                 for name, value in parameters.items()}}
    extra = {key: value for key, value in (("angles", angles), ("options", options or None)) if value is not None}
    cube = entry.sweep(solved, args.method, progress=True, config=config, **scaling, **extra, **parameters)
    if entry.designs and grid is not None:
        design = entry.design(grid, args.method, options, **{k: v for k, v in parameters.items() if k != grid.name})
        note_never_slides([version for motion in motions
                           for version in scaled_versions(motion, scaling.get("scale"), scaling.get("target_pga"))],
                          design)
        cube = entry.design_answer(cube, motions, args.q, reference)
    print(write_cube(cube, args.out))
    return 0
