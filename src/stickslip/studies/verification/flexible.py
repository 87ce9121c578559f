"""SLAMMER 1.1's own flexible-block results, recomputed by both our schemes and judged by pySLAMMER's rules.

The reference file is the rigid verification's (:mod:`stickslip.studies.verification.slammer`):
SLAMMER 1.1's results for 2,520 decoupled and coupled analyses on pyslammer's
18 sample motions (each scaled to a target PGA as SLAMMER scales it, by the
PGA its database states to 0.001 g: :func:`~stickslip.studies.verification.slammer.stated_pga`), each with a
layer height H, V_s = V_s,base = 600 m/s, a damping ratio, a soil model
(linear elastic or equivalent linear, with a reference strain in %) and a
yield coefficient k_y; displacements in cm, in normal and inverse polarity.
Every analysis is recomputed with :func:`stickslip.solve`
by the two schemes of :data:`SCHEMES` (``slammer``, SLAMMER's own stepping,
and ``exact``, closed forms per step with located events) and judged by
:data:`~stickslip.studies.verification.slammer.PYSLAMMER_RULES` per scheme and
group (model × soil model).  Also:

* SLAMMER's k_max, final V_s and final damping beside ours (our k_max at the samples, as SLAMMER's is:
  :attr:`~stickslip.models.layer.result.FlexibleResult.kmax_samples`);
* **the damping reading**: 1,620 linear-elastic analyses store a damping
  ratio of −0.05 and a final damping of 0.15.  Both readings are computed:
  −0.05 as given (plus the foundation damping 0.20, SLAMMER's cap at
  V_s = V_s,base: 0.15) and its absolute value (0.25); the summary gives the
  pass rate of each;
* **pySLAMMER's results** on the same analyses (``pyslammer_0.2.3_results.json.gz``
  beside SLAMMER's, when there): its pass rate per group by the same rules,
  and how often it and we agree with each other;
* **every miss of the exact scheme checked by computation**, as for the rigid
  block: the ``slammer`` scheme on the record resampled linearly to dt/20 and
  dt/100 (:data:`~stickslip.studies.verification.slammer.REFINEMENTS`; the
  exact answer does not change) must come closer to the exact answer than
  SLAMMER 1.1 is, and within tolerance of it: the difference is SLAMMER's time step.

The ``slammer`` scheme, which steps as SLAMMER does, has no check of its
misses: with SLAMMER's own scaling it has none (docs/solvers.md).
"""

from __future__ import annotations

import gzip
import hashlib
import json
import sys
import warnings
from collections.abc import Mapping, Sequence
from dataclasses import asdict
from pathlib import Path
from typing import NamedTuple

import numpy as np

from stickslip.models import MODELS, solve
from stickslip.errors import StickslipError, StickslipWarning
from stickslip.studies.verification.slammer import (
    POLARITIES,
    PYSLAMMER_RULES,
    REFINEMENTS,
    SCALING,
    AcceptanceRules,
    group_summary,
    sample_motions,
    scaled_records,
    unavailable_summary,
    verification_source,
)

#: Our schemes, in report order: SLAMMER's own stepping, then the exact solution.
SCHEMES = ("slammer", "exact")

#: pySLAMMER's own results on the same analyses, read when beside SLAMMER's.
PYSLAMMER_FILE = "pyslammer_0.2.3_results.json.gz"

#: The groups judged apart, as (model, soil model): SLAMMER's method × mode.
GROUPS = (("decoupled", "linear"), ("decoupled", "equivalent-linear"), ("coupled", "linear"),
          ("coupled", "equivalent-linear"))

#: SLAMMER's mode names -> our soil models.
SOIL_MODELS = {"linear_elastic": "linear", "equivalent_linear": "equivalent-linear"}

