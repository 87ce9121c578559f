"""Speed benchmarks (run on demand: ``make benchmark`` or ``python benchmarks/run.py``).

Each job is timed with time.perf_counter over several repeats after a warm-up
call (numba compilation is timed separately); where a job has a previous
implementation (the reference kernel, the one-file reader) or a peer
(pySLAMMER, np.loadtxt), they run alternately in the same run.  Medians are
printed as a markdown table with the load average and written to
``benchmarks/results.json``.

Records come from the shared folder ``../shared/records`` beside the checkout
(override with STICKSLIP_SHARED_DIR, as the tests do).
"""

from __future__ import annotations

import json
import os
import platform
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

import database
import optimum_command
import slammer_verification
from stickslip.plumbing.files import provenance, write_text_atomic
from stickslip.records.acquire import acquire

REPO_ROOT = Path(__file__).resolve().parents[1]
RESULTS = Path(__file__).resolve().parent / "results.json"
G = 9.81
PAPER_RECORD_IDS = (
    "cape_mendocino",
    "chichi_chy080n",
    "coyote_g06_230",
    "coyote_g06_320",
    "kobe_kjm090",
    "northridge_nwh090",
)
BENCH_RECORD = "chichi_chy080n"  # the longest shared record: 18,000 samples at 0.005 s
N_MU = 1000
PYSLAMMER_KY = (0.05, 0.1, 0.2)  # [g]; a few values, extrapolated per update
CLI_RECORD = "CHY080-N.AT2"  # the same Chi-Chi record, as PEER AT2 (a header gives dt and units)


def records_dir() -> Path:
    shared = Path(os.environ.get("STICKSLIP_SHARED_DIR", REPO_ROOT.parent / "shared"))
    return shared / "records" / "paper"


def timed(job, repeats: int) -> list[float]:
    """Wall-clock seconds of ``repeats`` calls of ``job()``."""
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        job()
        times.append(time.perf_counter() - start)
    return times


def first_call_seconds(job) -> float:
    start = time.perf_counter()
    job()
    return time.perf_counter() - start


def alternated(jobs: dict, rounds: int) -> dict[str, list[float]]:
    """Seconds of each job in ``rounds`` rounds, the jobs taking turns within a round (after one warm-up each)."""
    for job in jobs.values():
        job()
    times = {name: [] for name in jobs}
    for _ in range(rounds):
        for name, job in jobs.items():
            times[name].extend(timed(job, 1))
    return times


def bulk_reading() -> dict:
    """(f) read, validate and measure the SLAMMER near-fault records in this process, against np.loadtxt alone."""
    from stickslip.measures import intensity_measures
    from stickslip.records.readers import read_record, read_records

    paths, dts = database.subset_files(database.slammer_dir())
    times = alternated({
        "read_records": lambda: [intensity_measures(r) for r in read_records(paths, dts, format="slammer_1col", units="g")],
        "read_record": lambda: [intensity_measures(read_record(path, format="slammer_1col", dt=dt, units="g"))
                                for path, dt in zip(paths, dts)],
        "loadtxt": lambda: [np.loadtxt(path) for path in paths],
    }, rounds=5)
    medians = {name: statistics.median(values) for name, values in times.items()}
    return {
        "n_files": len(paths), "megabytes": sum(path.stat().st_size for path in paths) / 1e6,
        **{f"{name}_median_s": value for name, value in medians.items()},
        **{f"{name}_records_per_s": len(paths) / value for name, value in medians.items()},
        "read_records_speed_over_loadtxt": statistics.median(
            old / new for new, old in zip(times["read_records"], times["loadtxt"])),
        "read_record_speed_over_loadtxt": statistics.median(
            old / new for new, old in zip(times["read_record"], times["loadtxt"])),
    }


