"""Atomic file output and provenance attributes."""

from __future__ import annotations

import contextlib
import csv
import functools
import io
import os
import platform
import re
import signal
import socket
import subprocess
import tempfile
import threading
import time
from collections.abc import Iterator
from pathlib import Path

from stickslip.errors import StickslipError


#: ``.part`` files older than this [s] are removed even when their writer is unknown: written
#: on another machine (a shared folder under a batch system) or named without a process id.
STALE_PART_AGE = 3600.0

_exit_on_interrupted_write = False


def exit_on_interrupted_writes(enabled: bool = True) -> None:
    """Make Ctrl-C or SIGTERM during a write remove the temporary file and end the process at once.

    The command line turns this on: the exit code is 128 + the signal number
    (130 for Ctrl-C, 143 for SIGTERM).  Off (the library's default), the
    signal is held until the write is over and then delivered, the output
    being dropped; either way no library code (xarray's file lock in
    ``to_netcdf``) is left half-way.
    """
    global _exit_on_interrupted_write
    _exit_on_interrupted_write = enabled


@contextlib.contextmanager
def atomic_path(target: str | Path) -> Iterator[Path]:
    """Yield a temporary path beside ``target``; rename it to ``target`` on success.

    If the body raises, or the process is interrupted (Ctrl-C, SIGTERM), the
    temporary file is removed and ``target`` is left as it was: a reader
    never sees a half-written file.  The temporary file is named
    ``.{name}.{host}-{pid}.{random}.part``; those that killed processes left
    in the same folder are removed first (:func:`remove_stale_parts`).
    """
    target = Path(target)
    target.parent.mkdir(parents=True, exist_ok=True)
    remove_stale_parts(target)
    handle, tmp_name = tempfile.mkstemp(prefix=f".{target.name}.{_host()}-{os.getpid()}.", suffix=".part", dir=target.parent)
    os.close(handle)
    tmp = Path(tmp_name)
    tmp.chmod(0o666 & ~_current_umask())  # mkstemp makes 0600; give the file the usual permissions
    try:
        with _signals_held(tmp) as interrupted:
            yield tmp
            if not interrupted:
                os.replace(tmp, target)
    finally:
        tmp.unlink(missing_ok=True)


def remove_stale_parts(target: str | Path) -> list[Path]:
    """Remove the ``.part`` files that unfinished writes left in the folder of ``target``; return them.

    A ``.part`` file named by :func:`atomic_path` is stale when its process
    (host and pid in the name) is no longer running on this machine; one
    from another machine, or named otherwise, when it is older than
    :data:`STALE_PART_AGE`.  Files of running writers are left alone.
    """
    owner = re.compile(r"\..+\.(?P<host>[^.]+)-(?P<pid>\d+)\.[^.]+\.part")
    removed = []
    for path in Path(target).parent.glob(".*.part"):
        match = owner.fullmatch(path.name)
        if match is not None and match["host"] == _host():
            stale = not _process_alive(int(match["pid"]))
        else:
            try:
                stale = time.time() - path.stat().st_mtime > STALE_PART_AGE
            except OSError:
                stale = False
        if stale:
            path.unlink(missing_ok=True)
            removed.append(path)
    return removed


def _host() -> str:
    return socket.gethostname().split(".")[0] or "host"


def _process_alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


@contextlib.contextmanager
def _signals_held(tmp: Path) -> Iterator[list[int]]:
    """Catch SIGINT and SIGTERM while ``tmp`` is written; yield the list of signals received.

    With :func:`exit_on_interrupted_writes` on, a signal removes ``tmp`` and
    exits at once with 128 + signal.  Otherwise it is recorded, and delivered
    again (``tmp`` removed) when the write is over.  A signal the process
    ignores (a background job's SIGINT) stays ignored.  Outside the main
    thread signals cannot be caught, and nothing changes.
    """
    received: list[int] = []
    if threading.current_thread() is not threading.main_thread():
        yield received
        return

    def handler(signum, frame):
        if _exit_on_interrupted_write:
            tmp.unlink(missing_ok=True)
            os.write(2, b"stickslip: interrupted; no partial output was kept\n")
            os._exit(128 + signum)
        received.append(signum)

    ignored = {number for number in (signal.SIGINT, signal.SIGTERM) if signal.getsignal(number) == signal.SIG_IGN}
    previous = {number: signal.signal(number, handler) for number in (signal.SIGINT, signal.SIGTERM) if number not in ignored}
    try:
        yield received
    finally:
        for number, old in previous.items():
            signal.signal(number, old)
    if received:
        tmp.unlink(missing_ok=True)
        signal.raise_signal(received[0])


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


def read_csv_rows(path: str | Path) -> list[dict[str, str]]:
    """The rows of a CSV table with a header, as dicts of strings."""
    with open(path, newline="", encoding="utf-8") as handle:
        return list(csv.DictReader(handle))


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


@functools.cache
def git_commit() -> str:
    """The git commit of the stickslip source tree, or ``"unknown"`` outside a checkout (asked once per process)."""
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
