"""Sweeps: many records × friction ratios or yield coefficients (× scalings) into one labelled cube.

A cube is an :class:`xarray.Dataset` with dimensions ``record``, ``mu`` (a
flat surface's friction ratios) or ``ky`` (yield coefficients of a block on a
slope, with the coordinate ``yield_acceleration`` = k_y·g) and, when the
records are scaled, ``scale`` (scale factors [1]) or ``target_pga`` (target
PGAs [m s-2]).  Its data variables are the response scalars of every case
(energies in J for the given block mass, lengths in m; a ``ky`` cube adds the
permanent ``downslope_displacement`` and the body-force work), its coordinates
describe the records (event, station, intensity measures, SHA-256 of the
source file), and its attributes say which code, solver, mass, gravity,
sliding direction, polarity and configuration produced it.
:func:`write_cube` stores it as compressed NetCDF-4, atomically.
"""

from __future__ import annotations

import json
import sys
from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path

import numpy as np
import xarray as xr
from tqdm import tqdm

from stickslip.constants import PAPER_BLOCK_MASS, STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.grids import COEFFICIENTS, Grid, positive_increasing
from stickslip.plumbing.files import atomic_path, provenance
from stickslip.measures import intensity_measures
from stickslip.records.process import peak_ground_acceleration, record_name, scaled_versions
from stickslip.records.record import Record
from stickslip.checks import checked_finite_results, checked_positive
from stickslip.limits import check_memory
from stickslip.response import SCALAR_ATTRS as RESPONSE_SCALAR_ATTRS
from stickslip.response import SLOPE_SCALAR_ATTRS as RESPONSE_SLOPE_SCALAR_ATTRS
from stickslip.solvers.registry import scheme
from stickslip.solvers.history import SCALAR_NAMES
from stickslip.units import CF_CONVENTIONS, UNITS

#: Response scalars of a cube, in the kernel's column order: name -> CF
#: attributes.  No CF standard_name exists for these quantities, so they carry
#: units and long_name only.
SCALAR_ATTRS: dict[str, dict[str, str]] = {
    name: {"units": RESPONSE_SCALAR_ATTRS[name][0], "long_name": RESPONSE_SCALAR_ATTRS[name][1]}
    for name in SCALAR_NAMES
}

#: Scalars a ``ky`` cube adds after :data:`SCALAR_ATTRS`: name -> CF attributes.
SLOPE_SCALAR_ATTRS: dict[str, dict[str, str]] = {
    name: {"units": units, "long_name": long_name} for name, (units, long_name) in RESPONSE_SLOPE_SCALAR_ATTRS.items()
}

#: Scalars that are energies: the kernel gives them per unit mass [J/kg].
ENERGY_SCALARS = ("energy_dissipated", "energy_input", "kinetic_energy_final")

#: The coordinate of each kind of sweep: its name -> CF attributes.
GRID_ATTRS = {name: {"units": UNITS[name], "long_name": coefficient.long_name}
              for name, coefficient in COEFFICIENTS.items()}

#: The cube's ``polarity`` attribute: whether the records were solved with their sign flipped.
POLARITY = {False: "normal (record as given)", True: "inverse (record sign flipped)"}

#: Intensity measures stored as record coordinates: name -> CF attributes.
MEASURE_ATTRS: dict[str, dict[str, str]] = {
    name: {"units": UNITS[name], "long_name": long_name} for name, long_name in (
        ("pga", "peak ground acceleration"),
        ("pgv", "peak ground velocity (no baseline correction)"),
        ("rms_acceleration", "RMS ground acceleration over the 5-95 % significant duration"),
        ("arias_intensity", "Arias intensity"),
        ("significant_duration", "5-95 % significant duration (Trifunac and Brady)"),
    )
}

#: Descriptive record coordinates: name -> long_name.
DESCRIPTION_COORDS = {
    "event": "earthquake event",
    "station": "recording station",
    "component": "record component",
    "sha256": "SHA-256 of the record's source file",
}


def _record_ids(records: Sequence[Record]) -> list[str]:
    """Each record's id (``record_<i>`` when it has none); duplicates are an error."""
    return _record_ids_unique([record.meta.record_id or f"record_{index}" for index, record in enumerate(records)])


def _record_ids_unique(ids: list[str]) -> list[str]:
    """``ids`` when no id appears twice; else a StickslipError naming the first repeated id."""
    seen = set()
    for record_id in ids:
        if record_id in seen:
            raise StickslipError(f"record id {record_id!r} appears twice in the sweep; give each record its own id")
        seen.add(record_id)
    return ids


