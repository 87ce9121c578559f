"""What ``sweep``, ``optimum`` and ``report`` sweep over besides the model's parameters, and the grids' reading.

A grid of a swept parameter is read by :mod:`stickslip.cli.grid_values`
(the options themselves come from the models, :mod:`stickslip.cli.model_options`);
``--scale FACTOR...`` or ``--target-pga PGA...`` ([g], or ``3.92m/s2``) scale
the records; ``--q`` and ``--reference-mu`` (``--reference-ky``) define the
per-record results of :mod:`stickslip.optimum`, and ``--range-points`` how
finely ``optimum`` and ``report`` refine the grid around each near-optimal
range (:func:`stickslip.optimum.refine_for_ranges`).  Also the one-line note that
the block never slides at a value of the grid where the record's ground
acceleration stays inside the stick band.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence

from stickslip.cli.grid_values import parse_pga
from stickslip.cli.quantities import of_unit, quantity_type
from stickslip.errors import StickslipError
from stickslip.grids import COEFFICIENTS
from stickslip.optimum import DEFAULT_MU, DEFAULT_Q, MIN_RANGE_POINTS, checked_q, checked_reference
from stickslip.records.process import record_name
from stickslip.records.record import Record

#: The optimum's default friction grid (:data:`stickslip.optimum.DEFAULT_MU`) as ``--mu`` writes it.
DEFAULT_MU_TEXT = f"{DEFAULT_MU['start']:g}:{DEFAULT_MU['stop']:g}:{DEFAULT_MU['step']:g}"

def add_scaling_options(parser: argparse.ArgumentParser) -> None:
    """Add ``--scale FACTOR...`` [1] and ``--target-pga PGA...`` ([g], or with a unit) to ``parser``."""
    scaling = parser.add_mutually_exclusive_group()
    scaling.add_argument("--scale", type=float, nargs="+", metavar="FACTOR", help="scale factors [-]")
    scaling.add_argument(
        "--target-pga", nargs="+", metavar="PGA",
        help="scale each record to these PGAs [g] (0.4 0.6), or with their unit (3.92m/s2)",
    )


def add_optimum_options(parser: argparse.ArgumentParser) -> None:
    """Add ``--q`` and ``--reference-{name}`` for each swept coefficient (:data:`stickslip.grids.COEFFICIENTS`).

    The defaults are the optimum's (:data:`stickslip.optimum.DEFAULT_Q`,
    :data:`~stickslip.grids.COEFFICIENTS`' ``reference``); :func:`check_optimum_options`
    checks them and gives the reference value of the grid.
    """
    parser.add_argument(
        "--q", type=quantity_type(of_unit("1"), "--q"), default=DEFAULT_Q,
        help="near-optimal fraction: the range of the swept coefficient whose E_df is at least q times the maximum "
             "(default %(default)s; or a percentage, 90%%)",
    )
    for name, coefficient in COEFFICIENTS.items():
        parser.add_argument(
            f"--reference-{name}", default=None, metavar=name.upper(),
            help=f"with a grid of {coefficient.plural}: the {coefficient.noun} whose E_df and efficiency "
                 f"(E_df / E_df,max) are reported (default {coefficient.reference:g})",
        )


def add_range_points_option(parser: argparse.ArgumentParser) -> None:
    """Add ``--range-points N``: the fewest grid values of each near-optimal range (:func:`stickslip.optimum.refine_for_ranges`)."""
    parser.add_argument(
        "--range-points", type=int, default=MIN_RANGE_POINTS, metavar="N",
        help="the fewest grid values each record's near-optimal range holds: where it holds fewer (a weak record on "
             "a coarse grid), the grid is refined around the range, and the output says where (default "
             "%(default)s; 0: no refinement; a grid whose edge cuts a range is extended all the same)",
    )


def add_chart_values_options(parser: argparse.ArgumentParser) -> None:
    """``--chart-values``: the values of the design chart's other coordinate, the model's own
    (:attr:`~stickslip.models.entry.Model.chart_over`), and ``--chart-radii``, its name for a chart over a radius."""
    from stickslip.models import MODELS

    charts = "; ".join(f"{entry.name}: {entry.chart_long_name} [{_unit(entry)}], default "
                       f"{','.join(f'{value:g}' for value in entry.chart_values)}"
                       for entry in MODELS.values() if entry.chart_over)
    parser.add_argument("--chart-values", default=None, metavar="V1,V2,...",
                        help="the values of the design chart's other coordinate beside mu, the model's own ("
                             f"{charts}); a comma list or START:STOP:STEP, each in its unit or with a unit of the same "
                             "quantity (150cm, 2%%)")
    parser.add_argument("--chart-radii", default=None, metavar="R1,R2,...",
                        help="the same, for a design chart over a surface radius R [m]")


def _unit(entry) -> str:
    """The unit of the model ``entry``'s chart coordinate as people read it (``m``, ``-``)."""
    from stickslip.units import readable_units

    return readable_units(entry.parameter(entry.chart_over).unit)


