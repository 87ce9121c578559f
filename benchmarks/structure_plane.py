"""The isolated building in the plane on SLAMMER station pairs: the CPU time of one integrated solve, per pair.

Eight pairs of the SLAMMER library (``../shared/records/slammer`` or
``STICKSLIP_SLAMMER_DIR``; 1,115 to 30,759 samples), each padded and solved in
the plane by ``stickslip.solve(..., model="isolated", method="integrated")``
(the one-story building, T = 0.5 s, m_s/m_b = 4, ζ = 0.02, R = 2 m, μ = 0.06:
the in-plane isolation study's point), ``--rounds`` times after one warm-up
solve (which loads or compiles the kernels), timed by the process's CPU time
(the clock a busy shared machine disturbs least).  Prints each pair's best
time, their median, and the load average at the start and the end.  Run it at
two commits (``git worktree``) one after the other to compare them.

    python benchmarks/structure_plane.py [--rounds 3]
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from stickslip.models import solve  # noqa: E402
from stickslip.records.pair import RecordPair  # noqa: E402
from stickslip.records.readers import read_record  # noqa: E402

#: (event folder, first, second) of the library's station pairs timed.
PAIRS = (("Chi-Chi, Taiwan 1999", "CHY006-000", "CHY006-270"), ("Kobe, Japan 1995", "KJM-000", "KJM-090"),
         ("Northridge 1994", "ARL-090", "ARL-360"), ("Loma Prieta 1989", "BRN-000", "BRN-090"),
         ("Imperial Valley 1979", "AEP-045", "AEP-315"), ("Landers 1992", "JOS-000", "JOS-090"),
         ("Cape Mendocino 1992", "CPM-000", "CPM-090"), ("Duzce, Turkey 1999", "1058-000", "1058-090"))


def solved(pair) -> dict:
    """The in-plane isolation study's building on ``pair`` at R = 2 m, μ = 0.06."""
    return solve(pair, model="isolated", method="integrated", superstructure_period=0.5, stories=1, mass_ratio=4.0,
                 superstructure_damping=0.02, radius=2.0, mu=0.06, mass=1.0, g=9.81).scalars()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()
    library = Path(os.environ.get("STICKSLIP_SLAMMER_DIR", ROOT.parent / "shared" / "records" / "slammer"))
    print(f"load average at the start: {os.getloadavg()[0]:.2f}", flush=True)
    pairs = [RecordPair.padded(read_record(library / "records" / event / first),
                               read_record(library / "records" / event / second)) for event, first, second in PAIRS]
    started = time.process_time()
    solved(pairs[0])
    print(f"warm-up solve (kernels loaded or compiled): {time.process_time() - started:.2f} s CPU", flush=True)
    best = []
    for (_, first, _), pair in zip(PAIRS, pairs):
        times = []
        for _ in range(args.rounds):
            started = time.process_time()
            solved(pair)
            times.append(time.process_time() - started)
        best.append(min(times))
        print(f"{first}: {best[-1]:.3f} s CPU ({pair.first.npts} samples)", flush=True)
    print(f"median over the pairs: {statistics.median(best):.3f} s CPU; load average at the end: "
          f"{os.getloadavg()[0]:.2f}", flush=True)


if __name__ == "__main__":
    main()
