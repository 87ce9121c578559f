"""SLAMMER 1.1's own rigid-block results, recomputed by both of our schemes and judged by pySLAMMER's rules.

The reference is ``slammer_1.1_results.json.gz``: the displacements that the
USGS program SLAMMER 1.1 computed, as the pySLAMMER project extracted them for
its verification suite.  It is read from a folder (config key
``verification_dir``, or :data:`ENVIRONMENT_VARIABLE`) and never shipped.  Its
rigid analyses are Newmark's one-way block on pyslammer's 18 sample motions:
each motion scaled to a target PGA [g] as SLAMMER scales it, by the PGA its
database states to 0.001 g (:func:`stated_pga`; pySLAMMER uses the exact PGA),
a yield coefficient k_y [1], g = 9.80665 m/s²
(:data:`~stickslip.models.rigid.slammer.SLAMMER_GRAVITY`), in normal polarity
(the record as given: a positive acceleration drives the block downslope) and
inverse polarity (its sign flipped).  Displacements are in cm, SLAMMER's unit.

Each analysis is recomputed by the two schemes of :data:`SCHEMES`:

* ``slammer``, SLAMMER's own stepping (:mod:`stickslip.models.rigid.slammer`,
  through :func:`stickslip.solve`), which should reproduce every analysis;
* ``exact``, the event-driven solver (the batched kernel
  :func:`stickslip.models.rigid.exact.sweep_scalars`), which differs from SLAMMER
  by SLAMMER's time-step error.

Both are judged by :data:`~stickslip.reference.acceptance.PYSLAMMER_RULES`, one place for pySLAMMER's
acceptance rules.  Every analysis where ``exact`` is beyond tolerance is
then checked by computation: the ``slammer`` scheme on the record resampled
linearly to dt/20 and dt/100 (:data:`REFINEMENTS`; the exact answer of a
piecewise-linear record does not change) must converge to the exact answer.
A miss is *explained* when, at the finest step, the scheme is closer to the
exact answer than SLAMMER 1.1 is and within tolerance of it: the difference
is SLAMMER's time step, not ours.

This study reads pyslammer's sample motions itself (package data, one job):
the verification is one self-contained check, not a stage of the paper's flow.
"""

from __future__ import annotations

import gzip
import hashlib
import json
import math
from collections.abc import Mapping, Sequence
from dataclasses import asdict
from pathlib import Path
from typing import NamedTuple

import numpy as np

from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.models.parameters import POLARITIES
from stickslip.reference.acceptance import PYSLAMMER_RULES, AcceptanceRules

#: The reference file's name in the verification folder.
RESULTS_FILE = "slammer_1.1_results.json.gz"

#: The environment variable that names the verification folder (overrides the config's ``verification_dir``).
ENVIRONMENT_VARIABLE = "STICKSLIP_VERIFICATION_DIR"

#: Where the reference comes from, for a report that cannot run without it.
HOW_TO_GET = (
    "The file is SLAMMER 1.1's own results as the pySLAMMER project extracted them: "
    "tests/verification_data/results/slammer_results.json.gz of the public repository pySLAMMER/pySLAMMER "
    f"(commit dd8cfad). Save it as {RESULTS_FILE} in a folder and name that folder with the config key "
    f"verification_dir or the environment variable {ENVIRONMENT_VARIABLE}; make reproduce uses "
    "../shared/verification beside the checkout when that folder exists."
)

#: The recomputing schemes, in report order: SLAMMER's own stepping, then the exact solver.
SCHEMES = ("slammer", "exact")

#: The record's time step is divided by these for the convergence check of the exact solver's misses.
REFINEMENTS = (20, 100)

#: Columns of the per-analysis table (one row per analysis, polarity and scheme); units in ``units.csv``.
ANALYSIS_COLUMNS = ("analysis_id", "earthquake", "station", "motion_file", "slammer_target_pga", "ky", "dt",
                    "polarity", "scheme", "reference_displacement", "computed_displacement",
                    "displacement_difference", "displacement_tolerance", "normalized_difference", "passes")

#: Columns of the convergence table (one row per exact miss and time step).
CONVERGENCE_COLUMNS = ("analysis_id", "earthquake", "station", "motion_file", "slammer_target_pga", "ky", "polarity",
                       "refinement", "time_step", "reference_displacement", "exact_displacement",
                       "scheme_displacement", "difference_from_exact", "displacement_tolerance")


