"""The ``stickslip`` command line.

Each sub-command lives in its own module of this package and provides
``register(subparsers)``, which adds its parser and sets ``func``.  A
:class:`~stickslip.errors.StickslipError` raised by a command becomes one line
on stderr and exit code 2; so does an :class:`OSError` (a file that could not
be written), as ``<filename>: <strerror>``, and a mistake in the options.  A
:class:`~stickslip.errors.StickslipWarning` is one ``stickslip: warning:``
line.  Ctrl-C ends a command with exit code 130 and SIGTERM with 143, leaving
no partial output (see :func:`stickslip.plumbing.files.exit_on_interrupted_writes`).  A
reader that stops reading (``stickslip ... | head``) ends the command quietly
with exit code 141, as SIGPIPE ends a Unix tool.  Any other exception is a
bug and keeps its traceback.
"""

from __future__ import annotations

import argparse
import contextlib
import importlib
import os
import re
import signal
import sys
import threading
import warnings

from stickslip import __version__
from stickslip.errors import StickslipError, StickslipWarning

#: Sub-command modules, in the order ``--help`` lists them.
COMMAND_MODULES = ("records", "measures", "spectrum", "solve", "displacements", "estimate", "optimum", "sweep", "report",
                   "isolation")


class UsageError(StickslipError):
    """A mistake in the command-line options (an unknown choice, a value that is not a number)."""


class Terminated(KeyboardInterrupt):
    """SIGTERM, raised where the program is so that cleanup runs as for Ctrl-C."""


class _Parser(argparse.ArgumentParser):
    """argparse, with a mistake reported as one line (the usage block is for ``--help``)."""

    def error(self, message: str):
        raise UsageError(f"{self.prog}: {message} (see '{self.prog} --help')")


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(
        prog="stickslip",
        description="Rigid sliding blocks with Coulomb friction under seismic base motion.",
    )
    parser.add_argument("--version", action="version", version=f"stickslip {__version__}")
    subparsers = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for name in COMMAND_MODULES:
        importlib.import_module(f"stickslip.cli.{name}").register(subparsers)
    return parser


def parse_arguments(argv: list[str]) -> argparse.Namespace:
    """The parsed command line; arguments a command does not take are its mistake, pointing to its own ``--help``."""
    parser = build_parser()
    args, extra = parser.parse_known_args(argv)
    if extra:
        _refuse_files_after_vertical(args, argv, extra)
        _command_parser(parser, args).error(f"unrecognized arguments: {' '.join(extra)}")
    return args


def _refuse_files_after_vertical(args: argparse.Namespace, argv: list[str], extra: list[str]) -> None:
    """``--vertical A B``: one line saying that ``--vertical`` takes one file, and where the others go."""
    vertical = getattr(args, "vertical", None)
    if vertical is None or extra[0].startswith("-"):
        return
    for index, token in enumerate(argv):
        if token == "--vertical" or token.startswith("--vertical="):
            following = index + (2 if token == "--vertical" else 1)  # the token after the option's one file
            if following < len(argv) and argv[following] == extra[0]:
                raise UsageError(f"--vertical {vertical} {extra[0]}: --vertical takes one file, the vertical "
                                 "component of the station whose record (or pair, with --pair) the command's paths "
                                 "give: --vertical FILE, with the other files before it")


def _command_parser(parser: argparse.ArgumentParser, args: argparse.Namespace) -> argparse.ArgumentParser:
    """The parser of the (sub)command that ``args`` ran: ``stickslip records validate``'s for ``records validate``."""
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction) and getattr(args, action.dest, None) in action.choices:
            return _command_parser(action.choices[getattr(args, action.dest)], args)
    return parser