#: Sample·μ updates of the exact kernel per batch of records (about a tenth of a second on one core).
BATCH_WORK = 2e8


def _record_batches(records: Sequence[Record], cases_per_sample: int, batched: bool) -> list[list[int]]:
    """Indices of ``records`` in consecutive batches solved together.

    A scheme with the batched kernel solves a batch in one parallel call, so
    that many short records do not each pay the call's start-up; a batch holds
    about :data:`BATCH_WORK` updates, so the progress bar still moves.  The
    other schemes go one record at a time.
    """
    if not batched:
        return [[index] for index in range(len(records))]
    batches, current, work = [], [], 0.0
    for index, record in enumerate(records):
        current.append(index)
        work += record.npts * cases_per_sample
        if work >= BATCH_WORK:
            batches.append(current)
            current, work = [], 0.0
    return batches + [current] if current else batches


def _batched_scalars(versions: list[Record], grid: Grid, mass: float) -> np.ndarray:
    """Response scalars (n_versions, n_grid, n_scalars) from the batched exact kernel, energies in J."""
    values = np.array(grid.sweep_scalars([v.acceleration for v in versions], [v.dt for v in versions]), dtype=float)
    for name in ENERGY_SCALARS:
        values[..., SCALAR_NAMES.index(name)] *= mass
    if grid.name == "ky":
        displacement = values[..., SCALAR_NAMES.index("residual_displacement")]
        body = np.array([resistance.body for resistance in grid.resistances])
        body_work = np.where(body == 0.0, 0.0, mass * body * displacement)  # as Response.body_force_work
        values = np.concatenate([values, -displacement[..., None], body_work[..., None]], axis=-1)
    return values


def _solver_scalars(versions: list[Record], grid: Grid, mass: float, method: str, options: Mapping) -> np.ndarray:
    """Response scalars (n_versions, n_grid, n_scalars) from one :func:`stickslip.solution.solve` per case."""
    from stickslip.solution import solve

    names = scalar_names(grid)
    values = np.empty((len(versions), grid.values.size, len(names)))
    for i, version in enumerate(versions):
        for j, value in enumerate(grid.values):
            scalars = solve(version, mass=mass, method=method, g=grid.g, inverse=grid.inverse,
                            **{grid.name: float(value)}, **grid.options, **options).scalars()
            values[i, j] = [scalars[name] for name in names]
    return values


def scalar_names(grid: Grid) -> list[str]:
    """The cube's data variables from the solver, in order (a ``ky`` grid adds :data:`SLOPE_SCALAR_ATTRS`)."""
    return list(SCALAR_ATTRS) + (list(SLOPE_SCALAR_ATTRS) if grid.name == "ky" else [])


def grid_attrs(grid: Grid) -> dict:
    """The cube attributes that describe the sliding (ky grids: direction and thrust angle)."""
    if grid.name == "mu":
        return {"sliding": "flat surface, Coulomb friction"}
    parameters = grid.resistances[0].parameters
    if parameters["direction"] == "down":
        return {"sliding": "one-way (downslope only)", "direction": "down"}
    return {"sliding": "two-way (downslope and upslope)", "direction": "both",
            "thrust_angle": parameters["thrust_angle"], "thrust_angle_units": UNITS["thrust_angle"]}


def scaled_measures(measures: Mapping[str, float], factor: float) -> dict[str, float]:
    """The intensity measures of a record scaled by ``factor`` [1], from the unscaled ones.

    Accelerations, velocities and displacements scale with the factor, the Arias
    intensity with its square; times and durations do not change.
    """
    powers = {"pga": 1, "pgv": 1, "pgd": 1, "rms_acceleration": 1, "arias_intensity": 2}
    return {name: value * factor ** powers.get(name, 0) for name, value in measures.items()}