def command_line() -> dict:
    """(g) whole-process wall time of three commands (warm numba cache), taking turns, median of 7.

    Each command runs as it is and with ``PYTHONDONTWRITEBYTECODE=1`` (``_nobytecode``), as many
    containers and CI images set it: the environment is byte-compiled at install, so the two should
    take as long (before, the variable made every start compile the imports afresh).
    """
    command = str(Path(sys.executable).with_name("stickslip"))
    record = str(records_dir() / CLI_RECORD)
    commands = {
        "help": [command, "--help"],
        "measures": [command, "measures", record, "--json"],
        "solve": [command, "solve", record, "--mu", "0.1", "--json"],
    }
    plain = {key: value for key, value in os.environ.items() if key != "PYTHONDONTWRITEBYTECODE"}
    environments = {"": plain, "_nobytecode": {**plain, "PYTHONDONTWRITEBYTECODE": "1"}}
    times = alternated({name + suffix: lambda argv=argv, env=env: subprocess.run(argv, check=True, capture_output=True,
                                                                                   env=env)
                        for name, argv in commands.items() for suffix, env in environments.items()}, rounds=7)
    return {f"{name}_median_s": statistics.median(values) for name, values in times.items()}


def main() -> dict:
    from stickslip.models.rigid import exact
    from stickslip.models.rigid import newmark
    from stickslip.models import sweep

    records = {rid: acquire(rid, records_dir=records_dir(), download=False) for rid in PAPER_RECORD_IDS}
    bench = records[BENCH_RECORD]
    mu = np.linspace(0.01, 0.4, N_MU)
    results: dict[str, dict] = {"load_average_start": list(os.getloadavg())}

    # (a) exact kernel: one record x 1,000 mu, today's and the previous (reference) kernel, alternated.
    job_a = lambda: exact.sweep_scalars([bench.acceleration], [bench.dt], mu, G)  # noqa: E731
    job_a_ref = lambda: exact.sweep_scalars_reference([bench.acceleration], [bench.dt], mu, G)  # noqa: E731
    compile_a = first_call_seconds(job_a)
    first_call_seconds(job_a_ref)
    pairs = [(timed(job_a, 1)[0], timed(job_a_ref, 1)[0]) for _ in range(7)]
    median_a = statistics.median(new for new, _ in pairs)
    median_a_ref = statistics.median(old for _, old in pairs)
    updates_a = bench.npts * N_MU
    results["exact_sweep_one_record"] = {
        "record": BENCH_RECORD, "npts": bench.npts, "n_mu": N_MU, "first_call_s": compile_a,
        "median_s": median_a, "updates_per_s": updates_a / median_a,
        "reference_median_s": median_a_ref, "reference_updates_per_s": updates_a / median_a_ref,
        "speedup_median_of_pairs": statistics.median(old / new for new, old in pairs),
    }

    # (b) pyslammer's rigid (one-way) analysis on the same record, a few ky values.
    import pyslammer

    motion = pyslammer.GroundMotion(bench.acceleration / G, bench.dt, name=BENCH_RECORD)
    job_b = lambda: [pyslammer.RigidAnalysis(ky, motion) for ky in PYSLAMMER_KY]  # noqa: E731
    first_b = first_call_seconds(job_b)
    median_b = statistics.median(timed(job_b, 3))
    updates_b = bench.npts * len(PYSLAMMER_KY)
    results["pyslammer_rigid_one_record"] = {
        "record": BENCH_RECORD, "npts": bench.npts, "n_ky": len(PYSLAMMER_KY), "first_call_s": first_b,
        "median_s": median_b, "updates_per_s": updates_b / median_b,
        "extrapolated_s_for_1000_mu": median_b / len(PYSLAMMER_KY) * N_MU,
    }

    # (c) newmark (converging reading) at 0.001 s on the same record: 90,000 steps.
    job_c = lambda: newmark.solve_history(bench.acceleration, bench.dt, 0.1, G, time_step=0.001)  # noqa: E731
    compile_c = first_call_seconds(job_c)
    median_c = statistics.median(timed(job_c, 10))
    steps_c = int(round(bench.duration / 0.001))
    results["newmark_one_solve"] = {
        "record": BENCH_RECORD, "time_step_s": 0.001, "n_steps": steps_c, "first_call_s": compile_c,
        "median_s": median_c, "steps_per_s": steps_c / median_c,
    }

    # (d) the six shared paper records x 1,000 mu: the public sweep (cube with measures) and the bare kernel.
    ordered = list(records.values())
    job_d = lambda: sweep(ordered, mu=mu)  # noqa: E731
    first_d = first_call_seconds(job_d)
    median_d = statistics.median(timed(job_d, 3))
    job_d_kernel = lambda: exact.sweep_scalars([r.acceleration for r in ordered], [r.dt for r in ordered], mu, G)  # noqa: E731
    median_d_kernel = statistics.median(timed(job_d_kernel, 3))
    job_d_reference = lambda: exact.sweep_scalars_reference(  # noqa: E731
        [r.acceleration for r in ordered], [r.dt for r in ordered], mu, G)
    median_d_reference = statistics.median(timed(job_d_reference, 3))
    updates_d = sum(r.npts for r in ordered) * N_MU
    results["six_records_sweep"] = {
        "records": list(records), "n_mu": N_MU, "samples": sum(r.npts for r in ordered),
        "stickslip_sweep_first_call_s": first_d, "stickslip_sweep_median_s": median_d,
        "sweep_scalars_median_s": median_d_kernel, "updates_per_s_kernel": updates_d / median_d_kernel,
        "reference_median_s": median_d_reference, "reference_updates_per_s": updates_d / median_d_reference,
    }

    results["bulk_reading"] = bulk_reading()
    results["command_line"] = command_line()
    results["optimum_command"] = optimum_command.main()
    # (i) pySLAMMER and ours on SLAMMER 1.1's 180 rigid analyses (needs ../shared/verification).
    if slammer_verification.reference_file().is_file():
        results["slammer_verification"] = slammer_verification.main()

    # (e) database scale, in its own process so that its peak memory is its own.
    database = subprocess.run([sys.executable, str(Path(__file__).resolve().parent / "database.py")],
                              check=True, capture_output=True, text=True)
    results["database_scale"] = json.loads(database.stdout)
    results["ratio_exact_over_pyslammer_updates_per_s"] = (
        results["exact_sweep_one_record"]["updates_per_s"] / results["pyslammer_rigid_one_record"]["updates_per_s"]
    )
    results["load_average_end"] = list(os.getloadavg())
    results["machine"] = {
        "platform": platform.platform(), "processor": platform.processor(), "cpu_count": os.cpu_count(),
        "numba_threads": __import__("numba").get_num_threads(), **provenance(),
    }
    return results


