"""``stickslip solve PATH... --mu MU`` (or ``--ky KY``): solve each record for one resistance, print the scalars."""

from __future__ import annotations

import json
from pathlib import Path

from stickslip.cli.accelerations import warn_if_above_one
from stickslip.cli.layer_options import (add_layer_options, check_flexible_args, layer_from_args, note_coarse_step,
                                         warn_softened_layer)
from stickslip.cli.scheme_options import add_scheme_options, scheme_options_from_args
from stickslip.cli.grid_options import note_never_slides, parse_pga
from stickslip.grids import Grid
from stickslip.cli.pair_options import (add_pair_options, any_pair_note, check_pair_args, pairs_from_args,
                                        planar_requested)
from stickslip.cli.record_options import add_record_options, read_records_from_args
from stickslip.cli.sliding_options import (
    KY_HELP,
    KY_TABLE_HELP,
    add_sliding_options,
    parse_yield_coefficient,
    parse_yield_table,
    sliding_options,
)
from stickslip.constants import PAPER_BLOCK_MASS, STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.plumbing.files import atomic_path, check_output_path
from stickslip.records.components import vertical_component
from stickslip.records.process import record_name, scale, scale_to_pga
from stickslip.response import SCALAR_ATTRS, SLOPE_SCALAR_ATTRS
from stickslip.solution import solve
from stickslip.solvers.flexible import SCALAR_UNITS, solve_flexible
from stickslip.solvers.yield_table import YieldTable
from stickslip.units import UNITS


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "solve",
        help="solve a sliding block on records for one friction ratio or yield acceleration",
        description=(
            "Read ground-motion records (formats may mix), solve, for each, the rigid block with Coulomb friction (the paper's Eq. 1, --mu) "
            "or a yield acceleration (Newmark's block on a slope, --ky, or --ky-table for a k_y that varies with "
            "displacement) and print the energies [J], "
            "displacements [m] and slip statistics; with --ky also the permanent downslope displacement [m] "
            "(positive downslope; a positive ground acceleration drives the block downslope). With --model "
            "decoupled or coupled and --ky, the sliding mass is a soil layer (SLAMMER's flexible analyses): "
            "print the permanent displacement D [m], k_max [g], the final V_s [m/s] and damping [-]. With --pair, "
            "the files are taken two by two as the horizontal components of one station and the block slides in "
            "the plane under both (--mu): print its energies [J] and distances [m] beside each component's alone. "
            "Optionally write every time history to a NetCDF file."
        ),
    )
    parser.add_argument("paths", type=Path, nargs="+", metavar="path", help="record files")
    resistance = parser.add_mutually_exclusive_group(required=True)
    resistance.add_argument("--mu", type=float, help="friction ratio mu [-] of a flat surface")
    resistance.add_argument("--ky", metavar="KY", help=KY_HELP)
    resistance.add_argument("--ky-table", metavar="TABLE", help=KY_TABLE_HELP)
    add_sliding_options(parser)
    parser.add_argument("--mass", type=float, default=PAPER_BLOCK_MASS, help=f"block mass [kg] (default {PAPER_BLOCK_MASS})")
    parser.add_argument("--g", type=float, default=STANDARD_GRAVITY,
                        help=f"gravity [m/s2] (default {STANDARD_GRAVITY}; SLAMMER's is 9.80665)")
    add_scheme_options(parser)
    add_layer_options(parser)
    add_pair_options(parser)
    scaling = parser.add_mutually_exclusive_group()
    scaling.add_argument("--scale", type=float, default=None, help="multiply the record by this factor [-]")
    scaling.add_argument(
        "--target-pga", default=None, metavar="PGA",
        help="scale the record to this PGA [g] (0.4, the same as 0.4g), or with its unit (3.92m/s2)",
    )
    add_record_options(parser)
    parser.add_argument(
        "--json", action="store_true",
        help="print one JSON object per file and line: the scalars, the case solved (record, mu or ky, mass, method, dt ...) and the "
        "units of each, UDUNITS spelling",
    )
    parser.add_argument("--out", type=Path, default=None,
                        help="write all time histories to this NetCDF file (one record file only)")
    parser.set_defaults(func=run)


