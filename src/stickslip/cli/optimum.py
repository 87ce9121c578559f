"""``stickslip optimum PATH...``: the design answer of each record (μ_max, near-optimal range, stroke, residual).

For every record (and scaled version) the exact solver sweeps the friction
grid, then :mod:`stickslip.optimum` gives μ_max on the grid and
continuous, E_df,max, the near-optimal range, whether μ_max is on the grid's
edge, the stroke (peak |x|) and residual displacement at μ_max and at both
ends of the range, and E_df and the efficiency at the reference μ.  A table
on the terminal, or ``--json``; ``--csv`` writes the same rows, ``--out`` the
sweep cube with the per-record results (as ``stickslip sweep`` does).

The table comes without xarray or pandas (the cube needs xarray), so that
the command answers in about the time numba takes to load its kernel.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

from stickslip.cli.grid_options import (
    add_grid_options,
    check_optimum_options,
    friction_ratios,
    note_never_slides,
    target_pgas,
)
from stickslip.cli.record_options import add_record_options, read_records_from_args
from stickslip.io import check_output_path, write_csv_atomic
from stickslip.optimum import DEFAULT_MU, RESULTS, STATUS
from stickslip.records.process import peak_ground_acceleration, scaled_versions
from stickslip.units import UNITS

#: The default grid as ``--mu`` writes it.
DEFAULT_MU_TEXT = f"{DEFAULT_MU['start']:g}:{DEFAULT_MU['stop']:g}:{DEFAULT_MU['step']:g}"


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "optimum",
        help="the friction ratio of maximum dissipation, its near-optimal range, and the stroke and residual "
             "displacement there, per record file",
        description=(
            "For each record file (formats may be mixed; each file's dt comes from the file, else from the "
            "manifests stickslip ships, else --dt), sweep the friction ratio mu with the exact solver and report: "
            "mu_max on the grid and continuous, E_df,max [J], the near-optimal range {mu : E_df >= q E_df,max}, "
            "whether mu_max is on the grid's edge, the stroke (peak |x| [m], x the block's displacement relative "
            "to the base) and the residual displacement x at the end [m] at mu_max and at both ends of the range, "
            "and E_df and the efficiency E_df / E_df,max at the reference mu. "
            f"The default grid, {DEFAULT_MU_TEXT} (400 values), is the collection study's: mu*g beyond a "
            "record's PGA dissipates nothing and few records exceed 1 g; steps of 0.0025 place mu_max well "
            "enough for the continuous search between its neighbours. Definitions: docs/studies.md."
        ),
    )
    parser.add_argument("paths", type=Path, nargs="+", metavar="PATH", help="record files (formats may be mixed)")
    add_grid_options(parser, default_mu=DEFAULT_MU_TEXT)
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
    check_optimum_options(args)
    explicit = args.mu != DEFAULT_MU_TEXT or args.mu_list is not None
    mu = friction_ratios(args)
    target_pga = target_pgas(args)
    records = read_records_from_args(args.paths, args)
    versions = [(record, version) for record in records for version in scaled_versions(record, args.scale, target_pga)]
    if explicit:
        note_never_slides([version for _, version in versions], mu, args.g)
    if args.out is not None:
        results, statuses = _with_cube(records, mu, target_pga, args)
    else:
        from stickslip.optimum import optimum, solve_curves

        flat = [version for _, version in versions]
        results, statuses = optimum(flat, solve_curves(flat, mu, args.mass, args.g), args.mass, args.g, args.q,
                                    args.reference_mu)
    rows = _rows(versions, results, statuses, args)
    if args.csv is not None:
        write_csv_atomic(args.csv, [{name: _cell(value) for name, value in row.items()} for row in rows])
    if args.json:
        print(json.dumps(_document(rows, mu, args), allow_nan=False))
    else:
        print(format_tables(rows, mu, args))
        for path in (args.csv, args.out):
            if path is not None:
                print(f"written: {path}")
    return 0


def _with_cube(records, mu, target_pga, args) -> tuple[dict, list[str]]:
    """Sweep into a cube with the per-record results, write it to ``--out``; the results, flat (record-major)."""
    from stickslip.optimum import with_optimum
    from stickslip.sweeps import sweep, write_cube

    cube = sweep(records, mu, scale=args.scale, target_pga=target_pga, mass=args.mass, g=args.g, progress=True,
                 config={"command": "stickslip optimum", "paths": [str(p) for p in args.paths],
                         "mu": list(map(float, mu))})
    cube = with_optimum(cube, records, args.q, args.reference_mu)
    write_cube(cube, args.out)
    return ({name: cube[name].values.reshape(-1) for name in RESULTS},
            [str(status) for status in cube[STATUS].values.reshape(-1)])


def _rows(versions, results: dict, statuses: list[str], args) -> list[dict]:
    """One dict per record (and scaled version): what was solved, the status and the :data:`RESULTS`."""
    rows = []
    for index, (record, version) in enumerate(versions):
        row = {"record": record.meta.record_id, "source": record.meta.source, "event": record.meta.event,
               "station": record.meta.station, "component": record.meta.component, "format": record.meta.format,
               "dt": record.dt, "dt_source": record.meta.dt_source, "pga": peak_ground_acceleration(version)}
        if args.scale is not None:
            row["scale"] = args.scale[index % len(args.scale)]
        elif args.target_pga is not None:
            row["target_pga"] = row["pga"]
            row["scale_factor"] = row["pga"] / peak_ground_acceleration(record)
        row[STATUS] = statuses[index]
        row.update({name: float(results[name][index]) for name in RESULTS})
        row.update(near_optimal_fraction=args.q, reference_mu=args.reference_mu)
        rows.append(row)
    return rows


def _cell(value):
    """A CSV cell: "" for NaN."""
    return "" if isinstance(value, float) and math.isnan(value) else value


def _document(rows: list[dict], mu: np.ndarray, args) -> dict:
    """The ``--json`` object: settings, the units of every number, and the rows (NaN as null)."""
    settings = {"mu": [float(value) for value in mu], "near_optimal_fraction": args.q, "reference_mu": args.reference_mu,
                "mass": args.mass, "g": args.g, "method": "exact"}
    units = {name: UNITS[name] for name, value in rows[0].items() if isinstance(value, float)}
    units.update(mu=UNITS["mu"], mass=UNITS["block_mass"], g=UNITS["gravity"])
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


def _number(value: float, digits: int = 4) -> str:
    return "-" if math.isnan(value) else f"{value:.{digits}g}"


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


def format_tables(rows: list[dict], mu: np.ndarray, args) -> str:
    """The terminal output: the grid, then μ_max and the range, then the stroke and residual, then the records."""
    g, q, reference = args.g, args.q, args.reference_mu
    step = np.diff(mu)
    spacing = f", step {step[0]:g}" if mu.size > 1 and np.allclose(step, step[0], rtol=1e-6) else ""
    lines = [f"friction grid: {mu.size:,} value{'s' if mu.size != 1 else ''} of mu from {mu[0]:g} to {mu[-1]:g}"
             f"{spacing}; block {args.mass:g} kg, "
             f"g = {g:g} m/s2; exact solver", ""]
    notes = {index: row[STATUS] for index, row in enumerate(rows) if row[STATUS] != "ok"}
    edge = any(row["mu_max_at_grid_edge"] == 1.0 for row in rows)
    gap = any(row["contiguous"] == 0.0 for row in rows)
    design = [[_label(row, g), _number(row["pga"] / g, 3),
               _number(row["mu_max"]) + ("*" if row["mu_max_at_grid_edge"] == 1.0 else ""),
               _number(row["mu_max_continuous"], 5), _number(row["energy_dissipated_max"]),
               f"{_number(row['mu_low'])} to {_number(row['mu_high'])}" + (" (gap)" if row["contiguous"] == 0.0 else ""),
               _number(row["energy_dissipated_reference"]), _number(row["efficiency"], 3)] for row in rows]
    lines += _table([("", "record"), ("PGA", "[g]"), ("mu_max", "grid"), ("mu_max", "continuous"),
                     ("E_df,max", "[J]"), ("near-optimal mu", f"(q = {q:g})"), (f"E_df at mu = {reference:g}", "[J]"),
                     ("efficiency", f"at mu = {reference:g}")], design, notes)
    stroke = [[_label(row, g), _number(row["pga"] / g, 3)]
              + [_number(row[f"{name}_at_{at}"]) for name in ("peak_relative_displacement", "residual_displacement")
                 for at in ("mu_low", "mu_max", "mu_high")] for row in rows]
    lines += [""] + _table([("", "record"), ("PGA", "[g]"), ("stroke [m]", "at mu_low"), ("stroke [m]", "at mu_max"),
                            ("stroke [m]", "at mu_high"), ("residual [m]", "at mu_low"),
                            ("residual [m]", "at mu_max"), ("residual [m]", "at mu_high")], stroke, notes)
    lines += ["", "stroke: largest |x|, x the block's displacement relative to the base; residual: x at the end; "
                  f"near-optimal: E_df >= {q:g} E_df,max; efficiency: E_df(mu = {reference:g}) / E_df,max (continuous)"]
    if edge:
        lines.append("* mu_max is the first or last mu of the grid: the maximum may lie beyond it (widen --mu)")
    if gap:
        lines.append("(gap): some mu between the range's ends fall below q E_df,max")
    lines.append("")
    seen = set()
    for row in rows:
        if row["record"] in seen:
            continue
        seen.add(row["record"])
        description = ", ".join(part for part in (row["event"], row["station"], row["component"]) if part)
        lines.append(f"{row['record']}: {description or 'no description'}; {row['source']}; {row['format']}, "
                     f"dt = {row['dt']:g} s from {row['dt_source']}")
    return "\n".join(lines)
