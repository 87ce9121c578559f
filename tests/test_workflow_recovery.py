"""The workflow recovers by itself after an interruption, with results byte-identical to an uninterrupted run.

The .test/ workflow's computation (the target ``results``: every table, cube
and JSON file, not the notebooks that draw them) is interrupted (SIGINT, as
Ctrl-C sends it to the whole process group, early; SIGKILL, later, amid the
sweeps and studies), then run again the way ``make reproduce`` runs it:
``snakemake --unlock``, then the default profile, which reruns incomplete
outputs.  Every table and JSON file must then equal the one of the
uninterrupted run of the whole workflow (the ``test_workflow`` fixture) byte
for byte.  The notebooks' own recovery (a killed papermill run leaves only
its ``.part.ipynb``) is covered by the whole run's fixture and the interrupt
tests of ``stickslip report``.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from conftest import REPO_ROOT, snakemake

TEST_CONFIG = REPO_ROOT / ".test" / "config" / "config.yaml"
PROFILE = str(REPO_ROOT / "workflow" / "profiles" / "default")


def _command(workdir: Path) -> list[str]:
    return [str(Path(sys.executable).with_name("snakemake")), "--snakefile", str(REPO_ROOT / "Snakefile"),
            "--directory", str(workdir), "results", "--profile", PROFILE, "--configfile", str(TEST_CONFIG)]


def interrupted_run(workdir: Path, after: float, sent: signal.Signals) -> None:
    """Start the workflow and send ``sent`` to its whole process group ``after`` seconds later."""
    env = {key: value for key, value in os.environ.items()  # the records folders as conftest.snakemake leaves them
           if key not in ("STICKSLIP_RECORDS_DIR", "STICKSLIP_SLAMMER_DIR", "STICKSLIP_VERIFICATION_DIR",
                          "STICKSLIP_THREE_COMPONENT_DIR")}
    env["PATH"] = f"{Path(sys.executable).parent}{os.pathsep}{env['PATH']}"
    process = subprocess.Popen(_command(workdir), cwd=workdir, env=env, stdout=subprocess.DEVNULL,
                               stderr=subprocess.DEVNULL, start_new_session=True)
    time.sleep(after)
    if process.poll() is None:
        os.killpg(process.pid, sent)
    try:
        process.wait(timeout=60)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        process.wait()
        pytest.fail(f"the workflow did not stop within 60 s of {sent.name}")


def products(results: Path) -> dict[str, bytes]:
    return {path.relative_to(results).as_posix(): path.read_bytes()
            for path in sorted(results.rglob("*")) if path.suffix in (".csv", ".json")}


@pytest.mark.slow
@pytest.mark.parametrize(("after", "sent"), [(4.0, signal.SIGINT), (12.0, signal.SIGKILL)])
def test_a_run_interrupted_then_repeated_gives_the_same_results(request, tmp_path, after, sent):
    interrupted_run(tmp_path, after, sent)
    assert snakemake(tmp_path, TEST_CONFIG, "--unlock").returncode == 0
    result = snakemake(tmp_path, TEST_CONFIG, "results", "--profile", PROFILE)
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:]
    # asked for only now: under pytest-xdist another worker may be running it meanwhile
    test_workflow = request.getfixturevalue("test_workflow")
    assert products(tmp_path / "results") == products(test_workflow)
    assert not list(tmp_path.rglob("*.part")) and not list(tmp_path.rglob("*.part.ipynb"))
