"""Limits on the work a command may take on: memory and the size of a record file.

Every command estimates the memory [bytes] it is about to allocate and calls
:func:`check_memory` first, so that a mistyped time step or grid is refused
with one line instead of filling the machine.  The limits come, in order,
from :func:`set_limits` (the command-line options ``--memory-limit`` and
``--max-file-size``), the environment variables ``STICKSLIP_MEMORY_LIMIT``
and ``STICKSLIP_MAX_FILE_SIZE``, or the defaults below.  Sizes are written as
a number of bytes with an optional suffix K, M, G or T (powers of 1024).
"""

from __future__ import annotations

import os
import re

from stickslip.errors import StickslipError

#: Default memory limit [bytes] for one command's arrays.
DEFAULT_MEMORY_LIMIT = 4 * 1024**3

#: Default size limit [bytes] of a record file (real records are at most a few MB).
DEFAULT_MAX_FILE_SIZE = 100 * 1024**2

#: Bytes per history point of one solve: about 30 float64 arrays along the time axis
#: (resampled input, ground motion, kernel outputs, the response's histories and their NetCDF copy).
HISTORY_BYTES_PER_POINT = 30 * 8

_SUFFIXES = {"": 1, "K": 1024, "M": 1024**2, "G": 1024**3, "T": 1024**4}
_SIZE = re.compile(r"^\s*([0-9]*\.?[0-9]+(?:[eE][+-]?[0-9]+)?)\s*([KMGT]?)(?:i?B)?\s*$", re.IGNORECASE)

_overrides: dict[str, int | None] = {"memory": None, "file": None}


def parse_size(text: str, what: str) -> int:
    """Bytes from ``"4G"``, ``"512M"``, ``"1e9"``…; :class:`StickslipError` naming ``what`` if unreadable."""
    match = _SIZE.match(str(text))
    if not match:
        raise StickslipError(f"{what} {text!r}: expected a size such as 512M, 4G or a number of bytes")
    size = float(match.group(1)) * _SUFFIXES[match.group(2).upper()]
    if not size >= 1:
        raise StickslipError(f"{what} {text!r}: must be at least 1 byte")
    return int(size)


def format_size(size: float) -> str:
    """``size`` [bytes] for a message: ``"1.5 GiB"``."""
    for unit, factor in (("TiB", 1024**4), ("GiB", 1024**3), ("MiB", 1024**2), ("KiB", 1024)):
        if size >= factor:
            return f"{size / factor:.3g} {unit}"
    return f"{size:.0f} bytes"


def set_limits(memory: int | None = None, file_size: int | None = None) -> None:
    """Override the memory and file-size limits [bytes] for this process; ``None`` restores the default."""
    _overrides["memory"] = memory
    _overrides["file"] = file_size


def memory_limit() -> int:
    """The memory limit [bytes]."""
    return _limit("memory", "STICKSLIP_MEMORY_LIMIT", DEFAULT_MEMORY_LIMIT)


def max_file_size() -> int:
    """The largest record file [bytes] a reader accepts."""
    return _limit("file", "STICKSLIP_MAX_FILE_SIZE", DEFAULT_MAX_FILE_SIZE)


def _limit(key: str, variable: str, default: int) -> int:
    if _overrides[key] is not None:
        return _overrides[key]
    text = os.environ.get(variable)
    return parse_size(text, variable) if text else default


def check_memory(nbytes: float, what: str) -> None:
    """Refuse, before allocating, work that needs more than :func:`memory_limit` bytes.

    ``nbytes`` is the estimate [bytes]; ``what`` says what would need it
    (``"newmark with time_step 1e-07 s on 18,000 samples"``).
    """
    limit = memory_limit()
    if not nbytes <= limit:
        raise StickslipError(
            f"{what} would need about {format_size(nbytes)} of memory, more than the limit of {format_size(limit)}; "
            "raise it with --memory-limit or STICKSLIP_MEMORY_LIMIT if the machine has the memory"
        )
