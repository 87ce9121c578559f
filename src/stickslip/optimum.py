"""The design answer of a friction-ratio sweep, per record: μ_max, the near-optimal range and the block's stroke there.

The one definition of each per-record result, used by ``stickslip optimum``,
the cubes of ``stickslip sweep``, the workflow's Tables 6 and 7
(:mod:`stickslip.studies.mu_max`) and the collection study
(:mod:`stickslip.studies.collection_sweep`).  For each record (or scaled
version of one) swept over a friction grid μ_1 < … < μ_n [1]:

``mu_max``, ``energy_dissipated_max`` [J]
    the grid μ of largest dissipated energy E_df and E_df there
    (:func:`stickslip.analysis.mu_max_on_grid`; ties go to the smallest μ);
``mu_max_at_grid_edge``
    1 when μ_max is μ_1 or μ_n (the true maximum may lie outside the grid), else 0;
``mu_max_continuous``, ``energy_dissipated_max_continuous`` [J]
    the maximum of E_df(μ) found continuously between the neighbours of the
    grid's best point (:func:`stickslip.analysis.refine_maximum`), with the sweep's solver;
``mu_low``, ``mu_high``, ``contiguous``
    the near-optimal range {μ : E_df ≥ q·E_df,max} on the grid
    (:func:`stickslip.analysis.near_optimal_range`), and 1 when every grid μ
    between its ends qualifies;
``energy_dissipated_reference`` [J], ``efficiency`` [1]
    E_df at the reference friction ratio μ_ref (the paper's recommended 0.1),
    and E_df(μ_ref) / E_df,max,continuous;
``peak_relative_displacement_at_*``, ``residual_displacement_at_*`` [m]
    the stroke (largest |x|, x the block's displacement relative to the base)
    and the residual displacement x at the end of the record, at μ_max, μ_low and μ_high;
``optimum_status``
    ``"ok"``; ``"never slides: …"`` for a record whose block slides at no μ of
    the grid (E_df = 0 everywhere: its PGA is at most μ_1·g), which then has
    no μ_max, range, stroke or efficiency (NaN; its E_df,max is 0 J); or
    ``"not solved"`` for a record that could not be swept (missing, rejected).

Everything here works on NumPy arrays; only :func:`with_optimum` and
:func:`optimum_variables`, which read and write cubes, use xarray.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from stickslip.analysis import (
    energy_dissipated_function,
    grid_maximum_index,
    mu_max_on_grid,
    mu_max_on_grid_edge,
    near_optimal_range,
    refine_mu_max,
)
from stickslip.checks import checked_finite_results
from stickslip.errors import StickslipError
from stickslip.limits import check_memory
from stickslip.records.process import peak_ground_acceleration, record_name
from stickslip.records.record import Record
from stickslip.solvers.history import SCALAR_NAMES

#: The friction grid of ``stickslip optimum`` when none is given (the collection study's): μ from 0.0025 to
#: 1.0 in steps of 0.0025 (400 values) [1].  Up to 1 because μ·g beyond a record's PGA dissipates nothing,
#: and few records exceed 1 g; steps of 0.0025 resolve μ_max well enough for the continuous search that
#: follows, and keep a record's sweep far below a second.
DEFAULT_MU = {"start": 0.0025, "stop": 1.0, "step": 0.0025}

#: The near-optimal fraction q [1] (the workflow's, ``mu_max.near_optimal_fraction``).
DEFAULT_Q = 0.95

#: The reference friction ratio [1]: the paper's recommended μ.
DEFAULT_REFERENCE_MU = 0.10

#: Per-record results: name -> (units, long_name).
RESULTS: dict[str, tuple[str, str]] = {
    "mu_max": ("1", "friction ratio of maximum energy dissipated, on the grid"),
    "energy_dissipated_max": ("J", "maximum energy dissipated by friction on the grid"),
    "mu_max_at_grid_edge": ("1", "1 where mu_max is the grid's first or last point, else 0"),
    "mu_max_continuous": ("1", "friction ratio of maximum energy dissipated, maximised continuously"),
    "energy_dissipated_max_continuous": ("J", "maximum energy dissipated by friction, continuous in mu"),
    "mu_low": ("1", "smallest grid mu with energy dissipated >= q times the maximum"),
    "mu_high": ("1", "largest grid mu with energy dissipated >= q times the maximum"),
    "contiguous": ("1", "1 where every grid mu between mu_low and mu_high qualifies, else 0"),
    "energy_dissipated_reference": ("J", "energy dissipated by friction at the reference friction ratio"),
    "efficiency": ("1", "energy dissipated at the reference friction ratio over the continuous maximum"),
    "peak_relative_displacement_at_mu_max": ("m", "stroke: largest |block displacement relative to the base| at mu_max"),
    "residual_displacement_at_mu_max": ("m", "block displacement relative to the base at the end, at mu_max"),
    "peak_relative_displacement_at_mu_low": ("m", "stroke: largest |block displacement relative to the base| at mu_low"),
    "peak_relative_displacement_at_mu_high": ("m", "stroke: largest |block displacement relative to the base| at mu_high"),
    "residual_displacement_at_mu_low": ("m", "block displacement relative to the base at the end, at mu_low"),
    "residual_displacement_at_mu_high": ("m", "block displacement relative to the base at the end, at mu_high"),
}

#: The text variable that says whether a record has an optimum.
STATUS = "optimum_status"

#: ``optimum_status`` of a record that could not be swept (missing or rejected).
NOT_SOLVED = "not solved"

#: How the ``optimum_status`` of a record whose block slides at no μ of the grid starts.
NEVER_SLIDES = "never slides"

#: The response curves a sweep gives and the optimum reads: name in the cube -> name in :class:`Curves`.
_CURVES = ("energy_dissipated", "peak_relative_displacement", "residual_displacement")


@dataclass(frozen=True)
class Curves:
    """The response of n cases (records, or scaled versions of them) over the friction grid ``mu``.

    Attributes
    ----------
    mu:
        Friction ratios [1], increasing, shape (n_mu,).
    energy_dissipated:
        E_df [J], shape (n, n_mu).
    peak_relative_displacement:
        Largest |x| [m], shape (n, n_mu).
    residual_displacement:
        x at the end of the record [m], shape (n, n_mu).
    """

    mu: np.ndarray
    energy_dissipated: np.ndarray
    peak_relative_displacement: np.ndarray
    residual_displacement: np.ndarray


def solve_curves(versions: Sequence[Record], mu, mass: float, g: float) -> Curves:
    """The :class:`Curves` of ``versions`` over the friction ratios ``mu`` [1] from the exact solver's batched kernel.

    Block mass ``mass`` [kg], gravity ``g`` [m/s²].  What :func:`stickslip.sweeps.sweep`
    computes, without building a cube (and without importing xarray).
    """
    from stickslip.solvers.exact import sweep_scalars

    mu = np.asarray(mu, dtype=float)
    check_memory(len(versions) * mu.size * len(SCALAR_NAMES) * 8 * 2,
                 f"{len(versions)} record(s) x {mu.size:,} friction ratios")
    values = sweep_scalars([version.acceleration for version in versions], [version.dt for version in versions], mu, g)
    for version, record_values in zip(versions, values):
        largest = np.max(np.abs(record_values), axis=0)
        checked_finite_results(dict(zip(SCALAR_NAMES, map(float, largest))), f"{record_name(version)} (sweep)")
    columns = {name: values[..., SCALAR_NAMES.index(name)] for name in _CURVES}
    return Curves(mu, columns["energy_dissipated"] * mass, columns["peak_relative_displacement"],
                  columns["residual_displacement"])


def grid_results(curves: Curves, q: float = DEFAULT_Q) -> dict[str, np.ndarray]:
    """The per-record :data:`RESULTS` that the grid alone gives, each of shape (n,).

    A case whose block never slides (E_df = 0 at every μ) gets NaN for every
    friction ratio, flag and displacement, and 0 J for E_df,max.
    """
    energy, mu = curves.energy_dissipated, curves.mu
    rows = np.arange(energy.shape[0])
    best = grid_maximum_index(energy)
    maximum = np.where(best >= 0, energy[rows, np.maximum(best, 0)], np.nan)
    slides = maximum > 0.0

    def where_slides(values) -> np.ndarray:
        return np.where(slides, np.asarray(values, dtype=float), np.nan)

    mu_low, mu_high, contiguous = (where_slides(value) for value in near_optimal_range(energy, mu, q=q))
    results = {
        "mu_max": where_slides(mu_max_on_grid(energy, mu)),
        "energy_dissipated_max": maximum,
        "mu_max_at_grid_edge": where_slides(mu_max_on_grid_edge(energy, mu)),
        "mu_low": mu_low,
        "mu_high": mu_high,
        "contiguous": contiguous,
    }
    columns = {"mu_max": np.maximum(best, 0)}
    for end, values in (("mu_low", mu_low), ("mu_high", mu_high)):
        columns[end] = np.minimum(np.searchsorted(mu, np.where(slides, values, mu[0])), mu.size - 1)
    for name, values in (("peak_relative_displacement", curves.peak_relative_displacement),
                         ("residual_displacement", curves.residual_displacement)):
        for at, column in columns.items():
            results[f"{name}_at_{at}"] = where_slides(values[rows, column])
    return results


def never_slides_status(pga: float, mu: np.ndarray, g: float) -> str:
    """The ``optimum_status`` of a record of PGA ``pga`` [m/s²] whose block slides at no μ of the grid ``mu`` [1]."""
    threshold = float(mu[0]) * g
    compared = "is at most" if pga <= threshold else "barely exceeds"
    return (f"{NEVER_SLIDES}: E_df = 0 at every mu of the grid; its PGA {pga:.4g} m/s2 ({pga / g:.4g} g) {compared} "
            f"mu*g = {threshold:.4g} m/s2 at the grid's smallest mu, {float(mu[0]):g}")


def optimum(versions: Sequence[Record], curves: Curves, mass: float, g: float, q: float = DEFAULT_Q,
            reference_mu: float = DEFAULT_REFERENCE_MU, method: str = "exact",
            options: Mapping | None = None) -> tuple[dict[str, np.ndarray], list[str]]:
    """Every :data:`RESULTS` value and the ``optimum_status`` of each case of ``curves``.

    ``versions`` are the records the curves belong to, in the same order
    (acceleration in m/s²); the continuous maximum and the energy at
    ``reference_mu`` [1] are computed with the solver ``method`` (and its
    ``options``) that gave the curves, for a block of ``mass`` [kg] under
    gravity ``g`` [m/s²].  Returns (name -> array of shape (n,), statuses).
    """
    if len(versions) != curves.energy_dissipated.shape[0]:
        raise StickslipError(f"{len(versions)} records for {curves.energy_dissipated.shape[0]} response curves")
    results = grid_results(curves, q)
    n = len(versions)
    continuous, continuous_energy = np.full(n, np.nan), results["energy_dissipated_max"].copy()
    reference, statuses = np.empty(n), []
    for index, version in enumerate(versions):
        reference[index] = energy_dissipated_function(version, mass, g, method, options)(reference_mu)
        if np.isnan(results["mu_max"][index]):
            statuses.append(never_slides_status(peak_ground_acceleration(version), curves.mu, g))
            continue
        if curves.mu.size >= 2:
            found = refine_mu_max(version, curves.mu, mass, g, curves.energy_dissipated[index], method=method,
                                  options=options)
            continuous[index], continuous_energy[index] = found.argument, found.value
        else:  # one friction ratio: nothing to refine between
            continuous[index] = results["mu_max"][index]
        statuses.append("ok")
    results.update(
        mu_max_continuous=continuous,
        energy_dissipated_max_continuous=continuous_energy,
        energy_dissipated_reference=reference,
        efficiency=np.divide(reference, continuous_energy, out=np.full(n, np.nan), where=continuous_energy > 0),
    )
    return {name: results[name] for name in RESULTS}, statuses


def attributes(q: float, reference_mu: float) -> dict[str, object]:
    """The cube attributes that say how the per-record results were defined: q and μ_ref, with units."""
    return {"near_optimal_fraction": float(q), "near_optimal_fraction_units": "1",
            "reference_mu": float(reference_mu), "reference_mu_units": "1"}


def optimum_variables(cube, results: Mapping[str, np.ndarray], statuses: Sequence[str], q: float,
                      reference_mu: float):
    """``cube`` with the per-record ``results`` and statuses (flat, record-major) as variables, and q and μ_ref.

    The variables have the cube's dimensions without ``mu``: ``record`` and the
    scaling dimension if any.
    """
    template = cube.energy_dissipated.isel(mu=0, drop=True)
    shape, dims = template.shape, template.dims

    def variable(values, attrs):
        return (dims, np.asarray(values).reshape(shape), attrs)

    variables = {name: variable(results[name], {"units": units, "long_name": long_name})
                 for name, (units, long_name) in RESULTS.items()}
    variables[STATUS] = variable(np.array(list(statuses), dtype=object),
                                 {"long_name": f"ok, '{NEVER_SLIDES}: ...' or '{NOT_SOLVED}'"})
    return cube.assign(variables).assign_attrs(attributes(q, reference_mu))


def curves_of(cube) -> Curves:
    """The :class:`Curves` of every case of ``cube`` (record-major, then the scaling dimension)."""
    def flat(name):
        values = cube[name].transpose(..., "mu").values
        return values.reshape(-1, values.shape[-1])

    return Curves(cube.mu.values, *(flat(name) for name in _CURVES))


def with_optimum(cube, records: Sequence[Record], q: float = DEFAULT_Q, reference_mu: float = DEFAULT_REFERENCE_MU,
                 options: Mapping | None = None):
    """``cube`` (of :func:`stickslip.sweeps.sweep` or :func:`~stickslip.sweeps.missing_cube`) with the :data:`RESULTS`.

    ``records`` are the unscaled records of the cube's ``ok`` records, found
    by their id; a record whose status is not ``ok`` gets NaN and
    ``"not solved"``.  The solver, mass and gravity are the cube's
    (``options``: the solver's, as passed to the sweep).
    """
    from stickslip.records.process import scaled_versions

    by_id = {record.meta.record_id: record for record in records}
    scale = cube["scale"].values if "scale" in cube.dims else None
    target_pga = cube["target_pga"].values if "target_pga" in cube.dims else None
    per_record = cube.energy_dissipated.isel(mu=0).size // cube.sizes["record"]
    mass, g, method = float(cube.attrs["block_mass"]), float(cube.attrs["gravity"]), cube.attrs["solver"]
    curves = curves_of(cube)
    results = {name: np.full(curves.energy_dissipated.shape[0], np.nan) for name in RESULTS}
    statuses = [NOT_SOLVED] * curves.energy_dissipated.shape[0]
    for index, (record_id, status) in enumerate(zip(cube.record.values, cube.status.values)):
        if status != "ok":
            continue
        if record_id not in by_id:
            raise StickslipError(f"no record given for {record_id!r} of the cube")
        cases = slice(index * per_record, (index + 1) * per_record)
        versions = scaled_versions(by_id[record_id], scale, target_pga)
        found, found_statuses = optimum(
            versions, Curves(curves.mu, *(getattr(curves, name)[cases] for name in _CURVES)),
            mass, g, q, reference_mu, method, options)
        for name, values in found.items():
            results[name][cases] = values
        statuses[cases] = found_statuses
    return optimum_variables(cube, results, statuses, q, reference_mu)
