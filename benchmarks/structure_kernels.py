"""The isolated building's exact sweep against the friction pendulum's exact kernel, per sample·μ, in one run.

Both sweep the same record (Chi-Chi CHY080-N, 18,000 samples at 0.005 s, from
``../shared/records/paper`` or ``STICKSLIP_SHARED_DIR``) over the same friction
ratios (μ from 0.01 to 0.2, 96 values) on the same surface (R = 2 m), each on one
numba thread and timed by the process's CPU time (the clock a busy shared
machine disturbs least), alternately, ``--rounds`` times after one warm-up
call; the building is the two-degree-of-freedom design model (one story,
fixed-base period 0.5 s, m_s/m_b = 4, modal damping 0.02).  Prints the
median time per sample·μ of each, their ratio, and the load average at the
start and the end.

    python benchmarks/structure_kernels.py [--rounds 5]
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import time
from pathlib import Path

import numba
import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from stickslip.models.registry import MODELS  # noqa: E402
from stickslip.records.readers import read_record  # noqa: E402


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args()
    shared = Path(os.environ.get("STICKSLIP_SHARED_DIR", ROOT.parent / "shared"))
    record = read_record(shared / "records" / "paper" / "CHY080-N.AT2")
    numba.set_num_threads(1)
    mus = np.linspace(0.01, 0.2, 96)
    isolated = MODELS["isolated"]
    pendulum = MODELS["pendulum"]
    building = isolated.case(isolated.checked({"mu": 0.05, "superstructure_period": 0.5, "radius": 2.0}))
    slider = pendulum.case(pendulum.checked({"mu": 0.05, "radius": 2.0}))
    jobs = {"isolated (2 dof)": lambda: isolated.scheme().sweep([record], building, "mu", mus),
            "pendulum": lambda: pendulum.scheme().sweep([record], slider, "mu", mus)}
    load = os.getloadavg()
    for job in jobs.values():  # warm-up: numba's cache loaded
        job()
    times = {name: [] for name in jobs}
    for _ in range(args.rounds):
        for name, job in jobs.items():
            start = time.process_time()
            job()
            times[name].append(time.process_time() - start)
    updates = record.acceleration.size * mus.size
    medians = {name: statistics.median(values) / updates for name, values in times.items()}
    for name, value in medians.items():
        print(f"{name:18s} {value * 1e9:8.1f} ns per sample·mu (CPU, one thread, median of {args.rounds})")
    print(f"ratio isolated / pendulum: {medians['isolated (2 dof)'] / medians['pendulum']:.1f}")
    print(f"load average (1 min) at the start {load[0]:.2f}, at the end {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
