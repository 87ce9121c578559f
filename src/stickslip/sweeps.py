"""Cubes: many records × a swept coefficient (× scalings), labelled and self-describing; gathered, written, read.

A cube is an :class:`xarray.Dataset` with dimensions ``record``, the swept
coefficient's (``mu``, a flat surface's friction ratios, or ``ky``, yield
coefficients of a block on a slope: :data:`stickslip.grids.COEFFICIENTS`)
and, when the records are scaled, ``scale`` (scale factors [1]) or
``target_pga`` (target PGAs [m s-2]).  Its data variables are a model's end
results for every case, its coordinates describe the records (event,
station, intensity measures, SHA-256 of the source file), and its attributes
say which code, model, solver, parameters and configuration produced it.

A model's sweep (the rigid block's: :mod:`stickslip.models.rigid.sweep`)
describes its cube as a :class:`CubeLayout` and hands :func:`fill_cube` a
function that solves a batch of records; :func:`missing_cube` gives a record
that could not be swept the same layout, filled with NaN.  :func:`write_cube`
stores a cube as compressed NetCDF-4, atomically.  xarray is imported where a
cube is built, read or gathered, so that a command that needs the end results
only (``stickslip optimum`` without ``--out``) starts without it.
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
from tqdm import tqdm

from stickslip.errors import StickslipError
from stickslip.grids import COEFFICIENTS, Grid, grid_dimension, positive_increasing
from stickslip.limits import check_memory
from stickslip.measures import intensity_measures
from stickslip.plumbing.files import atomic_path
from stickslip.records.process import peak_ground_acceleration, record_name, scaled_versions
from stickslip.records.record import Record
from stickslip.checks import checked_finite_results
from stickslip.units import UNITS

if TYPE_CHECKING:
    import xarray as xr

#: The coordinate of each kind of sweep: its name -> CF attributes.
GRID_ATTRS = {name: {"units": UNITS[name], "long_name": coefficient.long_name}
              for name, coefficient in COEFFICIENTS.items()}

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


@dataclass(frozen=True)
class CubeLayout:
    """What a model's cube holds besides its numbers.

    Attributes
    ----------
    grid:
        The swept coefficient and its values (:class:`~stickslip.grids.Grid`).
    variables:
        The end results, name -> CF attributes (units, long_name), in the
        order of the last axis of the arrays the model's solver returns.
    attrs:
        The cube's attributes (title, model, solver, mass, gravity, sliding,
        polarity, configuration, provenance …).
    g:
        Gravity [m/s²] of the intensity measures and of the target PGAs.
    scale, target_pga:
        Scale factors [1] or target PGAs [m/s²] (at most one): a dimension of
        scaled versions of every record; None: the records as given.
    grid_coords:
        More coordinates along the grid: name -> (values, CF attributes), such
        as a yield grid's ``yield_acceleration`` = k_y·g [m s-2].
    counts:
        The variables that count something (stored as integers, -1 where unknown).
    """

    grid: Grid
    variables: dict
    attrs: dict
    g: float
    scale: np.ndarray | None = None
    target_pga: np.ndarray | None = None
    grid_coords: dict = field(default_factory=dict)
    counts: tuple[str, ...] = ()

    def __post_init__(self):
        if self.scale is not None and self.target_pga is not None:
            raise StickslipError("give either scale factors or target PGAs, not both")
        if self.scale is not None:
            object.__setattr__(self, "scale", positive_increasing(self.scale, "scale factors"))
        if self.target_pga is not None:
            object.__setattr__(self, "target_pga", positive_increasing(self.target_pga, "target PGAs [m/s²]"))

    @property
    def versions_per_record(self) -> int:
        """How many versions of each record the cube holds: one per scale factor or target PGA, else one."""
        return len(self.scale if self.scale is not None else self.target_pga if self.target_pga is not None else [1])

    def versions(self, record: Record) -> list[Record]:
        """The versions of ``record`` the cube holds (:func:`~stickslip.records.process.scaled_versions`)."""
        return scaled_versions(record, self.scale, self.target_pga)


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


def scaled_measures(measures: Mapping[str, float], factor: float) -> dict[str, float]:
    """The intensity measures of a record scaled by ``factor`` [1], from the unscaled ones.

    Accelerations, velocities and displacements scale with the factor, the Arias
    intensity with its square; times and durations do not change.
    """
    powers = {"pga": 1, "pgv": 1, "pgd": 1, "rms_acceleration": 1, "arias_intensity": 2}
    return {name: value * factor ** powers.get(name, 0) for name, value in measures.items()}


def fill_cube(records: Sequence[Record], layout: CubeLayout,
              solve_batch: Callable[[list[Record]], np.ndarray], *, batched: bool = True,
              measures: Sequence[Mapping[str, float]] | None = None, progress: bool = False) -> xr.Dataset:
    """The cube of ``records`` (acceleration in m/s²): every version of each at every grid value.

    Parameters
    ----------
    records:
        The ground motions; their ``meta.record_id`` label the ``record`` dimension (duplicates are an error).
    layout:
        What the cube holds (:class:`CubeLayout`).
    solve_batch:
        The model's solver: a list of record versions -> their end results,
        shape (versions, grid values, variables) in the units of ``layout.variables``.
    batched:
        Whether ``solve_batch`` is a batched kernel: then batches of records
        of about :data:`BATCH_WORK` updates are solved together, else one record at a time.
    measures:
        The intensity measures of each unscaled record (as
        :meth:`stickslip.measures.IntensityMeasures.as_dict`, computed with the
        layout's ``g``), when they are already known; those of scaled versions
        follow from :func:`scaled_measures`.  Default: computed here.
    progress:
        Show a progress bar over the records, when stderr is a terminal.

    A cube whose memory estimate exceeds :func:`stickslip.limits.memory_limit`,
    or whose results are not finite, raises :class:`StickslipError`.
    """
    records = list(records)
    if not records:
        raise StickslipError("a sweep needs at least one record")
    if measures is not None and len(measures) != len(records):
        raise StickslipError(f"{len(measures)} sets of measures given for {len(records)} records")
    ids = _record_ids(records)
    grid, names = layout.grid, list(layout.variables)
    per_record = layout.versions_per_record
    check_memory(
        len(records) * per_record * grid.values.size * len(names) * 8 * 4,  # output, stack, variables, netCDF copy
        f"a sweep of {len(records)} record(s) x {per_record} scaling(s) x {grid.values.size:,} "
        f"{grid.coefficient.plural}",
    )
    values, case_measures, factors = [], [], []
    show = progress and sys.stderr.isatty()
    with tqdm(total=len(records), desc="sweep", unit="record", disable=not show, file=sys.stderr) as bar:
        for batch in _record_batches(records, per_record * grid.values.size, batched):
            versions = [layout.versions(records[index]) for index in batch]
            solved = solve_batch([version for record_versions in versions for version in record_versions])
            for position, index in enumerate(batch):
                record, record_versions = records[index], versions[position]
                values.append(solved[position * per_record:(position + 1) * per_record])
                largest = np.max(np.abs(values[-1]), axis=(0, 1))  # NaN or inf wherever any case has one
                checked_finite_results(dict(zip(names, map(float, largest))), f"{record_name(record)} (sweep)")
                record_factors = [peak_ground_acceleration(version) / peak_ground_acceleration(record)
                                  for version in record_versions]
                if measures is None:
                    case_measures.append([intensity_measures(version, g=layout.g).as_dict()
                                          for version in record_versions])
                else:
                    case_measures.append([scaled_measures(measures[index], factor) for factor in record_factors])
                factors.append(record_factors)
            bar.update(len(batch))
    descriptions = [{name: getattr(record.meta, name) for name in DESCRIPTION_COORDS} for record in records]
    return _assemble_cube(ids, descriptions, ["ok"] * len(ids), np.stack(values), case_measures, factors, layout)


def missing_cube(record_id: str, status: str, layout: CubeLayout) -> xr.Dataset:
    """The cube of a record that could not be swept, with the ``layout`` its sweep would give it.

    Every value is NaN (``n_slip_episodes``: -1) and the ``status`` coordinate
    holds ``status`` (``"missing: <how to obtain the record>"``), so that studies
    gather available and missing records alike and every table can name what it
    could not include.
    """
    n_versions = layout.versions_per_record
    values = np.full((1, n_versions, layout.grid.values.size, len(layout.variables)), np.nan)
    nan_measures = [[dict.fromkeys(MEASURE_ATTRS, np.nan)] * n_versions]
    descriptions = [dict.fromkeys(DESCRIPTION_COORDS, "")]
    return _assemble_cube([record_id], descriptions, [status], values, nan_measures, [[np.nan] * n_versions], layout)


def available(cube: xr.Dataset) -> xr.Dataset:
    """The records of ``cube`` whose status is ``"ok"``."""
    return cube.isel(record=np.flatnonzero(cube.status.values == "ok"))


def missing_records(cube: xr.Dataset) -> dict[str, str]:
    """Record id -> status of the records of ``cube`` that could not be swept."""
    return {str(record): str(status) for record, status in zip(cube.record.values, cube.status.values) if status != "ok"}


def cube_grid(cube: xr.Dataset) -> Grid:
    """The :class:`~stickslip.grids.Grid` a cube of :func:`fill_cube` or :func:`missing_cube` was swept over."""
    name = grid_dimension(cube.dims)
    return Grid(name, cube[name].values)


def gather(cubes: Sequence[xr.Dataset]) -> xr.Dataset:
    """Per-record (or per-chunk) cubes of one grid joined along ``record``, in the given order."""
    import xarray as xr

    if not cubes:
        raise StickslipError("nothing to gather: no cubes given")
    _record_ids_unique([str(record) for cube in cubes for record in cube.record.values])
    cube = xr.concat(cubes, dim="record", data_vars="minimal", coords="minimal", compat="override",
                     combine_attrs="override")
    for variable in cube.variables.values():
        variable.encoding = {}  # the first file's encoding (a string width, say) need not fit the others
    return cube


def with_grid_values(cube: xr.Dataset, extra: xr.Dataset) -> xr.Dataset:
    """``cube`` and ``extra``, the same records swept with the same block over other values of the grid's coefficient,
    as one cube over all the values in order (the records' coordinates and the attributes are ``cube``'s)."""
    import xarray as xr

    name = grid_dimension(cube.dims)
    joined = xr.concat([cube, extra], dim=name, data_vars="minimal", coords="minimal", compat="override",
                       combine_attrs="override").sortby(name)
    for variable in joined.variables.values():
        variable.encoding = {}  # a stored cube's encoding (a string width, say) need not fit the values added
    return joined


def _assemble_cube(ids, descriptions, statuses, stacked, case_measures, factors, layout: CubeLayout) -> xr.Dataset:
    """The cube from the end results ``stacked`` (record, version, grid, variable) and the records' descriptions."""
    import xarray as xr

    grid, scale, target_pga = layout.grid, layout.scale, layout.target_pga
    scaled = scale is not None or target_pga is not None
    scaling_dim = "scale" if scale is not None else "target_pga"
    dims = ("record", scaling_dim, grid.name) if scaled else ("record", grid.name)
    case_dims = dims[:-1]
    if not scaled:
        stacked = stacked[:, 0]
    data_vars = {}
    for k, (name, attrs) in enumerate(layout.variables.items()):
        data = stacked[..., k]
        if name in layout.counts:  # an integer, -1 where unknown
            data = np.where(np.isnan(data), -1, np.rint(data)).astype(np.int64)
        data_vars[name] = xr.Variable(dims, data, attrs=attrs)

    coords = {
        "record": xr.Variable("record", np.array(ids, dtype=object), attrs={"long_name": "record identifier"}),
        grid.name: xr.Variable(grid.name, grid.values, attrs=GRID_ATTRS[grid.name]),
        "status": xr.Variable("record", np.array(statuses, dtype=object),
                              attrs={"long_name": "ok, or why the record could not be swept"}),
    }
    for name, (values, attrs) in layout.grid_coords.items():
        coords[name] = xr.Variable(grid.name, values, attrs=attrs)
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
    return xr.Dataset(data_vars, coords=coords, attrs=layout.attrs)


def read_cube(path: str | Path) -> xr.Dataset:
    """A cube written by :func:`write_cube`, loaded into memory (the file is closed again)."""
    import xarray as xr

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
