"""``stickslip optimum`` on five records of mixed formats, whole process, warm (issue 15's target: under 2 s).

The five files, written to a temporary folder from the shared records
(``../shared/records``, or STICKSLIP_SHARED_DIR):

- ``RSN181_IMPVALL.H_H-E06230.AT2`` (NGA-West2 AT2, 7,818 samples) and
  ``CHY080-N.AT2`` (NGA-West1 AT2, 18,000 samples), as they are;
- a SLAMMER library file under its library name, ``ALS-000`` (10,130 samples,
  no header: dt from the shipped manifest, no ``--dt``);
- two NGA-West2 AT2 files generated from the SLAMMER library records
  ``Northridge 1994/ARL-090`` (1,998 samples, padded to 2,000 with zeros) and
  ``Landers 1992/LCN-260`` (samples and dt as the library's).

The command is the one the issue names (default grid: 400 friction ratios),
run 7 times after one warm-up run (numba's cache filled); prints one JSON
object with the median and every time [s] and the load average before and after.
"""

from __future__ import annotations

import csv
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

RUNS = 7


def shared_records() -> Path:
    return Path(os.environ.get("STICKSLIP_SHARED_DIR", Path(__file__).resolve().parents[2] / "shared")) / "records"


def library_dt(event_record: str) -> float:
    """The SLAMMER library's time step [s] of ``<event>/<record>``, from the shipped manifest."""
    manifest = Path(__file__).resolve().parents[1] / "src" / "stickslip" / "data" / "slammer_library.csv"
    with open(manifest, newline="", encoding="utf-8") as handle:
        return next(float(row["dt"]) for row in csv.DictReader(handle) if row["file"] == event_record)


def write_at2(path: Path, values_in_g: np.ndarray, dt: float, description: str) -> None:
    """An NGA-West2 AT2 file: four header lines and five E15.7 values per line."""
    lines = ["PEER NGA STRONG MOTION DATABASE RECORD", description, "ACCELERATION TIME SERIES IN UNITS OF G",
             f"NPTS= {values_in_g.size:6d}, DT= {dt:.4f} SEC"]
    lines += ["".join(f"{value:15.7E}" for value in values_in_g[start:start + 5])
              for start in range(0, values_in_g.size, 5)]
    path.write_text("\n".join(lines) + "\n", encoding="ascii")


def five_files(folder: Path) -> list[Path]:
    records = shared_records()
    library = records / "slammer" / "records"
    paths = [records / "formats" / "RSN181_IMPVALL.H_H-E06230.AT2", records / "paper" / "CHY080-N.AT2"]
    als = folder / "ALS-000"
    shutil.copyfile(library / "Chi-Chi, Taiwan 1999" / "ALS-000", als)
    paths.append(als)
    for name, description, length in (("Northridge 1994/ARL-090", "Northridge-01, 1/17/1994, Arleta, 090", 2000),
                                      ("Landers 1992/LCN-260", "Landers, 6/28/1992, Lucerne, 260", None)):
        values = np.loadtxt(library / name)
        if length is not None:
            values = np.pad(values, (0, max(0, length - values.size)))
        path = folder / f"{name.split('/')[1]}.AT2"
        write_at2(path, values, library_dt(name), description)
        paths.append(path)
    return paths


def main() -> dict:
    command = str(Path(sys.executable).with_name("stickslip"))
    with tempfile.TemporaryDirectory() as folder:
        paths = five_files(Path(folder))
        argv = [command, "optimum", *map(str, paths)]
        samples = [json.loads(subprocess.run([command, "measures", str(path), "--json"], check=True,
                                             capture_output=True, text=True).stdout)["npts"] for path in paths]
        subprocess.run(argv, check=True, capture_output=True)  # warm-up: numba's cache, the OS's file cache
        load_start = list(os.getloadavg())
        times = []
        for _ in range(RUNS):
            start = time.perf_counter()
            subprocess.run(argv, check=True, capture_output=True)
            times.append(time.perf_counter() - start)
        load_end = list(os.getloadavg())
    return {"files": [path.name for path in paths], "samples": samples, "runs": RUNS,
            "median_s": statistics.median(times), "times_s": times, "load_average_start": load_start,
            "load_average_end": load_end, "cpu_count": os.cpu_count()}


if __name__ == "__main__":
    print(json.dumps(main(), indent=2))