def format_table(scalars: dict[str, float | int], units: dict[str, str] | None = None) -> str:
    """The scalars as an aligned table: name, value, units (``units`` by name; the rigid block's by default)."""
    units = units or {name: attrs[0] for name, attrs in {**SCALAR_ATTRS, **SLOPE_SCALAR_ATTRS}.items()}
    width = max(len(name) for name in scalars)
    lines = []
    for name, value in scalars.items():
        shown = f"{value:d}" if isinstance(value, int) else f"{value:.6g}"
        lines.append(f"{name:<{width}}  {shown:>14}  {'' if units[name] == '1' else units[name]}".rstrip())
    return "\n".join(lines)


def json_document(record, response, scalars: dict, inverse: bool) -> dict:
    """The ``--json`` object: what was solved (record, whether it is a vertical component, mu or ky, mass, g, method
    and its options, dt), the scalars, units."""
    options = response.solver_options
    case = {
        "record": record.meta.record_id, "source": record.meta.source, "event": record.meta.event,
        "station": record.meta.station, "component": record.meta.component, "format": record.meta.format,
        "vertical": vertical_component(record.meta),
        "dt": record.dt, "dt_source": record.meta.dt_source, "npts": record.npts, "processing": list(record.meta.processing),
        **response.resistance.parameters, "polarity": "inverse" if inverse else "normal",
        "mass": response.mass, "g": response.g, "method": response.method,
        **options,
    }
    units = {"dt": UNITS["dt"], "npts": "1", "mass": UNITS["block_mass"], "g": UNITS["gravity"],
             **{name: UNITS[name] for name in (*response.resistance.parameters, *options) if name in UNITS},
             **{name: {**SCALAR_ATTRS, **SLOPE_SCALAR_ATTRS}[name][0] for name in scalars}}
    return {**case, **scalars, "units": units}


def run(args) -> int:
    check_pair_args(args)
    if args.mu is not None:
        warn_if_above_one(args.mu, f"--mu {args.mu:g}", "friction ratio")
    if planar_requested(args):
        return run_planar(args)
    layer = layer_from_args(args)
    if layer is not None:
        check_flexible_args(args)
    options = scheme_options_from_args(args)
    if args.scale == 0:
        raise StickslipError(
            f"--scale {args.scale:g}: a scale factor of zero leaves no ground motion; "
            "give a non-zero factor (a negative one flips the sign)"
        )
    sliding = sliding_options(args, has_ky=args.ky is not None or args.ky_table is not None)
    if args.ky is not None:
        sliding["ky"] = parse_yield_coefficient(args.ky, args.g)
    elif args.ky_table is not None:
        sliding["ky"] = parse_yield_table(args.ky_table)
    if args.out is not None:
        if len(args.paths) > 1:
            raise StickslipError(f"--out writes the time histories of one record, but {len(args.paths)} files were "
                                 "given: solve them one at a time, or use stickslip sweep for one cube of all")
        check_output_path(args.out, "the NetCDF file")
    records = read_records_from_args(args.paths, args)
    if args.scale is not None:
        records = [scale(record, args.scale) for record in records]
    elif args.target_pga is not None:
        records = [scale_to_pga(record, parse_pga(args.target_pga, args.g)) for record in records]
    if layer is not None:
        return run_flexible(args, records, layer, sliding)
    resistance = {key: value for key, value in sliding.items() if key != "ky"}
    ky = sliding.get("ky")
    initial_ky = ky.ky[0] if isinstance(ky, YieldTable) else ky  # the block first slides past the table's first k_y
    coefficient = {"mu": [args.mu]} if args.mu is not None else {"ky": [initial_ky]}
    for number, record in enumerate(records):
        response = solve(record, args.mu, mass=args.mass, method=args.method, g=args.g, inverse=args.inverse,
                         **sliding, **options)  # checks mu or ky, mass and the options first
        note_never_slides([record], Grid(args.g, **coefficient, **resistance, inverse=args.inverse))
        scalars = response.scalars()
        if args.out is not None:
            write_histories(response, args.out)
        if args.json:
            print(json.dumps(json_document(record, response, scalars, args.inverse), allow_nan=False))  # no Infinity or NaN
        else:
            polarity = ", inverse polarity" if args.inverse else ""
            print(("\n" if number else "") + f"{record_name(record)}  {response.resistance.describe(response.g)}"
                  f"{polarity}, "
                  f"mass = {response.mass:g} kg, g = {response.g:g} m/s2, method = {response.method}")
            print(format_table(scalars))
            if args.out is not None:
                print(f"time histories written to {args.out}")
    return 0