#: Columns of the per-analysis table (one row per analysis and polarity); units in the docs.
ANALYSIS_COLUMNS = ("analysis_id", "earthquake", "station", "motion_file", "slammer_target_pga", "model", "soil_model",
                    "height", "vs", "vs_base", "damping", "reference_strain", "ky", "dt", "polarity", "scheme",
                    "reference_displacement", "computed_displacement", "displacement_difference",
                    "displacement_tolerance", "normalized_difference", "passes", "pyslammer_displacement",
                    "pyslammer_passes", "reference_kmax", "computed_kmax", "reference_vs_final", "computed_vs_final",
                    "reference_damping_final", "computed_damping_final")


class FlexibleVerification(NamedTuple):
    """What :func:`run_flexible_verification` computed: the per-analysis rows and the summary."""

    rows: list[dict]
    summary: dict


def read_flexible_analyses(path: str | Path) -> list[dict]:
    """The decoupled and coupled analyses of a results file ``path``, each as a flat dict.

    Keys: ``analysis_id``, ``earthquake``, ``station``, ``motion_file``,
    ``target_pga_g`` [g], ``ky`` [1], ``model``, ``soil_model``, ``height`` [m],
    ``vs``, ``vs_base`` [m/s], ``damping`` [1] as stored, ``reference_strain``
    [%] (None for a linear layer), ``reference`` (polarity -> displacement [cm])
    and ``properties`` (``kmax`` [1], ``vs_final`` [m/s], ``damping_final`` [1]
    where given).  A file that is not such a results file raises :class:`StickslipError` naming it.
    """
    try:
        with gzip.open(path, "rt", encoding="utf-8") as handle:
            document = json.load(handle)
        analyses = []
        for item in document["analyses"]:
            if item["analysis"]["method"] not in ("decoupled", "coupled"):
                continue
            site, results = item["site_parameters"], item["results"]
            analyses.append({
                "analysis_id": str(item["analysis_id"]),
                "earthquake": str(item["ground_motion_parameters"]["earthquake"]),
                "station": str(item["ground_motion_parameters"]["record_station"]),
                "motion_file": str(item["ground_motion_parameters"]["ground_motion_file"]),
                "target_pga_g": float(item["ground_motion_parameters"]["target_pga_g"]),
                "ky": float(site["ky_g"]), "model": str(item["analysis"]["method"]),
                "soil_model": SOIL_MODELS[item["analysis"]["mode"]], "height": float(site["height_m"]),
                "vs": float(site["vs_slope_mps"]), "vs_base": float(site["vs_base_mps"]),
                "damping": float(site["damping_ratio"]),
                "reference_strain": float(site["reference_strain"]) if "reference_strain" in site else None,
                "reference": {polarity: float(results[f"{polarity}_displacement_cm"]) for polarity in POLARITIES},
                "properties": {key: float(results[key]) for key in ("kmax", "vs_final_mps", "damping_final")
                               if key in results},
            })
    except (OSError, EOFError, ValueError, KeyError, TypeError) as error:
        raise StickslipError(f"{path}: not SLAMMER's results file as pySLAMMER stores it (gzip-compressed JSON with "
                             f"an 'analyses' list of flexible analyses): {type(error).__name__}: {error}") from None
    if not analyses:
        raise StickslipError(f"{path}: holds no decoupled or coupled analysis")
    return analyses


def read_displacements(path: str | Path) -> dict[tuple[str, str], float]:
    """(analysis_id, polarity) -> displacement [cm] of every analysis in a results file (pySLAMMER's or SLAMMER's)."""
    try:
        with gzip.open(path, "rt", encoding="utf-8") as handle:
            document = json.load(handle)
        return {(str(item["analysis_id"]), polarity): float(item["results"][f"{polarity}_displacement_cm"])
                for item in document["analyses"] for polarity in POLARITIES}
    except (OSError, EOFError, ValueError, KeyError, TypeError) as error:
        raise StickslipError(f"{path}: not a results file as pySLAMMER stores it: {type(error).__name__}: "
                             f"{error}") from None


