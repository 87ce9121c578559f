"""The planar kernel against the 1-D kernel on the SLAMMER library's near-fault station pairs, and its cost model.

The pairs are those the planar study forms (:func:`stickslip.studies.planar.pairs.form_pairs`)
from the near-fault records of ``../shared/records/slammer`` (override the
shared folder with STICKSLIP_SHARED_DIR), padded to the longer component.
After one warm-up (numba's cache), :data:`ROUNDS` alternated rounds time

- ``plane``: the plane solver (:mod:`stickslip.solvers.plane`) as the flat block calls it,
  :func:`stickslip.models.planar.solver.sweep_pairs`, on every pair × :data:`N_MU` μ;
- ``line``: :func:`stickslip.models.rigid.exact.sweep_scalars` on both components of every pair × the same μ,

and print their medians, the throughputs in sample·μ updates per second (a
pair's samples counted once for the plane, each component's for the line),
the ratio (of wall and of processor time: on a shared machine the wall time
of the long plane job depends on the others' load), and the load average
before and after, as JSON (markdown with ``--markdown``).  The cost model: one
more serial run of the planar kernel per (pair, μ) on a sample of pairs, its
time fitted by least squares to a·(samples) + b·(samples sliding) +
c·(slip episodes), in ns, and the plane job's time split by it into those
three shares, each over the 1-D job's processor time.  Two revisions' plane
jobs are timed side by side by ``benchmarks/commits.py``.
"""

from __future__ import annotations

import json
import os
import statistics
import sys
import time

import numpy as np

from database import slammer_dir  # the near-fault folder, as the database benchmark finds it
from slammer_verification import load_text

ROUNDS = 3
N_MU = 100
G = 9.81
#: Pairs in the cost-model sample (every k-th pair), and its friction ratios.
MODEL_PAIRS = 40
MODEL_MU = (0.01, 0.03, 0.1, 0.3)


def shared_pairs():
    """The near-fault station pairs of the shared SLAMMER folder, as padded :class:`RecordPair` objects."""
    from stickslip.collections.slammer import slammer_manifest
    from stickslip.records.pair import RecordPair
    from stickslip.records.readers import read_records
    from stickslip.studies.planar.pairs import form_pairs

    folder = slammer_dir()
    table = slammer_manifest(folder / "eq.sql", folder / "sha256.csv")
    here = table[[(folder / "records" / file).is_file() for file in table["file"]]]
    members = [{"id": row.id, "event": row.event, "record": row.record, "dt": row.dt} for row in here.itertuples()]
    pairs, _ = form_pairs(members)
    path_of = {row.id: folder / "records" / row.file for row in here.itertuples()}
    dt_of = dict(zip(here["id"], here["dt"]))
    ids = [pair[side] for pair in pairs for side in ("first", "second")]
    records = dict(zip(ids, read_records([path_of[i] for i in ids], [dt_of[i] for i in ids])))
    return [RecordPair.padded(records[pair["first"]], records[pair["second"]]) for pair in pairs]


def main(rounds: int = ROUNDS) -> dict:
    from stickslip.models.planar.solver import sweep_pairs
    from stickslip.solvers.plane import LOCK_RATIO, PLANAR_SCALAR_NAMES, RTOL
    from stickslip.models.rigid.exact import sweep_scalars

    load_start = os.getloadavg()
    pairs = shared_pairs()
    axes = [pair.horizontal() for pair in pairs]
    mu = np.linspace(0.005, 0.5, N_MU)
    sizes = np.array([pair.npts for pair in pairs])
    offsets = np.concatenate([[0], np.cumsum(sizes)]).astype(np.int64)
    first = np.concatenate([a for a, _ in axes])
    second = np.concatenate([b for _, b in axes])
    dts = np.array([pair.dt for pair in pairs])
    lines = [a for pair_axes in axes for a in pair_axes]
    line_dts = [pair.dt for pair in pairs for _ in range(2)]

    def plane():
        out = np.empty((len(pairs), N_MU, len(PLANAR_SCALAR_NAMES)))
        sweep_pairs(first, second, offsets, dts, mu * G, RTOL, LOCK_RATIO, out)
        return out

    def line():
        return sweep_scalars(lines, line_dts, mu, G)

    jobs = {"plane": plane, "line": line}
    results = {name: job() for name, job in jobs.items()}  # numba's cache
    times = {name: [] for name in jobs}
    processor = {name: [] for name in jobs}
    for _ in range(rounds):
        for name, job in jobs.items():
            start = time.perf_counter()
            start_processor = time.process_time()
            job()
            times[name].append(time.perf_counter() - start)
            processor[name].append(time.process_time() - start_processor)
    medians = {name: statistics.median(values) for name, values in times.items()}
    processor_medians = {name: statistics.median(values) for name, values in processor.items()}
    pair_samples = int(sizes.sum())
    return {
        "pairs": len(pairs), "mu": N_MU, "samples_per_pair_median": float(np.median(sizes)),
        "pair_samples": pair_samples, "rounds": rounds, "median_s": medians,
        "throughput_sample_mu_per_s": {"plane": pair_samples * N_MU / medians["plane"],
                                       "line": 2 * pair_samples * N_MU / medians["line"]},
        "plane_over_line_time": medians["plane"] / medians["line"],
        "processor_median_s": processor_medians,
        "plane_over_line_processor_time": processor_medians["plane"] / processor_medians["line"],
        "cost_model": (model := cost_model(pairs, axes)),
        "cost_shares_over_line_processor": cost_shares(model, results["plane"], sizes,
                                                       processor_medians["line"]),
        "load_average_start": load_start, "load_average_end": os.getloadavg(),
    }