def sweep(
    records: Sequence[Record],
    mu: Iterable[float] | None = None,
    scale: Iterable[float] | None = None,
    target_pga: Iterable[float] | None = None,
    mass: float = PAPER_BLOCK_MASS,
    method: str = "exact",
    g: float = STANDARD_GRAVITY,
    progress: bool = False,
    config: Mapping | None = None,
    measures: Sequence[Mapping[str, float]] | None = None,
    *,
    ky: Iterable[float] | None = None,
    direction: str | None = None,
    thrust_angle: float | None = None,
    inverse: bool = False,
    options: Mapping | None = None,
) -> xr.Dataset:
    """Solve every record for every friction ratio or yield coefficient (and scaling); gather the scalars in a cube.

    Parameters
    ----------
    records:
        The ground motions (acceleration in m/s²); their ``meta.record_id`` label the ``record`` dimension.
    mu:
        Friction ratios μ [1] of a flat surface, positive and strictly increasing.
    scale:
        Scale factors [1]: adds a ``scale`` dimension holding the factors.
    target_pga:
        Target peak ground accelerations [m/s²] (instead of ``scale``): adds a
        ``target_pga`` dimension holding them, and the variable
        ``scale_factor`` (record, target_pga) [1], the factor used for each record.
    mass:
        Block mass m [kg]; energies are for this mass [J].
    method:
        ``"exact"`` (the batched event-driven kernel), ``"newmark"`` (flat
        friction only) or ``"slammer"`` (one solve per case).
    g:
        Gravitational acceleration [m/s²].
    progress:
        Show a progress bar over the records, when stderr is a terminal.
    config:
        Settings to record in the cube's ``config`` attribute (JSON).
    measures:
        The intensity measures of each unscaled record (as
        :meth:`stickslip.measures.IntensityMeasures.as_dict`, computed with the
        same ``g``), when they are already known; those of scaled versions follow
        from :func:`scaled_measures`.  Default: computed here.
    ky:
        Instead of ``mu``: yield coefficients k_y [1] (yield acceleration / g),
        positive and strictly increasing: a ``ky`` dimension.
    direction, thrust_angle:
        With ``ky``: ``"down"`` (default, one-way) or ``"both"`` with the
        thrust angle [degrees], as :func:`stickslip.solve` takes them.
    inverse:
        Solve every record with its sign flipped (SLAMMER's inverse polarity);
        the cube's ``polarity`` attribute says which.
    options:
        Options of the solver, e.g. ``{"time_step": 0.001}`` [s] for ``newmark``
        (``exact`` takes none).  The cube's attributes record every option the
        solver ran with (``solver_time_step`` and ``solver_time_step_units``).

    Returns
    -------
    The cube, dimensions ``(record, [scale or target_pga,] mu or ky)``; its ``status`` coordinate is
    ``"ok"`` for every record (see :func:`missing_cube` for the other status).
    A sweep whose memory estimate exceeds :func:`stickslip.limits.memory_limit`,
    or whose results are not finite, raises :class:`StickslipError`.
    """
    records = list(records)
    if not records:
        raise StickslipError("a sweep needs at least one record")
    solver = scheme(method)
    if scale is not None and target_pga is not None:
        raise StickslipError("give either scale factors or target PGAs, not both")
    if measures is not None and len(measures) != len(records):
        raise StickslipError(f"{len(measures)} sets of measures given for {len(records)} records")
    grid = Grid(g, mu=mu, ky=ky, direction=direction, thrust_angle=thrust_angle, inverse=inverse)
    solver.check_resistance(grid.resistance(grid.values[0]))
    scale = None if scale is None else positive_increasing(scale, "scale factors")
    target_pga = None if target_pga is None else positive_increasing(target_pga, "target PGAs [m/s²]")
    mass = checked_positive(mass, "block mass [kg]")
    given, options = dict(options or {}), solver.options(options, grid.inverse)  # given: what each solve is passed
    ids = _record_ids(records)
    versions_per_record = len(scale if scale is not None else target_pga if target_pga is not None else [1.0])
    cases = len(records) * versions_per_record * grid.values.size
    names = scalar_names(grid)
    check_memory(
        cases * len(names) * 8 * 4,  # the kernel's output, the stacked cube, its variables and the netCDF copy
        f"a sweep of {len(records)} record(s) x {versions_per_record} scaling(s) x {grid.values.size:,} "
        f"{'friction ratios' if grid.name == 'mu' else 'yield coefficients'}",
    )

    values, case_measures, factors = [], [], []
    show = progress and sys.stderr.isatty()
    with tqdm(total=len(records), desc="sweep", unit="record", disable=not show, file=sys.stderr) as bar:
        for batch in _record_batches(records, versions_per_record * grid.values.size, solver.batched):
            versions = [scaled_versions(records[index], scale, target_pga) for index in batch]
            flat = [version for record_versions in versions for version in record_versions]
            solved = (_batched_scalars(flat, grid, mass) if solver.batched
                      else _solver_scalars(flat, grid, mass, method, given))
            for position, index in enumerate(batch):
                record, record_versions = records[index], versions[position]
                values.append(solved[position * versions_per_record:(position + 1) * versions_per_record])
                largest = np.max(np.abs(values[-1]), axis=(0, 1))  # NaN or inf wherever any case has one
                checked_finite_results(dict(zip(names, map(float, largest))), f"{record_name(record)} (sweep)")
                record_factors = [peak_ground_acceleration(version) / peak_ground_acceleration(record)
                                  for version in record_versions]
                if measures is None:
                    case_measures.append([intensity_measures(version, g=grid.g).as_dict() for version in record_versions])
                else:
                    case_measures.append([scaled_measures(measures[index], factor) for factor in record_factors])
                factors.append(record_factors)
            bar.update(len(batch))
    descriptions = [{name: getattr(record.meta, name) for name in DESCRIPTION_COORDS} for record in records]
    return _assemble_cube(ids, descriptions, ["ok"] * len(ids), np.stack(values), case_measures, factors,
                          grid, scale, target_pga, _cube_attrs(method, mass, grid, scale, target_pga, config, options))


