"""``stickslip optimum PATH...``: the design answer of each record (μ_max or k_y,max, near-optimal range, stroke, residual).

For every record (and scaled version) the exact solver sweeps the friction
grid (or, with ``--ky``, the yield coefficients of a block on a slope), then
:mod:`stickslip.optimum` gives the value of maximum dissipation on the grid
and continuous, E_df,max, the near-optimal range, whether the maximum is on
the grid's edge, the stroke (peak |x|) and residual displacement (and, for
k_y, the downslope displacement) at the maximum and at both ends of the
range, and E_df and the efficiency at the reference value.  A table on the
terminal, or ``--json``; ``--csv`` writes the same rows, ``--out`` the sweep
cube with the per-record results (as ``stickslip sweep`` does).

The table comes without xarray or pandas (the cube needs xarray), so that
the command answers in about the time numba takes to load its kernel.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

from stickslip.cli.grid_options import (
    DEFAULT_MU_TEXT,
    add_grid_options,
    check_optimum_options,
    grid_from_args,
    note_never_slides,
    target_pgas,
)
from stickslip.cli.pair_options import (
    add_angle_option,
    add_pair_options,
    angles_from_args,
    any_pair_note,
    check_pair_args,
    pairs_from_args,
    planar_requested,
)
from stickslip.cli.record_options import add_record_options, read_records_from_args
from stickslip.errors import StickslipError
from stickslip.plumbing.files import check_output_path, write_csv_atomic
from stickslip.records.components import vertical_component
from stickslip.optimum import STATUS, results_of
from stickslip.records.process import peak_ground_acceleration, scaled_versions
from stickslip.reports.design_answer import format_number, shown
from stickslip.units import UNITS

#: How the terminal output names each kind of grid.
GRID_LABELS = {"mu": "friction grid", "ky": "yield-coefficient grid"}


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "optimum",
        help="the friction ratio (or yield acceleration) of maximum dissipation, its near-optimal range, and the "
             "stroke and residual displacement there, per record file",
        description=(
            "For each record file (formats may be mixed; each file's dt comes from the file, else from the "
            "manifests stickslip ships, else --dt), sweep the friction ratio mu with the exact solver and report: "
            "mu_max on the grid and continuous, E_df,max [J], the near-optimal range {mu : E_df >= q E_df,max}, "
            "whether mu_max is on the grid's edge, the stroke (peak |x| [m], x the block's displacement relative "
            "to the base) and the residual displacement x at the end [m] at mu_max and at both ends of the range, "
            "and E_df and the efficiency E_df / E_df,max at the reference mu. "
            f"The default grid, {DEFAULT_MU_TEXT} (400 values), is the collection study's: mu*g beyond a "
            "record's PGA dissipates nothing and few records exceed 1 g; steps of 0.0025 place mu_max well "
            "enough for the continuous search between its neighbours. "
            "With --ky or --ky-list (no default: give the yield accelerations, such as 0.01g:0.5g:0.01g) the "
            "block sits on a slope and slides downslope past ky*g (--direction both: also upslope, at a "
            "--thrust-angle); the same results are named ky_max, ky_low, ky_high ..., and the permanent "
            "downslope displacement (SLAMMER's) at ky_max and the range's ends is added. With --pair, the files are "
            "taken two by two as the components of one station: mu_max, E_df,max and the stroke and final distance "
            "at mu_max for the block in the plane and for each component alone (--angles STEP: also the worst "
            "turned axis). Definitions: docs/studies.md."
        ),
    )
    parser.add_argument("paths", type=Path, nargs="+", metavar="PATH", help="record files (formats may be mixed)")
    add_grid_options(parser, default_mu=DEFAULT_MU_TEXT, yield_grid=True)
    add_pair_options(parser)
    add_angle_option(parser)
    add_record_options(parser)
    parser.add_argument("--json", action="store_true",
                        help="print one JSON object (settings, units, one entry per record) instead of the table")
    parser.add_argument("--csv", type=Path, default=None, metavar="FILE", help="write one row per record to FILE")
    parser.add_argument("--out", type=Path, default=None, metavar="CUBE",
                        help="write the sweep cube with the per-record results (NetCDF), as 'stickslip sweep' does")
    parser.set_defaults(func=run)


def run(args) -> int:
    for path, what in ((args.csv, "the CSV table"), (args.out, "the NetCDF cube")):
        if path is not None:
            check_output_path(path, what)
    check_pair_args(args)
    if planar_requested(args):
        return run_planar(args)
    angles_from_args(args)  # refuses --angles without --pair
    grid = grid_from_args(args)
    reference = check_optimum_options(args, grid.name)
    explicit = grid.name != "mu" or args.mu != DEFAULT_MU_TEXT or args.mu_list is not None
    target_pga = target_pgas(args)
    records = read_records_from_args(args.paths, args)
    versions = [(record, version) for record in records for version in scaled_versions(record, args.scale, target_pga)]
    if explicit:
        note_never_slides([version for _, version in versions], grid)
    if args.out is not None:
        results, statuses = _with_cube(records, grid, target_pga, reference, args)
    else:
        from stickslip.optimum import optimum, solve_curves

        flat = [version for _, version in versions]
        results, statuses = optimum(flat, solve_curves(flat, grid, args.mass, args.g), args.mass, args.g, args.q,
                                    reference)
    rows = _rows(versions, results, statuses, grid, reference, args)
    if args.csv is not None:
        write_csv_atomic(args.csv, [{name: _cell(value) for name, value in row.items()} for row in rows])
    if args.json:
        print(json.dumps(_document(rows, grid, reference, args), allow_nan=False))
    else:
        print(format_tables(rows, grid, reference, args))
        for path in (args.csv, args.out):
            if path is not None:
                print(f"written: {path}")
    return 0


def _with_cube(records, grid, target_pga, reference: float, args) -> tuple[dict, list[str]]:
    """Sweep into a cube with the per-record results, write it to ``--out``; the results, flat (record-major)."""
    from stickslip.optimum import with_optimum
    from stickslip.sweeps import sweep, write_cube

    cube = sweep(records, scale=args.scale, target_pga=target_pga, mass=args.mass, g=args.g, progress=True,
                 config={"command": "stickslip optimum", "paths": [str(p) for p in args.paths],
                         grid.name: list(map(float, grid.values)), **grid.options, "inverse": grid.inverse},
                 **{grid.name: grid.values}, **grid.options, inverse=grid.inverse)
    cube = with_optimum(cube, records, args.q, reference)
    write_cube(cube, args.out)
    return ({name: cube[name].values.reshape(-1) for name in results_of(grid.name)},
            [str(status) for status in cube[STATUS].values.reshape(-1)])


def _rows(versions, results: dict, statuses: list[str], grid, reference: float, args) -> list[dict]:
    """One dict per record (and scaled version): what was solved, the status and the per-record results."""
    rows = []
    for index, (record, version) in enumerate(versions):
        row = {"record": record.meta.record_id, "source": record.meta.source, "event": record.meta.event,
               "station": record.meta.station, "component": record.meta.component,
               "vertical": vertical_component(record.meta), "format": record.meta.format,
               "dt": record.dt, "dt_source": record.meta.dt_source, "pga": peak_ground_acceleration(version)}
        if args.scale is not None:
            row["scale"] = args.scale[index % len(args.scale)]
        elif args.target_pga is not None:
            row["target_pga"] = row["pga"]
            row["scale_factor"] = row["pga"] / peak_ground_acceleration(record)
        row[STATUS] = statuses[index]
        row.update({name: float(results[name][index]) for name in results_of(grid.name)})
        row.update({"near_optimal_fraction": args.q, f"reference_{grid.name}": reference})
        rows.append(row)
    return rows


def _cell(value):
    """A CSV cell: "" for NaN or None."""
    return "" if value is None or isinstance(value, float) and math.isnan(value) else value


def _document(rows: list[dict], grid, reference: float, args) -> dict:
    """The ``--json`` object: settings, the units of every number, and the rows (NaN as null)."""
    settings = {grid.name: [float(value) for value in grid.values], **grid.options, "inverse": grid.inverse,
                "near_optimal_fraction": args.q, f"reference_{grid.name}": reference, "mass": args.mass, "g": args.g,
                "method": "exact"}
    units = {name: UNITS[name] for name, value in rows[0].items() if isinstance(value, float)}
    units.update({grid.name: UNITS[grid.name], "mass": UNITS["block_mass"], "g": UNITS["gravity"]})
    if "thrust_angle" in grid.options:
        units["thrust_angle"] = UNITS["thrust_angle"]
    plain = [{name: None if isinstance(value, float) and math.isnan(value) else value for name, value in row.items()}
             for row in rows]
    return {"settings": settings, "units": units, "records": plain}


def _label(row: dict, g: float) -> str:
    """The record's id, with the scaling of the version."""
    if "scale" in row:
        return f"{row['record']} x{row['scale']:g}"
    if "target_pga" in row:
        return f"{row['record']} at {row['target_pga'] / g:.3g} g"
    return row["record"]