class Verification(NamedTuple):
    """What :func:`run_verification` computed: the two tables' rows and the summary."""

    rows: list[dict]
    convergence: list[dict]
    summary: dict


def verification_source(folder: str | Path | None) -> dict:
    """Where the reference file is, or why the verification cannot run here.

    Returns ``{"path": <the file>, "reason": ""}`` when ``folder`` holds
    :data:`RESULTS_FILE` and pyslammer's sample motions are installed, else
    ``{"path": None, "reason": <one sentence>}``.
    """
    from stickslip.records.acquire import pyslammer_samples_folder

    if not folder:
        reason = (f"no verification folder is configured (config key verification_dir, or the environment variable "
                  f"{ENVIRONMENT_VARIABLE})")
    elif not (Path(folder) / RESULTS_FILE).is_file():
        reason = f"{RESULTS_FILE} is not in the verification folder {folder}"
    elif pyslammer_samples_folder() is None:
        reason = "the pyslammer package, whose sample motions the analyses use, is not installed"
    else:
        return {"path": str(Path(folder) / RESULTS_FILE), "reason": ""}
    return {"path": None, "reason": reason}


def read_rigid_analyses(path: str | Path) -> list[dict]:
    """SLAMMER's rigid analyses in the results file ``path``, each as a flat dict.

    Keys: ``analysis_id``, ``earthquake``, ``station``, ``motion_file`` (the
    pyslammer sample file), ``target_pga_g`` [g], ``ky`` [1] and
    ``reference`` (polarity -> SLAMMER's displacement [cm]).  A file that is
    not such a results file raises :class:`StickslipError` naming it.
    """
    try:
        with gzip.open(path, "rt", encoding="utf-8") as handle:
            document = json.load(handle)
        analyses = [{
            "analysis_id": str(item["analysis_id"]),
            "earthquake": str(item["ground_motion_parameters"]["earthquake"]),
            "station": str(item["ground_motion_parameters"]["record_station"]),
            "motion_file": str(item["ground_motion_parameters"]["ground_motion_file"]),
            "target_pga_g": float(item["ground_motion_parameters"]["target_pga_g"]),
            "ky": float(item["site_parameters"]["ky_g"]),
            "reference": {polarity: float(item["results"][f"{polarity}_displacement_cm"]) for polarity in POLARITIES},
        } for item in document["analyses"] if item["analysis"]["method"] == "rigid"]
    except (OSError, EOFError, ValueError, KeyError, TypeError) as error:
        raise StickslipError(f"{path}: not SLAMMER's results file as pySLAMMER stores it (gzip-compressed JSON with "
                             f"an 'analyses' list): {type(error).__name__}: {error}") from None
    if not analyses:
        raise StickslipError(f"{path}: holds no rigid analysis")
    for analysis in analyses:
        values = [analysis["target_pga_g"], analysis["ky"], *analysis["reference"].values()]
        if not all(math.isfinite(value) for value in values) or analysis["target_pga_g"] <= 0 or analysis["ky"] <= 0:
            raise StickslipError(f"{path}: analysis {analysis['analysis_id']} has a target PGA, k_y or displacement "
                                 "that is not a finite number (PGA and k_y positive)")
    return analyses


def sample_motions(analyses: Sequence[Mapping]) -> dict[str, object]:
    """The pyslammer sample motions the analyses name, as records [m/s²], by file name."""
    from stickslip.records.acquire import pyslammer_sample
    from stickslip.records.readers import read_record

    motions = {}
    for name in dict.fromkeys(analysis["motion_file"] for analysis in analyses):
        sample = pyslammer_sample(name)
        if sample is None:
            raise StickslipError(f"pyslammer's sample motion {name}, which SLAMMER's results name, is not installed")
        motions[name] = read_record(sample, units="g")
    return motions


#: How each analysis's motion is scaled to its target PGA (:func:`scaled_records`), as the summaries say it.
SCALING = ("each pyslammer sample motion scaled to its target PGA by the PGA SLAMMER's database states (max |a| in "
           "g, to 0.001 g), as SLAMMER does")


def stated_pga(motion) -> float:
    """The motion's PGA [g] as SLAMMER's database states it: the file's largest |a| in g, to 0.001 g.

    SLAMMER scales a record by (target PGA) / (this value) (``gui/ResultsPanel.java``:
    ``scale = paramScale / pga``, ``pga`` read from its ``data`` table, which
    ``analysis/ImportRecords.java`` fills with ``round(FindMax(data) / Gcmss, 3)``;
    ``records/eq.sql`` holds the same numbers).  ``motion`` was read in g, converted
    with :data:`~stickslip.constants.STANDARD_GRAVITY`.
    """
    return round(float(np.max(np.abs(motion.acceleration))) / STANDARD_GRAVITY, 3)


