"""The workflow recovers by itself after an interruption, with results byte-identical to an uninterrupted run.

A part of the .test/ workflow's computation (:data:`TARGETS`: the records, their
measures, per-record sweeps, gathered cubes, the mu_max study, the relations'
fits and the comparisons with the paper, 18 jobs) is interrupted (SIGINT, as
Ctrl-C sends it to the whole process group, as soon as the first record is
stored; SIGKILL amid the sweeps, as soon as the first sweep cube is written),
then run again the way ``make reproduce`` runs it: ``snakemake --unlock``, then
the default profile, which reruns incomplete outputs.  Every table and JSON
file it wrote must then equal the one of the uninterrupted run of the whole
workflow (the ``test_workflow`` fixture) byte for byte.  The interruption is
tied to the files written, not to a clock, so that it always lands amid the
jobs, however busy the machine.  Recovery is plumbing (Snakemake's incomplete
outputs, the steps' atomic writes), the same for every rule: the rest of the
workflow would only make the test longer.  The notebooks' own recovery (a
killed papermill run leaves only its ``.part.ipynb``) is covered by the whole
run's fixture and the interrupt tests of ``stickslip report``.
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
#: What the interrupted run computes: every stage from acquisition to the comparisons with the paper.
TARGETS = ["results/tables/table5_records.csv", "results/tables/table6_comparison.csv", "results/fits.json"]


def _command(workdir: Path) -> list[str]:
    return [str(Path(sys.executable).with_name("snakemake")), "--snakefile", str(REPO_ROOT / "Snakefile"),
            "--directory", str(workdir), *TARGETS, "--profile", PROFILE, "--configfile", str(TEST_CONFIG)]


def interrupted_run(workdir: Path, written: str, sent: signal.Signals) -> None:
    """Start the workflow; send ``sent`` to its whole process group once a file matches ``written`` (a glob in workdir)."""
    env = {key: value for key, value in os.environ.items()  # the records folders as conftest.snakemake leaves them
           if key not in ("STICKSLIP_RECORDS_DIR", "STICKSLIP_SLAMMER_DIR", "STICKSLIP_VERIFICATION_DIR",
                          "STICKSLIP_THREE_COMPONENT_DIR")}
    env["PATH"] = f"{Path(sys.executable).parent}{os.pathsep}{env['PATH']}"
    process = subprocess.Popen(_command(workdir), cwd=workdir, env=env, stdout=subprocess.DEVNULL,
                               stderr=subprocess.DEVNULL, start_new_session=True)
    deadline = time.monotonic() + 600
    while not any(workdir.glob(written)) and process.poll() is None and time.monotonic() < deadline:
        time.sleep(0.05)
    if process.poll() is not None:
        pytest.fail(f"the workflow ended (exit code {process.returncode}) before it wrote {written}: "
                    "there was nothing to interrupt")
    if not any(workdir.glob(written)):
        os.killpg(process.pid, signal.SIGKILL)
        process.wait()
        pytest.fail(f"the workflow wrote no {written} within 600 s")
    os.killpg(process.pid, sent)
    try:
        process.wait(timeout=60)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        process.wait()
        pytest.fail(f"the workflow did not stop within 60 s of {sent.name}")
    assert process.returncode != 0, f"the workflow finished in spite of {sent.name}"


def products(results: Path) -> dict[str, bytes]:
    return {path.relative_to(results).as_posix(): path.read_bytes()
            for path in sorted(results.rglob("*")) if path.suffix in (".csv", ".json")}


@pytest.mark.slow
@pytest.mark.parametrize(("written", "sent"), [("results/records/*.nc", signal.SIGINT),
                                                ("results/sweeps/*/*.nc", signal.SIGKILL)])
def test_a_run_interrupted_then_repeated_gives_the_same_results(request, tmp_path, written, sent):
    interrupted_run(tmp_path, written, sent)
    assert snakemake(tmp_path, TEST_CONFIG, "--unlock").returncode == 0
    result = snakemake(tmp_path, TEST_CONFIG, *TARGETS, "--profile", PROFILE)
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:]
    # asked for only now: under pytest-xdist another worker may be running it meanwhile
    test_workflow = request.getfixturevalue("test_workflow")
    repeated, whole = products(tmp_path / "results"), products(test_workflow)
    assert {Path(target).relative_to("results").as_posix() for target in TARGETS} <= repeated.keys() <= whole.keys()
    assert repeated == {name: whole[name] for name in repeated}
    assert not list(tmp_path.rglob("*.part")) and not list(tmp_path.rglob("*.part.ipynb"))
