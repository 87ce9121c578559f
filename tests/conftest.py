"""Shared test fixtures: where the shared records are, the distinct paper records, the CLI and workflow runners.

Tests that need the project's shared records (``../shared/records`` beside the
checkout, or the folder named by ``STICKSLIP_SHARED_DIR``) are skipped with a
reason when they are absent, so that ``make test`` passes on a stranger's
machine.  CI has them: ``.ci/run`` sets ``STICKSLIP_REQUIRE_SHARED=1``, which
turns such a skip into a failure.
"""

from __future__ import annotations

import csv
import fcntl
import os
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from stickslip.records.readers import read_record
from stickslip.records.record import Record, RecordMeta

REPO_ROOT = Path(__file__).resolve().parents[1]
#: The workflow's configuration and its schema (the library reads neither unless told to).
PROJECT_CONFIG = REPO_ROOT / "config" / "config.yaml"
CONFIG_SCHEMA = REPO_ROOT / "workflow" / "schemas" / "config.schema.yaml"


def project_config() -> dict:
    """The workflow's configuration, checked against its schema (:func:`stickslip.plumbing.config.load_config`)."""
    from stickslip.plumbing.config import load_config

    return load_config(PROJECT_CONFIG, CONFIG_SCHEMA)
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


def pytest_collection_modifyitems(items) -> None:
    """The test modules with a slow test first, each kept whole and in its order.

    Under pytest-xdist (``make test``: ``--dist loadfile``, one module to a worker) they then start first, and
    the many quick modules fill the workers' time around them rather than wait behind them at the end.
    """
    slow = {item.path for item in items if item.get_closest_marker("slow") is not None}
    items.sort(key=lambda item: item.path not in slow)  # a stable sort


def shared_dir() -> Path:
    """The project's shared data folder: ../shared beside the checkout, or STICKSLIP_SHARED_DIR."""
    return Path(os.environ.get("STICKSLIP_SHARED_DIR", REPO_ROOT.parent / "shared")).resolve()


def require_shared_records() -> Path:
    """The shared records folder; skip the calling test when it is absent (fail when CI requires it)."""
    path = shared_dir() / "records"
    if not (path / "manifest.csv").is_file():
        reason = (f"the project's shared records are not at {path}: they come with the project's shared data "
                  "folder (../shared beside the checkout, or set STICKSLIP_SHARED_DIR)")
        if os.environ.get("STICKSLIP_REQUIRE_SHARED") == "1":
            pytest.fail(f"{reason}; STICKSLIP_REQUIRE_SHARED=1 requires them")
        pytest.skip(reason)
    return path


def require_shared_verification() -> Path:
    """SLAMMER 1.1's results file in the shared folder; skip the calling test when it is absent (fail when CI requires it)."""
    from stickslip.studies.verification.slammer import RESULTS_FILE

    path = shared_dir() / "verification" / RESULTS_FILE
    if not path.is_file():
        reason = (f"SLAMMER's results are not at {path}: they come with the project's shared data folder "
                  "(../shared beside the checkout, or set STICKSLIP_SHARED_DIR)")
        if os.environ.get("STICKSLIP_REQUIRE_SHARED") == "1":
            pytest.fail(f"{reason}; STICKSLIP_REQUIRE_SHARED=1 requires them")
        pytest.skip(reason)
    return path


@pytest.fixture(scope="session")
def shared_records() -> Path:
    """The shared records folder (``../shared/records`` beside the checkout)."""
    return require_shared_records()


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


@pytest.fixture(scope="session")
def two_tone_record() -> Record:
    """A decaying two-tone motion (1.1 and 3.7 Hz) with a 0.6 g peak, 12 s sampled every 0.01 s."""
    time = np.arange(0.0, 12.0, 0.01)
    wave = (np.sin(2 * np.pi * 1.1 * time) + 0.4 * np.sin(2 * np.pi * 3.7 * time)) * np.exp(-0.25 * time)
    return Record(0.6 * 9.80665 * wave / np.max(np.abs(wave)), 0.01, RecordMeta(record_id="wave"))


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


SNAKEMAKE = str(Path(sys.executable).with_name("snakemake"))


