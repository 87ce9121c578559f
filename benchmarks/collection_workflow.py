"""The collection study through the workflow against its bare computation, in one run.

The workflow runs the study in one job per chunk of records and stage
(acquisition, measures, sweep), then gathers and analyses: every job is a new
Python process that imports the library and loads the compiled kernels
afresh.  This benchmark measures how much of the study's wall time that costs:

1. ``workflow``: ``snakemake`` on the study's computed tables (records,
   measures, sweeps, the gathered cube and table, the measures check, the
   analysis, the scaling law; not the notebook), in a fresh folder, whole
   process, with the project's default profile and 2 cores;
2. ``bare``: the same step functions, with the same arguments, called one
   after the other in this process (after one warm-up that imports the
   library and loads the kernels), on 1 core.

Each is run ``--rounds`` times, alternately; the ratio of the medians says how
much the per-job overhead adds.  ``--chunk-size`` (several values allowed)
sets ``collection_study.chunk_size``.  The collection is pyslammer's 18 sample
motions, or ``--collection slammer`` for the SLAMMER library's files in
``../shared/records/slammer`` (override with ``STICKSLIP_SHARED_DIR``).

Run it in the project's environment: ``.venv/bin/python benchmarks/collection_workflow.py``.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import yaml

REPO_ROOT = Path(__file__).resolve().parents[1]
SNAKEMAKE = str(Path(sys.executable).with_name("snakemake"))


def study_settings(collection: str) -> dict:
    """The resolved collection of the study, as ``workflow/rules/common.smk`` makes it."""
    if collection == "pyslammer":
        return {"kind": "pyslammer", "folder": None, "metadata": None, "download": False, "dt": None, "units": None}
    shared = Path(os.environ.get("STICKSLIP_SHARED_DIR", REPO_ROOT.parent / "shared"))
    return {"kind": "slammer", "folder": str((shared / "records" / "slammer").resolve()), "metadata": None,
            "download": False, "dt": None, "units": None}


def targets(kind: str) -> list[str]:
    study = f"results/collections/{kind}"
    return [f"{study}/{name}" for name in ("claims.csv", "measures_check.json", "scaling_law.csv")]


def workflow_seconds(settings: dict, chunk_size: int) -> float:
    """Wall time [s] of the workflow's study jobs in a fresh folder."""
    with tempfile.TemporaryDirectory(prefix="stickslip-bench-") as folder:
        configfile = Path(folder) / "bench.yaml"
        configfile.write_text(yaml.safe_dump({"collection_study": {
            "collection": settings["kind"], "folder": settings["folder"], "chunk_size": chunk_size}}))
        env = {key: value for key, value in os.environ.items() if key not in ("STICKSLIP_SLAMMER_DIR",)}
        env["PATH"] = f"{Path(sys.executable).parent}{os.pathsep}{env['PATH']}"
        command = [SNAKEMAKE, "--snakefile", str(REPO_ROOT / "Snakefile"), "--directory", folder,
                   *targets(settings["kind"]), "--configfile", str(configfile),
                   "--profile", str(REPO_ROOT / "workflow" / "profiles" / "default"), "--cores", "2",
                   "--config", f"records_manifest={REPO_ROOT / 'config' / 'records.yaml'}"]
        start = time.perf_counter()
        subprocess.run(command, cwd=folder, env=env, check=True, capture_output=True)
        return time.perf_counter() - start


def bare_seconds(settings: dict, chunk_size: int, config: dict) -> float:
    """Wall time [s] of the study's step functions called in this process, with the workflow's arguments."""
    from stickslip.collections.collection import selected_ids
    from stickslip.studies.collections.analysis import write_collection_analysis
    from stickslip.studies.collections.measures import write_chunk_measures
    from stickslip.studies.collections.records import store_chunk
    from stickslip.studies.collections.sweep import gather_study, write_chunk_sweep
    from stickslip.studies.collections.measures_check import write_measures_check
    from stickslip.studies.collections.scaling_law import write_scaling_law

    study = config["collection_study"]
    g, q = config["gravity"], config["mu_max"]["near_optimal_fraction"]
    ids, _ = selected_ids(settings, study["filters"])
    chunks = [ids[start:start + chunk_size] for start in range(0, len(ids), chunk_size)]
    with tempfile.TemporaryDirectory(prefix="stickslip-bench-") as folder:
        out = Path(folder)
        start = time.perf_counter()
        stores, measures, cubes = [], [], []
        for index, chunk in enumerate(chunks):
            stores.append(store_chunk(chunk, out / f"records_{index}.nc", settings))
            measures.append(write_chunk_measures(stores[-1], out / f"measures_{index}.csv", g))
            cubes.append(write_chunk_sweep(stores[-1], measures[-1], out / f"sweep_{index}.nc", study["mu"],
                                           config["block_mass"], g, q, study["reference_mu"]))
        gather_study(cubes, measures, out / "study.nc", out / "records.csv", settings, g)
        write_measures_check(out / "records.csv", out / "check.csv", out / "check.json", study["check_pass_rate"])
        write_collection_analysis(
            out / "records.csv", out / "study.nc", out / "relations.csv", out / "coverage.csv", out / "claims.csv",
            out / "near_far.csv", out / "design.json", n_boot=config["relations"]["n_boot"],
            seed=config["relations"]["seed"], min_records=study["min_records"], reference_mu=study["reference_mu"],
            near_optimal_fraction=q, efficiency_target=study["efficiency_target"],
            coverage_target=study["coverage_target"], pga_bands_g=study["pga_bands_g"],
            near_fault_km=study["near_fault_km"], g=g)
        write_scaling_law(stores[0], out / "law.csv", study["mu"], [0.5, 2.0, 3.0], g)
        return time.perf_counter() - start


def main() -> dict:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--collection", choices=("pyslammer", "slammer"), default="pyslammer")
    parser.add_argument("--chunk-size", type=int, nargs="+", default=[100])
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()
    os.environ["NUMBA_NUM_THREADS"] = "1"  # as the workflow's sweep jobs (sweep_threads: 1)
    config = yaml.safe_load((REPO_ROOT / "config" / "config.yaml").read_text(encoding="utf-8"))
    settings = study_settings(args.collection)
    load = [os.getloadavg()]
    bare_seconds(settings, args.chunk_size[0], config)  # warm-up: imports, kernels
    results = {}
    for chunk_size in args.chunk_size:
        times = {"workflow": [], "bare": []}
        for _ in range(args.rounds):
            times["workflow"].append(workflow_seconds(settings, chunk_size))
            times["bare"].append(bare_seconds(settings, chunk_size, config))
        medians = {name: statistics.median(values) for name, values in times.items()}
        results[chunk_size] = {**{f"{name}_median_s": value for name, value in medians.items()},
                               "ratio": medians["workflow"] / medians["bare"], "times": times}
    load.append(os.getloadavg())
    print(f"collection {args.collection}; load average {load[0][0]:.2f} at the start, {load[1][0]:.2f} at the end")
    print("| chunk size | workflow (median) | bare computation (median) | ratio |")
    print("| --- | --- | --- | --- |")
    for chunk_size, result in results.items():
        print(f"| {chunk_size} | {result['workflow_median_s']:.1f} s | {result['bare_median_s']:.1f} s "
              f"| {result['ratio']:.1f} |")
    return {"collection": args.collection, "load": load, "results": results}


if __name__ == "__main__":
    main()
