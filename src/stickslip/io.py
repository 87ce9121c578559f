"""Atomic file output and provenance attributes."""

from __future__ import annotations

import contextlib
import csv
import io
import os
import platform
import subprocess
import tempfile
from collections.abc import Iterator
from pathlib import Path

from stickslip.errors import StickslipError


@contextlib.contextmanager
def atomic_path(target: str | Path) -> Iterator[Path]:
    """Yield a temporary path beside ``target``; rename it to ``target`` on success.

    If the body raises (or the process is interrupted), the temporary file is
    removed and ``target`` is left as it was: a reader never sees a
    half-written file.
    """
    target = Path(target)
    target.parent.mkdir(parents=True, exist_ok=True)
    handle, tmp_name = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".part", dir=target.parent)
    os.close(handle)
    tmp = Path(tmp_name)
    tmp.chmod(0o666 & ~_current_umask())  # mkstemp makes 0600; give the file the usual permissions
    try:
        yield tmp
        os.replace(tmp, target)
    finally:
        tmp.unlink(missing_ok=True)


def check_output_path(target: str | Path, what: str = "the output file") -> Path:
    """Check, before any work, that ``target`` can be written as a file; return it as a Path.

    Raises :class:`~stickslip.errors.StickslipError` naming ``target`` when it
    is a directory, when one of its parents is a file, or when the nearest
    existing parent folder is not writable (the folders in between are created
    by :func:`atomic_path`).  Nothing is created here.
    """
    target = Path(target)
    if target.is_dir():
        raise StickslipError(f"{target}: cannot write {what}: it is a directory; give a file name")
    _check_parents(target, target.parent, what)
    return target


def check_output_dir(folder: str | Path, what: str = "output") -> Path:
    """Check, before any work, that files can be written under the folder ``folder``; return it as a Path.

    Raises :class:`~stickslip.errors.StickslipError` naming ``folder`` when it
    (or one of its parents) is a file, or when the nearest existing folder is
    not writable.  Nothing is created here.
    """
    folder = Path(folder)
    _check_parents(folder, folder, what)
    return folder


def _check_parents(target: Path, folder: Path, what: str) -> None:
    """The nearest existing ancestor of ``folder`` (itself included) must be a writable folder."""
    existing = folder
    while not existing.exists() and existing != existing.parent:
        existing = existing.parent
    shown = existing if str(existing) else Path(".")
    if not existing.is_dir():
        where = "it" if existing == target else str(shown)
        raise StickslipError(f"{target}: cannot write {what}: {where} is a file, not a folder")
    problem = None if os.access(existing, os.W_OK | os.X_OK) else "permission denied"
    if problem is None:
        try:  # os.access says yes to root everywhere; a nameless temporary file is the real test
            with tempfile.TemporaryFile(dir=existing):
                pass
        except OSError as error:
            problem = error.strerror or str(error)
    if problem is not None:
        raise StickslipError(f"{target}: cannot write {what}: folder {shown} is not writable ({problem})")


def _current_umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def write_text_atomic(target: str | Path, text: str) -> None:
    """Write ``text`` to ``target`` atomically (UTF-8)."""
    with atomic_path(target) as tmp:
        tmp.write_text(text, encoding="utf-8")


def write_csv_atomic(target: str | Path, rows: list[dict], fieldnames: list[str] | None = None) -> Path:
    """Write ``rows`` (dicts) to ``target`` as CSV with a header, atomically; return ``target``.

    The columns are ``fieldnames``, or the keys of the rows in first-seen order.
    """
    if fieldnames is None:
        fieldnames = list(dict.fromkeys(key for row in rows for key in row))
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, fieldnames=fieldnames, lineterminator="\n")
    writer.writeheader()
    writer.writerows(rows)
    write_text_atomic(target, buffer.getvalue())
    return Path(target)


def git_commit() -> str:
    """The git commit of the stickslip source tree, or ``"unknown"`` outside a checkout."""
    try:
        out = subprocess.run(
            ["git", "rev-parse", "HEAD"],
            cwd=Path(__file__).resolve().parent,
            capture_output=True,
            text=True,
            timeout=5,
            check=True,
        )
    except (OSError, subprocess.SubprocessError):
        return "unknown"
    return out.stdout.strip() or "unknown"


def provenance() -> dict[str, str]:
    """Attributes that say which code produced a file."""
    from stickslip import __version__

    return {
        "stickslip_version": __version__,
        "git_commit": git_commit(),
        "python_version": platform.python_version(),
    }
