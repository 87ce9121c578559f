"""Job (a) of run.py, the exact μ sweep, for an earlier commit and for the working tree, alternated in one run.

    .venv/bin/python benchmarks/commits.py BASE [--rounds N]

The source of commit BASE (``git archive``) is unpacked into a temporary
folder; each round starts one process per version (``PYTHONPATH`` pointing at
its ``src``), which loads the kernels from its own numba cache, makes one
warm-up call and times :data:`CALLS` calls of
``exact.sweep_scalars([chichi], dt, 1,000 μ in [0.01, 0.4], 9.81)``.  The
versions take turns, so both see the same machine load; the printout gives the
median over rounds of each process's median, the median of the per-round
ratios (today / BASE) and the load average.  Nothing is written.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tarfile
import tempfile
import time
from io import BytesIO
from pathlib import Path

REPO_ROOT = Path(__file__).resolve().parents[1]
RECORD = "CHY080-N.AT2"  # job (a)'s record: Chi-Chi CHY080-N, 18,000 samples
CALLS = 7


def worker(record_path: str) -> None:
    """Time job (a) with the stickslip on ``sys.path``; print the seconds of each call as JSON."""
    import numpy as np

    from stickslip.records.readers import read_record
    from stickslip.models.rigid import exact

    record = read_record(record_path)
    mu = np.linspace(0.01, 0.4, 1000)
    exact.sweep_scalars([record.acceleration], [record.dt], mu, 9.81)
    seconds = []
    for _ in range(CALLS):
        start = time.perf_counter()
        exact.sweep_scalars([record.acceleration], [record.dt], mu, 9.81)
        seconds.append(time.perf_counter() - start)
    print(json.dumps(seconds))


def run_version(src: Path, record_path: Path) -> float:
    """The median seconds of job (a) in a fresh process running the package under ``src``."""
    env = {**os.environ, "PYTHONPATH": str(src)}
    result = subprocess.run([sys.executable, __file__, "--worker", str(record_path)], env=env, check=True,
                            capture_output=True, text=True, cwd=src.parent)
    return statistics.median(json.loads(result.stdout))


def main() -> None:
    if sys.argv[1:2] == ["--worker"]:
        worker(sys.argv[2])
        return
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("base", help="the earlier commit (any git revision)")
    parser.add_argument("--rounds", type=int, default=15)
    args = parser.parse_args()
    shared = Path(os.environ.get("STICKSLIP_SHARED_DIR", REPO_ROOT.parent / "shared"))
    record_path = shared / "records" / "paper" / RECORD
    archive = subprocess.run(["git", "-C", str(REPO_ROOT), "archive", args.base, "src"], check=True,
                             capture_output=True).stdout
    with tempfile.TemporaryDirectory() as folder:
        with tarfile.open(fileobj=BytesIO(archive)) as tar:
            tar.extractall(folder, filter="data")
        versions = {args.base: Path(folder) / "src", "today": REPO_ROOT / "src"}
        for src in versions.values():
            run_version(src, record_path)  # fills each version's numba cache
        load_start = os.getloadavg()
        times = {name: [] for name in versions}
        for _ in range(args.rounds):
            for name, src in versions.items():
                times[name].append(run_version(src, record_path))
        load_end = os.getloadavg()
    medians = {name: statistics.median(values) for name, values in times.items()}
    ratio = statistics.median(new / old for new, old in zip(times["today"], times[args.base]))
    print(f"job (a), {args.rounds} alternated rounds of {CALLS} calls per process:")
    for name, value in medians.items():
        print(f"  {name}: median {value:.4f} s")
    print(f"  today / {args.base}: {ratio:.3f} (median of the per-round ratios)")
    print("  load average (1, 5, 15 min) at start: " + ", ".join(f"{x:.2f}" for x in load_start)
          + "; at end: " + ", ".join(f"{x:.2f}" for x in load_end))


if __name__ == "__main__":
    main()
