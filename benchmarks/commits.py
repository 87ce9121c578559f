"""A job for an earlier commit and for the working tree, alternated in one run.

    .venv/bin/python benchmarks/commits.py BASE [--job sweep|flexible|pendulum|vertical|plane] [--rounds N]
                                                [--threads N]

The source of commit BASE (``git archive``) is unpacked into a temporary
folder; each round starts one process per version (``PYTHONPATH`` pointing at
its ``src``), which loads the kernels from its own numba cache, makes one
warm-up call and times :data:`CALLS` calls of the job (:data:`JOBS`):

- ``sweep`` (job (a) of run.py): ``exact.sweep_scalars([chichi], dt, 1,000 μ in [0.01, 0.4], 9.81)``;
- ``flexible``: the ``exact`` scheme on SLAMMER 1.1's 2,520 flexible analyses, both polarities (5,040
  ``solve_flexible`` calls without the ledger, as the flexible verification makes them; needs
  ``../shared/verification``), the motions scaled in memory outside the timing.  Its kernels run in
  the calling thread, so it is timed by the process's CPU time, which other people's jobs on a
  busy machine disturb less than the wall time; the sweep (numba's threads) by the wall time;
- ``pendulum``: the exact friction pendulum in one direction, R = 2 m, on job (a)'s record and μ grid
  (``pendulum_sweep``);
- ``vertical``: the exact flat block under a horizontal component and its vertical, Tabas TAB-L1 with TAB-V1
  (``../shared/records/three_component``), 200 μ in [0.01, 0.4] (``vertical_sweep``);
- ``plane``: the planar block under both horizontal components of that station, 16 μ in [0.05, 0.4],
  through the public ``stickslip.sweep`` (the plane's kernel moves; its entry point does not).

With ``--threads N`` each process runs N numba threads (``NUMBA_NUM_THREADS``); with
``--threads 1`` every job is timed by the process's CPU time, one thread's work, which
the load of a shared machine disturbs least.

The versions take turns, so both see the same machine load; the printout gives the
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
#: The three-component station of the vertical and plane jobs: its two horizontals and its vertical.
STATION = ("Tabas_Tabas", "RSN143_TABAS_TAB-L1.AT2", "RSN143_TABAS_TAB-T1.AT2", "RSN143_TABAS_TAB-V1.AT2")
CALLS = {"sweep": 7, "flexible": 3, "pendulum": 7, "vertical": 7, "plane": 3}

#: The clock of each job: wall time for the parallel sweeps, the process's CPU time for the one-thread job.
CLOCKS = {"sweep": time.perf_counter, "flexible": time.process_time, "pendulum": time.perf_counter,
          "vertical": time.perf_counter, "plane": time.perf_counter}


def sweep_job(shared: Path):
    """Job (a): the exact μ sweep of Chi-Chi CHY080-N, as a call without arguments."""
    import numpy as np

    from stickslip.records.readers import read_record

    try:
        from stickslip.models.rigid import exact
    except ImportError:  # a commit before the models registry: the kernels lived in stickslip.solvers
        from stickslip.solvers import exact

    record = read_record(shared / "records" / "paper" / RECORD)
    mu = np.linspace(0.01, 0.4, 1000)
    return lambda: exact.sweep_scalars([record.acceleration], [record.dt], mu, 9.81)


def flexible_job(shared: Path):
    """The exact scheme on SLAMMER's 5,040 flexible values (no ledger), as a call without arguments."""
    try:
        from stickslip.models.rigid.slammer import SLAMMER_GRAVITY
    except ImportError:  # a commit before the models registry
        from stickslip.solvers.slammer import SLAMMER_GRAVITY
    try:
        from stickslip.studies.verification import flexible
        from stickslip.studies.verification.slammer import POLARITIES, sample_motions, scaled_records
    except ImportError:  # a commit before the studies became folders
        from stickslip.studies import flexible_verification as flexible
        from stickslip.studies.slammer_verification import POLARITIES, sample_motions, scaled_records

    analyses = flexible.read_flexible_analyses(shared / "verification" / "slammer_1.1_results.json.gz")
    records = scaled_records(analyses, sample_motions(analyses), SLAMMER_GRAVITY)
    return lambda: [flexible.solved(analysis, records[analysis["analysis_id"]], SLAMMER_GRAVITY, polarity,
                                    scheme="exact") for analysis in analyses for polarity in POLARITIES]


def pendulum_job(shared: Path):
    """The exact pendulum in one direction (R = 2 m) on job (a)'s record and μ grid, as a call without arguments."""
    import numpy as np

    from stickslip.models.pendulum.exact import pendulum_sweep
    from stickslip.records.readers import read_record

    record = read_record(shared / "records" / "paper" / RECORD)
    mu = np.linspace(0.01, 0.4, 1000)
    return lambda: pendulum_sweep([record.acceleration], [record.dt], mu, 2.0, 9.81)