def add_chart_levels_option(parser: argparse.ArgumentParser) -> None:
    """``--chart-levels``: the steps of the design chart's levels, of its colours and of its lines, in the units of
    the quantities the model's chart draws (:meth:`~stickslip.models.entry.Model.chart_quantities`)."""
    parser.add_argument("--chart-levels", default=None, metavar="COLOURS,LINES",
                        help="levels of the design chart: its colours every COLOURS and its lines every LINES, from "
                             f"zero, each in its quantity's units, the model's ({chart_contents(steps=True)}); "
                             "default: round levels, "
                             "fixed ones, the same for every chart, for a chart of fixed quantities, and round steps "
                             "over the chart's own values for a chart of an --objective's quantity")


def chart_contents(steps: bool = False) -> str:
    """What the design chart of each model that draws one shows with its default objective
    (:meth:`~stickslip.models.entry.Model.chart_quantities`), one ``name: ...`` each, for the help; with ``steps``,
    as the steps of ``--chart-levels`` (:func:`chart_steps`)."""
    from stickslip.models import MODELS

    return "; ".join(f"{entry.name}: {chart_steps(entry) if steps else chart_drawn(entry)}"
                     for entry in MODELS.values() if entry.chart_over)


def chart_drawn(entry, objective: str | None = None) -> str:
    """The quantities the model ``entry``'s design chart draws for the ``objective`` named (None: its default), in
    words: ``the displacement demand [m] in colours, the ... in lines``."""
    filled, lines = entry.chart_quantities(objective)
    return f"the {filled} in colours" + _other_objectives(entry, objective) + (f", the {lines} in lines" if lines
                                                                                  else ", no lines")


def chart_steps(entry, objective: str | None = None) -> str:
    """The quantities of the model ``entry``'s design chart whose steps ``--chart-levels`` gives, for the
    ``objective`` named (None: its default), in words: ``COLOURS the displacement demand [m], LINES the ...``."""
    filled, lines = entry.chart_quantities(objective)
    return (f"COLOURS the {filled}" + _other_objectives(entry, objective)
            + (f", LINES the {lines}" if lines else ", LINES unused: no lines drawn"))


def _other_objectives(entry, objective: str | None) -> str:
    """The remark that the chart's colours follow the objective, for a model of several and no objective named."""
    return (" (with the default objective; another objective colours its own quantity)"
            if objective is None and len(entry.objectives) > 1 else "")


def refuse_chart_without_model_chart(args: argparse.Namespace, entry, chart_asked: bool = False) -> None:
    """One line refusing a design chart's option (``--chart`` itself where ``chart_asked``, ``--chart-values``,
    ``--chart-radii``, ``--chart-levels``) for the model ``entry`` when it draws no design chart, naming the first
    option given and the models that draw one."""
    from stickslip.models.registry import MODELS

    asked = ["chart"] if chart_asked else []
    asked += [name for name in ("chart_values", "chart_radii", "chart_levels") if getattr(args, name, None) is not None]
    if asked and not entry.chart_over:
        charting = sorted(f"{other.name} (over its {other.chart_long_name})" for other in MODELS.values()
                          if other.chart_over)
        option = "--" + asked[0].replace("_", "-")
        raise StickslipError(f"{option}: the {entry.name} model draws no design chart; {', '.join(charting)} do")


def chart_levels_from_args(args: argparse.Namespace, entry) -> tuple[float, float] | None:
    """The ``--chart-levels`` steps of the model ``entry``'s design chart for the ``--objective`` given (its
    colours' and its lines', in their quantities' units), or None when not given or the model draws no chart (the
    caller refuses it); one line naming the chart's quantities for a bad pair of steps."""
    from stickslip.reports.isolator_plots import ChartLevels

    if args.chart_levels is None or not entry.chart_over:
        return None
    objective = getattr(args, "objective", None)
    parts = args.chart_levels.split(",")
    try:
        steps = tuple(float(part) for part in parts)
    except ValueError:
        steps = ()
    if len(steps) != 2:
        raise StickslipError(f"--chart-levels {args.chart_levels!r}: expected two steps, COLOURS,LINES, of the "
                             f"{entry.name} model's design chart: {chart_steps(entry, objective)}")
    try:
        ChartLevels.every(*steps, quantities=entry.chart_quantities(objective))
    except StickslipError as error:
        raise StickslipError(f"--chart-levels {args.chart_levels!r}: {error} ({entry.name} model)") from None
    return steps