def run_flexible(args, records, layer, sliding: dict) -> int:
    """``solve --model decoupled|coupled``: each record's flexible analysis, printed as a table or JSON."""
    for number, record in enumerate(records):
        note_coarse_step(record, layer, args.method)
        result = solve_flexible(record, sliding["ky"], layer, args.model, args.method, g=args.g, inverse=args.inverse)
        warn_softened_layer(record, layer, result.vs_final)
        if args.out is not None:
            write_dataset(result.to_xarray(), args.out)
        scalars = result.scalars()
        if args.json:
            case = {"record": record.meta.record_id, "source": record.meta.source, "format": record.meta.format,
                    "vertical": vertical_component(record.meta), "dt": record.dt, "npts": record.npts, "processing": list(record.meta.processing),
                    "model": args.model, "method": args.method, **result.yield_parameters(), "g": result.g,
                    "polarity": result.polarity, "height": layer.height, "vs": layer.vs, "vs_base": layer.vs_base,
                    "damping": layer.damping, "soil_model": layer.soil_model,
                    "reference_strain": layer.reference_strain}
            units = {"dt": "s", "npts": "1", **{name: UNITS[name] for name in result.yield_parameters()},
                     "g": UNITS["gravity"], "height": "m", "vs": "m s-1",
                     "vs_base": "m s-1", "damping": "1", "reference_strain": "percent",
                     **{name: SCALAR_UNITS[name] for name in scalars}}
            print(json.dumps({**case, **scalars, "units": units}, allow_nan=False))
        else:
            polarity = ", inverse polarity" if args.inverse else ""
            soil = (f"equivalent-linear, reference strain {layer.reference_strain:g} %"
                    if layer.soil_model == "equivalent-linear" else "linear")
            print(("\n" if number else "") + f"{record_name(record)}  {args.model} layer H = {layer.height:g} m, "
                  f"V_s = {layer.vs:g} m/s over {layer.vs_base:g} m/s, damping {layer.damping:g} ({soil}); "
                  f"{result.describe_yield()}{polarity}, g = {result.g:g} m/s2, method = {args.method}")
            print(format_table(scalars, SCALAR_UNITS))
            print(ledger_note(result))
            if args.out is not None:
                print(f"time histories written to {args.out}")
    return 0


def ledger_note(result) -> str:
    """One line on what the flexible result's energies are, or why it has none."""
    if result.ledger is None:
        return (f"no energy ledger: method {result.method} keeps none (method exact does); "
                "energy_dissipated_per_mass is the friction's work, k_y g over the slide")
    if result.model == "decoupled":
        return ("energies per kg of the sliding mass: energy_input is the ground's work on the layer, "
                "block_energy_input the layer's on the block; each ledger closes alone")
    return "energies per kg of the sliding mass: the ground's work on the layer and block, one closed ledger"


def write_histories(response, path: Path) -> None:
    """Write every time history of ``response`` to the NetCDF file ``path``, whole or not at all."""
    write_dataset(response.to_xarray(), path)