def snakemake(workdir: Path, configfile: Path, *args: str, records_dir: Path | None = None,
              slammer_dir: Path | None = None, three_component_dir: Path | None = None, config: dict | None = None,
              timeout: float = 600) -> subprocess.CompletedProcess:
    """Run the project's workflow in ``workdir`` with ``configfile``, the project's manifest and ``config`` overrides.

    The records folders come from the arguments only: without ``slammer_dir`` the
    collection study of the configuration ``auto`` runs on pyslammer's samples, and
    without ``verification_dir`` in ``config`` the verification against SLAMMER says
    that its data are not here (one cheap job), and without ``three_component_dir`` the
    vertical-motion study says that its records were not available (empty tables).
    """
    env = {key: value for key, value in os.environ.items()
           if key not in ("STICKSLIP_RECORDS_DIR", "STICKSLIP_SLAMMER_DIR", "STICKSLIP_VERIFICATION_DIR",
                          "STICKSLIP_THREE_COMPONENT_DIR")}
    env["PATH"] = f"{Path(sys.executable).parent}{os.pathsep}{env['PATH']}"
    env["MPLBACKEND"] = "Agg"
    if records_dir is not None:
        env["STICKSLIP_RECORDS_DIR"] = str(records_dir)
    if slammer_dir is not None:
        env["STICKSLIP_SLAMMER_DIR"] = str(slammer_dir)
    if three_component_dir is not None:
        env["STICKSLIP_THREE_COMPONENT_DIR"] = str(three_component_dir)
    # The targets and options in args come first: --configfile and --config take every value that follows.
    overrides = [f"{key}={value}" for key, value in (config or {}).items()]
    command = [SNAKEMAKE, "--snakefile", str(REPO_ROOT / "Snakefile"), "--directory", str(workdir), *args,
               "--cores", "2", "--configfile", str(configfile), *(["--config", *overrides] if overrides else [])]
    return subprocess.run(command, cwd=workdir, env=env, capture_output=True, text=True, timeout=timeout)


def made_once(tmp_path_factory, name: str, make: Callable[[Path], str | None], description: str) -> Path:
    """The folder ``name`` that ``make(folder)`` fills, made once for the whole test run.

    ``make`` returns None when it succeeded, or what went wrong.  Under
    pytest-xdist the workers share the folder: the first that asks makes it in
    the run's base folder, and the others wait for it on a lock
    (``fcntl.flock``) and reuse it, or its failure.  Each test that needs it
    fails with ``description`` and what went wrong when making it failed; when
    ``make`` raised, the test that called it fails with the exception, and the
    others say that it did not finish.
    """
    base = tmp_path_factory.getbasetemp()
    root = base.parent if os.environ.get("PYTEST_XDIST_WORKER") else base  # the run's folder, its workers' parent
    folder, failure = root / name, root / f"{name}.failure"
    with open(root / f"{name}.lock", "w", encoding="utf-8") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)  # released when the file is closed
        if not folder.is_dir():
            folder.mkdir()
            failure.write_text("it did not finish (see the test that ran it)", encoding="utf-8")
            problem = make(folder)
            if problem is None:
                failure.unlink()
            else:
                failure.write_text(problem, encoding="utf-8")
    if failure.is_file():
        pytest.fail(f"{description} failed:\n{failure.read_text(encoding='utf-8')}")
    return folder


def workflow_run_once(tmp_path_factory, name: str, configfile: Path, **kwargs) -> Path:
    """The working folder of one run of the workflow (:func:`snakemake`), made once for the whole test run (:func:`made_once`)."""

    def run(workdir: Path) -> str | None:
        result = snakemake(workdir, configfile, **kwargs)
        return None if result.returncode == 0 else result.stdout[-3000:] + result.stderr[-3000:]

    return made_once(tmp_path_factory, name, run, f"the workflow run {name}")


@pytest.fixture(scope="session")
def paper_workflow(tmp_path_factory) -> Path:
    """The results folder of the whole workflow, run once on the shared paper records with config/config.yaml."""
    records_dir = require_shared_records() / "paper"
    return workflow_run_once(tmp_path_factory, "paper_workflow", REPO_ROOT / "config" / "config.yaml",
                             records_dir=records_dir) / "results"


@pytest.fixture(scope="session")
def test_workflow(tmp_path_factory) -> Path:
    """The results folder of the whole workflow run with the small .test/ configuration (offline records)."""
    configfile = REPO_ROOT / ".test" / "config" / "config.yaml"
    return workflow_run_once(tmp_path_factory, "test_workflow", configfile) / "results"


@pytest.fixture(scope="session")
def flexible_verification_folder(tmp_path_factory) -> Path:
    """The folder with the flexible block's verification against SLAMMER 1.1, made once for the whole test run.

    The workflow's step (``flexible_summary.json`` and ``flexible_analyses.csv``), run in-process on the shared
    reference: some forty seconds of computing that the flexible block's tests and the verification page share.
    """
    from stickslip.studies.verification.flexible import write_flexible_verification

    reference = require_shared_verification()

    def verify(folder: Path) -> None:
        write_flexible_verification(folder / "flexible_summary.json", folder / "flexible_analyses.csv",
                                    folder=reference.parent)

    return made_once(tmp_path_factory, "flexible_verification", verify, "the flexible block's verification")


@pytest.fixture(scope="session")
def three_component_sets() -> dict[str, dict[str, Record]]:
    """The fifteen three-component PEER sets of ``../shared/records/three_component``: set -> {"H1", "H2", "UP"}.

    The vertical component is read as the file gives it (``UP``, ``DWN`` or ``V``), each file with its own length.
    """
    folder = require_shared_records() / "three_component"
    sets: dict[str, dict[str, Record]] = {}
    with open(folder / "manifest.csv", newline="", encoding="utf-8") as handle:
        for row in csv.DictReader(handle):
            sets.setdefault(row["set"], {})[row["component"]] = read_record(folder / row["file"])
    return sets