def _station(shared: Path):
    """The :data:`STATION`'s two horizontal records and its vertical one."""
    from stickslip.records.readers import read_record

    folder = shared / "records" / "three_component" / STATION[0]
    return [read_record(folder / name) for name in STATION[1:]]


def vertical_job(shared: Path):
    """The exact flat block under the station's first horizontal and its vertical, as a call without arguments."""
    import numpy as np

    from stickslip.models.pendulum.vertical_exact import vertical_sweep

    horizontal, _, vertical = _station(shared)
    size = min(horizontal.acceleration.size, vertical.acceleration.size)
    mu = np.linspace(0.01, 0.4, 200)
    return lambda: vertical_sweep([horizontal.acceleration[:size]], [vertical.acceleration[:size]],
                                  [horizontal.dt], mu, 9.81)


def plane_job(shared: Path):
    """The planar block under the station's two horizontals through ``stickslip.sweep``, as a call without arguments."""
    import numpy as np

    import stickslip
    from stickslip.records.pair import RecordPair

    first, second, _ = _station(shared)
    mu = list(np.linspace(0.05, 0.4, 16))
    return lambda: stickslip.sweep([RecordPair.padded(first, second)], model="planar", mu=mu)


#: The jobs, by name: each builds its call from the shared folder.
JOBS = {"sweep": sweep_job, "flexible": flexible_job, "pendulum": pendulum_job, "vertical": vertical_job,
        "plane": plane_job}


def clock_of(job_name: str, threads: int | None):
    """The clock of a job: the process's CPU time on one thread, else the job's own (:data:`CLOCKS`)."""
    return time.process_time if threads == 1 else CLOCKS[job_name]


def worker(job_name: str, shared: str, threads: str) -> None:
    """Time the job with the stickslip on ``sys.path``; print the seconds of each call as JSON."""
    job, clock = JOBS[job_name](Path(shared)), clock_of(job_name, int(threads) or None)
    job()
    seconds = []
    for _ in range(CALLS[job_name]):
        start = clock()
        job()
        seconds.append(clock() - start)
    print(json.dumps(seconds))


def run_version(src: Path, job_name: str, shared: Path, threads: int | None) -> float:
    """The median seconds of the job in a fresh process running the package under ``src`` (``threads`` numba
    threads, or numba's default)."""
    env = {**os.environ, "PYTHONPATH": str(src)}
    if threads is not None:
        env["NUMBA_NUM_THREADS"] = str(threads)
    result = subprocess.run([sys.executable, __file__, "--worker", job_name, str(shared), str(threads or 0)],
                            env=env, check=True, capture_output=True, text=True, cwd=src.parent)
    return statistics.median(json.loads(result.stdout))


def main() -> None:
    if sys.argv[1:2] == ["--worker"]:
        worker(sys.argv[2], sys.argv[3], sys.argv[4])
        return
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("base", help="the earlier commit (any git revision)")
    parser.add_argument("--job", choices=sorted(JOBS), default="sweep")
    parser.add_argument("--rounds", type=int, default=15)
    parser.add_argument("--threads", type=int, help="numba threads per process (default: numba's); 1 times the "
                        "process's CPU time")
    args = parser.parse_args()
    if args.threads is not None and args.threads < 1:
        parser.error(f"--threads: expected a positive number of threads, got {args.threads}")
    shared = Path(os.environ.get("STICKSLIP_SHARED_DIR", REPO_ROOT.parent / "shared"))
    archive = subprocess.run(["git", "-C", str(REPO_ROOT), "archive", args.base, "src"], check=True,
                             capture_output=True).stdout
    with tempfile.TemporaryDirectory() as folder:
        with tarfile.open(fileobj=BytesIO(archive)) as tar:
            tar.extractall(folder, filter="data")
        versions = {args.base: Path(folder) / "src", "today": REPO_ROOT / "src"}
        for src in versions.values():
            run_version(src, args.job, shared, args.threads)  # fills each version's numba cache
        load_start = os.getloadavg()
        times = {name: [] for name in versions}
        for _ in range(args.rounds):
            for name, src in versions.items():
                times[name].append(run_version(src, args.job, shared, args.threads))
        load_end = os.getloadavg()
    medians = {name: statistics.median(values) for name, values in times.items()}
    ratio = statistics.median(new / old for new, old in zip(times["today"], times[args.base]))
    clock = "CPU time of the process" if clock_of(args.job, args.threads) is time.process_time else "wall time"
    threads = "" if args.threads is None else f", {args.threads} numba thread{'s' if args.threads > 1 else ''}"
    print(f"job {args.job}, {args.rounds} alternated rounds of {CALLS[args.job]} calls per process ({clock}"
          f"{threads}):")
    for name, value in medians.items():
        print(f"  {name}: median {value:.4f} s")
    print(f"  today / {args.base}: {ratio:.3f} (median of the per-round ratios)")
    print("  load average (1, 5, 15 min) at start: " + ", ".join(f"{x:.2f}" for x in load_start)
          + "; at end: " + ", ".join(f"{x:.2f}" for x in load_end))


if __name__ == "__main__":
    main()
