"""``--method`` and ``--time-step``: which solver scheme, and its options (``solve``, ``sweep``).

The choices come from :data:`stickslip.solvers.registry.SCHEME_MODULES`
without importing a scheme (the command line starts fast); what a scheme
accepts is asked of its entry only when an option needs it.
"""

from __future__ import annotations

import argparse

from stickslip.errors import StickslipError
from stickslip.solvers.registry import SCHEME_MODULES, schemes_with_option


def add_scheme_options(parser: argparse.ArgumentParser, time_step_help: str = "") -> None:
    """``--method`` (a scheme of the registry, default ``exact``, which solves every model) and ``--time-step`` [s]."""
    parser.add_argument("--method", choices=tuple(SCHEME_MODULES), default="exact",
                        help=f"solver scheme: {', '.join(SCHEME_MODULES)} (default exact; docs/solvers.md): newmark "
                             "is the paper's Algorithm 1 (rigid block, --mu only), slammer SLAMMER's scheme (rigid, "
                             "decoupled or coupled)")
    parser.add_argument("--time-step", type=float, default=None,
                        help="integration step [s] of a scheme that takes one (newmark: default 0.001)" + time_step_help)


def scheme_options_from_args(args: argparse.Namespace) -> dict:
    """The scheme options the command line gives (``time_step``), refused for a scheme that does not take them."""
    if args.time_step is None:
        return {}
    takers = schemes_with_option("time_step")
    if args.method not in takers:
        raise StickslipError(f"--time-step applies to --method {' or '.join(takers)} only ({args.method} follows the "
                             "record's samples)")
    return {"time_step": args.time_step}
