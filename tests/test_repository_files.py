"""The repository tracks no large file: records, data sets and tool downloads stay out of it."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

CHECKOUT = Path(__file__).resolve().parents[1]

#: The largest file the repository may track [bytes]: 1 MB.
MAX_TRACKED_BYTES = 1_000_000


def tracked_files(checkout: Path) -> list[Path] | None:
    """The files git tracks in ``checkout`` (as they stand in the work tree), or None where it is no git checkout."""
    if shutil.which("git") is None:
        return None
    listing = subprocess.run(["git", "-C", str(checkout), "ls-files", "-z"], capture_output=True, check=False)
    if listing.returncode != 0:
        return None
    names = listing.stdout.decode().split("\0")
    return [checkout / name for name in names if name]


def oversized(files: list[Path], limit: int = MAX_TRACKED_BYTES) -> dict[str, int]:
    """``{path: size [bytes]}`` of the files of ``files`` larger than ``limit`` bytes (a missing file is skipped)."""
    return {str(path): path.stat().st_size for path in files if path.is_file() and path.stat().st_size > limit}


def test_no_tracked_file_exceeds_one_megabyte():
    files = tracked_files(CHECKOUT)
    if files is None:
        pytest.skip("not a git checkout (or git is missing): no list of tracked files to check")
    assert len(files) > 100
    assert oversized(files) == {}


def test_a_large_tracked_file_is_found(tmp_path):
    if shutil.which("git") is None:
        pytest.skip("git is missing")
    subprocess.run(["git", "init", "-q", str(tmp_path)], check=True)
    (tmp_path / "small.txt").write_bytes(b"x" * MAX_TRACKED_BYTES)
    (tmp_path / "tool.whl").write_bytes(b"x" * (MAX_TRACKED_BYTES + 1))
    (tmp_path / "untracked.bin").write_bytes(b"x" * (2 * MAX_TRACKED_BYTES))
    subprocess.run(["git", "-C", str(tmp_path), "add", "small.txt", "tool.whl"], check=True)
    assert oversized(tracked_files(tmp_path)) == {str(tmp_path / "tool.whl"): MAX_TRACKED_BYTES + 1}


def test_a_folder_outside_git_has_no_tracked_files(tmp_path):
    if shutil.which("git") is None:
        pytest.skip("git is missing")
    assert tracked_files(tmp_path) is None
