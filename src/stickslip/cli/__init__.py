"""The ``stickslip`` command line.

Each sub-command lives in its own module of this package and provides
``register(subparsers)``, which adds its parser and sets ``func``.  A
:class:`~stickslip.errors.StickslipError` raised by a command becomes one line
on stderr and exit code 2.
"""

from __future__ import annotations

import argparse
import importlib
import sys

from stickslip import __version__
from stickslip.errors import StickslipError

#: Sub-command modules, in the order ``--help`` lists them.
COMMAND_MODULES = ("records", "measures", "solve", "sweep", "study")


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="stickslip",
        description="Rigid sliding blocks with Coulomb friction under seismic base motion.",
    )
    parser.add_argument("--version", action="version", version=f"stickslip {__version__}")
    subparsers = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for name in COMMAND_MODULES:
        importlib.import_module(f"stickslip.cli.{name}").register(subparsers)
    return parser


def main(argv: list[str] | None = None) -> int:
    """Run the command line; return the exit code (0 success, 2 bad input)."""
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return args.func(args) or 0
    except StickslipError as error:
        print(f"stickslip: error: {error}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("stickslip: interrupted; no partial output was kept", file=sys.stderr)
        return 130


if __name__ == "__main__":
    sys.exit(main())
