"""The one-direction kernels of the friction pendulum and of the vertical motion against the 1-D exact kernel.

Records: the fifteen three-component PEER sets of ``../shared/records/three_component`` (override
the shared folder with STICKSLIP_SHARED_DIR).  After one warm-up call of each job (numba's cache
load; its time is reported), :data:`ROUNDS` alternated rounds time, per unit mass, over
:data:`N_MU` friction ratios μ evenly spaced in [0.01, 0.3]:

- ``flat``: :func:`stickslip.models.rigid.exact.sweep_scalars`, the flat block, on both horizontal
  components of every set (30 records);
- ``pendulum closed form``: :func:`stickslip.models.pendulum.exact.pendulum_sweep`, R = 2 m, same job;
- ``pendulum integrated``: :func:`stickslip.models.pendulum.integrated.integrated_sweep`, Coulomb
  friction, R = 2 m, same job (the tolerance-controlled kernel where the closed form applies);
- ``flat + vertical closed form``: :func:`stickslip.models.pendulum.vertical_exact.vertical_sweep`, the first
  horizontal component of every set with its vertical (15 records, each cut to the shorter);
- ``pendulum integrated, μ(v) + vertical``: ``integrated_sweep``, R = 2 m, μ(v) from μ/2 to μ at
  20 s/m, the same 15 records with their verticals.

It prints (JSON, or markdown with ``--markdown``) each job's median, its throughput in
sample·μ updates per second (each record's samples counted once per μ) and its time per
sample·μ over the flat kernel's, and the load average before and after.
"""

from __future__ import annotations

import csv
import json
import os
import statistics
import sys
import time
from pathlib import Path

import numpy as np

ROUNDS = 3
N_MU = 100
RADIUS = 2.0  # m
RATE = 20.0  # s/m


def three_component_folder() -> Path:
    shared = Path(os.environ.get("STICKSLIP_SHARED_DIR", Path(__file__).resolve().parents[2] / "shared"))
    return shared / "records" / "three_component"


def records():
    """(horizontals, their dts) of the 30 horizontal components, and (first horizontals, verticals, dts) of the sets."""
    from stickslip.records.readers import read_record

    folder = three_component_folder()
    sets: dict[str, dict] = {}
    with open(folder / "manifest.csv", newline="", encoding="utf-8") as handle:
        for row in csv.DictReader(handle):
            sets.setdefault(row["set"], {})[row["component"]] = read_record(folder / row["file"])
    horizontals = [station[name] for station in sets.values() for name in ("H1", "H2")]
    firsts, verticals, dts = [], [], []
    for station in sets.values():
        size = min(station["H1"].acceleration.size, station["UP"].acceleration.size)
        firsts.append(station["H1"].acceleration[:size])
        verticals.append(station["UP"].acceleration[:size])
        dts.append(station["H1"].dt)
    return ([r.acceleration for r in horizontals], [r.dt for r in horizontals]), (firsts, verticals, dts)


def main(rounds: int = ROUNDS) -> dict:
    import numba

    from stickslip.models.rigid.exact import sweep_scalars
    from stickslip.solvers.friction_law import FrictionLaw
    from stickslip.models.pendulum.exact import pendulum_sweep
    from stickslip.models.pendulum.integrated import integrated_sweep
    from stickslip.models.pendulum.vertical_exact import vertical_sweep

    load_start = os.getloadavg()
    (horizontals, horizontal_dts), (firsts, verticals, vertical_dts) = records()
    mu = np.linspace(0.01, 0.3, N_MU)
    coulomb = [FrictionLaw.coulomb(m) for m in mu]
    velocity_dependent = [FrictionLaw.velocity_dependent(m / 2, m, RATE) for m in mu]
    jobs = {
        "flat": (lambda: sweep_scalars(horizontals, horizontal_dts, mu, 9.81), horizontals),
        "pendulum closed form": (lambda: pendulum_sweep(horizontals, horizontal_dts, mu, RADIUS), horizontals),
        "pendulum integrated": (lambda: integrated_sweep(horizontals, None, horizontal_dts, coulomb, RADIUS),
                                horizontals),
        "flat + vertical closed form": (lambda: vertical_sweep(firsts, verticals, vertical_dts, mu), firsts),
        "pendulum integrated, mu(v) + vertical": (
            lambda: integrated_sweep(firsts, verticals, vertical_dts, velocity_dependent, RADIUS), firsts),
    }
    first_call = {}
    for name, (job, _) in jobs.items():
        start = time.perf_counter()
        job()
        first_call[name] = time.perf_counter() - start
    times = {name: [] for name in jobs}
    for _ in range(rounds):
        for name, (job, _) in jobs.items():
            start = time.perf_counter()
            job()
            times[name].append(time.perf_counter() - start)
    medians = {name: statistics.median(values) for name, values in times.items()}
    throughput = {name: sum(a.size for a in data) * N_MU / medians[name] for name, (_, data) in jobs.items()}
    return {
        "records": {"horizontal": len(horizontals), "with_vertical": len(firsts)},
        "samples": {"horizontal": int(sum(a.size for a in horizontals)),
                    "with_vertical": int(sum(a.size for a in firsts))},
        "mu": N_MU, "radius_m": RADIUS, "rounds": rounds, "threads": numba.get_num_threads(),
        "first_call_s": first_call, "median_s": medians,
        "throughput_sample_mu_per_s": throughput,
        "time_per_sample_mu_over_flat": {name: throughput["flat"] / value for name, value in throughput.items()},
        "load_average_start": load_start, "load_average_end": os.getloadavg(),
    }


def markdown(result: dict) -> str:
    lines = [
        f"{result['records']['horizontal']} horizontal components ({result['samples']['horizontal']:,} samples) and "
        f"{result['records']['with_vertical']} sets with their vertical ({result['samples']['with_vertical']:,} "
        f"samples) × {result['mu']} μ in [0.01, 0.3], R = {result['radius_m']:g} m, {result['rounds']} alternated "
        f"rounds, {result['threads']} threads; load average (1, 5, 15 min) at start: "
        + ", ".join(f"{x:.2f}" for x in result["load_average_start"]) + "; at end: "
        + ", ".join(f"{x:.2f}" for x in result["load_average_end"]),
        "",
        "| job | median | throughput | time per sample·μ over the flat kernel's | first call |",
        "| --- | --- | --- | --- | --- |",
    ]
    for name, median in result["median_s"].items():
        lines.append(f"| {name} | {median:.3f} s | {result['throughput_sample_mu_per_s'][name]:.3g} sample·μ/s | "
                     f"{result['time_per_sample_mu_over_flat'][name]:.1f} | {result['first_call_s'][name]:.2f} s |")
    return "\n".join(lines)


if __name__ == "__main__":
    outcome = main(int(sys.argv[sys.argv.index("--rounds") + 1]) if "--rounds" in sys.argv else ROUNDS)
    print(markdown(outcome) if "--markdown" in sys.argv else json.dumps(outcome, indent=1))