def analysis_parameters(analysis: Mapping, damping: float | None = None) -> dict:
    """The layer of ``analysis`` as the flexible models' parameters (:func:`stickslip.solve`'s ``height`` [m], ``vs``,
    ``vs_base`` [m/s], ``damping`` [1], ``equivalent_linear`` and its ``reference_strain`` [%]), with its damping as
    stored unless ``damping`` is given."""
    equivalent_linear = analysis["soil_model"] == "equivalent-linear"
    strain = analysis["reference_strain"]
    return {"height": analysis["height"], "vs": analysis["vs"], "vs_base": analysis["vs_base"],
            "damping": analysis["damping"] if damping is None else damping, "equivalent_linear": equivalent_linear,
            **({"reference_strain": strain} if equivalent_linear and strain is not None else {})}


def solved(analysis: Mapping, record, g: float, polarity: str, damping: float | None = None,
           scheme: str = "slammer"):
    """One of our schemes on one analysis and polarity (:func:`stickslip.solve`; SLAMMER gives no energies, so
    no ledger is kept).

    SLAMMER's analyses are recomputed as SLAMMER specified them: the warning of a layer that softens below a fifth
    of its V_s (:func:`~stickslip.models.layer.result.warn_if_softened`), meant for a user's reference strain, is
    not raised here, since such layers are part of what is compared.
    """
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", StickslipWarning)
        return solve(record, model=analysis["model"], method=scheme, ky=analysis["ky"], g=g,
                     inverse=polarity == "inverse", ledger=False, **analysis_parameters(analysis, damping))


def analysis_row(analysis: Mapping, polarity: str, scheme: str, result, pyslammer: float | None,
                 rules: AcceptanceRules) -> dict:
    """One row of the per-analysis table: the case, SLAMMER's, ours and pySLAMMER's values, the verdicts."""
    reference = analysis["reference"][polarity]
    computed = 100.0 * result.displacement
    tolerance = rules.tolerance(reference)
    properties = analysis["properties"]
    return {
        "analysis_id": analysis["analysis_id"], "earthquake": analysis["earthquake"], "station": analysis["station"],
        "motion_file": analysis["motion_file"], "slammer_target_pga": analysis["target_pga_g"],
        "model": analysis["model"], "soil_model": analysis["soil_model"], "height": analysis["height"],
        "vs": analysis["vs"], "vs_base": analysis["vs_base"], "damping": analysis["damping"],
        "reference_strain": analysis["reference_strain"] if analysis["reference_strain"] is not None else "",
        "ky": analysis["ky"], "dt": analysis["dt"], "polarity": polarity, "scheme": scheme,
        "reference_displacement": reference, "computed_displacement": computed,
        "displacement_difference": computed - reference, "displacement_tolerance": tolerance,
        "normalized_difference": (computed - reference) / tolerance, "passes": rules.passes(computed, reference),
        "pyslammer_displacement": "" if pyslammer is None else pyslammer,
        "pyslammer_passes": "" if pyslammer is None else rules.passes(pyslammer, reference),
        "reference_kmax": properties.get("kmax", ""), "computed_kmax": result.kmax_samples,  # SLAMMER's: at the samples
        "reference_vs_final": properties.get("vs_final_mps", ""), "computed_vs_final": result.vs_final,
        "reference_damping_final": properties.get("damping_final", ""), "computed_damping_final": result.damping_final,
    }


def property_agreement(rows: Sequence[Mapping]) -> dict:
    """For k_max, final V_s and final damping: the largest relative difference from SLAMMER's value over the rows [1]."""
    agreement = {}
    for name in ("kmax", "vs_final", "damping_final"):
        pairs = [(float(row[f"computed_{name}"]), float(row[f"reference_{name}"])) for row in rows
                 if row[f"reference_{name}"] != "" and float(row[f"reference_{name}"]) != 0.0]
        differences = [abs(ours - theirs) / abs(theirs) for ours, theirs in pairs]
        agreement[name] = {"compared": len(pairs), "largest_relative_difference": max(differences, default=None)}
    return agreement