def main(argv: list[str] | None = None) -> int:
    """Run the command line; return the exit code (0 success, 2 bad input, 130 Ctrl-C, 141 closed pipe, 143 SIGTERM)."""
    from stickslip.plumbing.files import exit_on_interrupted_writes
    from stickslip.limits import set_limits

    exit_on_interrupted_writes(True)
    args = None
    try:
        with _terminate_as_interrupt(), warnings.catch_warnings():
            warnings.showwarning = _show_warning
            args = parse_arguments(_join_negative_ranges(sys.argv[1:] if argv is None else list(argv)))
            set_limits(getattr(args, "memory_limit", None), getattr(args, "max_file_size", None))
            code = args.func(args) or 0
            sys.stdout.flush()  # a closed pipe shows here, not at the interpreter's exit
            return 2 if _list_unread(args, done=True) else code
    except BrokenPipeError:
        # The reader of stdout went away (`stickslip ... | head`): stop quietly, as SIGPIPE stops a Unix tool.
        # Python would flush stdout again at exit and complain; point it at /dev/null.
        with contextlib.suppress(OSError, ValueError):
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 128 + signal.SIGPIPE
    except Terminated:
        print("stickslip: terminated; no partial output was kept", file=sys.stderr)
        return 128 + signal.SIGTERM
    except StickslipError as error:
        _list_unread(args)
        print(f"stickslip: error: {_as_options(str(error))}", file=sys.stderr)
        return 2
    except OSError as error:
        # A backstop for output that could not be written (disk full, permissions
        # changed after the early checks): one line, no traceback.  Outputs go
        # through stickslip.plumbing.files.atomic_path, so nothing half-written is left.
        print(f"stickslip: error: {_describe_os_error(error)}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("stickslip: interrupted; no partial output was kept", file=sys.stderr)
        return 128 + signal.SIGINT
    finally:
        exit_on_interrupted_writes(False)
        set_limits()


def _list_unread(args: argparse.Namespace | None, done: bool = False) -> bool:
    """The files ``--keep-going`` left out, one error line each (and, when the command ``done`` its work on the
    others, a last line that says so); whether there were any."""
    unread = getattr(args, "unread_files", [])
    for message in unread:
        print(f"stickslip: error: {_as_options(message)}", file=sys.stderr)
    if unread and done:
        print(f"stickslip: error: {len(unread)} file{'s' if len(unread) > 1 else ''} could not be read (listed above); "
              "--keep-going computed the others", file=sys.stderr)
    return bool(unread)


def _as_options(message: str) -> str:
    """A library message with the arguments it names written as this command line's options.

    The record reader's ``dt=`` becomes ``--dt``; a model's parameter written
    ``name=`` becomes ``--name``, and ``name=value`` ``--name value``
    (``vs_base=`` -> ``--vs-base``, ``model=coupled`` -> ``--model coupled``).
    """
    from stickslip.models import MODELS
    from stickslip.records.readers import ARGUMENT_IN_MESSAGE

    message = ARGUMENT_IN_MESSAGE.sub(r"--\1", message)
    names = {"model", *(parameter.name for entry in MODELS.values() for parameter in entry.parameters)}
    pattern = re.compile(r"\b(" + "|".join(sorted(names, key=len, reverse=True)) + r")=(\S*)")

    def option(match: re.Match) -> str:
        value = match.group(2)
        return "--" + match.group(1).replace("_", "-") + (f" {value}" if value and value[0] not in ",)" else value)

    return pattern.sub(option, message)


@contextlib.contextmanager
def _terminate_as_interrupt():
    """While the command runs, SIGTERM raises :class:`Terminated` (in the main thread)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def terminate(signum, frame):
        raise Terminated()

    previous = signal.signal(signal.SIGTERM, terminate)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)


def _show_warning(message, category, filename, lineno, file=None, line=None) -> None:
    """A :class:`StickslipWarning` as one line on stderr; other warnings as Python shows them."""
    if issubclass(category, StickslipWarning):
        print(f"stickslip: warning: {_as_options(str(message))}", file=sys.stderr)
    else:
        sys.stderr.write(warnings.formatwarning(message, category, filename, lineno, line))


def _join_negative_ranges(argv: list[str]) -> list[str]:
    """``--mu -0.1:0.2:0.05`` -> ``--mu=-0.1:0.2:0.05``, ``--ky -0.1g`` -> ``--ky=-0.1g``.

    argparse takes a value that starts with ``-`` and is not a plain number for
    an option, and stops with "expected one argument"; joined, the range (or
    the yield acceleration) reaches the command's own check, which says what is
    wrong with it.
    """
    joined: list[str] = []
    index = 0
    while index < len(argv):
        token = argv[index]
        following = argv[index + 1] if index + 1 < len(argv) else ""
        negative = re.match(r"-[0-9.]", following)
        if (token == "--mu" and negative and ":" in following) or (token == "--ky" and negative):
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