def missing_cube(
    record_id: str,
    status: str,
    mu: Iterable[float] | None = None,
    scale: Iterable[float] | None = None,
    target_pga: Iterable[float] | None = None,
    mass: float = PAPER_BLOCK_MASS,
    method: str = "exact",
    g: float = STANDARD_GRAVITY,
    config: Mapping | None = None,
    *,
    ky: Iterable[float] | None = None,
    direction: str | None = None,
    thrust_angle: float | None = None,
    inverse: bool = False,
) -> xr.Dataset:
    """The cube of a record that could not be swept, with the layout :func:`sweep` would give it.

    Every value is NaN (``n_slip_episodes``: -1) and the ``status`` coordinate
    holds ``status`` (``"missing: <how to obtain the record>"``), so that studies
    gather available and missing records alike and every table can name what it
    could not include.
    """
    grid = Grid(g, mu=mu, ky=ky, direction=direction, thrust_angle=thrust_angle, inverse=inverse)
    scale = None if scale is None else positive_increasing(scale, "scale factors")
    target_pga = None if target_pga is None else positive_increasing(target_pga, "target PGAs [m/s²]")
    n_versions = len(scale if scale is not None else target_pga if target_pga is not None else [None])
    values = np.full((1, n_versions, grid.values.size, len(scalar_names(grid))), np.nan)
    nan_measures = [[dict.fromkeys(MEASURE_ATTRS, np.nan)] * n_versions]
    descriptions = [dict.fromkeys(DESCRIPTION_COORDS, "")]
    return _assemble_cube([record_id], descriptions, [status], values, nan_measures, [[np.nan] * n_versions],
                          grid, scale, target_pga, _cube_attrs(method, mass, grid, scale, target_pga, config))


def available(cube: xr.Dataset) -> xr.Dataset:
    """The records of ``cube`` whose status is ``"ok"``."""
    return cube.isel(record=np.flatnonzero(cube.status.values == "ok"))


def missing_records(cube: xr.Dataset) -> dict[str, str]:
    """Record id -> status of the records of ``cube`` that could not be swept."""
    return {str(record): str(status) for record, status in zip(cube.record.values, cube.status.values) if status != "ok"}


def cube_grid(cube: xr.Dataset) -> Grid:
    """The :class:`~stickslip.grids.Grid` a cube of :func:`sweep` or :func:`missing_cube` was swept over.

    Its values are the ``mu`` or ``ky`` coordinate; gravity, sliding direction,
    thrust angle and polarity come from the cube's attributes.
    """
    name = "mu" if "mu" in cube.dims else "ky"
    options = {key: cube.attrs[key] for key in ("direction", "thrust_angle") if key in cube.attrs}
    return Grid(float(cube.attrs["gravity"]), **{name: cube[name].values}, **options,
                inverse=cube.attrs.get("polarity", POLARITY[False]) == POLARITY[True])


def gather(cubes: Sequence[xr.Dataset]) -> xr.Dataset:
    """Per-record (or per-chunk) cubes of one grid joined along ``record``, in the given order."""
    if not cubes:
        raise StickslipError("nothing to gather: no cubes given")
    _record_ids_unique([str(record) for cube in cubes for record in cube.record.values])
    cube = xr.concat(cubes, dim="record", data_vars="minimal", coords="minimal", compat="override",
                     combine_attrs="override")
    for variable in cube.variables.values():
        variable.encoding = {}  # the first file's encoding (a string width, say) need not fit the others
    return cube