def convergence_check(analysis: Mapping, polarity: str, record, g: float, exact: float, rules: AcceptanceRules,
                      refinements: Sequence[int] = REFINEMENTS) -> dict:
    """An exact miss: the ``slammer`` scheme on the record resampled to dt/k beside the exact answer ``exact`` [cm]."""
    from stickslip.records.process import resample

    reference = analysis["reference"][polarity]
    scheme = {1: 100.0 * solved(analysis, record, g, polarity).displacement}
    for factor in refinements:
        scheme[factor] = 100.0 * solved(analysis, resample(record, record.dt / factor), g, polarity).displacement
    finest = refinements[-1]
    tolerance = rules.tolerance(exact)
    closer = abs(scheme[finest] - exact) < abs(reference - exact)
    within = abs(scheme[finest] - exact) <= tolerance
    return {"analysis_id": analysis["analysis_id"], "polarity": polarity, "reference_displacement": reference,
            "exact_displacement": exact, "scheme_displacements": {str(k): value for k, value in scheme.items()},
            "finest_difference_from_exact": scheme[finest] - exact, "tolerance": tolerance,
            "closer_than_slammer": closer, "within_tolerance": within, "explained": closer and within}


def damping_readings(analyses: Sequence[Mapping], rows: Sequence[Mapping], records: Mapping, g: float,
                     rules: AcceptanceRules) -> dict:
    """The pass rate of the analyses stored with a negative damping, read as given and as its absolute value.

    As given is the ``slammer`` scheme's verdict in ``rows``; the absolute value is solved here.
    """
    negative = [analysis for analysis in analyses if analysis["damping"] < 0.0]
    ids = {analysis["analysis_id"] for analysis in negative}
    as_given = [bool(row["passes"]) for row in rows if row["scheme"] == "slammer" and row["analysis_id"] in ids]
    absolute = [bool(rules.passes(100.0 * solved(analysis, records[analysis["analysis_id"]], g, polarity,
                                                 abs(analysis["damping"])).displacement,
                                  analysis["reference"][polarity]))
                for analysis in negative for polarity in POLARITIES]
    readings = {reading: {"values": len(verdicts), "passed": sum(verdicts),
                          "pass_rate": sum(verdicts) / len(verdicts) if verdicts else None}
                for reading, verdicts in (("as_given", as_given), ("absolute_value", absolute))}
    return {"analyses": len(negative), "stored_damping": sorted({a["damping"] for a in negative}),
            "stored_final_damping": sorted({a["properties"].get("damping_final") for a in negative} - {None}),
            "readings": readings}