def chart_values_from_args(args: argparse.Namespace, entry) -> list[float] | None:
    """The values of the model ``entry``'s design chart coordinate (``--chart-values``, or ``--chart-radii`` for a
    chart over a radius), each bare in the coordinate's unit or with a unit of its quantity, increasing and positive,
    or None when neither is given (one line for a bad list, or for ``--chart-radii`` of a chart over another
    coordinate); a warning for each value outside the parameter's usual range
    (:attr:`~stickslip.models.entry.Parameter.usual`)."""
    from stickslip.cli.grid_values import parse_values
    from stickslip.cli.quantities import grid_part, parse_quantity, warn_if_unusual
    from stickslip.grids import positive_increasing

    given = [(option, text) for option, text in (("--chart-values", args.chart_values),
                                                 ("--chart-radii", args.chart_radii)) if text is not None]
    if not given:
        return None
    if len(given) == 2:
        raise StickslipError("--chart-radii and --chart-values are one option: give one")
    option, text = given[0]
    if not entry.chart_over:
        return None  # the caller refuses a chart of a model that draws none
    if option == "--chart-radii" and entry.chart_over != "radius":
        raise StickslipError(f"--chart-radii: the {entry.name} model's design chart runs over the "
                             f"{entry.chart_long_name} [{_unit(entry)}], not a radius: give --chart-values")
    declared = entry.parameter(entry.chart_over)
    quantity = of_unit(declared.unit, declared.usual)
    written = []

    def value(part: str) -> float:
        number, bare = parse_quantity(part, option, quantity)
        written.append(bare)
        return number

    example = ",".join(f"{number:g}" for number in entry.chart_values[:4])
    values = parse_values(text, option, f"{entry.chart_long_name} [{_unit(entry)}] of the design chart", example,
                          grid_part(value))
    values = [float(number) for number in positive_increasing(values, option)]
    if all(written):
        for number in values:
            warn_if_unusual(f"{option} {text}", number, quantity, f"{number:g}")
    return values


def checked_range_points(args: argparse.Namespace) -> int:
    """``--range-points`` (0 or more), else one line naming it."""
    if args.range_points < 0:
        raise StickslipError(f"--range-points {args.range_points}: expected 0 (no refinement) or more grid values, "
                             f"such as {MIN_RANGE_POINTS}")
    return args.range_points


def target_pgas(args: argparse.Namespace) -> list[float] | None:
    """The ``--target-pga`` values [m/s²] (each given in g, or with its unit), or None."""
    from stickslip.cli.model_options import gravity

    return None if args.target_pga is None else [parse_pga(text, gravity(args)) for text in args.target_pga]


def check_optimum_options(args: argparse.Namespace, entry, grid: str) -> float:
    """``--q`` in (0, 1] and the reference value [1] of the swept coefficient ``grid``, else one clear line.

    Returns ``--reference-{grid}`` (read as the model ``entry`` reads that
    parameter: a yield coefficient may be an acceleration with its unit) or
    the optimum's default; another coefficient's reference is refused.
    """
    from stickslip.cli.model_options import gravity, read_value

    checked_q(args.q, "--q")
    for name, coefficient in COEFFICIENTS.items():
        given = getattr(args, f"reference_{name}", None)
        if name != grid and given is not None:
            raise StickslipError(f"--reference-{name} {given}: applies to a {coefficient.grid} (--{name} or "
                                 f"--{name}-list); for {COEFFICIENTS[grid].plural} give --reference-{grid}")
    given = getattr(args, f"reference_{grid}", None)
    if given is None:
        return COEFFICIENTS[grid].reference
    parameter = entry.parameter(grid)
    return checked_reference(read_value(parameter, given, gravity(args), f"--reference-{grid}"), grid,
                             f"--reference-{grid}")


def note_never_slides(versions: Sequence[Record], design) -> None:
    """For each record (or scaled version), one note on stderr if the block never slides at some values of the grid.

    The block slides only where the ground acceleration leaves the stick band
    of its resistance, so at those values it sticks to the base throughout and
    dissipates nothing; ``design`` is the model's block over its grid
    (:meth:`~stickslip.optimum.Design.first_still` and ``still_reason``).
    """
    grid = design.grid
    values, noun = grid.values, grid.coefficient
    for version in versions:
        first = design.first_still(version)
        still = values[first:]
        if still.size == 0:
            continue
        scaled = f" ({version.meta.processing[-1]})" if version.meta.processing else ""
        which = (f"{grid.name} = {still[0]:g}" if still.size == 1 else
                 f"the {still.size:,} {noun.plural} from {still[0]:g} to {still[-1]:g}" if still.size < values.size else
                 f"any of the {values.size:,} {noun.plural} (from {values[0]:g})")
        print(f"stickslip: note: {record_name(version)}{scaled}: the block never slides at {which}: "
              f"{design.still_reason(version, first)}, so E_df = 0 there", file=sys.stderr)
