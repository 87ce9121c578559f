"""The options that tell the commands how to read record files: ``--format``, ``--dt`` and ``--units``."""

from __future__ import annotations

import argparse
from pathlib import Path

from stickslip.records.readers import KNOWN_FORMATS, UNIT_FACTORS, read_record
from stickslip.records.record import Record


def add_record_options(parser: argparse.ArgumentParser, *, check_choices: bool = True) -> None:
    """Add ``--format``, ``--dt`` [s] and ``--units`` to ``parser``, each defaulting to ``None``.

    With ``check_choices`` False argparse accepts any format and units, and the
    reader reports an unknown one as an error about the file read.
    """
    parser.add_argument(
        "--format", choices=KNOWN_FORMATS if check_choices else None, default=None, help="file format (default: detected)"
    )
    parser.add_argument("--dt", type=float, default=None, help="time step [s] for a file without one")
    parser.add_argument(
        "--units",
        choices=tuple(UNIT_FACTORS) if check_choices else None,
        default=None,
        help="units of the values in the file: g, m/s2 or cm/s2",
    )


def read_record_from_args(path: str | Path, args: argparse.Namespace, manifest: dict | None = None) -> Record:
    """Read the record file ``path`` (into m/s² and s) as the options of :func:`add_record_options` say."""
    return read_record(path, format=args.format, dt=args.dt, units=args.units, manifest=manifest)