def scaled_records(analyses: Sequence[Mapping], motions: Mapping, g: float) -> dict[str, object]:
    """Each analysis's record as SLAMMER scales it, by analysis id: the motion in g times
    (target PGA) / :func:`stated_pga`, in m/s² with SLAMMER's ``g`` [m/s²].

    Not the motion's exact PGA: the stated one is rounded to 0.001 g, which moves
    the scale factor by up to 0.0005 g over the PGA (0.24 % for the 0.211 g of
    Coyote Lake G02-050), and some of SLAMMER's analyses are that sensitive
    (docs/solvers.md).
    """
    from stickslip.records.process import scale

    stated = {name: stated_pga(motion) for name, motion in motions.items()}
    return {analysis["analysis_id"]: scale(motions[analysis["motion_file"]],
                                           g / STANDARD_GRAVITY * analysis["target_pga_g"] / stated[analysis["motion_file"]])
            for analysis in analyses}


def batched_displacements(scheme: str, records: Sequence, kys: Sequence[float], g: float,
                          inverse: bool = False) -> np.ndarray:
    """Downslope displacement [cm] of every (record, k_y) pair, one-way, from ``scheme``'s batched kernel.

    ``records`` in m/s² (sign flipped with ``inverse``), ``kys`` [1], ``g`` [m/s²];
    returns an array (n_records, n_ky).
    """
    from stickslip.grids import Grid
    from stickslip.models.rigid import RIGID

    design = RIGID.design(Grid("ky", kys), method=scheme, g=g, inverse=inverse)
    return -100.0 * design.curves(list(records))["residual_displacement"]


def scheme_displacement(scheme: str, record, ky: float, g: float, polarity: str) -> float:
    """The downslope displacement [cm] of one analysis and polarity by ``scheme`` (:func:`stickslip.solve`)."""
    from stickslip.models import solve

    return 100.0 * solve(record, ky=ky, method=scheme, g=g, inverse=polarity == "inverse").downslope_displacement


def computed_displacements(scheme: str, analyses: Sequence[Mapping], records: Mapping,
                           g: float) -> dict[tuple[str, str], float]:
    """(analysis_id, polarity) -> the displacement [cm] that ``scheme`` (one of :data:`SCHEMES`) computes.

    ``records`` by analysis id (:func:`scaled_records`).  A scheme with a
    batched kernel (``exact``) runs it once per target PGA and polarity, over
    its records and k_y; another (``slammer``) solves each analysis and polarity
    (:func:`stickslip.solve`).
    """
    from stickslip.models.rigid import RIGID

    if scheme not in SCHEMES:
        raise StickslipError(f"unknown scheme {scheme!r}; known: {', '.join(SCHEMES)}")
    computed = {}
    if not RIGID.scheme(scheme).batched:
        for analysis in analyses:
            for polarity in POLARITIES:
                computed[analysis["analysis_id"], polarity] = scheme_displacement(
                    scheme, records[analysis["analysis_id"]], analysis["ky"], g, polarity)
        return computed
    for target in sorted({analysis["target_pga_g"] for analysis in analyses}):
        group = [analysis for analysis in analyses if analysis["target_pga_g"] == target]
        kys = sorted({analysis["ky"] for analysis in group})
        for polarity in POLARITIES:
            values = batched_displacements(scheme, [records[a["analysis_id"]] for a in group], kys, g,
                                           inverse=polarity == "inverse")
            for row, analysis in enumerate(group):
                computed[analysis["analysis_id"], polarity] = float(values[row, kys.index(analysis["ky"])])
    return computed


def judged_row(analysis: Mapping, polarity: str, scheme: str, computed: float, rules: AcceptanceRules) -> dict:
    """One row of the per-analysis table: the analysis, SLAMMER's and the scheme's displacement [cm], the verdict.

    ``analysis`` as :func:`read_rigid_analyses` gives it, with the record's time step ``dt`` [s] if known.
    """
    reference = analysis["reference"][polarity]
    tolerance = rules.tolerance(reference)
    return {
        "analysis_id": analysis["analysis_id"], "earthquake": analysis["earthquake"], "station": analysis["station"],
        "motion_file": analysis["motion_file"], "slammer_target_pga": analysis["target_pga_g"], "ky": analysis["ky"],
        "dt": analysis.get("dt", ""), "polarity": polarity, "scheme": scheme, "reference_displacement": reference,
        "computed_displacement": computed, "displacement_difference": computed - reference,
        "displacement_tolerance": tolerance, "normalized_difference": (computed - reference) / tolerance,
        "passes": rules.passes(computed, reference),
    }


