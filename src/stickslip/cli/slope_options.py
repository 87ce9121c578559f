"""The slope's yield coefficients on the command line: ``--ky`` (a list), or ``--fs`` with ``--slope-angle``.

``--ky 0.05,0.1,0.15`` (or ``START:STOP:STEP``) gives the yield coefficients
k_y [1] directly, each a bare number in g, a percentage of g (``15%``) or an
acceleration with its unit (``0.49m/s2``); a bare one above 1 gets a warning
naming its likely readings (15 % first).  ``--fs F --slope-angle DEG`` gives
the one of an infinite slope, k_y = (F − 1)·sin α (Newmark 1965:
:mod:`stickslip.estimates.infinite_slope`).  Both at once is one error line.
"""

from __future__ import annotations

import argparse

import numpy as np

from stickslip.cli.quantities import Quantity, read_quantity
from stickslip.errors import StickslipError

#: The slope angle: degrees, bare or with the unit.
SLOPE_ANGLE = Quantity("degrees", {None: 1.0, "deg": 1.0, "degrees": 1.0, "°": 1.0}, "30 or 30deg")

#: The form and its source, as the help and the outputs name them.
INFINITE_SLOPE = "k_y = (F - 1) sin(alpha), the infinite slope of Newmark (1965)"


def add_slope_options(parser: argparse.ArgumentParser, ky_help: str, default_ky: str | None = None) -> None:
    """``--ky`` (with ``ky_help`` and ``default_ky``), ``--fs`` and ``--slope-angle``."""
    parser.add_argument("--ky", default=None, metavar="KY",
                        help=ky_help + (f" (default {default_ky})" if default_ky else ""))
    slope = parser.add_argument_group(f"the slope instead of --ky: {INFINITE_SLOPE}")
    slope.add_argument("--fs", metavar="F", help="static factor of safety F of the slope (> 1)")
    slope.add_argument("--slope-angle", metavar="DEG", help="slope angle alpha [degrees]: 30 or 30deg")
    parser.set_defaults(default_ky=default_ky)


def yield_coefficients(args: argparse.Namespace, g: float) -> tuple[np.ndarray, dict | None]:
    """The yield coefficients k_y [1], increasing, and the slope that gave them (``{"factor_of_safety": F,
    "slope_angle": α [degrees]}``) or None; ``g`` [m/s²] reads a k_y given as an acceleration."""
    from stickslip.cli.grid_values import parse_ky_range
    from stickslip.estimates.infinite_slope import yield_coefficient

    slope = [option for option, value in (("--fs", args.fs), ("--slope-angle", args.slope_angle)) if value is not None]
    if slope and args.ky is not None:
        raise StickslipError(f"--ky and {' and '.join(slope)} both set the yield coefficient: give --ky, or --fs with "
                             "--slope-angle")
    if slope:
        if len(slope) == 1:
            other = "--slope-angle" if slope[0] == "--fs" else "--fs"
            raise StickslipError(f"{slope[0]} needs {other}: {INFINITE_SLOPE}")
        try:
            factor = float(args.fs)
        except ValueError:
            raise StickslipError(f"--fs {args.fs!r}: expected a factor of safety, a number above 1") from None
        angle = read_quantity(args.slope_angle, "--slope-angle", SLOPE_ANGLE)
        try:
            ky = yield_coefficient(factor, angle)
        except StickslipError as error:
            raise StickslipError(f"--fs {args.fs} --slope-angle {args.slope_angle}: {error}") from None
        return np.array([ky]), {"factor_of_safety": factor, "slope_angle": angle}
    text = args.ky if args.ky is not None else args.default_ky
    if text is None:
        raise StickslipError("give the yield coefficient: --ky K (a comma list for several), or --fs F with "
                             "--slope-angle DEG")
    return parse_ky_range(text, g), None