def markdown(results: dict) -> str:
    a, b = results["exact_sweep_one_record"], results["pyslammer_rigid_one_record"]
    c, d, e = results["newmark_one_solve"], results["six_records_sweep"], results["database_scale"]
    f, g, h = results["bulk_reading"], results["command_line"], results["optimum_command"]
    pyslammer_rate = b["updates_per_s"]  # sample·ky updates per second

    def pyslammer_s(updates: float) -> str:
        return f"≈ {updates / pyslammer_rate:.1f} s (extrapolated)"

    lines = [
        "| job | today (median) | previous (median, today's speed-up) | pySLAMMER / np.loadtxt | today's throughput |",
        "| --- | --- | --- | --- | --- |",
        f"| (a) exact sweep_scalars, {a['record']} ({a['npts']} samples) x {a['n_mu']} mu | {a['median_s']:.4f} s "
        f"| {a['reference_median_s']:.4f} s ({a['speedup_median_of_pairs']:.2f}x, median of alternated pairs) "
        f"| {pyslammer_s(a['npts'] * a['n_mu'])} | {a['updates_per_s']:.3g} sample·mu/s |",
        f"| (b) pySLAMMER RigidAnalysis, same record x {b['n_ky']} ky | — | — | {b['median_s']:.3f} s "
        f"| {b['updates_per_s']:.3g} sample·ky/s |",
        f"| (c) newmark, dt = 0.001 s, {c['n_steps']} steps | {c['median_s'] * 1e3:.2f} ms | — | — "
        f"| {c['steps_per_s']:.3g} steps/s |",
        f"| (d) stickslip.sweep, 6 records x {d['n_mu']} mu (with measures, cube) "
        f"| {d['stickslip_sweep_median_s']:.3f} s | — | — | — |",
        f"| (d') exact sweep_scalars, 6 records x {d['n_mu']} mu | {d['sweep_scalars_median_s']:.4f} s "
        f"| {d['reference_median_s']:.4f} s ({d['reference_median_s'] / d['sweep_scalars_median_s']:.2f}x) "
        f"| {pyslammer_s(d['samples'] * d['n_mu'])} | {d['updates_per_s_kernel']:.3g} sample·mu/s |",
        f"| (e) sweep_scalars, {e['n_records']} records ({e['distinct_records']} SLAMMER near-fault, tiled) "
        f"x {e['n_mu']} mu, one run | {e['wall_s']:.1f} s, peak memory {e['peak_rss_mib']:.0f} MiB | not run "
        f"| {pyslammer_s(e['samples'] * e['n_mu'])} | {e['updates_per_s']:.3g} sample·mu/s |",
        f"| (f) read + validate + measures, {f['n_files']} SLAMMER near-fault files ({f['megabytes']:.1f} MB), "
        f"read_records | {f['read_records_median_s']:.3f} s "
        f"| read_record file by file: {f['read_record_median_s']:.3f} s "
        f"| np.loadtxt alone: {f['loadtxt_median_s']:.3f} s "
        f"| {f['read_records_records_per_s']:.0f} records/s, {f['read_records_speed_over_loadtxt']:.0%} of "
        f"np.loadtxt's speed (file by file: {f['read_record_speed_over_loadtxt']:.0%}) |",
        f"| (g) `stickslip --help`, whole process | {g['help_median_s']:.2f} s | — | — | — |",
        f"| (g) `stickslip measures {CLI_RECORD} --json` | {g['measures_median_s']:.2f} s | — | — | — |",
        f"| (g) `stickslip solve {CLI_RECORD} --mu 0.1 --json` | {g['solve_median_s']:.2f} s | — | — | — |",
        f"| (g) the same three with `PYTHONDONTWRITEBYTECODE=1` | {g['help_nobytecode_median_s']:.2f} / "
        f"{g['measures_nobytecode_median_s']:.2f} / {g['solve_nobytecode_median_s']:.2f} s | — | — | — |",
        f"| (h) `stickslip optimum`, {len(h['files'])} files of mixed formats ({min(h['samples']):,} to "
        f"{max(h['samples']):,} samples), whole process | {h['median_s']:.2f} s | — | — | — |",
    ]
    if "slammer_verification" in results:
        v = results["slammer_verification"]
        ratio = v["pyslammer_over_ours_median_of_rounds"]
        lines.append(f"| (i) SLAMMER 1.1's {v['analyses']} rigid analyses, whole run: exact (batched kernel) "
                     f"| {v['median_s']['exact batched']:.4f} s; SLAMMER's scheme {v['median_s']['slammer solve']:.3f} s "
                     f"| — | pySLAMMER {v['median_s']['pyslammer']:.3f} s ({ratio['exact batched']:.1f}x and "
                     f"{ratio['slammer solve']:.1f}x ours) | passes: exact {v['passes']['exact batched']['passed']}, "
                     f"slammer {v['passes']['slammer solve']['passed']}, pySLAMMER {v['passes']['pyslammer']['passed']} |")
    lines += [
        "",
        "load average (1, 5, 15 min) at start: " + ", ".join(f"{x:.2f}" for x in results["load_average_start"])
        + "; at end: " + ", ".join(f"{x:.2f}" for x in results["load_average_end"]) + ".",
        f"exact / pySLAMMER throughput ratio: {results['ratio_exact_over_pyslammer_updates_per_s']:.3g}; "
        f"first calls (numba compile or cache load): (a) {a['first_call_s']:.2f} s, (c) {c['first_call_s']:.2f} s, "
        f"(d) {d['stickslip_sweep_first_call_s']:.2f} s; "
        f"machine: {results['machine']['cpu_count']} CPUs, numba threads {results['machine']['numba_threads']}.",
    ]
    return "\n".join(lines)


if __name__ == "__main__":
    outcome = main()
    write_text_atomic(RESULTS, json.dumps(outcome, indent=2) + "\n")
    print(markdown(outcome))