def group_summary(rows: Sequence[Mapping], scheme: str, rules: AcceptanceRules = PYSLAMMER_RULES) -> dict:
    """The group rules for ``scheme``'s rows: pass counts and rates, and per polarity the regression and verdicts."""
    mine = [row for row in rows if row["scheme"] == scheme]
    passed = sum(bool(row["passes"]) for row in mine)
    summary = {"analyses": len(mine), "passed": passed, "pass_rate": passed / len(mine) if mine else None,
               "polarities": {}}
    for polarity in POLARITIES:
        group = [row for row in mine if row["polarity"] == polarity]
        if len(group) < 3:
            summary["polarities"][polarity] = {"analyses": len(group), "passes": False,
                                               "reason": "fewer than 3 analyses: no regression"}
            continue
        group_passed = sum(bool(row["passes"]) for row in group)
        fit = rules.regression([row["computed_displacement"] for row in group],
                               [row["reference_displacement"] for row in group])
        rate = group_passed / len(group)
        summary["polarities"][polarity] = {
            "analyses": len(group), "passed": group_passed, "pass_rate": rate, "pass_rate_ok": rate >= rules.pass_rate,
            **fit, "passes": rate >= rules.pass_rate and fit["slope_ok"] and fit["intercept_ok"] and fit["r_squared_ok"],
        }
    summary["pass_rate_ok"] = bool(mine) and summary["pass_rate"] >= rules.pass_rate
    summary["passes"] = summary["pass_rate_ok"] and all(group["passes"] for group in summary["polarities"].values())
    summary["misses"] = [{"analysis_id": row["analysis_id"], "polarity": row["polarity"]}
                         for row in mine if not row["passes"]]
    return summary


def convergence_check(analyses: Mapping[str, Mapping], records: Mapping, misses: Sequence[Mapping], g: float,
                      rules: AcceptanceRules = PYSLAMMER_RULES,
                      refinements: Sequence[int] = REFINEMENTS) -> tuple[list[dict], list[dict]]:
    """The ``slammer`` scheme on each miss's record resampled to dt/k, beside the exact answer.

    ``analyses`` by id; ``misses`` the exact solver's (``analysis_id``,
    ``polarity``).  Returns the table's rows (k = 1 and each of
    ``refinements``; the exact answer recomputed on every resampled record)
    and one verdict per miss: ``explained`` when at the finest step the scheme
    is closer to the exact answer (at the record's own step) than SLAMMER 1.1
    is, and within tolerance of it; ``observed_order`` of convergence between
    the two finest steps.
    """
    from stickslip.records.process import resample

    rows, verdicts = [], []
    for miss in misses:
        analysis, polarity = analyses[miss["analysis_id"]], miss["polarity"]
        record = records[miss["analysis_id"]]
        reference = analysis["reference"][polarity]
        errors = {}
        for factor in (1, *refinements):
            finer = record if factor == 1 else resample(record, record.dt / factor)
            scheme = scheme_displacement("slammer", finer, analysis["ky"], g, polarity)
            exact = float(batched_displacements("exact", [finer], [analysis["ky"]], g, polarity == "inverse")[0, 0])
            if factor == 1:
                exact_at_dt = exact
            errors[factor] = scheme - exact_at_dt
            rows.append({
                "analysis_id": analysis["analysis_id"], "earthquake": analysis["earthquake"],
                "station": analysis["station"], "motion_file": analysis["motion_file"],
                "slammer_target_pga": analysis["target_pga_g"], "ky": analysis["ky"], "polarity": polarity,
                "refinement": factor, "time_step": finer.dt, "reference_displacement": reference,
                "exact_displacement": exact, "scheme_displacement": scheme, "difference_from_exact": errors[factor],
                "displacement_tolerance": rules.tolerance(exact_at_dt),
            })
        finest, previous = refinements[-1], refinements[-2] if len(refinements) > 1 else 1
        closer = abs(errors[finest]) < abs(reference - exact_at_dt)
        within = abs(errors[finest]) <= rules.tolerance(exact_at_dt)
        order = (math.log(abs(errors[previous]) / abs(errors[finest])) / math.log(finest / previous)
                 if errors[finest] != 0.0 and errors[previous] != 0.0 else None)
        verdicts.append({
            "analysis_id": analysis["analysis_id"], "polarity": polarity, "reference_displacement": reference,
            "exact_displacement": exact_at_dt, "scheme_displacements": {str(k): exact_at_dt + e for k, e in errors.items()},
            "reference_difference_from_exact": reference - exact_at_dt,
            "finest_difference_from_exact": errors[finest], "tolerance": rules.tolerance(exact_at_dt),
            "closer_than_slammer": closer, "within_tolerance": within, "explained": closer and within,
            "observed_order": order,
        })
    return rows, verdicts


