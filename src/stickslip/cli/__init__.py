"""The ``stickslip`` command line.

Each sub-command lives in its own module of this package and provides
``register(subparsers)``, which adds its parser and sets ``func``.  A
:class:`~stickslip.errors.StickslipError` raised by a command becomes one line
on stderr and exit code 2; so does an :class:`OSError` (a file that could not
be written), as ``<filename>: <strerror>``.  Any other exception is a bug and
keeps its traceback.
"""

from __future__ import annotations

import argparse
import importlib
import re
import sys

from stickslip import __version__
from stickslip.errors import StickslipError

#: Sub-command modules, in the order ``--help`` lists them.
COMMAND_MODULES = ("records", "measures", "solve", "sweep")


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
    args = parser.parse_args(_join_negative_ranges(sys.argv[1:] if argv is None else list(argv)))
    try:
        return args.func(args) or 0
    except StickslipError as error:
        print(f"stickslip: error: {error}", file=sys.stderr)
        return 2
    except OSError as error:
        # A backstop for output that could not be written (disk full, permissions
        # changed after the early checks): one line, no traceback.  Outputs go
        # through stickslip.io.atomic_path, so nothing half-written is left.
        print(f"stickslip: error: {_describe_os_error(error)}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("stickslip: interrupted; no partial output was kept", file=sys.stderr)
        return 130


def _join_negative_ranges(argv: list[str]) -> list[str]:
    """``--mu -0.1:0.2:0.05`` -> ``--mu=-0.1:0.2:0.05``.

    argparse takes a value that starts with ``-`` and is not a plain number for
    an option, and stops with "expected one argument"; joined, the range reaches
    the command's own check, which says what is wrong with it.
    """
    joined: list[str] = []
    index = 0
    while index < len(argv):
        token = argv[index]
        following = argv[index + 1] if index + 1 < len(argv) else ""
        if token == "--mu" and re.match(r"-[0-9.]", following) and ":" in following:
            joined.append(f"{token}={following}")
            index += 2
            continue
        if token == "--":
            joined.extend(argv[index:])
            break
        joined.append(token)
        index += 1
    return joined


def _describe_os_error(error: OSError) -> str:
    """``<filename>: <strerror>`` for an OSError (the file it names, when it names one)."""
    problem = error.strerror or str(error) or type(error).__name__
    if error.filename is not None:
        return f"{error.filename}: {problem}"
    return problem


if __name__ == "__main__":
    sys.exit(main())