def write_dataset(dataset, path: Path) -> None:
    """Write ``dataset`` to the NetCDF file ``path``, whole or not at all."""
    try:
        with atomic_path(path) as tmp:
            dataset.to_netcdf(tmp, engine="netcdf4")
    except OSError as error:
        raise StickslipError(f"{path}: cannot write the NetCDF file ({error.strerror or error})") from None


#: What ``solve --pair`` compares between the plane and each component alone.
COMPARED = ("energy_dissipated", "peak_displacement", "residual_displacement", "sliding_path")


def run_planar(args) -> int:
    """``solve --pair``: each pair's block in the plane, with each component alone beside it; a table or JSON."""
    from stickslip.planar_sweeps import VARIABLES, components_alone
    from stickslip.solvers.planar import SCALAR_ATTRS as PLANAR_ATTRS

    if args.mu is None:
        raise StickslipError("--pair slides the block on a flat surface: give a friction ratio --mu")
    if args.out is not None:
        if len(args.paths) != 2:
            raise StickslipError(f"--out writes the time histories of one pair, but {len(args.paths)} files were given")
        check_output_path(args.out, "the NetCDF file")
    pairs = pairs_from_args(args, args.scale)
    units = {name: attrs[0] for name, attrs in PLANAR_ATTRS.items()}
    for number, pair in enumerate(pairs):
        response = solve(pair, args.mu, mass=args.mass, g=args.g)
        scalars = response.scalars()
        alone = {"plane": scalars, **components_alone(pair, args.mu, mass=args.mass, g=args.g)}
        names = [pair.first.meta.component or pair.first.meta.record_id,
                 pair.second.meta.component or pair.second.meta.record_id]
        if args.out is not None:
            write_dataset(response.to_xarray(), args.out)
        if args.json:
            each = {name: {quantity: alone[direction][quantity] for quantity in COMPARED}
                    for name, direction in zip(names, ("first", "second"))}
            document = {"pair": pair.name, "sources": [pair.first.meta.source, pair.second.meta.source],
                        "event": pair.first.meta.event, "dt": pair.dt, "npts": pair.npts,
                        "processing": [list(pair.first.meta.processing), list(pair.second.meta.processing)],
                        "separation": pair.separation, "any_pair": pair.any_pair,
                        "any_pair_note": any_pair_note(pair) if pair.any_pair else None,
                        "model": "planar", "method": "exact", "mu": args.mu,
                        "mass": args.mass, "g": args.g, **scalars, "components_alone": each,
                        "units": {"dt": "s", "npts": "1", "separation": "degree", "mu": "1", "mass": "kg",
                                  "g": UNITS["gravity"], **units}}
            print(json.dumps(document, allow_nan=False))
            continue
        turned = "" if pair.orthogonal else f" (components {abs(pair.separation):g} deg apart, resolved onto " \
                                             "orthogonal axes)"
        paired = f"\npaired with --any-pair, {any_pair_note(pair)}" if pair.any_pair else ""
        print(("\n" if number else "") + f"{record_name(pair.first)} + {record_name(pair.second)}{turned}{paired}\n"
              f"in the plane: mu = {args.mu:g}, mass = {args.mass:g} kg, g = {args.g:g} m/s2, method = exact")
        print(format_table(scalars, units))
        width = max(len(name) for name in COMPARED) + 6
        print(f"\n{'':<{width}}  {'plane':>14}  " + "  ".join(f"{name + ' alone':>16}" for name in names))
        for quantity in COMPARED:
            cells = [alone[direction][quantity] for direction in ("plane", "first", "second")]
            label = f"{quantity} [{VARIABLES[quantity][0]}]"
            print(f"{label:<{width}}  {cells[0]:>14.6g}  " + "  ".join(f"{cell:>16.6g}" for cell in cells[1:]))
        if args.out is not None:
            print(f"time histories written to {args.out}")
    return 0