def _cube_attrs(method, mass, grid, scale, target_pga, config, options=None) -> dict:
    solver = {}
    for name, value in (options or {}).items():
        solver[f"solver_{name}"] = int(value) if isinstance(value, bool) else value  # NetCDF has no booleans
        if name in UNITS:
            solver[f"solver_{name}_units"] = UNITS[name]
    return {
        "title": "stickslip friction-ratio sweep" if grid.name == "mu" else "stickslip yield-coefficient sweep",
        "Conventions": CF_CONVENTIONS,
        **provenance(),
        "solver": method,
        **solver,
        "block_mass": mass,
        "block_mass_units": UNITS["block_mass"],
        "gravity": grid.g,
        "gravity_units": UNITS["gravity"],
        **grid_attrs(grid),
        "polarity": POLARITY[grid.inverse],
        "scaling": "factor" if scale is not None else "target_pga" if target_pga is not None else "none",
        "config": json.dumps(dict(config or {}), sort_keys=True, default=str),
    }


def _assemble_cube(ids, descriptions, statuses, stacked, case_measures, factors, grid, scale, target_pga,
                   attrs) -> xr.Dataset:
    """The cube from the scalars ``stacked`` (record, version, grid, scalar) and the records' descriptions."""
    scaled = scale is not None or target_pga is not None
    scaling_dim = "scale" if scale is not None else "target_pga"
    dims = ("record", scaling_dim, grid.name) if scaled else ("record", grid.name)
    case_dims = dims[:-1]
    if not scaled:
        stacked = stacked[:, 0]
    data_vars = {}
    variable_attrs = {**SCALAR_ATTRS, **SLOPE_SCALAR_ATTRS}
    for k, name in enumerate(scalar_names(grid)):
        data = stacked[..., k]
        if name == "n_slip_episodes":
            data = np.where(np.isnan(data), -1, np.rint(data)).astype(np.int64)
        data_vars[name] = xr.Variable(dims, data, attrs=variable_attrs[name])

    coords = {
        "record": xr.Variable("record", np.array(ids, dtype=object), attrs={"long_name": "record identifier"}),
        grid.name: xr.Variable(grid.name, grid.values, attrs=GRID_ATTRS[grid.name]),
        "status": xr.Variable("record", np.array(statuses, dtype=object),
                              attrs={"long_name": "ok, or why the record could not be swept"}),
    }
    if grid.name == "ky":
        coords["yield_acceleration"] = xr.Variable(
            "ky", grid.values * grid.g, attrs={"units": UNITS["yield_acceleration"], "long_name": "yield acceleration k_y g"}
        )
    for name, long_name in DESCRIPTION_COORDS.items():
        coords[name] = xr.Variable(
            "record", np.array([d[name] for d in descriptions], dtype=object), attrs={"long_name": long_name}
        )
    for name, measure_attrs in MEASURE_ATTRS.items():
        data = np.array([[m[name] for m in row] for row in case_measures], dtype=float)
        coords[name] = xr.Variable(case_dims, data if scaled else data[:, 0], attrs=measure_attrs)
    if scale is not None:
        coords["scale"] = xr.Variable("scale", scale, attrs={"units": UNITS["scale_factor"], "long_name": "scale factor"})
    elif target_pga is not None:
        coords["target_pga"] = xr.Variable(
            "target_pga", target_pga, attrs={"units": UNITS["target_pga"], "long_name": "target peak ground acceleration"}
        )
        data_vars["scale_factor"] = xr.Variable(
            ("record", "target_pga"), np.array(factors, dtype=float),
            attrs={"units": UNITS["scale_factor"], "long_name": "scale factor applied to the record"}
        )
    return xr.Dataset(data_vars, coords=coords, attrs=attrs)


def read_cube(path: str | Path) -> xr.Dataset:
    """A cube written by :func:`write_cube`, loaded into memory (the file is closed again)."""
    with xr.open_dataset(path, engine="netcdf4") as cube:
        return cube.load()


def write_cube(cube: xr.Dataset, path: str | Path) -> Path:
    """Write ``cube`` to ``path`` as NetCDF-4 with zlib compression, atomically.

    Text variables (record ids, events, status …) are stored as character
    arrays, the CF-1.8 way, not as variable-length strings.  The file appears
    under its name only when complete; on any error or interruption an existing
    file at ``path`` is left untouched.
    """
    path = Path(path)
    encoding = {
        name: {"zlib": True, "complevel": 4}
        for name, variable in cube.variables.items()
        if variable.dtype.kind in "fiu"
    }
    encoding.update({name: {"dtype": "S1"} for name, variable in cube.variables.items() if variable.dtype.kind in "OU"})
    with atomic_path(path) as tmp:
        cube.to_netcdf(tmp, engine="netcdf4", encoding=encoding)
    return path
