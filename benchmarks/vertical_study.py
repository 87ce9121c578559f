"""The whole vertical-motion study through the workflow: wall time and CPU time, median of a few runs.

Each round runs ``snakemake`` on the study's page (``reports/html/vertical_study.html``: acquisition of the
fifteen three-component sets, one sweep job per direction, the gathered cube, the tables and the page) in a fresh
folder, with the project's configuration and default profile, 2 cores, ``STICKSLIP_THREE_COMPONENT_DIR`` pointing
at ``../shared/records/three_component`` (override the shared folder with ``STICKSLIP_SHARED_DIR``): the whole
study as ``make reproduce`` runs it, Snakemake's start-up included.  It prints (JSON) each round's wall time [s]
and the CPU time [s] of its processes (user + system, children included), their medians, and the load average
(1, 5, 15 min) before and after, since the machine's 2 cores may be shared.

Run it in the project's environment: ``.venv/bin/python benchmarks/vertical_study.py [--rounds N]``.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO_ROOT = Path(__file__).resolve().parents[1]
SNAKEMAKE = str(Path(sys.executable).with_name("snakemake"))
TARGET = "reports/html/vertical_study.html"


def records_folder() -> Path:
    shared = Path(os.environ.get("STICKSLIP_SHARED_DIR", REPO_ROOT.parent / "shared"))
    return (shared / "records" / "three_component").resolve()


def one_run() -> tuple[float, float]:
    """Wall time [s] and CPU time [s] of the whole study in a fresh folder."""
    env = {**os.environ, "STICKSLIP_THREE_COMPONENT_DIR": str(records_folder()), "MPLBACKEND": "Agg",
           "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}"}
    with tempfile.TemporaryDirectory(prefix="stickslip-vertical-") as folder:
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        start = time.perf_counter()
        done = subprocess.run([SNAKEMAKE, "--snakefile", str(REPO_ROOT / "Snakefile"), "--directory", folder,
                               "--cores", "2", "--profile", str(REPO_ROOT / "workflow" / "profiles" / "default"),
                               TARGET], env=env, capture_output=True, text=True)
        wall = time.perf_counter() - start
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        if done.returncode != 0:
            raise SystemExit(f"snakemake failed:\n{done.stdout[-2000:]}\n{done.stderr[-2000:]}")
        if not (Path(folder) / TARGET).is_file():
            raise SystemExit(f"no {TARGET} written")
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main(rounds: int) -> dict:
    if not (records_folder() / "manifest.csv").is_file():
        raise SystemExit(f"the three-component records are not in {records_folder()}")
    load_start = os.getloadavg()
    runs = [one_run() for _ in range(rounds)]
    return {"target": TARGET, "rounds": rounds, "wall_s": [wall for wall, _ in runs],
            "cpu_s": [cpu for _, cpu in runs], "median_wall_s": statistics.median(wall for wall, _ in runs),
            "median_cpu_s": statistics.median(cpu for _, cpu in runs), "cpu_count": os.cpu_count(),
            "load_average_start": load_start, "load_average_end": os.getloadavg()}


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=3, help="runs of the whole study (default 3)")
    print(json.dumps(main(parser.parse_args().rounds), indent=2))
