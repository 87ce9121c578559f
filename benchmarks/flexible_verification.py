"""pySLAMMER's ``Decoupled`` and ``Coupled`` and ours on SLAMMER 1.1's 2,520 flexible analyses (5,040 values).

The analyses are those of ``../shared/verification/slammer_1.1_results.json.gz``
(override the shared folder with STICKSLIP_SHARED_DIR).  Each job computes
every displacement from the motions already in memory (read once, outside the
timing), scaling included:

- ``pyslammer``: pySLAMMER's ``Decoupled`` / ``Coupled(ky, motion, height, vs_slope, vs_base, damp_ratio,
  ref_strain, target_pga=..., soil_model=..., inverse=...)``, one per analysis and polarity;
- ``ours (slammer scheme)`` and ``ours (exact scheme)``: :func:`stickslip.models.layer.result.solve_flexible`
  with each scheme, one per analysis and polarity (numba kernels).

After one warm-up of ours (numba's cache), ours run :data:`ROUNDS` times and
pySLAMMER, which takes minutes, once, after our first round; the times, the
ratio of pySLAMMER's to our median, the time per group (model × soil model) of
our job, and the load average before and after are printed as JSON (and as
markdown with ``--markdown``).  The equivalent-linear
groups cost more: each iteration of the strain loop is one more layer response
over the record (the iterations run are counted and printed).
"""

from __future__ import annotations

import json
import os
import statistics
import sys
import time

from slammer_verification import load_text, reference_file  # as the rigid benchmark finds and reports them

ROUNDS = 3


def main(rounds: int = ROUNDS) -> dict:
    import pyslammer

    from stickslip.models.rigid.slammer import SLAMMER_GRAVITY as G
    from stickslip.studies.verification import flexible
    from stickslip.studies.verification.slammer import POLARITIES, sample_motions, scaled_records

    analyses = flexible.read_flexible_analyses(reference_file())
    motions = sample_motions(analyses)
    peer_motions = {name: pyslammer.load_sample_ground_motion(name) for name in motions}
    records = scaled_records(analyses, motions, G)
    peers = {"decoupled": pyslammer.Decoupled, "coupled": pyslammer.Coupled}
    soil_models = {"linear": "linear_elastic", "equivalent-linear": "equivalent_linear"}

    def peer() -> dict:
        return {(a["analysis_id"], polarity): 100.0 * peers[a["model"]](
                    a["ky"], peer_motions[a["motion_file"]], a["height"], a["vs"], a["vs_base"], a["damping"],
                    a["reference_strain"], target_pga=a["target_pga_g"], soil_model=soil_models[a["soil_model"]],
                    inverse=polarity == "inverse").max_sliding_disp
                for a in analyses for polarity in POLARITIES}

    group_times: dict[str, float] = {}
    iterations: dict[str, int] = {}

    def ours(scheme: str):
        def job() -> dict:
            computed = {}
            for a in analyses:
                group = f"{scheme}: {a['model']} {a['soil_model']}"
                start = time.perf_counter()
                for polarity in POLARITIES:
                    result = flexible.solved(a, records[a["analysis_id"]], G, polarity, scheme=scheme)
                    computed[a["analysis_id"], polarity] = 100.0 * result.displacement
                    iterations[group] = iterations.get(group, 0) + result.iterations
                group_times[group] = group_times.get(group, 0.0) + time.perf_counter() - start
            return computed

        return job

    jobs = {f"ours ({scheme} scheme)": ours(scheme) for scheme in flexible.SCHEMES}
    load_start = list(os.getloadavg())
    first, results = {}, {}
    for name, job in jobs.items():  # warm-up: numba's cache, imports
        start = time.perf_counter()
        results[name] = job()
        first[name] = time.perf_counter() - start
    group_times.clear()
    iterations.clear()
    times = {"pyslammer": [], **{name: [] for name in jobs}}
    for round_number in range(rounds):
        for name, job in jobs.items():
            start = time.perf_counter()
            job()
            times[name].append(time.perf_counter() - start)
        if round_number == 0:  # pySLAMMER takes minutes: once, after our first round
            start = time.perf_counter()
            results["pyslammer"] = peer()
            times["pyslammer"].append(time.perf_counter() - start)
    rules = flexible.PYSLAMMER_RULES
    passes = {name: sum(bool(rules.passes(value, a["reference"][polarity]))
                        for a in analyses for polarity in POLARITIES
                        for value in [computed[a["analysis_id"], polarity]])
              for name, computed in results.items()}
    return {
        "values": 2 * len(analyses), "rounds": rounds, "pyslammer_version": pyslammer.__version__,
        "load_average_start": load_start, "ours_first_call_s": first,
        "median_s": {name: statistics.median(values) for name, values in times.items()},
        "times_s": times,
        "pyslammer_over_ours_median": {name: times["pyslammer"][0] / statistics.median(times[name]) for name in jobs},
        "ours_per_group_s_per_round": {group: seconds / rounds for group, seconds in group_times.items()},
        "ours_iterations_per_group_per_round": {group: count // rounds for group, count in iterations.items()},
        "passes": passes,
        "load_average_end": list(os.getloadavg()),
    }


def markdown(result: dict) -> str:
    lines = [f"| job ({result['values']:,} values, whole run) | median of {result['rounds']} [s] | "
             "within pySLAMMER's tolerance of SLAMMER 1.1 |", "| --- | --- | --- |"]
    for name, median in result["median_s"].items():
        lines.append(f"| {name} | {median:.3f} | {result['passes'][name]:,} |")
    lines += ["", "pySLAMMER (one run) / ours (median of " + str(result["rounds"]) + "): "
              + ", ".join(f"{name} {ratio:.0f}" for name, ratio in result["pyslammer_over_ours_median"].items()),
              "", "| scheme: group | ours per round [s] | equivalent-linear iterations per round |", "| --- | --- | --- |"]
    for group, seconds in result["ours_per_group_s_per_round"].items():
        lines.append(f"| {group} | {seconds:.3f} | {result['ours_iterations_per_group_per_round'].get(group, 0):,} |")
    lines += ["", load_text(result) + f"; pyslammer {result['pyslammer_version']}."]
    return "\n".join(lines)


if __name__ == "__main__":
    outcome = main()
    print(markdown(outcome) if "--markdown" in sys.argv else json.dumps(outcome, indent=1))
