"""The options that tell the commands how to read record files, and how much work to accept.

``--format``, ``--dt`` [s] and ``--units`` say how to read a file (each
file's format, time step and units come first from the file itself and the
manifests we ship, so files of different formats mix in one call);
``--max-file-size`` and ``--memory-limit`` raise (or lower) the limits of
:mod:`stickslip.limits`.  Values in g are converted with the command's ``--g``
[m/s²] (:func:`add_gravity_option` where the command has no other use for it):
one g per call.  A record that is a vertical component gets a note on stderr
when it is analysed alone (:func:`note_vertical`).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from stickslip.cli.model_options import gravity
from stickslip.cli.quantities import of_unit, quantity_type, read_gravity
from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.limits import (
    DEFAULT_MAX_FILE_SIZE,
    DEFAULT_MEMORY_LIMIT,
    format_size,
    parse_size,
)
from stickslip.records.components import vertical_component
from stickslip.records.formats import FORMATS, RECORD_UNITS
from stickslip.records.process import record_name
from stickslip.records.readers import read_record
from stickslip.records.record import Record


def add_record_options(parser: argparse.ArgumentParser, *, check_choices: bool = True) -> None:
    """Add ``--format``, ``--dt`` [s] and ``--units`` to ``parser``, each defaulting to ``None``.

    With ``check_choices`` False argparse accepts any format and units, and the
    reader reports an unknown one as an error about the file read.
    """
    parser.add_argument(
        "--format", choices=sorted(FORMATS) if check_choices else None, default=None, help="file format (default: detected)"
    )
    parser.add_argument(
        "--dt", type=quantity_type(of_unit("s"), "--dt"), default=None,
        help="time step [s] for a file that states none and that no manifest we ship knows (a dt that contradicts "
        "the file's or the manifest's is an error; or with its unit, 5ms)",
    )
    parser.add_argument(
        "--units",
        choices=RECORD_UNITS if check_choices else None,
        default=None,
        help="units of the values in the file: g, m/s2 or cm/s2 (values in g are converted with --g)",
    )
    parser.add_argument(
        "--max-file-size", type=_size, default=None, metavar="SIZE",
        help=f"largest record file to read, e.g. 500M (default {format_size(DEFAULT_MAX_FILE_SIZE)}, "
        "or STICKSLIP_MAX_FILE_SIZE)",
    )
    parser.add_argument(
        "--memory-limit", type=_size, default=None, metavar="SIZE",
        help=f"refuse work estimated to need more memory, e.g. 16G (default {format_size(DEFAULT_MEMORY_LIMIT)}, "
        "or STICKSLIP_MEMORY_LIMIT)",
    )


def add_gravity_option(parser: argparse.ArgumentParser) -> None:
    """Add ``--g`` [m/s²], the gravity that converts values in g (for a command whose only use of g that is)."""
    parser.add_argument("--g", type=read_gravity, default=STANDARD_GRAVITY,
                        help=f"gravity [m/s2] that converts values in g, and the PGA in g (default {STANDARD_GRAVITY}; "
                             "SLAMMER's is 9.80665; or with its unit, 981cm/s2)")


def _size(text: str) -> int:
    """A size option's value in bytes; argparse reports a bad one as one line."""
    try:
        return parse_size(text, "size")
    except StickslipError as error:
        raise argparse.ArgumentTypeError(str(error)) from None


def read_record_from_args(path: str | Path, args: argparse.Namespace, manifest: dict | None = None,
                          accept_zero: bool = False) -> Record:
    """Read the record file ``path`` (into m/s² and s) as the options of :func:`add_record_options` say, values in g
    converted with the command's ``--g`` [m/s²]; ``accept_zero`` as for :func:`~stickslip.records.readers.read_record`."""
    return read_record(path, format=args.format, dt=args.dt, units=args.units, manifest=manifest, g=gravity(args),
                       accept_zero=accept_zero)


def note_vertical(records) -> None:
    """One note on stderr per record that is a vertical component (:func:`~stickslip.records.components.vertical_component`)."""
    for record in records:
        vertical = vertical_component(record.meta)
        if vertical is not None:
            print(f"stickslip: note: {record_name(record)} is a vertical component ({vertical}); it is analysed as "
                  "given, as a horizontal ground motion would be", file=sys.stderr)


def record_files(paths) -> list[Path]:
    """``paths`` without its directories, each skipped with one note on stderr (``my_records/*`` may hold a folder).

    Only directories are left out: a missing file stays, for the reader to report.
    """
    paths = [Path(path) for path in paths]
    folders = {path for path in paths if path.is_dir()}
    if len(folders) == len(paths):
        raise StickslipError(f"{', '.join(map(str, paths))}: {'a directory' if len(paths) == 1 else 'directories'}, "
                             f"no record file (give the files in it, e.g. {paths[0]}/*)")
    for path in paths:
        if path in folders:
            print(f"stickslip: note: {path} is a directory, skipped (give the files in it, e.g. {path}/*)",
                  file=sys.stderr)
    return [path for path in paths if path not in folders]


def add_keep_going_option(parser: argparse.ArgumentParser) -> None:
    """Add ``--keep-going``: with several files, compute every file that can be read and list the others at the end."""
    parser.add_argument("--keep-going", action="store_true",
                        help="with several files: compute every file that can be read, then list the others, each "
                             "with its reason, and exit with code 2 (without it the first file that cannot be read "
                             "stops the call)")


def unread_files(args: argparse.Namespace) -> list[str]:
    """The files ``--keep-going`` left out, each as one line naming the file and why (filled in as files are read)."""
    if not hasattr(args, "unread_files"):
        args.unread_files = []
    return args.unread_files


def read_records_from_args(paths, args: argparse.Namespace, manifest: dict | None = None,
                           alone: bool = True, places: bool = False) -> list[Record]:
    """:func:`read_record_from_args` of each file of ``paths``, in order (each error names its file).

    Directories among ``paths`` are skipped with a note (:func:`record_files`).
    Two files with the same record id (the file name, or a manifest's id) are
    an error naming both: the results are labelled by record.  Records to be
    analysed ``alone`` get a note when vertical (:func:`note_vertical`); the
    components of pairs (not ``alone``) may be zero throughout (a uniaxial test).

    The first file that cannot be read stops the call, unless ``--keep-going``
    (``args.keep_going``) and several files: then each such file is left out,
    its error kept in :func:`unread_files` for the command line to list at the
    end, and the others are read (``places``: a None where each was left out,
    so that pairs keep their places); one line when none can be read.
    """
    files = record_files(paths)
    keep_going = getattr(args, "keep_going", False) and len(files) > 1
    records, first = [], {}
    for path in files:
        try:
            record = read_record_from_args(path, args, manifest, accept_zero=not alone)
        except StickslipError as error:
            if not keep_going:
                raise
            unread_files(args).append(str(error))
            records.extend([None] if places else [])
            continue
        earlier = first.get(record.meta.record_id)
        if earlier is not None:
            problem = ("is given twice" if Path(earlier).resolve() == Path(path).resolve() else
                       f"and {path} have the same record id {record.meta.record_id!r} (the file name, or the id a "
                       "manifest gives the file); give one of them another name")
            raise StickslipError(f"{earlier} {problem}")
        first[record.meta.record_id] = path
        records.append(record)
    if keep_going and not first:
        raise StickslipError(f"--keep-going: none of the {len(files)} files could be read")
    if alone:
        note_vertical([record for record in records if record is not None])
    return records