def _table(headers: list[tuple[str, str]], rows: list[list[str]], notes: dict[int, str]) -> list[str]:
    """Aligned text: two header lines, the first column left-aligned, the others right-aligned.

    ``notes`` maps a row index to a text printed after its first two cells instead of the rest.
    """
    widths = [max(len(header[0]), len(header[1]), *(len(row[column]) for i, row in enumerate(rows)
                                                     if i not in notes or column < 2))
              for column, header in enumerate(headers)]

    def line(cells: list[str]) -> str:
        return "  ".join(cell.ljust(widths[0]) if column == 0 else cell.rjust(widths[column])
                         for column, cell in enumerate(cells)).rstrip()

    lines = [line([header[0] for header in headers]), line([header[1] for header in headers])]
    for index, row in enumerate(rows):
        lines.append(line(row[:2]) + "  " + notes[index] if index in notes else line(row))
    return lines


def format_tables(rows: list[dict], grid, reference: float, args) -> str:
    """The terminal output: the grid, then the optimum and the range, then the stroke and residual, then the records.

    A yield grid shows the downslope displacement (−x at the end) where a friction grid shows the residual x.
    """
    g, q, c, values = args.g, args.q, grid.name, grid.values
    step = np.diff(values)
    spacing = f", step {step[0]:g}" if values.size > 1 and np.allclose(step, step[0], rtol=1e-6) else ""
    sliding = "" if c == "mu" and not grid.inverse else f"; {grid.describe()}"
    accelerations = (f" (yield accelerations k_y*g from {values[0] * g:.4g} to {values[-1] * g:.4g} m/s2)"
                     if c == "ky" else "")
    lines = [f"{GRID_LABELS[c]}: {values.size:,} value{'s' if values.size != 1 else ''} of {c} from {values[0]:g} to "
             f"{values[-1]:g}{spacing}{accelerations}{sliding}; block {args.mass:g} kg, g = {g:g} m/s2; exact solver",
             ""]
    notes = {index: row[STATUS] for index, row in enumerate(rows) if row[STATUS] != "ok"}
    edge = any(row[f"{c}_max_at_grid_edge"] == 1.0 for row in rows)
    gap = any(row["contiguous"] == 0.0 for row in rows)
    design = [[_label(row, g), format_number(row["pga"] / g, 3),
               shown(row, f"{c}_max", c) + ("*" if row[f"{c}_max_at_grid_edge"] == 1.0 else ""),
               shown(row, f"{c}_max_continuous", c), shown(row, "energy_dissipated_max", c),
               f"{shown(row, f'{c}_low', c)} to {shown(row, f'{c}_high', c)}"
               + (" (gap)" if row["contiguous"] == 0.0 else ""),
               shown(row, "energy_dissipated_reference", c), shown(row, "efficiency", c)] for row in rows]
    lines += _table([("", "record"), ("PGA", "[g]"), (f"{c}_max", "grid"), (f"{c}_max", "continuous"),
                     ("E_df,max", "[J]"), (f"near-optimal {c}", f"(q = {q:g})"), (f"E_df at {c} = {reference:g}", "[J]"),
                     ("efficiency", f"at {c} = {reference:g}")], design, notes)
    displaced, label = (("downslope_displacement", "downslope [m]") if c == "ky" else
                        ("residual_displacement", "residual [m]"))
    ends = (f"{c}_low", f"{c}_max", f"{c}_high")
    largest = "largest_downslope_displacement" if c == "ky" else "largest_residual_displacement"
    for name, largest_name, at_name, heading in (
            ("peak_relative_displacement", "largest_stroke", f"{c}_at_largest_stroke", "stroke [m]"),
            (displaced, largest, f"{c}_at_largest_residual_displacement", label)):
        table = [[_label(row, g), format_number(row["pga"] / g, 3)]
                 + [shown(row, f"{name}_at_{at}", c) for at in ends]
                 + [shown(row, largest_name, c), shown(row, at_name, c)] for row in rows]
        lines += [""] + _table([("", "record"), ("PGA", "[g]")] + [(heading, f"at {at}") for at in ends]
                               + [(heading, "largest in range"), ("where", c)], table, notes)
    displacement = ("downslope: -x at the end, SLAMMER's permanent displacement (the residual x is in --json and "
                    "--csv)" if c == "ky" else "residual: x at the end")
    lines += ["", f"stroke: largest |x|, x the block's displacement relative to the base; {displacement}; "
                  f"largest: over every grid {c} of the near-optimal range (what a device chosen in it must "
                  f"accommodate); near-optimal: E_df >= {q:g} E_df,max; efficiency: E_df({c} = {reference:g}) / "
                  "E_df,max (continuous)"]
    if edge:
        lines.append(f"* {c}_max is the first or last {c} of the grid: the maximum may lie beyond it "
                     f"(widen --{c.replace('_', '-')})")
    if gap:
        lines.append(f"(gap): some {c} between the range's ends fall below q E_df,max")
    lines.append("")
    seen = set()
    for row in rows:
        if row["record"] in seen:
            continue
        seen.add(row["record"])
        description = ", ".join(part for part in (row["event"], row["station"], row["component"]) if part)
        vertical = f"; a vertical component ({row['vertical']})" if row["vertical"] else ""
        lines.append(f"{row['record']}: {description or 'no description'}{vertical}; {row['source']}; "
                     f"{row['format']}, dt = {row['dt']:g} s from {row['dt_source']}")
    return "\n".join(lines)


