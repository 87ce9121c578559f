"""``stickslip optimum PATH...``: the design answer of each record (μ_max or k_y,max, near-optimal range, stroke, residual).

For every record (and scaled version) the exact solver sweeps the friction
grid (or, with ``--ky``, the yield coefficients of a block on a slope),
extended beyond any edge that cuts a near-optimal range and refined around
any range that holds fewer than ``--range-points`` grid values
(:func:`stickslip.optimum.grid_for_ranges`; the output says where), then :mod:`stickslip.optimum` gives the value of maximum dissipation
on the grid and continuous, E_df at the continuous maximum, the near-optimal
range, whether the maximum is on the grid's edge, the stroke (peak |x|) and
residual displacement (and, for k_y, the downslope displacement) at the
grid's maximum and at both ends of the range, and E_df and the efficiency at
the reference value.  A table on the terminal, or ``--json``; ``--csv``
writes the same rows, ``--out`` the sweep cube on the same grid with the
per-record results (as ``stickslip sweep`` does).

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
    add_chart_levels_option,
    add_chart_values_options,
    add_optimum_options,
    add_range_points_option,
    add_scaling_options,
    chart_contents,
    chart_levels_from_args,
    chart_values_from_args,
    check_optimum_options,
    checked_range_points,
    note_never_slides,
    refuse_chart_without_model_chart,
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
    any_vertical_note,
    motion_config,
    motion_kind_from_args,
    motion_notes,
    motions_from_args,
    pair_fields,
)
from stickslip.cli.record_options import add_keep_going_option, add_record_options
from stickslip.errors import StickslipError
from stickslip.objectives import OBJECTIVES
from stickslip.grids import COEFFICIENTS, Grid, range_values
from stickslip.optimum import (
    DEFAULT_MU,
    PERCENTILES,
    STATUS,
    STROKES,
    SUMMARISED,
    Curves,
    range_sizes,
    AT_LEAST,
    AT_MOST,
    EITHER_SIDE,
    grid_for_ranges,
    range_bounds,
    results_of,
    solve_curves,
    statistics_over_records,
)
from stickslip.plumbing.files import check_output_path, write_csv_atomic
from stickslip.records.components import vertical_component
from stickslip.records.process import peak_ground_acceleration, scaled_versions
from stickslip.records.verticals_apart import left_out_line, verticals_apart
from stickslip.reports.design_answer import format_number, shown
from stickslip.units import UNITS, energy_units, readable_units

def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "optimum",
        help="the friction ratio (or yield acceleration) of maximum dissipation, its near-optimal range, and the "
             "stroke and residual displacement there, per record file",
        description=(
            "For each record file (formats may be mixed; each file's dt comes from the file, else from the "
            "manifests stickslip ships, else --dt), sweep the friction ratio mu with the exact solver and report: "
            "mu_max on the grid and continuous, E_df,max [J] at the continuous mu_max, the near-optimal range "
            "{mu : E_df >= q E_df,max} on the grid, whether mu_max is on the grid's edge, the stroke (peak |x| [m], "
            "x the block's displacement relative to the base) and the residual displacement x at the end [m] at the "
            "grid's mu_max and at both ends of the range, and E_df and the efficiency E_df / E_df,max at the "
            "reference mu. "
            f"The default grid, {DEFAULT_MU_TEXT} (400 values), is the collection study's: mu*g beyond a "
            "record's PGA dissipates nothing and few records exceed 1 g; steps of 0.0025 place mu_max well "
            "enough for the continuous search between its neighbours. Where a record's near-optimal range holds "
            "fewer than --range-points grid values (a weak record: mu_max 0.0066 has two on the default grid), "
            "the grid is refined around it for every record; where a range reaches the grid's edge, the grid is first "
            "extended beyond it (down towards 0, or up), and where it cannot be, the range's end and largest values are "
            "marked as bounds (at most, at least); the output says which records and where. "
            "With --ky or --ky-list (no default: give the yield accelerations, such as 0.01g:0.5g:0.01g) the "
            "block sits on a slope and slides downslope past ky*g (--direction both: also upslope, at a "
            "--thrust-angle); the same results are named ky_max, ky_low, ky_high ..., and the permanent "
            "downslope displacement (SLAMMER's) at ky_max and the range's ends is added. With --pair, the files are "
            "taken two by two as the components of one station: the block in the plane and under each component alone "
            "each get a record's answer (mu_max on the grid and continuous, the near-optimal range, the grid extended "
            "and refined for it, the stroke), with a sentence on how the plane's mu_max relates to the components' "
            "(--angles STEP: also the worst turned axis). Definitions: docs/studies.md."
        ),
    )
    parser.add_argument("paths", type=Path, nargs="+", metavar="PATH", help="record files (formats may be mixed)")
    add_model_options(parser, grids=True)
    add_scaling_options(parser)
    add_optimum_options(parser)
    add_range_points_option(parser)
    add_pair_options(parser)
    add_vertical_options(parser)
    add_angle_option(parser)
    add_record_options(parser)
    add_keep_going_option(parser)
    parser.add_argument("--objective", choices=tuple(OBJECTIVES), default=None,
                        help="what is optimal: " + "; ".join(f"{name}, {objective.summary}" for name, objective in
                                                           OBJECTIVES.items())
                             + " (default: the model's own, energy for every model stickslip ships); the model must "
                               "declare it")
    parser.add_argument("--json", action="store_true",
                        help="print one JSON object (settings, units, one entry per record) instead of the table")
    parser.add_argument("--csv", type=Path, default=None, metavar="FILE", help="write one row per record to FILE")
    parser.add_argument("--out", type=Path, default=None, metavar="CUBE",
                        help="write the sweep cube with the per-record results (NetCDF), as 'stickslip sweep' does")
    parser.add_argument("--chart", type=Path, default=None, metavar="PNG",
                        help="write the model's design chart to PNG (a model that declares one): over the values of "
                             "--chart-values and the grid's mu, the record's own, or over several the median, the 84th "
                             "percentile and, over 7 or more, the mean; the model's quantities in colours and in "
                             f"lines ({chart_contents()}), and for a chart of an --objective's quantity the best mu "
                             "at each value marked")
    add_chart_values_options(parser)
    add_chart_levels_option(parser)
    parser.set_defaults(func=run)


def run(args) -> int:
    for path, what in ((args.csv, "the CSV table"), (args.out, "the NetCDF cube"), (args.chart, "the design chart")):
        if path is not None:
            check_output_path(path, what)
    kind = motion_kind_from_args(args)
    entry = model_from_args(args, kind)
    if not entry.designs and not entry.answer_columns:
        raise StickslipError(f"--model {entry.name} ({entry.summary}) has no design answer over a grid; its cube is "
                             "'stickslip sweep'")
    parameters = parameters_from_args(args, entry, grids=True)
    grid, explicit = optimum_grid(parameters)
    refuse_chart_without_model_chart(args, entry, chart_asked=args.chart is not None)
    entry.objective(args.objective, "--objective")  # refuses an objective the model does not declare
    chart_values, chart_levels = chart_values_from_args(args, entry), chart_levels_from_args(args, entry)
    for option, value in (("--chart-values" if args.chart_radii is None else "--chart-radii", chart_values),
                          ("--chart-levels", chart_levels)):
        if value is not None and args.chart is None:
            raise StickslipError(f"{option}: give --chart PNG, the file of the design chart they are for")
    if not entry.designs:
        return run_directions(args, entry, kind, grid, parameters)
    angles_from_args(args)  # refuses --angles without --pair
    reference = check_optimum_options(args, entry, grid.name)
    min_points = checked_range_points(args)
    options = scheme_options_from_args(args, entry)
    target_pga = target_pgas(args)
    design = entry.design(grid, args.method, options, args.objective, **parameters)
    records = motions_from_args(args, kind)
    if args.out is not None:  # the cube's every variable solved with the curves: one sweep for both
        design = design.with_results(entry.cube_variables(design.case, records))
    versions = [(record, version) for record in records for version in scaled_versions(record, args.scale, target_pga)]
    if explicit:
        note_never_slides([version for _, version in versions], design)
    flat = [version for _, version in versions]
    curves, extensions, refinements = grid_for_ranges(flat, solve_curves(flat, design), design, args.q, min_points)
    given, design = grid, design.with_values(curves.grid.values)  # the grid asked for; the block on the grid solved
    labels = [_label({"record": record.meta.record_id, **_scaling(record, version, index, args)}, design.g)
              for index, (record, version) in enumerate(versions)]
    refined = [(labels[refinement.case], refinement) for refinement in refinements]
    extended = [(labels[extension.case], extension) for extension in extensions]
    if args.out is not None:
        results, statuses = _with_cube(entry, records, design, curves, parameters, target_pga, reference, options,
                                       extended, refined, min_points, args)
    else:
        from stickslip.optimum import optimum

        results, statuses = optimum(flat, curves, design, args.q, reference)
    rows = _rows(entry, versions, results, statuses, design, range_sizes(curves, args.q), reference, args)
    included, apart = verticals_apart([(_label(row, design.g), row["source"], row["vertical"]) for row in rows])
    statistics = statistics_over_records(curves, included=included) if included.sum() > 1 else None
    if args.csv is not None:
        write_csv_atomic(args.csv, [{name: _cell(value) for name, value in row.items()} for row in rows])
    if args.chart is not None:
        horizontal = [record for record in records if vertical_component(record.meta) is None]
        _write_chart(args.chart, entry, horizontal or records, chart_values, given.values, parameters, chart_levels,
                     args.objective)
    if args.json:
        print(json.dumps(_document(rows, entry.name, design, given, extended, refined, min_points, reference, args,
                                   statistics, apart), allow_nan=False))
    else:
        print(format_tables(rows, entry, design, reference, args, given, extended, refined, min_points, statistics,
                            apart))
        for path in (args.csv, args.out, args.chart):
            if path is not None:
                print(f"written: {path}")
    return 0


def _write_chart(path: Path, entry, motions, values, mu, parameters: dict, steps: tuple[float, float] | None,
                 objective: str | None) -> None:
    """The model ``entry``'s design chart (:meth:`~stickslip.models.entry.Model.design_chart`) of ``motions`` over
    ``values`` of its :attr:`~stickslip.models.entry.Model.chart_over` (None: the model's own) and the friction
    ratios ``mu`` [1], for the ``objective`` named (None: the model's own), to the PNG ``path``: the motion's own
    responses, or their median, 84th percentile and mean over several, which the caller gives without the vertical
    components among several (unless every one is vertical); its levels every ``steps`` (the filled quantity's and
    the lines'), else the chart's own."""
    from stickslip.constants import STANDARD_GRAVITY
    from stickslip.records.vertical import WithVertical
    from stickslip.reports.isolator_plots import ChartLevels, plot_design_chart
    from stickslip.reports.plots import save_figure

    others = {name: value for name, value in parameters.items() if name != entry.chart_over and value is not None}
    statistics = entry.design_chart(motions, values, mu, progress=True, objective=objective, **others)
    title = None
    if len(motions) == 1:
        meta = motions[0].meta
        named = ", ".join(filter(None, (meta.event, meta.station, meta.component))) or meta.record_id
        title = f"{entry.chart_title}: {named}" + (", with its vertical" if isinstance(motions[0], WithVertical)
                                                   else "")
    levels = ChartLevels.every(*steps) if steps is not None else None
    figure = plot_design_chart(statistics, g=others.get("g") or STANDARD_GRAVITY, title=title,
                               levels=levels)
    save_figure(figure, path, dpi=110)


def optimum_grid(parameters: dict) -> tuple[Grid, bool]:
    """The grid of the swept coefficient given, taken out of ``parameters``, or the default friction grid;
    and whether it was given."""
    named = [name for name in COEFFICIENTS if name in parameters]
    if named:
        return Grid(named[0], parameters.pop(named[0])), True
    return Grid("mu", range_values(DEFAULT_MU["start"], DEFAULT_MU["stop"], DEFAULT_MU["step"])), False


def _refinement_text(refined: list, name: str, min_points: int) -> str:
    """The grid's refinements in one line each, ``record: what was added`` (empty for none)."""
    return "\n".join(f"{label}: {refinement.describe(name, min_points)}" for label, refinement in refined)


def _extension_text(extended: list, name: str) -> str:
    """The grid's extensions in one line each, ``record: what was added`` (empty for none)."""
    return "\n".join(f"{label}: {extension.describe(name)}" for label, extension in extended)


def _with_cube(entry, records, design, curves: Curves, parameters: dict, target_pga, reference: float, options: dict,
               extended: list, refined: list, min_points: int, args) -> tuple[dict, list[str]]:
    """The cube of ``curves`` with the per-record results, written to ``--out``; the results and the statuses, flat
    (record-major).

    ``design`` is the block on the grid after extension and refinement, ``curves`` what it solved there, every
    variable of the cube (:meth:`~stickslip.optimum.Design.with_results`), so that nothing is solved
    again; the cube's attributes ``grid_extension``,
    ``range_points`` and ``grid_refinement`` say how it was extended and refined (``extended``: (record label,
    :class:`~stickslip.optimum.GridExtension`); ``refined``: (record label,
    :class:`~stickslip.optimum.RangeRefinement`)).
    """
    from stickslip.sweeps import write_cube

    grid = design.grid
    config = {"command": "stickslip optimum", "model": entry.name, "paths": [str(p) for p in args.paths],
              **motion_config(args), grid.name: list(map(float, grid.values)), **parameters}
    cube = entry.sweep(records, args.method, scale=args.scale, target_pga=target_pga, progress=True, config=config,
                       options=options or None, solved=curves, **{grid.name: grid.values}, **parameters)
    cube = entry.design_answer(cube, records, args.q, reference, design.objective.name)
    cube.attrs.update(grid_extension=_extension_text(extended, grid.name) or "none", range_points=min_points,
                      grid_refinement=_refinement_text(refined, grid.name, min_points) or "none")
    write_cube(cube, args.out)
    return ({name: cube[name].values.reshape(-1) for name in results_of(grid.name, design.demands)},
            [str(status) for status in cube[STATUS].values.reshape(-1)])


def _scaling(record, version, index: int, args) -> dict:
    """How a version was scaled: ``scale``, or ``target_pga`` [m/s²] and ``scale_factor``; nothing when it was not."""
    if args.scale is not None:
        return {"scale": args.scale[index % len(args.scale)]}
    if args.target_pga is not None:
        pga = peak_ground_acceleration(version)
        return {"target_pga": pga, "scale_factor": pga / peak_ground_acceleration(record)}
    return {}


def _sources_and_vertical(motion) -> tuple[str, str | None]:
    """The files a motion was read from (a pair's two, joined by " + ") and its vertical with its sense (and, taken
    with ``--any-vertical``, what its names say against it), or None."""
    from stickslip.records.pair import RecordPair
    from stickslip.records.vertical import WithVertical

    horizontal = motion.horizontal if isinstance(motion, WithVertical) else motion
    records = (horizontal.first, horizontal.second) if isinstance(horizontal, RecordPair) else (horizontal,)
    sources = " + ".join(record.meta.source or record.meta.record_id or "" for record in records)
    if not isinstance(motion, WithVertical):
        return sources, None
    taken = f", taken with --any-vertical, {any_vertical_note(motion)}" if motion.any_vertical else ""
    return sources, f"{motion.vertical.meta.source or motion.vertical.meta.record_id}, read {motion.sense}{taken}"


def _rows(entry, versions, results: dict, statuses: list[str], design, in_range, reference: float, args) -> list[dict]:
    """One dict per record (and scaled version): what was solved, what the model ``entry`` notes of the motion
    alone (:meth:`~stickslip.models.entry.Model.motion_notes`: the pendulum's lift-off), the status and the
    per-record results.

    ``in_range``: how many grid values each near-optimal range holds (``grid_values_in_range``).
    """
    grid = design.grid
    rows = []
    for index, (record, version) in enumerate(versions):
        sources, with_vertical = _sources_and_vertical(record)
        row = {"record": record.meta.record_id, "source": sources, "event": record.meta.event,
               "station": record.meta.station, "component": record.meta.component,
               "vertical": vertical_component(record.meta), "with_vertical": with_vertical,
               "format": record.meta.format,
               "dt": record.dt, "dt_source": record.meta.dt_source, "pga": peak_ground_acceleration(version)}
        row.update(_scaling(record, version, index, args))
        row.update(entry.motion_notes(version, design.g))
        row[STATUS] = statuses[index]
        row.update({name: float(results[name][index]) for name in results_of(grid.name, design.demands)})
        row["grid_values_in_range"] = int(in_range[index])
        row.update({"near_optimal_fraction": args.q, f"reference_{grid.name}": reference})
        rows.append(row)
    return rows


def _cell(value):
    """A CSV cell: "" for NaN or None."""
    return "" if value is None or isinstance(value, float) and math.isnan(value) else value


def _document(rows: list[dict], model: str, design, given, extended: list, refined: list, min_points: int,
              reference: float, args, statistics: dict | None, apart: list[dict]) -> dict:
    """The ``--json`` object: settings, the units of every number, the rows (NaN as null, with the ``bounds`` of
    :func:`~stickslip.optimum.range_bounds`) and, for several records, the statistics over them at each grid value
    (``records``: how many entered; null with fewer than two) and ``left_out_of_statistics``, the vertical
    components left out of them (``record``, ``source``, ``reason``).

    The settings' grid is the one solved (``design.grid``, after extension and refinement); ``given_{c}`` is the
    grid asked for (``given``), ``grid_extensions`` one entry per record and side whose range reached the grid's
    edge (the side, the span added, its step, the values added, the grid's new edge there and whether the range
    now ends inside the grid), and ``grid_refinements`` one entry per record whose range needed more values (the
    span, its step, the values added, and the grid values in the range before and after).
    """
    grid = design.grid
    settings = {grid.name: [float(value) for value in grid.values], f"given_{grid.name}": given.values.tolist(),
                "model": model, **design.settings(), "read": motion_config(args),
                "grid_extensions": [{"record": label, "side": extension.side, "start": extension.start,
                                     "stop": extension.stop, "step": extension.step, "values_added": extension.added,
                                     "grid_edge": extension.edge, "range_inside": extension.inside}
                                    for label, extension in extended],
                "range_points": min_points,
                "grid_refinements": [{"record": label, "start": refinement.start, "stop": refinement.stop,
                                      "step": refinement.step, "values_added": refinement.added,
                                      "grid_values_in_range_before": refinement.before,
                                      "grid_values_in_range": refinement.after} for label, refinement in refined],
                "near_optimal_fraction": args.q, f"reference_{grid.name}": reference,
                "objective": design.objective.name}
    results = results_of(grid.name, design.demands)
    units = {name: results[name][0] if name in results else UNITS[name] for name, value in rows[0].items()
             if isinstance(value, float)}
    units.update({grid.name: UNITS[grid.name], f"given_{grid.name}": UNITS[grid.name], **design.settings_units()})
    plain = [{**{name: None if isinstance(value, float) and math.isnan(value) else value
                 for name, value in row.items()}, "bounds": range_bounds(row, grid.name, list(design.demands))}
             for row in rows]
    document = {"settings": settings, "units": units, "records": plain}
    if len(rows) > 1:
        document["statistics"] = None
        document["left_out_of_statistics"] = apart
    if statistics is not None:
        document["statistics"] = {"records": len(rows) - len(apart), "percentiles": list(PERCENTILES),
                                  grid.name: [float(value) for value in grid.values],
                                  **{name: [[_plain(value) for value in row] for row in values]
                                     for name, values in statistics.items()}}
        units.update({name: _statistic_units(design)[name] for name in statistics})
    return document


def _plain(value: float) -> float | None:
    """A JSON number: None for NaN."""
    return None if math.isnan(value) else float(value)


def _statistic_units(design) -> dict[str, str]:
    """The units of each response :func:`~stickslip.optimum.statistics_over_records` summarises."""
    return {**{name: units for name, (units, _) in SUMMARISED.items()},
            **{name: units for name, (units, _, _) in design.demands.items()}}


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


def format_tables(rows: list[dict], entry, design, reference: float, args, given, extended: list, refined: list,
                  min_points: int, statistics: dict | None = None, apart: list[dict] = ()) -> str:
    """The terminal output: the grid, then the optimum and the range, then the stroke and residual (and the
    model's demands), then the statistics over the records at each grid value and the vertical components
    ``apart`` from them, then the records.

    ``entry`` is the model's entry (what its mass is of, :attr:`~stickslip.models.entry.Model.mass_of`, and the
    columns of its notes on each motion alone, :attr:`~stickslip.models.entry.Model.motion_note_columns`),
    ``design`` the block on the grid solved, ``given`` the grid asked for, ``extended`` the (record label,
    :class:`~stickslip.optimum.GridExtension`) of every record whose near-optimal range reached the grid's edge,
    ``refined`` the (record label, :class:`~stickslip.optimum.RangeRefinement`) of every record whose range needed
    more values.  Every value beside the continuous maximum is the continuous one (E_df there); values on the grid
    say so; a value that is a bound (:func:`~stickslip.optimum.range_bounds`) has ``≤`` or ``≥`` before it.
    A yield grid shows the downslope displacement (−x at the end) where a friction grid shows the residual x.
    Energies are in J, or J/kg for the default 1 kg block (:func:`stickslip.units.energy_units`).
    """
    grid = design.grid
    g, q, c, values, slope = design.g, args.q, grid.name, given.values, grid.coefficient.slope
    energy = readable_units(energy_units(design.mass))
    step = np.diff(values)
    spacing = f", step {step[0]:g}" if values.size > 1 and np.allclose(step, step[0], rtol=1e-6) else ""
    sliding = f"; {design.describe()}" if design.describe() else ""
    accelerations = (f" (yield accelerations k_y*g from {values[0] * g:.4g} to {values[-1] * g:.4g} m/s2)"
                     if slope else "")
    lines = [f"{grid.coefficient.heading}: {values.size:,} value{'s' if values.size != 1 else ''} of {c} from {values[0]:g} to "
             f"{values[-1]:g}{spacing}{accelerations}{sliding}; {entry.mass_of} {design.mass:g} kg, g = {g:g} m/s2; "
             f"{design.scheme.name} solver"]
    if extended:
        lines.append("extended where a near-optimal range reached the grid's edge, for every record:")
        lines += [f"  {line}" for line in _extension_text(extended, c).splitlines()]
    if refined:
        lines.append(f"refined where a near-optimal range held fewer than {min_points} grid values (--range-points), "
                     f"for every record: {grid.values.size:,} values of {c} in all")
        lines += [f"  {line}" for line in _refinement_text(refined, c, min_points).splitlines()]
    elif extended:
        lines.append(f"{grid.values.size:,} values of {c} in all")
    lines.append("")
    notes = {index: row[STATUS] for index, row in enumerate(rows) if row[STATUS] != "ok"}
    marks = [range_bounds(row, c, list(design.demands)) for row in rows]
    edge = any(row[f"{c}_max_at_grid_edge"] == 1.0 for row in rows)
    gap = any(row["contiguous"] == 0.0 for row in rows)
    answers = [[_label(row, g), format_number(row["pga"] / g, 3),
               shown(row, f"{c}_max", c) + ("*" if row[f"{c}_max_at_grid_edge"] == 1.0 else ""),
               shown(row, f"{c}_max_continuous", c), shown(row, "energy_dissipated_max_continuous", c),
               f"{shown(row, f'{c}_low', c, mark)} to {shown(row, f'{c}_high', c, mark)}"
               + (" (gap)" if row["contiguous"] == 0.0 else ""),
               mark.get("grid_values_in_range", "") + f"{row['grid_values_in_range']:,}",
               shown(row, "energy_dissipated_reference", c), shown(row, "efficiency", c)]
               for row, mark in zip(rows, marks)]
    lines += _table([("", "record"), ("PGA", "[g]"), (f"{c}_max", "grid"), (f"{c}_max", "continuous"),
                     (f"E_df,max [{energy}]", f"at continuous {c}_max"),
                     (f"near-optimal {c}", f"on the grid, q = {q:g}"),
                     ("grid values", "in the range"), (f"E_df at {c} = {reference:g}", f"[{energy}]"),
                     ("efficiency", f"at {c} = {reference:g}")], answers, notes)
    displaced, label = (("downslope_displacement", "downslope [m]") if slope else
                        ("residual_displacement", "residual [m]"))
    ends = (f"{c}_low", f"{c}_max", f"{c}_high")
    largest = "largest_downslope_displacement" if slope else "largest_residual_displacement"
    demands = [(name, f"largest_{name}", f"{c}_at_largest_{name}",
                label + ("" if units == "1" else f" [{energy if units == 'J' else units}]"))
               for name, (units, _, label) in design.demands.items()]
    for name, largest_name, at_name, heading in (
            ("peak_relative_displacement", "largest_stroke", f"{c}_at_largest_stroke", "stroke [m]"),
            (displaced, largest, f"{c}_at_largest_residual_displacement", label), *demands):
        table = [[_label(row, g), format_number(row["pga"] / g, 3)]
                 + [shown(row, f"{name}_at_{at}", c) for at in ends]
                 + [shown(row, largest_name, c, mark), shown(row, at_name, c, mark)] for row, mark in zip(rows, marks)]
        places = [(heading, f"at grid {at}" if at == f"{c}_max" else f"at {at}") for at in ends]
        lines += [""] + _table([("", "record"), ("PGA", "[g]"), *places, (heading, "largest in range"), ("where", c)],
                               table, notes)
    displacement = ("downslope: -x at the end, SLAMMER's permanent displacement (the residual x is in --json and "
                    "--csv)" if slope else "residual: x at the end")
    stroke = (f"stroke: largest |x|, x the block's displacement relative to the base; {displacement}"
              if tuple(design.strokes) == STROKES else
              f"stroke: the {design.strokes[0]}; residual: the {design.strokes[1]}".replace("_", " "))
    # Under another objective than the paper's, its own note (below) says what near-optimal and efficiency mean.
    energy_terms = (f"; near-optimal: the grid's {c} with E_df >= {q:g} E_df,max; E_df,max: E_df at the continuous "
                    f"{c}_max; efficiency: E_df({c} = {reference:g}) / E_df,max"
                    if design.objective.name == "energy" else "")
    lines += ["", f"{stroke}; largest: over every grid {c} of the near-optimal range (what a device chosen in it "
                  f"must accommodate){energy_terms}"]
    if edge:
        lines.append(f"* {c}_max is the first or last {c} of the grid: the maximum may lie beyond it "
                     f"(widen --{c.replace('_', '-')})")
    if gap:
        lines.append(f"(gap): some {c} between the range's ends fall below q E_df,max")
    if any(marks):
        lines.append(f"{AT_MOST} {AT_LEAST}: the near-optimal range reaches the grid's edge, which could not be "
                     f"extended far enough: its end there is a bound ({AT_MOST} {c}_low, {AT_LEAST} {c}_high), so are "
                     f"its largest values (in magnitude) and the grid values in it; the {c} where a largest value "
                     f"occurs lies on the bound's side ({EITHER_SIDE}: either side)")
    lines += [f"{label}: {long_name}" for _, long_name, label in design.demands.values()]
    if design.objective.note:
        lines.append(design.objective.note.format(c=c))
    noted = [name for name in entry.motion_note_columns if name in rows[0]]
    if noted:
        table = [[_label(row, g), format_number(row["pga"] / g, 3)]
                 + [f"{row[name]:,}" if isinstance(row[name], int) else format_number(row[name]) for name in noted]
                 for row in rows]
        lines += [""] + _table([("", "record"), ("PGA", "[g]"), *(entry.motion_note_columns[name] for name in noted)],
                               table, {})
        lines.append(entry.motion_note_text.format(c=c))
    if statistics is not None:
        lines += [""] + _statistics_table(statistics, design, len(rows) - len(apart))
    elif len(rows) > 1:
        lines += ["", f"no statistics over the records: {len(rows) - len(apart)} horizontal record(s), they need two"]
    lines += [line for line in (left_out_line(apart),) if line]
    lines.append("")
    seen = set()
    for row in rows:
        if row["record"] in seen:
            continue
        seen.add(row["record"])
        description = ", ".join(part for part in (row["event"], row["station"], row["component"]) if part)
        vertical = f"; a vertical component ({row['vertical']})" if row["vertical"] else ""
        vertical += f"; with its vertical {row['with_vertical']}" if row["with_vertical"] else ""
        lines.append(f"{row['record']}: {description or 'no description'}{vertical}; {row['source']}; "
                     f"{row['format']}, dt = {row['dt']:g} s from {row['dt_source']}")
    return "\n".join(lines)


#: The most grid values the terminal's statistics table shows (--json has every one).
STATISTICS_ROWS = 20

#: The statistics table stops at the last grid value where E_df's 84th percentile is at least this share of its largest:
#: past it the block hardly slides, and the rows would be zeros.
SLIDING_SHOWN = 0.01


def _statistics_table(statistics: dict, design, cases: int) -> list[str]:
    """The median and 84th percentile over the ``cases`` of each response at (up to :data:`STATISTICS_ROWS`) grid
    values, the nearest to even steps over the range where the block slides: up to the last value where the largest
    percentile of E_df is at least :data:`SLIDING_SHOWN` of its largest (past it, rows of zeros or nearly; the whole
    grid when it is zero throughout)."""
    grid, c = design.grid, design.grid.name
    upper = np.nan_to_num(statistics["energy_dissipated"][-1])
    sliding = np.flatnonzero((upper > 0.0) & (upper >= SLIDING_SHOWN * upper.max()))
    last = int(sliding[-1]) if sliding.size else grid.values.size - 1
    evenly = np.linspace(grid.values[0], grid.values[last], min(last + 1, STATISTICS_ROWS))  # even in the value
    shown_at = np.unique(np.abs(grid.values[:last + 1, None] - evenly[None, :]).argmin(axis=0))
    energy = readable_units(energy_units(design.mass))  # J/kg for the default 1 kg block
    labels = {name: (label, energy if units == "J" else units) for name, (label, units) in (
        *((name, (label, units)) for name, (units, label) in SUMMARISED.items()),
        *((name, (label, units)) for name, (units, _, label) in design.demands.items()))}
    headers = [("", c)] + [(f"{labels[name][0]}" + ("" if labels[name][1] == "1" else f" [{labels[name][1]}]"),
                            f"p{percentile:g}") for name in statistics for percentile in PERCENTILES]
    table = [[format_number(float(grid.values[index]), 4)]
             + [format_number(float(values[row, index]), 4) for values in statistics.values()
                for row in range(len(PERCENTILES))]
             for index in shown_at]
    every = "" if shown_at.size == grid.values.size else (f"; {shown_at.size} of the grid's {grid.values.size:,} "
                                                           f"values shown, every one in --json")
    where = "" if last == grid.values.size - 1 else (
        f"; {c} up to {format_number(float(grid.values[last]), 4)}, where the block slides: above it E_df's "
        f"p{PERCENTILES[-1]:g} is below {SLIDING_SHOWN:.0%} of its largest")
    return [f"over the {cases} records, at each {c}: p50 the median, p84 the 84th percentile{where}{every}"] + \
        _table(headers, table, {})


def run_directions(args, entry, kind: str, grid: Grid, parameters: dict) -> int:
    """``optimum`` for a model whose sweep gives its design answer per direction (the plane and each component
    alone, ``--pair``; with ``--angles`` the worst turned axis too): a table or JSON per motion.

    Each direction's answer is a record's (continuous μ_max, near-optimal range, stroke), on the grid extended and
    refined for its range as ``optimum`` does for a record, with a sentence on how the plane's μ_max relates to
    the components'.
    """
    from stickslip.sweeps import write_cube

    if args.csv is not None:
        raise StickslipError(f"--csv: optimum of the {entry.name} model prints a table or --json; --out writes the "
                             "cube")
    angles = angles_from_args(args)
    reference = check_optimum_options(args, entry, grid.name)
    min_points = checked_range_points(args)
    options = scheme_options_from_args(args, entry)
    motions = motions_from_args(args, kind)
    settings = entry.checked(parameters)
    extra = {key: value for key, value in (("angles", angles), ("options", options or None)) if value is not None}
    cube = entry.sweep(motions, args.method, progress=True, **extra, **{grid.name: grid.values}, **parameters)
    if args.out is not None:
        write_cube(cube, args.out)
    entries = entry.answers(cube, motions, args.q, reference, min_points, options)
    columns = entry.answer_columns
    if args.json:
        print(json.dumps({grid.name: list(map(float, grid.values)), "model": entry.name,
                          "method": entry.scheme(args.method).name, **options,
                          "angles": None if angles is None else [float(angle) for angle in angles],
                          "read": motion_config(args), "mass": settings["mass"], "g": settings["g"],
                          "near_optimal_fraction": args.q, f"reference_{grid.name}": reference,
                          "range_points": min_points,
                          "units": {**{name: units for name, (units, _) in results_of(grid.name).items()},
                                    "grid_values_in_range": "1"},
                          "pairs": [_pair_document(motion, found) for motion, found in zip(motions, entries)]},
                         allow_nan=False))
        return 0
    shown_units = {units: readable_units(energy_units(settings["mass"])) if units == "J" else units
                   for _, units in columns.values()}
    for number, (motion, found) in enumerate(zip(motions, entries)):
        print(("\n" if number else "") + f"{motion.name}: {grid.values.size} values of {grid.name} from "
              f"{grid.values[0]:g} to {grid.values[-1]:g}, mass {settings['mass']:g} kg, g = {settings['g']:g} m/s2")
        for line in motion_notes(motion):
            print(line)
        for label, answer in found["directions"].items():
            changes = [extension.describe(grid.name) for extension in answer.extensions]
            changes += [refinement.describe(grid.name, min_points) for refinement in answer.refinements]
            if changes:
                print(f"  {label}: grid of {answer.grid_size:,} values, {'; '.join(changes)}")
        rows = [[label] + [shown(answer.results, name, grid.name, answer.bounds())
                           if isinstance(answer.results[name], float) else f"{answer.results[name]:,}"
                           for name in columns] for label, answer in found["directions"].items()]
        notes = {index: answer.results[STATUS] for index, answer in enumerate(found["directions"].values())
                 if answer.results[STATUS] != "ok"}
        if found["worst"] is not None:
            label, worst = found["worst"]
            rows.append([label] + [shown(worst, name, grid.name) if name in worst else "-" for name in columns])
        print("\n".join(_table([("", "")] + [(heading, f"[{shown_units[units]}]" if units != "1" else "")
                                              for heading, units in columns.values()], rows, notes)))
        print(found["relation"][0].upper() + found["relation"][1:] + ".")
    print(f"\nE_df,max: on the grid, and at the continuous {grid.name}_max; range: the grid's {grid.name} with "
          f"E_df >= {args.q:g} E_df,max; stroke: in the plane the largest distance from the start, alone the largest |x|; end: in the "
          f"plane the distance from the start at the end, alone x at the end; largest: over the range")
    if args.out is not None:
        print(f"written: {args.out}")
    return 0


def _pair_document(motion, found: dict) -> dict:
    """One pair of ``optimum --pair --json``: its files, what they are, and each direction's results (NaN as null),
    with the ``bounds`` of its range, its grid's extensions and refinements, and the relation of the μ_max values."""
    results = {label: {**{name: _plain(value) if isinstance(value, float) else value
                          for name, value in answer.results.items()},
                       "bounds": answer.bounds(), "grid_values": answer.grid_size,
                       "grid_extensions": [{"side": extension.side, "start": extension.start, "stop": extension.stop,
                                            "step": extension.step, "values_added": extension.added,
                                            "grid_edge": extension.edge, "range_inside": extension.inside}
                                           for extension in answer.extensions],
                       "grid_refinements": [{"start": refinement.start, "stop": refinement.stop,
                                             "step": refinement.step, "values_added": refinement.added,
                                             "grid_values_in_range_before": refinement.before,
                                             "grid_values_in_range": refinement.after}
                                            for refinement in answer.refinements]}
               for label, answer in found["directions"].items()}
    if found["worst"] is not None:
        label, worst = found["worst"]
        results[label] = {name: _plain(value) for name, value in worst.items()}
    return {"pair": motion.name, "sources": [motion.first.meta.source, motion.second.meta.source],
            **pair_fields(motion), "results": results, "relation": found["relation"]}
