"""Database-scale sweep: 20,000 records × 100 μ through ``stickslip.models.rigid.exact.sweep_scalars``.

The records are the SLAMMER near-fault subset (``../shared/records/slammer``,
521 records, one value in g per line, dt from ``eq.sql``) tiled to 20,000
records; the tiles share their arrays, as a database read once would.  Prints
one JSON object: wall time [s], throughput [sample·μ/s] and the process's peak
resident memory [MiB].  Run in its own process (``benchmarks/run.py`` does) so
that the peak memory is this job's.
"""

from __future__ import annotations

import csv
import json
import os
import resource
import sys
import time
from pathlib import Path

import numpy as np

N_RECORDS = 20_000
N_MU = 100
G = 9.81


def slammer_dir() -> Path:
    shared = Path(os.environ.get("STICKSLIP_SHARED_DIR", Path(__file__).resolve().parents[2] / "shared"))
    return shared / "records" / "slammer"


def subset_files(folder: Path) -> tuple[list[Path], list[float]]:
    """Every record file in ``folder/records`` (one value in g per line) and its time step [s] from ``eq.sql``."""
    with open(folder / "eq.sql", newline="", encoding="utf-8") as handle:
        dt_of = {(row[0], row[1]): float(row[2]) for row in csv.reader(handle, delimiter="\t")}
    paths = sorted((folder / "records").glob("*/*"))
    return paths, [dt_of[(path.parent.name, path.name)] for path in paths]


def read_subset(folder: Path) -> tuple[list[np.ndarray], list[float]]:
    """Accelerations [m/s²] and time steps [s] of every record file in ``folder/records``."""
    paths, dts = subset_files(folder)
    return [np.loadtxt(path) * G for path in paths], dts


def main() -> dict:
    from stickslip.models.rigid.exact import sweep_scalars

    accelerations, dts = read_subset(slammer_dir())
    tiles = [i % len(accelerations) for i in range(N_RECORDS)]
    records = [accelerations[i] for i in tiles]
    record_dts = [dts[i] for i in tiles]
    mu = np.linspace(0.01, 0.4, N_MU)
    sweep_scalars(records[:2], record_dts[:2], mu, G)  # numba cache load
    start = time.perf_counter()
    sweep_scalars(records, record_dts, mu, G)
    wall = time.perf_counter() - start
    samples = sum(a.size for a in records)
    return {
        "n_records": N_RECORDS, "distinct_records": len(accelerations), "n_mu": N_MU, "samples": samples,
        "median_record_npts": int(np.median([a.size for a in accelerations])),
        "wall_s": wall, "updates_per_s": samples * N_MU / wall,
        "peak_rss_mib": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024,
    }


if __name__ == "__main__":
    json.dump(main(), sys.stdout)
    print()