def run_flexible_verification(path: str | Path, pyslammer_path: str | Path | None = None,
                              rules: AcceptanceRules = PYSLAMMER_RULES, progress: bool = False) -> FlexibleVerification:
    """Recompute every flexible analysis of the results file ``path``; judge per group; check every miss."""
    from stickslip.plumbing.files import provenance
    from tqdm import tqdm
    from stickslip.models.rigid import SLAMMER_GRAVITY

    g = SLAMMER_GRAVITY
    analyses = read_flexible_analyses(path)
    motions = sample_motions(analyses)
    records = scaled_records(analyses, motions, g)
    analyses = [{**analysis, "dt": records[analysis["analysis_id"]].dt} for analysis in analyses]
    theirs = read_displacements(pyslammer_path) if pyslammer_path else {}
    rows = []
    for scheme in SCHEMES:
        for analysis in tqdm(analyses, desc=f"flexible analyses, {scheme}", unit="analysis", disable=not progress,
                             file=sys.stderr):
            for polarity in POLARITIES:
                result = solved(analysis, records[analysis["analysis_id"]], g, polarity, scheme=scheme)
                rows.append(analysis_row(analysis, polarity, scheme, result,
                                         theirs.get((analysis["analysis_id"], polarity)), rules))
    by_id = {analysis["analysis_id"]: analysis for analysis in analyses}
    schemes = {}
    for scheme in SCHEMES:
        groups = schemes[scheme] = {}
        for model_name, soil_model in GROUPS:
            mine = [row for row in rows
                    if row["scheme"] == scheme and row["model"] == model_name and row["soil_model"] == soil_model]
            summary = group_summary(mine, scheme, rules)
            misses = [by_id[miss["analysis_id"]] | {"polarity": miss["polarity"]} for miss in summary["misses"]]
            computed = {(row["analysis_id"], row["polarity"]): row["computed_displacement"] for row in mine}
            if not MODELS[model_name].scheme(scheme).min_steps_per_period:  # exact for the record: is a miss
                summary["misses"] = [convergence_check(miss, miss["polarity"], records[miss["analysis_id"]], g,
                                                       computed[miss["analysis_id"], miss["polarity"]], rules)
                                     for miss in tqdm(misses, desc=f"{model_name} {soil_model} misses",
                                                      disable=not progress, file=sys.stderr)]
            summary["explained"] = sum(miss.get("explained", False) for miss in summary["misses"])
            if theirs:
                pyslammer_rows = [{**row, "computed_displacement": row["pyslammer_displacement"],
                                   "passes": row["pyslammer_passes"]} for row in mine]
                pyslammer = group_summary(pyslammer_rows, scheme, rules)
                summary["pyslammer"] = {key: pyslammer[key] for key in ("analyses", "passed", "pass_rate")}
                summary["agreement_with_pyslammer"] = sum(
                    bool(rules.passes(row["computed_displacement"], row["pyslammer_displacement"])) for row in mine)
            groups[f"{model_name} {soil_model}"] = summary
    summary = {
        "status": "ok",
        "source": {"file": str(path), "sha256": hashlib.sha256(Path(path).read_bytes()).hexdigest(),
                   "flexible_analyses": len(analyses), "values": 2 * len(analyses),
                   "pyslammer_file": str(pyslammer_path) if pyslammer_path else None},
        "gravity": g, "rules": asdict(rules),
        "schemes": schemes,
        "scaling": SCALING,
        "explanations": {"exact": f"the slammer scheme at dt/{REFINEMENTS[-1]} closer to the exact answer than "
                                  "SLAMMER 1.1, and within tolerance of it"},
        "refinements": list(REFINEMENTS),
        "properties": property_agreement([row for row in rows if row["scheme"] == "slammer"]),
        "damping_reading": damping_readings(analyses, rows, records, g, rules),
        "provenance": provenance(),
    }
    return FlexibleVerification(rows, summary)


def write_flexible_verification(summary_path: str | Path, analyses_path: str | Path,
                                folder: str | Path | None = None) -> list[Path]:
    """The workflow's step: run the flexible verification on ``folder``'s results and write its two files.

    ``analyses_path`` (CSV, :data:`ANALYSIS_COLUMNS`, one row per analysis,
    polarity and scheme) and ``summary_path`` (JSON: per scheme and group the
    pass counts, regressions, pySLAMMER's counts and the misses with their
    check; the properties; the damping reading).  Without the
    reference the table is empty and the summary says why and how to get it.
    """
    from stickslip.plumbing.files import write_csv_atomic, write_text_atomic

    source = verification_source(folder)
    if source["path"] is None:
        verification = FlexibleVerification([], unavailable_summary(source["reason"]))
        print(f"flexible verification not run: {source['reason']}")
    else:
        pyslammer = Path(source["path"]).with_name(PYSLAMMER_FILE)
        verification = run_flexible_verification(source["path"], pyslammer if pyslammer.is_file() else None)
        for scheme, groups in verification.summary["schemes"].items():
            for group, result in groups.items():
                print(f"{scheme}, {group}: {result['passed']} of {result['analyses']} within tolerance; "
                      f"{result['explained']} of {len(result['misses'])} misses explained")
    write_csv_atomic(analyses_path, verification.rows, list(ANALYSIS_COLUMNS))
    write_text_atomic(summary_path, json.dumps(verification.summary, indent=1, default=_json_default) + "\n")
    return [Path(summary_path), Path(analyses_path)]


def _json_default(value):
    """numpy scalars as Python numbers in the summary."""
    if isinstance(value, np.generic):
        return value.item()
    raise TypeError(f"not JSON serialisable: {type(value).__name__}")

