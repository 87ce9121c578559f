"""pySLAMMER's ``RigidAnalysis`` and ours on SLAMMER 1.1's 180 rigid analyses: whole-run time in one run, and pass counts.

The analyses are those of ``../shared/verification/slammer_1.1_results.json.gz``
(override the shared folder with STICKSLIP_SHARED_DIR): 90 rigid analyses on
pyslammer's 18 sample motions, each in normal and inverse polarity.  Each job
computes all 180 displacements from the motions already in memory (read once,
outside the timing: pySLAMMER's ``GroundMotion`` objects, our records), scaling
included:

- ``pyslammer``: pySLAMMER 0.2.2's ``RigidAnalysis(ky, motion, target_pga=..., inverse=...)``, one per analysis;
- ``exact batched``: our exact solver, the batched kernel (one call per target PGA and polarity, numba threads as set);
- ``exact solve``: our exact solver, one :func:`stickslip.solve` per analysis (plain Python event solver);
- ``slammer solve``: SLAMMER's scheme, one :func:`stickslip.solve` per analysis (plain Python).

After one warm-up of each (numba's cache loaded), the jobs take turns for
:data:`ROUNDS` rounds; the medians, the median of the per-round ratios
pySLAMMER / ours, and the load average before and after are printed as JSON
(and as markdown with ``--markdown``).  pySLAMMER's own pass count on the 180,
by the same rules as ours (:data:`stickslip.studies.verification.slammer.PYSLAMMER_RULES`),
is printed beside ours.
"""

from __future__ import annotations

import json
import os
import statistics
import sys
import time
from pathlib import Path

ROUNDS = 7


def reference_file() -> Path:
    shared = Path(os.environ.get("STICKSLIP_SHARED_DIR", Path(__file__).resolve().parents[2] / "shared"))
    return shared / "verification" / "slammer_1.1_results.json.gz"


def main(rounds: int = ROUNDS) -> dict:
    import numba
    import pyslammer

    from stickslip.models import solve
    from stickslip.models.rigid.slammer import SLAMMER_GRAVITY as G
    from stickslip.studies.verification import slammer as verification

    analyses = verification.read_rigid_analyses(reference_file())
    motions = verification.sample_motions(analyses)
    peer_motions = {name: pyslammer.load_sample_ground_motion(name) for name in motions}
    polarities = verification.POLARITIES

    def peer() -> dict:
        return {(a["analysis_id"], polarity): 100.0 * pyslammer.RigidAnalysis(
                    a["ky"], peer_motions[a["motion_file"]], target_pga=a["target_pga_g"],
                    inverse=polarity == "inverse").max_sliding_disp
                for a in analyses for polarity in polarities}

    def ours(scheme: str):
        return lambda: verification.computed_displacements(
            scheme, analyses, verification.scaled_records(analyses, motions, G), G)

    def exact_solve() -> dict:
        records = verification.scaled_records(analyses, motions, G)
        return {(a["analysis_id"], polarity): 100.0 * solve(records[a["analysis_id"]], ky=a["ky"], g=G,
                                                            inverse=polarity == "inverse").downslope_displacement
                for a in analyses for polarity in polarities}

    jobs = {"pyslammer": peer, "exact batched": ours("exact"), "exact solve": exact_solve,
            "slammer solve": ours("slammer")}
    load_start = list(os.getloadavg())
    first = {}
    results = {}
    for name, job in jobs.items():  # warm-up: numba's cache, imports
        start = time.perf_counter()
        results[name] = job()
        first[name] = time.perf_counter() - start
    times = {name: [] for name in jobs}
    for _ in range(rounds):
        for name, job in jobs.items():
            start = time.perf_counter()
            job()
            times[name].append(time.perf_counter() - start)
    rules = verification.PYSLAMMER_RULES
    passes = {}
    for name, computed in results.items():
        rows = [verification.judged_row(a, polarity, name, computed[a["analysis_id"], polarity], rules)
                for a in analyses for polarity in polarities]
        summary = verification.group_summary(rows, name, rules)
        passes[name] = {"passed": summary["passed"], "analyses": summary["analyses"], "group_rules_met": summary["passes"],
                        "misses": summary["misses"]}
    return {
        "analyses": 2 * len(analyses), "rounds": rounds, "pyslammer_version": pyslammer.__version__,
        "numba_threads": numba.get_num_threads(), "load_average_start": load_start,
        "first_call_s": first,
        "median_s": {name: statistics.median(values) for name, values in times.items()},
        "times_s": times,
        "pyslammer_over_ours_median_of_rounds": {
            name: statistics.median(p / o for p, o in zip(times["pyslammer"], values))
            for name, values in times.items() if name != "pyslammer"},
        "passes": passes,
        "load_average_end": list(os.getloadavg()),
    }


def markdown(result: dict) -> str:
    lines = [f"| job ({result['analyses']} analyses, whole run) | median of {result['rounds']} [s] | "
             "pySLAMMER / ours (median of rounds) | within pySLAMMER's tolerance of SLAMMER 1.1 |",
             "| --- | --- | --- | --- |"]
    for name, median in result["median_s"].items():
        ratio = result["pyslammer_over_ours_median_of_rounds"].get(name)
        passed = result["passes"][name]
        lines.append(f"| {name} | {median:.4f} | {f'{ratio:.1f}' if ratio else '—'} | "
                     f"{passed['passed']} of {passed['analyses']} |")
    lines += ["", load_text(result) + f"; numba threads {result['numba_threads']}; pyslammer {result['pyslammer_version']}."]
    return "\n".join(lines)


def load_text(result: dict) -> str:
    """The load average (1, 5, 15 min) at the start and the end of a benchmark's run, as text."""
    return ("load average (1, 5, 15 min) at start: " + ", ".join(f"{x:.2f}" for x in result["load_average_start"])
            + "; at end: " + ", ".join(f"{x:.2f}" for x in result["load_average_end"]))


if __name__ == "__main__":
    outcome = main()
    print(markdown(outcome) if "--markdown" in sys.argv else json.dumps(outcome, indent=1))
