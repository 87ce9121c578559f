"""``stickslip sweep PATH... --mu START:STOP:STEP --out cube.nc``: a friction-ratio (or ``--ky``) sweep into a NetCDF cube."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from stickslip.cli.record_options import add_record_options, read_record_from_args
from stickslip.cli.sliding_options import add_sliding_options, parse_yield_coefficient, sliding_options
from stickslip.checks import checked_positive
from stickslip.constants import PAPER_BLOCK_MASS, STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.io import check_output_path
from stickslip.solution import SOLVERS


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "sweep",
        help="solve record files over a range of friction ratios or yield accelerations and write a NetCDF cube",
        description=(
            "Solve every record for every friction ratio (or yield acceleration, --ky; optionally scaled) and "
            "write the response scalars (energies in J, lengths in m; with --ky also the permanent downslope "
            "displacement in m) as a compressed NetCDF cube, atomically."
        ),
    )
    parser.add_argument("paths", type=Path, nargs="+", metavar="PATH", help="record files")
    friction = parser.add_mutually_exclusive_group(required=True)
    friction.add_argument(
        "--mu", metavar="START:STOP:STEP",
        help=f"friction ratios from START to STOP inclusive, at most {MAX_MU_VALUES:,} of them "
        "(write --mu=START:STOP:STEP when START starts with a minus sign)",
    )
    friction.add_argument("--mu-list", type=float, nargs="+", metavar="MU", help="explicit friction ratios")
    friction.add_argument(
        "--ky", metavar="START:STOP:STEP",
        help="yield accelerations from START to STOP inclusive (each in m/s2, or in units of g with the suffix g: "
        "0.02g:0.4g:0.02g); the cube's ky dimension holds k_y = yield acceleration / g",
    )
    friction.add_argument("--ky-list", nargs="+", metavar="KY",
                          help="explicit yield accelerations (m/s2, or with the suffix g: 0.05g 0.1g)")
    add_sliding_options(parser)
    scaling = parser.add_mutually_exclusive_group()
    scaling.add_argument("--scale", type=float, nargs="+", metavar="FACTOR", help="scale factors [-]")
    scaling.add_argument(
        "--target-pga", nargs="+", metavar="PGA", help="scale each record to these PGAs [m/s2]; a suffix g means units of g (0.6g)"
    )
    parser.add_argument("--mass", type=float, default=PAPER_BLOCK_MASS, help="block mass [kg] (default %(default)s)")
    parser.add_argument("--method", choices=tuple(SOLVERS), default="exact", help="solver (default exact)")
    parser.add_argument("--g", type=float, default=STANDARD_GRAVITY,
                        help="gravity [m/s2] (default %(default)s; SLAMMER's is 9.80665)")
    add_record_options(parser)
    parser.add_argument("--out", type=Path, required=True, help="the NetCDF cube to write")
    parser.set_defaults(func=run)


#: Most friction ratios a ``--mu`` range may hold (a guard against a mistyped STEP).
MAX_MU_VALUES = 1_000_000


def parse_mu_range(text: str) -> np.ndarray:
    """Friction ratios [1] from ``START:STOP:STEP``, STOP included when it lies on the grid."""
    return _parse_range(text, "--mu", "friction ratios", "friction ratios mu", "numbers such as 0.05:0.2:0.025", float)


def parse_ky_range(text: str, g: float) -> np.ndarray:
    """Yield coefficients k_y [1] from ``START:STOP:STEP`` yield accelerations [m/s², or with the suffix g]."""
    g = checked_positive(g, "gravity g [m/s2]")
    return _parse_range(text, "--ky", "yield accelerations", "yield accelerations",
                        "accelerations such as 0.02g:0.4g:0.02g", lambda part: _yield_number(part, g))


def _yield_number(text: str, g: float) -> float:
    """A yield acceleration in units of g from ``"1.47"`` [m/s²] or ``"0.15g"``, any sign (the range checks it)."""
    return float(text[:-1]) if text.lower().endswith("g") else float(text) / g


def _parse_range(text: str, option: str, noun: str, quantity: str, example: str, number) -> np.ndarray:
    """Grid values from ``START:STOP:STEP`` (each converted by ``number``), STOP included when it lies on the grid.

    ``noun`` (``"friction ratios"``) counts the values in a message, ``quantity``
    (``"friction ratios mu"``) names them.
    """
    parts = text.split(":")
    try:
        start, stop, step = (number(part) for part in parts)
    except ValueError:
        raise StickslipError(f"{option} {text!r}: expected START:STOP:STEP, three {example}") from None
    if not all(math.isfinite(v) for v in (start, stop, step)) or step <= 0:
        raise StickslipError(f"{option} {text!r}: STEP must be a positive number")
    if start <= 0:
        raise StickslipError(f"{option} {text!r}: {quantity} must be positive, START is {start:g}")
    if not start <= stop:
        raise StickslipError(f"{option} {text!r}: expected 0 < START <= STOP")
    intervals = (stop - start) / step + 1e-9
    if not intervals < MAX_MU_VALUES:  # also catches an infinite quotient
        raise StickslipError(
            f"{option} {text!r}: {f'{math.floor(intervals) + 1:,}' if math.isfinite(intervals) else 'infinitely many'} "
            f"{noun}; at most {MAX_MU_VALUES:,} are allowed (use a larger STEP)"
        )
    count = math.floor(intervals) + 1
    return np.round(start + step * np.arange(count), 12)


def parse_pga(text: str, g: float) -> float:
    """A PGA [m/s²] from ``"5.89"`` (m/s²) or ``"0.6g"`` (units of g)."""
    try:
        return float(text[:-1]) * g if text.lower().endswith("g") else float(text)
    except ValueError:
        raise StickslipError(f"--target-pga {text!r}: expected a number in m/s2, or a number followed by g") from None


def run(args) -> int:
    from stickslip.sweeps import sweep, write_cube

    check_output_path(args.out, "the NetCDF cube")
    sliding = sliding_options(args, has_ky=args.ky is not None or args.ky_list is not None)
    if args.ky is not None:
        grid = {"ky": parse_ky_range(args.ky, args.g)}
    elif args.ky_list is not None:
        grid = {"ky": [parse_yield_coefficient(text, args.g) for text in args.ky_list]}
    else:
        grid = {"mu": parse_mu_range(args.mu) if args.mu is not None else args.mu_list}
    target_pga = None if args.target_pga is None else [parse_pga(text, args.g) for text in args.target_pga]
    records = [read_record_from_args(path, args) for path in args.paths]
    (name, values), = grid.items()
    cube = sweep(
        records,
        scale=args.scale,
        target_pga=target_pga,
        mass=args.mass,
        method=args.method,
        g=args.g,
        progress=True,
        config={"command": "stickslip sweep", "paths": [str(p) for p in args.paths], name: list(map(float, values)),
                **sliding, "inverse": args.inverse},
        inverse=args.inverse,
        **grid,
        **sliding,
    )
    print(write_cube(cube, args.out))
    return 0
