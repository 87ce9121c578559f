"""Shared test fixtures: where the shared records are, the distinct paper records, and the CLI runner."""

from __future__ import annotations

import csv
import os
from pathlib import Path

import pytest

from stickslip.records.readers import read_record
from stickslip.records.record import Record

REPO_ROOT = Path(__file__).resolve().parents[1]
FIXTURES = Path(__file__).resolve().parent / "fixtures"

#: One file per distinct record among the shared paper records (CHY080-000 is a
#: trimmed copy of CHY080-N, and the pySLAMMER CSV repeats PET-090).
DISTINCT_PAPER_FILES = (
    "CHY080-N.AT2",
    "SLAMMER_Cape_Mendocino_1992_PET-090.txt",
    "SLAMMER_Coyote_Lake_1979_G06-230.txt",
    "SLAMMER_Coyote_Lake_1979_G06-320.txt",
    "SLAMMER_Kobe_1995_KJM-090.txt",
    "SLAMMER_Northridge_1994_NWH-090.txt",
)


def _shared_dir() -> Path:
    return Path(os.environ.get("STICKSLIP_SHARED_DIR", REPO_ROOT.parent / "shared")).resolve()


@pytest.fixture(scope="session")
def shared_records() -> Path:
    """The shared records folder (``../shared/records`` beside the checkout)."""
    path = _shared_dir() / "records"
    if not (path / "manifest.csv").is_file():
        pytest.fail(f"shared records not found at {path}; set STICKSLIP_SHARED_DIR")
    return path


@pytest.fixture(scope="session")
def paper_records_dir(shared_records: Path) -> Path:
    """The folder with six of the paper's eight records."""
    return shared_records / "paper"


def read_shared_paper_record(records_dir: Path, file_name: str) -> Record:
    """A shared paper record read by stickslip's reader, dt [s] and units from the shared manifest.csv."""
    with open(records_dir.parent / "manifest.csv", newline="", encoding="utf-8") as handle:
        row = next(r for r in csv.DictReader(handle) if r["file"] == f"paper/{file_name}")
    return read_record(records_dir / file_name, dt=float(row["dt_s"]), units=row["units"])


@pytest.fixture(scope="module")
def paper_records(paper_records_dir: Path) -> dict[str, Record]:
    """File name -> Record for each of :data:`DISTINCT_PAPER_FILES`."""
    return {name: read_shared_paper_record(paper_records_dir, name) for name in DISTINCT_PAPER_FILES}


@pytest.fixture(params=DISTINCT_PAPER_FILES)
def distinct_paper_file(request) -> str:
    """Each of :data:`DISTINCT_PAPER_FILES` in turn."""
    return request.param


@pytest.fixture
def run_cli(capsys):
    """Run ``stickslip ARGS...`` in-process; return (exit code, stdout, stderr)."""
    from stickslip.cli import main

    def run(*args: str):
        code = main([str(a) for a in args])
        captured = capsys.readouterr()
        return code, captured.out, captured.err

    return run


def assert_one_error_line(code: int, stdout: str, stderr: str, name, phrase: str) -> None:
    """A user's mistake: exit 2, nothing on stdout, one stderr line naming ``name`` and saying ``phrase``."""
    assert code == 2
    lines = stderr.splitlines()
    assert len(lines) == 1, stderr
    assert lines[0].startswith("stickslip: error: ")
    assert str(name) in lines[0] and phrase in lines[0]
    assert "Traceback" not in stderr and stdout == ""