def cost_model(pairs, axes) -> dict:
    """Serial time per (pair, μ) fitted to a·samples + b·(samples sliding) + c·episodes [ns]."""
    from stickslip.models.planar.solver import solve_pair
    from stickslip.solvers.plane import LOCK_RATIO, PLANAR_SCALAR_NAMES, RTOL

    rows, seconds = [], []
    out = np.zeros(len(PLANAR_SCALAR_NAMES))
    (one, other), pair = axes[0], pairs[0]  # numba's cache, outside the timing
    solve_pair(one, other, pair.dt, 0.1 * G, RTOL, LOCK_RATIO, np.zeros((0, 8)), out)
    for index in range(0, len(pairs), max(1, len(pairs) // MODEL_PAIRS)):
        (one, other), pair = axes[index], pairs[index]
        for mu in MODEL_MU:
            start = time.perf_counter()
            solve_pair(one, other, pair.dt, mu * G, RTOL, LOCK_RATIO, np.zeros((0, 8)), out)
            seconds.append(time.perf_counter() - start)
            rows.append([pair.npts, out[7] * (pair.npts - 1), out[8]])
    design = np.array(rows, dtype=float)
    coefficients, *_ = np.linalg.lstsq(design, np.array(seconds), rcond=None)
    predicted = design @ coefficients
    return {"cases": len(seconds), "ns_per_sample": coefficients[0] * 1e9,
            "ns_per_sliding_sample": coefficients[1] * 1e9, "ns_per_episode": coefficients[2] * 1e9,
            "r2": float(1 - np.sum((seconds - predicted) ** 2) / np.sum((seconds - np.mean(seconds)) ** 2))}


def cost_shares(model: dict, plane: np.ndarray, sizes: np.ndarray, line_processor: float) -> dict:
    """The plane job's time as the cost model splits it, each share over the 1-D job's processor time.

    ``plane`` holds the job's scalars (pairs, μ, the plane solver's ``PLANAR_SCALAR_NAMES``), whose slip
    fraction and episodes count the samples sliding and the slip episodes of the whole job.
    """
    from stickslip.solvers.plane import PLANAR_SCALAR_NAMES

    fraction, count = PLANAR_SCALAR_NAMES.index("slip_fraction"), PLANAR_SCALAR_NAMES.index("n_slip_episodes")
    samples = float(sizes.sum()) * plane.shape[1]
    sliding = float((plane[:, :, fraction] * (sizes[:, None] - 1)).sum())
    episodes = float(plane[:, :, count].sum())
    return {"sample_mu": samples, "sliding_sample_mu": sliding, "episodes": episodes,
            "share_of_samples": model["ns_per_sample"] * samples * 1e-9 / line_processor,
            "share_of_sliding_samples": model["ns_per_sliding_sample"] * sliding * 1e-9 / line_processor,
            "share_of_episodes": model["ns_per_episode"] * episodes * 1e-9 / line_processor}


def markdown(result: dict) -> str:
    model = result["cost_model"]
    rates = result["throughput_sample_mu_per_s"]
    return "\n".join([
        f"{result['pairs']} near-fault station pairs (median {result['samples_per_pair_median']:,.0f} samples) × "
        f"{result['mu']} μ in [0.005, 0.5], {result['rounds']} alternated rounds; {load_text(result)}",
        "",
        "| job | median (wall) | median (processor, both threads) | throughput (wall) |",
        "| --- | --- | --- | --- |",
        f"| planar kernel (both components) | {result['median_s']['plane']:.2f} s | "
        f"{result['processor_median_s']['plane']:.2f} s | {rates['plane']:.3g} sample·μ/s |",
        f"| 1-D exact kernel, each component | {result['median_s']['line']:.2f} s | "
        f"{result['processor_median_s']['line']:.2f} s | {rates['line']:.3g} sample·μ/s |",
        "",
        f"The plane takes {result['plane_over_line_time']:.1f} times as long as both components in 1-D "
        f"({result['plane_over_line_processor_time']:.1f} times the processor time). Cost model "
        f"({model['cases']} serial cases, R² = {model['r2']:.2f}): {model['ns_per_sample']:.0f} ns per sample + "
        f"{model['ns_per_sliding_sample']:.0f} ns per sample sliding + {model['ns_per_episode']:.0f} ns per slip "
        "episode.",
        "",
        shares_line(result["cost_shares_over_line_processor"]),
    ])


def shares_line(shares: dict) -> str:
    """The markdown sentence of :func:`cost_shares`."""
    return (f"The job's {shares['sample_mu']:.3g} sample·μ, {shares['sliding_sample_mu']:.3g} of them sliding, and "
            f"{shares['episodes']:.3g} slip episodes cost, by the model, {shares['share_of_samples']:.1f}, "
            f"{shares['share_of_sliding_samples']:.1f} and {shares['share_of_episodes']:.1f} times the 1-D job's "
            "processor time.")


if __name__ == "__main__":
    outcome = main()
    print(markdown(outcome) if "--markdown" in sys.argv else json.dumps(outcome, indent=1))
