"""The options that say what to sweep, shared by ``stickslip sweep`` and ``stickslip optimum``, and their checks.

``--mu START:STOP:STEP`` or ``--mu-list MU...`` (friction ratios [1]),
``--scale FACTOR...`` or ``--target-pga PGA...`` ([m/s2], or ``0.6g``),
``--mass`` [kg], ``--g`` [m/s2], ``--q`` and ``--reference-mu`` (the
per-record results of :mod:`stickslip.optimum`).  Also the one-line note
that the block never slides at a friction ratio whose μ·g reaches the record's PGA.
"""

from __future__ import annotations

import argparse
import math
import sys
from collections.abc import Sequence

import numpy as np

from stickslip.constants import PAPER_BLOCK_MASS, STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.optimum import DEFAULT_Q, DEFAULT_REFERENCE_MU
from stickslip.records.process import peak_ground_acceleration, record_name
from stickslip.records.record import Record

#: Most friction ratios a ``--mu`` range may hold (a guard against a mistyped STEP).
MAX_MU_VALUES = 1_000_000


def add_grid_options(parser: argparse.ArgumentParser, default_mu: str | None = None) -> None:
    """Add the friction grid, scaling, mass, gravity, q and reference-μ options to ``parser``.

    ``default_mu`` (``START:STOP:STEP``) is the grid when neither ``--mu`` nor
    ``--mu-list`` is given; without one, either is required.
    """
    friction = parser.add_mutually_exclusive_group(required=default_mu is None)
    friction.add_argument(
        "--mu", metavar="START:STOP:STEP", default=default_mu,
        help=f"friction ratios from START to STOP inclusive, at most {MAX_MU_VALUES:,} of them "
        "(write --mu=START:STOP:STEP when START starts with a minus sign)"
        + (f"; default {default_mu}" if default_mu else ""),
    )
    friction.add_argument("--mu-list", type=float, nargs="+", metavar="MU", help="explicit friction ratios")
    scaling = parser.add_mutually_exclusive_group()
    scaling.add_argument("--scale", type=float, nargs="+", metavar="FACTOR", help="scale factors [-]")
    scaling.add_argument(
        "--target-pga", nargs="+", metavar="PGA",
        help="scale each record to these PGAs [m/s2]; a suffix g means units of g (0.6g)",
    )
    parser.add_argument("--mass", type=float, default=PAPER_BLOCK_MASS, help="block mass [kg] (default %(default)s)")
    parser.add_argument("--g", type=float, default=STANDARD_GRAVITY, help="gravity [m/s2] (default %(default)s)")
    parser.add_argument(
        "--q", type=float, default=DEFAULT_Q,
        help="near-optimal fraction: the range of mu whose E_df is at least q times the maximum (default %(default)s)",
    )
    parser.add_argument(
        "--reference-mu", type=float, default=DEFAULT_REFERENCE_MU,
        help="friction ratio whose E_df and efficiency (E_df / E_df,max) are reported (default %(default)s)",
    )


def friction_ratios(args: argparse.Namespace) -> np.ndarray:
    """The friction ratios [1] of ``--mu`` or ``--mu-list``."""
    return parse_mu_range(args.mu) if args.mu_list is None else np.asarray(args.mu_list, dtype=float)


def target_pgas(args: argparse.Namespace) -> list[float] | None:
    """The ``--target-pga`` values [m/s2], or None."""
    return None if args.target_pga is None else [parse_pga(text, args.g) for text in args.target_pga]


def check_optimum_options(args: argparse.Namespace) -> None:
    """``--q`` in (0, 1] and ``--reference-mu`` positive, else one clear line."""
    if not 0.0 < args.q <= 1.0:
        raise StickslipError(f"--q {args.q:g}: the near-optimal fraction must be in (0, 1], such as 0.95")
    if not (math.isfinite(args.reference_mu) and args.reference_mu > 0.0):
        raise StickslipError(f"--reference-mu {args.reference_mu:g}: a friction ratio must be a positive number")


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


def parse_pga(text: str, g: float, option: str = "--target-pga") -> float:
    """A PGA [m/s²] from ``"5.89"`` (m/s²) or ``"0.6g"`` (units of g, ``g`` [m/s²] each)."""
    try:
        return float(text[:-1]) * g if text.lower().endswith("g") else float(text)
    except ValueError:
        raise StickslipError(f"{option} {text!r}: expected a number in m/s2, or a number followed by g") from None


def note_never_slides(versions: Sequence[Record], mu: np.ndarray, g: float) -> None:
    """For each record (or scaled version), one note on stderr if μ·g reaches its PGA at some of ``mu`` [1].

    The block slides only while |ü_g| exceeds μ·g, so at those friction
    ratios it sticks to the base throughout and dissipates nothing.
    """
    mu = np.atleast_1d(np.asarray(mu, dtype=float))
    for version in versions:
        pga = peak_ground_acceleration(version)
        still = mu[mu * g >= pga]
        if still.size == 0:
            continue
        scaled = f" ({version.meta.processing[-1]})" if version.meta.processing else ""
        which = (f"mu = {still[0]:g}" if still.size == 1 else
                 f"the {still.size:,} friction ratios from {still[0]:g} to {still[-1]:g}" if still.size < mu.size else
                 f"any of the {mu.size:,} friction ratios (from {mu[0]:g})")
        print(f"stickslip: note: {record_name(version)}{scaled}: the block never slides at {which}: mu*g is at least "
              f"the record's PGA, {pga:.4g} m/s2 ({pga / g:.4g} g), so E_df = 0 there", file=sys.stderr)
