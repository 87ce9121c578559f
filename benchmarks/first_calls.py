"""The first commands after a fresh install: a clone, ``make env``, then each command's first call, whole process.

    .venv/bin/python benchmarks/first_calls.py [REVISION ...] [--runs N]

For each revision (default: HEAD), in a temporary folder: ``git clone`` of this
repository, ``git checkout REVISION``, ``make env`` (timed), then each command of
:data:`COMMANDS` once, its first call after the install, and ``--runs`` more
times; every call a new process with ``PYTHONDONTWRITEBYTECODE=1`` (as a user's
shell may have it), timed by its wall time and its CPU time (user + system,
from the operating system's accounting of the finished child).  Also counted:
the numba cache files (``*.nbc``) the first call wrote into the clone, which
is the compilation it did.  The records are the two horizontal components of
Kocaeli 1999, Duzce (``RSN1158_KOCAELI_DZC180.AT2`` and ``DZC270``, 5,437
samples each at 0.005 s) of ``../shared/records/three_component`` (or STICKSLIP_SHARED_DIR).
Prints markdown with the load average at the start and the end of each
revision's run; writes nothing in the repository.
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

REPO_ROOT = Path(__file__).resolve().parents[1]
RUNS = 5
FIRST, SECOND = "RSN1158_KOCAELI_DZC180.AT2", "RSN1158_KOCAELI_DZC270.AT2"

#: The three first calls, by name: stickslip's arguments, the two components as FIRST and SECOND.
COMMANDS = {
    "solve A B --pair": ["solve", FIRST, SECOND, "--pair", "--mu", "0.1"],
    "solve A --model coupled --method exact": ["solve", FIRST, "--ky", "0.1", "--model", "coupled", "--method",
                                                "exact", "--height", "20", "--vs", "300", "--vs-base", "760"],
    "optimum A B": ["optimum", FIRST, SECOND],
}


def timed(argv: list[str], cwd: Path, env: dict) -> tuple[float, float]:
    """Wall and CPU seconds of one process running ``argv`` (its output discarded; a failure raises)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(argv, cwd=cwd, env=env, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def cache_files(clone: Path) -> int:
    """numba's cache data files in the clone's sources."""
    return sum(1 for _ in (clone / "src").rglob("*.nbc"))


def run_revision(revision: str, records: Path, runs: int) -> dict:
    """Clone, check out ``revision``, ``make env`` and time the first calls and ``runs`` more of each command."""
    with tempfile.TemporaryDirectory() as folder:
        clone = Path(folder) / "stickslip"
        subprocess.run(["git", "clone", "--quiet", "--no-hardlinks", str(REPO_ROOT), str(clone)], check=True)
        subprocess.run(["git", "-C", str(clone), "checkout", "--quiet", revision], check=True)
        commit = subprocess.run(["git", "-C", str(clone), "rev-parse", "--short", "HEAD"], check=True,
                                capture_output=True, text=True).stdout.strip()
        load_start = os.getloadavg()
        env = {key: value for key, value in os.environ.items() if key not in ("VIRTUAL_ENV", "NUMBA_CACHE_DIR")}
        make_env = timed(["make", "env"], clone, env)
        user = {**env, "PYTHONDONTWRITEBYTECODE": "1"}
        stickslip = str(clone / ".venv" / "bin" / "stickslip")
        commands = {}
        for name, arguments in COMMANDS.items():
            argv = [stickslip, *[str(records / part) if part in (FIRST, SECOND) else part for part in arguments]]
            written = cache_files(clone)
            first = timed(argv, clone, user)
            compiled = cache_files(clone) - written
            later = [timed(argv, clone, user) for _ in range(runs)]
            commands[name] = {"first": first, "compiled": compiled, "later_wall": [wall for wall, _ in later],
                              "later_cpu": [cpu for _, cpu in later]}
        return {"revision": revision, "commit": commit, "make_env": make_env, "commands": commands,
                "load_start": load_start, "load_end": os.getloadavg()}


def markdown(result: dict, runs: int) -> str:
    """One revision's table."""
    wall, cpu = result["make_env"]
    lines = [f"{result['revision']} ({result['commit']}): `make env` {wall:.1f} s wall, {cpu:.1f} s CPU; load "
             f"average (1, 5, 15 min) {', '.join(f'{x:.2f}' for x in result['load_start'])} at the start, "
             f"{', '.join(f'{x:.2f}' for x in result['load_end'])} at the end",
             "", f"| command | first call: wall, CPU | numba cache files it wrote | next {runs}: median wall, "
             "median CPU |", "| --- | --- | --- | --- |"]
    for name, timing in result["commands"].items():
        first_wall, first_cpu = timing["first"]
        lines.append(f"| `{name}` | {first_wall:.2f} s, {first_cpu:.2f} s | {timing['compiled']} | "
                     f"{statistics.median(timing['later_wall']):.2f} s, {statistics.median(timing['later_cpu']):.2f} s |")
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("revisions", nargs="*", default=["HEAD"], help="git revisions (default: HEAD)")
    parser.add_argument("--runs", type=int, default=RUNS, help="calls of each command after its first")
    args = parser.parse_args()
    shared = Path(os.environ.get("STICKSLIP_SHARED_DIR", REPO_ROOT.parent / "shared"))
    records = shared / "records" / "three_component" / "Kocaeli_Duzce"
    for revision in args.revisions:
        print(markdown(run_revision(revision, records, args.runs), args.runs), end="\n\n", flush=True)


if __name__ == "__main__":
    main()
