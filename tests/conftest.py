"""Shared test fixtures: where the shared records are, and the CLI runner."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

REPO_ROOT = Path(__file__).resolve().parents[1]
FIXTURES = Path(__file__).resolve().parent / "fixtures"


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


@pytest.fixture
def run_cli(capsys):
    """Run ``stickslip ARGS...`` in-process; return (exit code, stdout, stderr)."""
    from stickslip.cli import main

    def run(*args: str):
        code = main([str(a) for a in args])
        captured = capsys.readouterr()
        return code, captured.out, captured.err

    return run
