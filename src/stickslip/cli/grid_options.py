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


def add_chart_radii_option(parser: argparse.ArgumentParser) -> None:
    """``--chart-radii``: the radii R [m] of the friction pendulum's design chart."""
    parser.add_argument("--chart-radii", default=None, metavar="R1,R2,...",
                        help="radii R [m] of the friction pendulum's design chart (a model with --radius; default "
                             "1,1.5,2,2.5,3,4); a comma list or START:STOP:STEP, each in m or with its unit "
                             "(100cm,200cm)")


def add_chart_levels_option(parser: argparse.ArgumentParser) -> None:
    """``--chart-levels``: the steps of the friction pendulum's design chart's levels."""
    parser.add_argument("--chart-levels", default=None, metavar="D,VW",
                        help="levels of the friction pendulum's design chart: the displacement demand's colours every "
                             "D [m] and the V/W lines every VW [-], from zero (0.1,0.05); default: fixed round levels, "
                             "the same for every chart (0, 0.025, 0.05 ... 5 m; V/W 0.05, 0.1 ... 5)")


def chart_levels_from_args(args: argparse.Namespace) -> tuple[float, float] | None:
    """The ``--chart-levels`` steps (displacement demand [m], V/W [1]), or None when not given; one line for a bad
    pair of steps."""
    from stickslip.reports.isolator_plots import ChartLevels

    if args.chart_levels is None:
        return None
    parts = args.chart_levels.split(",")
    try:
        steps = tuple(float(part) for part in parts)
    except ValueError:
        steps = ()
    if len(steps) != 2:
        raise StickslipError(f"--chart-levels {args.chart_levels!r}: expected two steps, D,VW: the displacement "
                             "demand's [m] and V/W's [-], such as 0.1,0.05")
    try:
        ChartLevels.every(*steps)
    except StickslipError as error:
        raise StickslipError(f"--chart-levels {args.chart_levels!r}: {error}") from None
    return steps


def chart_radii_from_args(args: argparse.Namespace) -> list[float] | None:
    """The ``--chart-radii`` [m] (each bare in m, or with its unit), increasing and positive, or None when not given
    (one line for a bad list); a warning for each radius outside the usual radii
    (:attr:`stickslip.models.pendulum.RADIUS`'s ``usual``)."""
    from stickslip.cli.grid_values import parse_values
    from stickslip.cli.quantities import grid_part, parse_quantity, warn_if_unusual
    from stickslip.grids import positive_increasing
    from stickslip.models.pendulum import RADIUS

    if args.chart_radii is None:
        return None
    quantity = of_unit(RADIUS.unit, RADIUS.usual)
    written = []

    def radius(part: str) -> float:
        value, bare = parse_quantity(part, "--chart-radii", quantity)
        written.append(bare)
        return value

    values = parse_values(args.chart_radii, "--chart-radii", "radii R [m] of the design chart", "1,1.5,2,3",
                          grid_part(radius))
    radii = [float(value) for value in positive_increasing(values, "--chart-radii")]
    if all(written):
        for value in radii:
            warn_if_unusual(f"--chart-radii {args.chart_radii}", value, quantity, f"{value:g}")
    return radii


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
