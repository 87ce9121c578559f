"""The options that say what to sweep, shared by ``stickslip sweep``, ``optimum`` and ``report``, and their checks.

``--mu START:STOP:STEP`` or ``--mu-list MU...`` (friction ratios [1]), or,
where the command offers them, ``--ky START:STOP:STEP`` or ``--ky-list KY...``
(yield coefficients k_y [1]; a value with a unit, ``1.47m/s2``, is the yield
acceleration k_y·g: :mod:`stickslip.cli.accelerations`) with the options of
:mod:`stickslip.cli.sliding_options`;
``--scale FACTOR...`` or ``--target-pga PGA...`` ([g], or ``3.92m/s2``),
``--mass`` [kg], ``--g`` [m/s2], ``--q`` and ``--reference-mu`` (or
``--reference-ky``: the per-record results of :mod:`stickslip.optimum`).
Also the one-line note that the block never slides at a value of the grid
where the record's ground acceleration stays inside the stick band (μ·g at
least its PGA, for a friction ratio).
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence

import numpy as np

from stickslip.cli.accelerations import acceleration, in_units_of_g, warn_if_above_one
from stickslip.cli.sliding_options import add_sliding_options, parse_yield_coefficient, sliding_options
from stickslip.constants import PAPER_BLOCK_MASS, STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.grids import MAX_GRID_VALUES, Grid, checked_range, never_slides_reason, positive_increasing, range_values
from stickslip.optimum import DEFAULT_MU, DEFAULT_Q, DEFAULT_REFERENCE, checked_q, checked_reference
from stickslip.records.plausibility import PLAUSIBLE_PGA
from stickslip.records.process import peak_ground_acceleration, record_name
from stickslip.records.readers import POSSIBLE_PGA
from stickslip.records.record import Record

#: The optimum's default friction grid (:data:`stickslip.optimum.DEFAULT_MU`) as ``--mu`` writes it.
DEFAULT_MU_TEXT = f"{DEFAULT_MU['start']:g}:{DEFAULT_MU['stop']:g}:{DEFAULT_MU['step']:g}"

def add_grid_options(parser: argparse.ArgumentParser, default_mu: str | None = None, yield_grid: bool = False) -> None:
    """Add the friction grid, scaling, mass, gravity, q and reference-μ options to ``parser``.

    ``default_mu`` (``START:STOP:STEP``) is the grid when no grid option is
    given; without one, a grid option is required.  ``yield_grid`` adds
    ``--ky``/``--ky-list`` as the alternative to the friction grid, and
    ``--direction``, ``--thrust-angle`` and ``--inverse``.
    """
    friction = parser.add_mutually_exclusive_group(required=default_mu is None)
    friction.add_argument(
        "--mu", metavar="START:STOP:STEP", default=default_mu,
        help=f"friction ratios from START to STOP inclusive, at most {MAX_GRID_VALUES:,} of them "
        "(write --mu=START:STOP:STEP when START starts with a minus sign)"
        + (f"; default {default_mu}" if default_mu else ""),
    )
    friction.add_argument("--mu-list", type=float, nargs="+", metavar="MU", help="explicit friction ratios")
    if yield_grid:
        friction.add_argument(
            "--ky", metavar="START:STOP:STEP",
            help="yield coefficients k_y [-] from START to STOP inclusive (0.02:0.4:0.02); a part with a unit is a "
            "yield acceleration k_y*g (0.2m/s2:3.9m/s2:0.2m/s2)",
        )
        friction.add_argument("--ky-list", nargs="+", metavar="KY",
                              help="explicit yield coefficients k_y [-] (0.05 0.1), or yield accelerations with their "
                              "unit (0.49m/s2)")
        add_sliding_options(parser)
    scaling = parser.add_mutually_exclusive_group()
    scaling.add_argument("--scale", type=float, nargs="+", metavar="FACTOR", help="scale factors [-]")
    scaling.add_argument(
        "--target-pga", nargs="+", metavar="PGA",
        help="scale each record to these PGAs [g] (0.4 0.6), or with their unit (3.92m/s2)",
    )
    parser.add_argument("--mass", type=float, default=PAPER_BLOCK_MASS, help="block mass [kg] (default %(default)s)")
    parser.add_argument("--g", type=float, default=STANDARD_GRAVITY,
                        help="gravity [m/s2] (default %(default)s; SLAMMER's is 9.80665)")
    add_optimum_options(parser, yield_grid)


def add_optimum_options(parser: argparse.ArgumentParser, yield_grid: bool = False) -> None:
    """Add ``--q`` and ``--reference-mu`` (and, with ``yield_grid``, ``--reference-ky``) to ``parser``.

    The defaults are the optimum's (:data:`stickslip.optimum.DEFAULT_Q`,
    :data:`~stickslip.optimum.DEFAULT_REFERENCE`); :func:`check_optimum_options`
    checks them and gives the reference value of the grid.
    """
    parser.add_argument(
        "--q", type=float, default=DEFAULT_Q,
        help="near-optimal fraction: the range of mu (or ky) whose E_df is at least q times the maximum "
             "(default %(default)s)",
    )
    parser.add_argument(
        "--reference-mu", type=float, default=None, metavar="MU",
        help="friction ratio whose E_df and efficiency (E_df / E_df,max) are reported "
             f"(default {DEFAULT_REFERENCE['mu']:g})",
    )
    if yield_grid:
        parser.add_argument(
            "--reference-ky", default=None, metavar="KY",
            help="with --ky or --ky-list: the yield coefficient k_y [-] (or yield acceleration with its unit) whose "
                 f"E_df and efficiency are reported (default {DEFAULT_REFERENCE['ky']:g}, the same number as the "
                 "reference mu: two-way sliding at thrust angle 0 is flat friction with mu = ky)",
        )


def friction_ratios(args: argparse.Namespace) -> np.ndarray:
    """The friction ratios [1] of ``--mu`` or ``--mu-list``."""
    return parse_mu_range(args.mu) if args.mu_list is None else np.asarray(args.mu_list, dtype=float)


def sweep_grid(args: argparse.Namespace) -> tuple[dict, dict]:
    """``({"mu": values} or {"ky": values}, sliding options)`` for :func:`stickslip.sweeps.sweep`, checked.

    Friction ratios [1] from ``--mu``/``--mu-list``, or yield coefficients k_y
    [1] from ``--ky``/``--ky-list``; the sliding options are ``direction`` and
    ``thrust_angle`` [degrees] (:func:`stickslip.cli.sliding_options.sliding_options`).
    """
    ky, ky_list = getattr(args, "ky", None), getattr(args, "ky_list", None)
    sliding = sliding_options(args, has_ky=ky is not None or ky_list is not None)
    if ky is not None:
        values = parse_ky_range(ky, args.g)
        warn_if_above_one(float(values.max()), f"--ky {ky}", "yield coefficient")
        return {"ky": values}, sliding
    if ky_list is not None:
        return {"ky": np.array([parse_yield_coefficient(text, args.g) for text in ky_list])}, sliding
    values = friction_ratios(args)
    warn_if_above_one(float(values.max()), "--mu-list" if args.mu_list is not None else f"--mu {args.mu}",
                      "friction ratio")
    return {"mu": values}, sliding


def grid_from_args(args: argparse.Namespace) -> Grid:
    """The :class:`~stickslip.grids.Grid` of the grid options (:func:`sweep_grid`), with ``--g`` and ``--inverse``."""
    values, sliding = sweep_grid(args)
    return Grid(args.g, **values, **sliding, inverse=getattr(args, "inverse", False))


def target_pgas(args: argparse.Namespace) -> list[float] | None:
    """The ``--target-pga`` values [m/s²] (each given in g, or with its unit), or None."""
    return None if args.target_pga is None else [parse_pga(text, args.g) for text in args.target_pga]


def check_optimum_options(args: argparse.Namespace, grid: str = "mu") -> float:
    """``--q`` in (0, 1] and the reference value of a ``grid`` of ``"mu"`` or ``"ky"``, else one clear line.

    Returns the reference value [1]: ``--reference-mu`` for a friction grid,
    ``--reference-ky`` (a yield acceleration, as k_y) for a yield grid, or the
    optimum's default; the other grid's option is refused.
    """
    checked_q(args.q, "--q")
    reference_ky = getattr(args, "reference_ky", None)
    if grid == "mu" and reference_ky is not None:
        raise StickslipError(f"--reference-ky {reference_ky}: applies to a yield grid (--ky or --ky-list); "
                             "for friction ratios give --reference-mu")
    if grid == "ky":
        if args.reference_mu is not None:
            raise StickslipError(f"--reference-mu {args.reference_mu:g}: applies to a friction grid (--mu or "
                                 "--mu-list); for yield accelerations give --reference-ky")
        return (DEFAULT_REFERENCE["ky"] if reference_ky is None
                else parse_yield_coefficient(reference_ky, args.g, "--reference-ky"))
    return DEFAULT_REFERENCE["mu"] if args.reference_mu is None else checked_reference(args.reference_mu, "mu",
                                                                                         "--reference-mu")


def parse_mu_range(text: str) -> np.ndarray:
    """Friction ratios [1] from ``START:STOP:STEP`` (STOP included when it lies on the grid) or ``0.05,0.1,0.15``."""
    return _parse_range(text, "--mu", "friction ratios mu", "numbers such as 0.05:0.2:0.025", float)


def parse_mu_bounds(text: str, min_values: int = 1) -> tuple[float, float, float]:
    """(START, STOP, STEP) [1] of a ``--mu`` range of at least ``min_values``, checked: :func:`stickslip.grids.range_values` gives its grid."""
    return _parse_bounds(text, "--mu", "friction ratios mu", "numbers such as 0.05:0.2:0.025", float, min_values)


def parse_ky_range(text: str, g: float) -> np.ndarray:
    """Yield coefficients k_y [1] from ``START:STOP:STEP`` or ``0.05,0.1`` (each k_y, or k_y·g with its unit; ``g`` [m/s²])."""
    return _parse_range(text, "--ky", "yield coefficients k_y",
                        "numbers such as 0.02:0.4:0.02", lambda part: in_units_of_g(part, g, "--ky", "0.15"))


def parse_heights(text: str) -> np.ndarray:
    """Layer heights H [m] from ``START:STOP:STEP``, ``10,50,100`` or one height ``40`` (``--height`` of ``sweep``)."""
    if ":" in text or "," in text:
        return _parse_range(text, "--height", "layer heights H [m]", "numbers such as 10:100:10", float)
    try:
        height = float(text)
    except ValueError:
        raise StickslipError(f"--height {text!r}: expected a height [m], START:STOP:STEP or a comma list "
                             "(10,50,100)") from None
    return positive_increasing([height], f"--height {text!r}: layer heights H [m]")


def _parse_range(text: str, option: str, quantity: str, example: str, number) -> np.ndarray:
    """Grid values from ``START:STOP:STEP`` (STOP included when it lies on the grid) or a comma list ``A,B,C``.

    Each number is converted by ``number``; ``quantity`` (``"friction ratios mu"``) names them in a message.
    """
    if "," in text:
        try:
            values = [number(part) for part in text.split(",")]
        except ValueError:
            raise StickslipError(f"{option} {text!r}: expected a comma list of {quantity} (0.05,0.1,0.15) or "
                                 f"START:STOP:STEP") from None
        return positive_increasing(values, f"{option} {text!r}: {quantity}")
    return range_values(*_parse_bounds(text, option, quantity, example, number))


def _parse_bounds(text: str, option: str, quantity: str, example: str, number,
                  min_values: int = 1) -> tuple[float, float, float]:
    """(START, STOP, STEP) of ``START:STOP:STEP`` (at least ``min_values`` values), checked by :func:`stickslip.grids.checked_range`."""
    parts = text.split(":")
    try:
        start, stop, step = (number(part) for part in parts)
    except ValueError:
        raise StickslipError(f"{option} {text!r}: expected START:STOP:STEP, three {example}, or a comma list "
                             "(0.05,0.1,0.15)") from None
    return checked_range(start, stop, step, f"{option} {text!r}", quantity, min_values)


def parse_pga(text: str, g: float, option: str = "--target-pga") -> float:
    """A PGA [m/s²] from ``"0.6"`` or ``"0.6g"`` (units of g, ``g`` [m/s²] each), ``"5.89m/s2"`` or ``"589cm/s2"``
    (any units ``--units`` takes); a bare number above 4 g gives a warning naming its plausible readings, a PGA above
    100 g (:data:`~stickslip.records.readers.POSSIBLE_PGA`, as for a record) is an error."""
    return acceleration(text, g, option, "0.4", largest=PLAUSIBLE_PGA[1], impossible=POSSIBLE_PGA[1])


def note_never_slides(versions: Sequence[Record], grid: Grid) -> None:
    """For each record (or scaled version), one note on stderr if the block never slides at some values of ``grid``.

    The block slides only where the ground acceleration leaves the stick
    band of the resistance (beyond ±μ·g on a flat surface: μ·g at least the
    record's PGA; above k_y·g one-way), so at those values it sticks to the
    base throughout and dissipates nothing (:meth:`stickslip.grids.Grid.first_without_sliding`).
    """
    values, g, noun = grid.values, grid.g, grid.coefficient
    for version in versions:
        first = grid.first_without_sliding(version.acceleration)
        still = values[first:]
        if still.size == 0:
            continue
        scaled = f" ({version.meta.processing[-1]})" if version.meta.processing else ""
        which = (f"{grid.name} = {still[0]:g}" if still.size == 1 else
                 f"the {still.size:,} {noun.plural} from {still[0]:g} to {still[-1]:g}" if still.size < values.size else
                 f"any of the {values.size:,} {noun.plural} (from {values[0]:g})")
        if grid.name == "mu":
            pga = peak_ground_acceleration(version)
            why = f"mu*g is at least the record's PGA, {pga:.4g} m/s2 ({pga / g:.4g} g)"
        else:
            why = never_slides_reason(version, grid, first)
        print(f"stickslip: note: {record_name(version)}{scaled}: the block never slides at {which}: {why}, "
              "so E_df = 0 there", file=sys.stderr)