def run_verification(path: str | Path, rules: AcceptanceRules = PYSLAMMER_RULES,
                     refinements: Sequence[int] = REFINEMENTS) -> Verification:
    """Recompute every rigid analysis of the results file ``path`` with both schemes; judge; explain the misses."""
    from stickslip.plumbing.files import provenance
    from stickslip.models.rigid import SLAMMER_GRAVITY

    g = SLAMMER_GRAVITY
    analyses = read_rigid_analyses(path)
    records = scaled_records(analyses, sample_motions(analyses), g)
    analyses = [{**analysis, "dt": records[analysis["analysis_id"]].dt} for analysis in analyses]
    computed = {scheme: computed_displacements(scheme, analyses, records, g) for scheme in SCHEMES}
    rows = [judged_row(analysis, polarity, scheme, computed[scheme][analysis["analysis_id"], polarity], rules)
            for scheme in SCHEMES for analysis in analyses for polarity in POLARITIES]
    schemes = {scheme: group_summary(rows, scheme, rules) for scheme in SCHEMES}
    by_id = {analysis["analysis_id"]: analysis for analysis in analyses}
    convergence, verdicts = convergence_check(by_id, records, schemes["exact"]["misses"], g, rules, refinements)
    summary = {
        "status": "ok",
        "source": {"file": str(path), "sha256": hashlib.sha256(Path(path).read_bytes()).hexdigest(),
                   "rigid_analyses": len(analyses), "motions": len({a["motion_file"] for a in analyses})},
        "gravity": g,
        "scaling": SCALING,
        "rules": asdict(rules),
        "schemes": schemes,
        "convergence": {"refinements": list(refinements), "misses": len(verdicts),
                        "explained": sum(verdict["explained"] for verdict in verdicts),
                        "all_explained": all(verdict["explained"] for verdict in verdicts), "cases": verdicts},
        "provenance": provenance(),
    }
    return Verification(rows, convergence, summary)


def unavailable_summary(reason: str, rules: AcceptanceRules = PYSLAMMER_RULES) -> dict:
    """The summary of a verification that could not run here: the reason and how to get the reference."""
    return {"status": "not available", "reason": reason, "how_to_get": HOW_TO_GET, "rules": asdict(rules)}


def write_slammer_verification(summary_path: str | Path, analyses_path: str | Path, convergence_path: str | Path,
                               folder: str | Path | None = None) -> list[Path]:
    """The workflow's step: run the verification on ``folder``'s results file and write its three files.

    ``analyses_path`` (CSV, :data:`ANALYSIS_COLUMNS`), ``convergence_path``
    (CSV, :data:`CONVERGENCE_COLUMNS`) and ``summary_path`` (JSON: pass
    counts, regressions, the misses and their convergence).  Without the
    reference (:func:`verification_source`) the tables are empty and the
    summary says why and how to get it; a reference that cannot be read is an
    error.
    """
    from stickslip.plumbing.files import write_csv_atomic, write_text_atomic

    source = verification_source(folder)
    if source["path"] is None:
        verification = Verification([], [], unavailable_summary(source["reason"]))
        print(f"SLAMMER verification not run: {source['reason']}")
    else:
        verification = run_verification(source["path"])
        for scheme, result in verification.summary["schemes"].items():
            print(f"{scheme}: {result['passed']} of {result['analyses']} within tolerance")
    write_csv_atomic(analyses_path, verification.rows, list(ANALYSIS_COLUMNS))
    write_csv_atomic(convergence_path, verification.convergence, list(CONVERGENCE_COLUMNS))
    write_text_atomic(summary_path, json.dumps(verification.summary, indent=1) + "\n")
    return [Path(summary_path), Path(analyses_path), Path(convergence_path)]