#: The per-pair results of ``optimum --pair``, per direction: name -> (heading, units).
PLANAR_RESULTS = {"mu_max": ("mu_max", "1"), "energy_dissipated_max": ("E_df,max", "J"),
                  "peak_displacement_at_mu_max": ("stroke at mu_max", "m"),
                  "residual_displacement_at_mu_max": ("distance at the end", "m")}


def run_planar(args) -> int:
    """``optimum --pair``: per pair, the design answer in the plane and for each component alone; a table or JSON."""
    from stickslip.planar_sweeps import planar_sweep
    from stickslip.sweeps import write_cube

    if args.csv is not None:
        raise StickslipError("--csv: optimum --pair prints a table or --json; --out writes the cube")
    grid = grid_from_args(args)
    if grid.name != "mu":
        raise StickslipError("--pair sweeps friction ratios of a flat surface: give --mu or --mu-list")
    angles = angles_from_args(args)
    pairs = pairs_from_args(args)
    cube = planar_sweep(pairs, grid.values, mass=args.mass, g=args.g, angles=angles, progress=True)
    if args.out is not None:
        write_cube(cube, args.out)
    entries = []
    for index, pair in enumerate(pairs):
        at = cube.isel(pair=index)
        names = {"plane": "in the plane", "first": f"{at['first_component'].item()} alone",
                 "second": f"{at['second_component'].item()} alone"}
        rows = {names[direction]: {name: float(at[name].sel(direction=direction)) for name in PLANAR_RESULTS}
                for direction in names}
        if angles is not None:
            worst = int(np.argmax(at["energy_dissipated_max_azimuth"].values))
            rows[f"worst azimuth ({angles[worst]:g} deg)"] = {
                "mu_max": float(at["mu_max_azimuth"].values[worst]),
                "energy_dissipated_max": float(at["energy_dissipated_max_azimuth"].values[worst])}
        entries.append((pair, rows))
    if args.json:
        print(json.dumps({"mu": list(map(float, grid.values)), "mass": args.mass, "g": args.g,
                          "units": {name: units for name, (_, units) in PLANAR_RESULTS.items()},
                          "pairs": [{"pair": pair.name, "sources": [pair.first.meta.source, pair.second.meta.source],
                                     "any_pair": pair.any_pair,
                                     "any_pair_note": any_pair_note(pair) if pair.any_pair else None,
                                     "results": {label: {name: (None if math.isnan(value) else value)
                                                         for name, value in row.items()}
                                                 for label, row in rows.items()}}
                                    for pair, rows in entries]}, allow_nan=False))
        return 0
    width = max(len(label) for _, rows in entries for label in rows) + 2
    header = "".join(f"{heading + (f' [{units}]' if units != '1' else ''):>25}"
                     for heading, units in PLANAR_RESULTS.values())
    for number, (pair, rows) in enumerate(entries):
        print(("\n" if number else "") + f"{pair.name}: {grid.values.size} values of mu from {grid.values[0]:g} to "
              f"{grid.values[-1]:g}, mass {args.mass:g} kg, g = {args.g:g} m/s2"
              + (f"\npaired with --any-pair, {any_pair_note(pair)}" if pair.any_pair else ""))
        print(f"{'':<{width}}{header}")
        for label, row in rows.items():
            print(f"{label:<{width}}" + "".join(f"{row[name]:>25.5g}" if name in row and not math.isnan(row[name])
                                               else f"{'-':>25}" for name in PLANAR_RESULTS))
    if args.out is not None:
        print(f"written: {args.out}")
    return 0
