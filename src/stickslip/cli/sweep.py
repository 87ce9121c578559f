"""``stickslip sweep PATH... --mu START:STOP:STEP --out cube.nc``: a friction-ratio sweep into a NetCDF cube."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from stickslip.cli.record_options import add_record_options, read_record_from_args
from stickslip.constants import PAPER_BLOCK_MASS, STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.io import check_output_path
from stickslip.solution import SOLVERS


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "sweep",
        help="solve record files over a range of friction ratios and write a NetCDF cube",
        description=(
            "Solve every record for every friction ratio (optionally scaled) and write the response "
            "scalars (energies in J, lengths in m) as a compressed NetCDF cube, atomically."
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
    scaling = parser.add_mutually_exclusive_group()
    scaling.add_argument("--scale", type=float, nargs="+", metavar="FACTOR", help="scale factors [-]")
    scaling.add_argument(
        "--target-pga", nargs="+", metavar="PGA", help="scale each record to these PGAs [m/s2]; a suffix g means units of g (0.6g)"
    )
    parser.add_argument("--mass", type=float, default=PAPER_BLOCK_MASS, help="block mass [kg] (default %(default)s)")
    parser.add_argument("--method", choices=tuple(SOLVERS), default="exact", help="solver (default exact)")
    parser.add_argument("--g", type=float, default=STANDARD_GRAVITY, help="gravity [m/s2] (default %(default)s)")
    add_record_options(parser)
    parser.add_argument("--out", type=Path, required=True, help="the NetCDF cube to write")
    parser.set_defaults(func=run)


#: Most friction ratios a ``--mu`` range may hold (a guard against a mistyped STEP).
MAX_MU_VALUES = 1_000_000


def parse_mu_range(text: str) -> np.ndarray:
    """Friction ratios [1] from ``START:STOP:STEP``, STOP included when it lies on the grid."""
    parts = text.split(":")
    try:
        start, stop, step = (float(part) for part in parts)
    except ValueError:
        raise StickslipError(f"--mu {text!r}: expected START:STOP:STEP, three numbers such as 0.05:0.2:0.025") from None
    if not all(math.isfinite(v) for v in (start, stop, step)) or step <= 0:
        raise StickslipError(f"--mu {text!r}: STEP must be a positive number")
    if start <= 0:
        raise StickslipError(f"--mu {text!r}: friction ratios mu must be positive, START is {start:g}")
    if not start <= stop:
        raise StickslipError(f"--mu {text!r}: expected 0 < START <= STOP")
    intervals = (stop - start) / step + 1e-9
    if not intervals < MAX_MU_VALUES:  # also catches an infinite quotient
        raise StickslipError(
            f"--mu {text!r}: {f'{math.floor(intervals) + 1:,}' if math.isfinite(intervals) else 'infinitely many'} friction ratios; "
            f"at most {MAX_MU_VALUES:,} are allowed (use a larger STEP)"
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
    mu = parse_mu_range(args.mu) if args.mu is not None else args.mu_list
    target_pga = None if args.target_pga is None else [parse_pga(text, args.g) for text in args.target_pga]
    records = [read_record_from_args(path, args) for path in args.paths]
    cube = sweep(
        records,
        mu,
        scale=args.scale,
        target_pga=target_pga,
        mass=args.mass,
        method=args.method,
        g=args.g,
        progress=True,
        config={"command": "stickslip sweep", "paths": [str(p) for p in args.paths], "mu": list(map(float, mu))},
    )
    print(write_cube(cube, args.out))
    return 0
