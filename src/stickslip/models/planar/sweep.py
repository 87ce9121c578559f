"""Sweeps of record pairs over friction ratios: the block in the plane beside each component alone, and turned.

:func:`planar_cube` (the planar model's ``sweep``) solves, for every :class:`~stickslip.records.pair.RecordPair`
and friction ratio μ, the block sliding in the plane under both components
(:mod:`stickslip.solvers.plane`) and the 1-D block (the exact solver)
under each component alone, into one :class:`xarray.Dataset` with dimensions
``pair``, ``direction`` (``plane``, ``first``, ``second``) and ``mu``.  With
``angles`` it also turns the pair's axes through the given azimuths and solves
the 1-D block on the first turned axis at each: the RotD idea of ground-motion
intensity (Boore 2010) applied to the block's response.  Per pair and μ it
keeps the largest and the median over the azimuths (``*_rotd100``,
``*_rotd50``), and per pair and azimuth the μ of largest dissipation.

Energies are in J for the given block mass, lengths in m.  The per-pair
results of the optimum on the grid (μ_max, E_df,max, the stroke there) are
added by :func:`planar_optimum`; the design answer, refined as a record's, is
:mod:`stickslip.models.planar.design`'s.
"""

from __future__ import annotations

import sys
from collections.abc import Sequence

from typing import TYPE_CHECKING

import numpy as np
from tqdm import tqdm

from stickslip.analysis import grid_maximum_index
from stickslip.checks import checked_positive
from stickslip.constants import DEFAULT_BLOCK_MASS, STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.grids import positive_increasing
from stickslip.plumbing.files import provenance
from stickslip.records.pair import RecordPair, turned_axes
from stickslip.units import CF_CONVENTIONS

if TYPE_CHECKING:
    import xarray as xr

#: The directions of a cube: both components at once, and each alone.
DIRECTIONS = ("plane", "first", "second")

#: The cube's response variables: units and long names.
VARIABLES = {
    "energy_dissipated": ("J", "energy dissipated by friction E_df at the end of the record"),
    "energy_input": ("J", "absolute input energy E_I at the end of the record"),
    "kinetic_energy_final": ("J", "absolute kinetic energy E_k at the end of the record"),
    "peak_displacement": ("m", "largest distance of the block from its start, relative to the base"),
    "residual_displacement": ("m", "distance of the block from its start at the end of the record"),
    "sliding_path": ("m", "length of the path slid"),
    "slip_fraction": ("1", "fraction of the record duration spent sliding"),
    "n_slip_episodes": ("1", "number of stick-to-slip transitions"),
}

#: Where each variable is in the planar kernel's scalars (per unit mass).
_PLANAR_COLUMNS = {"energy_dissipated": 0, "energy_input": 1, "kinetic_energy_final": 2, "peak_displacement": 5,
                   "sliding_path": 6, "slip_fraction": 7, "n_slip_episodes": 8}
#: The 1-D block's variables a cube holds for each component alone (absolute values for lengths).
_LINE_NAMES = ("energy_dissipated", "energy_input", "kinetic_energy_final", "residual_displacement",
               "peak_displacement", "sliding_path", "slip_fraction", "n_slip_episodes")
_ENERGIES = ("energy_dissipated", "energy_input", "kinetic_energy_final")

#: Pairs per call of the parallel planar kernel (a progress step).
PAIRS_PER_BATCH = 8


def azimuths(angle_step: float) -> np.ndarray:
    """The azimuths [degrees] a pair is turned through: 0 to 180 (excluded) by ``angle_step``, and 90 always.

    0 and 90 are the pair's own axes, so the turned 1-D block's largest response
    over the azimuths is never below either component's.
    """
    return np.union1d(np.arange(0.0, 180.0, float(angle_step)), [90.0])


def plane_scalars(pairs: Sequence[RecordPair], mu, g: float, rtol: float | None = None,
                  axes: list | None = None) -> np.ndarray:
    """The planar kernel's scalars, shape (pairs, mu, 9), per unit mass, at the friction ratios ``mu`` [1].

    ``axes`` are each pair's :meth:`~stickslip.records.pair.RecordPair.horizontal` when already known;
    ``rtol`` the integration's relative tolerance (default 1e-10).
    """
    from stickslip.models.planar.solver import sweep_pairs
    from stickslip.solvers import plane

    mu = np.asarray(mu, dtype=float)
    rtol = plane.RTOL if rtol is None else checked_positive(rtol, "relative tolerance rtol")
    axes = [pair.horizontal() for pair in pairs] if axes is None else axes
    sizes = np.array([pair.npts for pair in pairs], dtype=np.int64)
    offsets = np.concatenate([[0], np.cumsum(sizes)])
    out = np.empty((len(pairs), mu.size, len(plane.PLANAR_SCALAR_NAMES)))
    stalled_at = sweep_pairs(np.concatenate([first for first, _ in axes]),
                             np.concatenate([second for _, second in axes]), offsets,
                             np.array([pair.dt for pair in pairs]), mu * g, rtol, plane.LOCK_RATIO, out)
    plane.check_progress(stalled_at, lambda index: f"{pairs[index[0]].name}, mu = {mu[index[1]]:g}")
    return out


def _line_results(accelerations: list[np.ndarray], dts: list[float], mu: np.ndarray, g: float,
                  mass: float) -> dict[str, np.ndarray]:
    """The rigid block's :data:`_LINE_NAMES` on each acceleration [m/s²] alone, each of shape (records, mu).

    Energies in J for ``mass`` [kg], lengths in m (absolute values): the rigid model's default scheme, its
    batched kernel (:meth:`stickslip.models.rigid.scheme.RigidScheme.sweep`).
    """
    from stickslip.models.rigid import RIGID
    from stickslip.records.record import Record

    case = RIGID.case(RIGID.checked({"mu": float(mu[0]), "g": g, "mass": mass}))
    found = RIGID.scheme().sweep([Record(a, dt) for a, dt in zip(accelerations, dts)], case, "mu", mu)
    found["peak_displacement"] = found.pop("peak_relative_displacement")
    return {name: found[name] if name in _ENERGIES else np.abs(found[name]) for name in _LINE_NAMES}


def components_alone(pair: RecordPair, mu: float, mass: float = DEFAULT_BLOCK_MASS,
                     g: float = STANDARD_GRAVITY) -> dict[str, dict[str, float]]:
    """The 1-D block on each axis of ``pair`` alone at one friction ratio ``mu`` [1]: ``{"first": {...}, "second": ...}``.

    The variables of :data:`VARIABLES` (units there; energies for ``mass`` [kg]), as a cube's ``first``
    and ``second`` directions hold them.
    """
    line = _line_results(list(pair.horizontal()), [pair.dt, pair.dt], np.array([float(mu)]), g, mass)
    return {direction: {name: float(line[name][row, 0]) for name in _LINE_NAMES}
            for row, direction in enumerate(("first", "second"))}


def _fill_plane(values: dict, index: tuple, scalars: np.ndarray, mass: float) -> None:
    """Copy the planar kernel's scalars (…, mu, columns) into ``values`` at ``index`` (energies times ``mass``)."""
    for name, column in _PLANAR_COLUMNS.items():
        data = scalars[..., column]
        values[name][index] = data * mass if name in _ENERGIES else np.abs(data)


def planar_cube(pairs: Sequence[RecordPair], mu, mass: float = DEFAULT_BLOCK_MASS, g: float = STANDARD_GRAVITY,
                angles=None, rtol: float | None = None, progress: bool = True) -> xr.Dataset:
    """Solve every pair at every friction ratio: in the plane, each component alone, and (``angles``) turned.

    Parameters
    ----------
    pairs:
        The record pairs (:class:`~stickslip.records.pair.RecordPair`; their
        components resolved onto orthogonal axes).
    mu:
        Friction ratios μ [1], positive and increasing.
    mass, g:
        Block mass [kg] and gravity [m/s²].
    angles:
        Azimuths [degrees] by which to turn the axes for the 1-D block on the
        turned first axis (e.g. :func:`azimuths` ``(5)``); none by default.
    rtol:
        The planar integration's relative tolerance (default 1e-10).
    progress:
        A progress bar on standard error when it is a terminal.
    """
    from stickslip.solvers.plane import RTOL

    if not pairs:
        raise StickslipError("a planar sweep needs at least one record pair")
    mu = positive_increasing(mu, "friction ratios mu")
    mass = checked_positive(mass, "block mass [kg]")
    g = checked_positive(g, "gravity g [m/s2]")
    rtol = RTOL if rtol is None else checked_positive(rtol, "relative tolerance rtol")
    turns = None if angles is None else np.asarray(list(angles), dtype=float)
    if turns is not None and (turns.size == 0 or not np.all(np.isfinite(turns))):
        raise StickslipError(f"angles: expected finite azimuths in degrees, got {angles!r}")
    shape = (len(pairs), len(DIRECTIONS), mu.size)
    values = {name: np.full(shape, np.nan) for name in VARIABLES}
    azimuth = {name: np.full((len(pairs), turns.size, mu.size), np.nan)
               for name in ("energy_dissipated", "peak_displacement")} if turns is not None else {}
    show = progress and sys.stderr.isatty()
    with tqdm(total=len(pairs), desc="planar sweep", unit="pair", disable=not show, file=sys.stderr) as bar:
        for start in range(0, len(pairs), PAIRS_PER_BATCH):
            batch = list(range(start, min(start + PAIRS_PER_BATCH, len(pairs))))
            chosen = [pairs[index] for index in batch]
            axes = [pair.horizontal() for pair in chosen]
            plane = plane_scalars(chosen, mu, g, rtol, axes)
            _fill_plane(values, (batch, 0), plane, mass)
            values["residual_displacement"][batch, 0] = np.hypot(plane[..., 3], plane[..., 4])
            dts = [pair.dt for pair in chosen]
            for direction in (1, 2):
                line = _line_results([axis[direction - 1] for axis in axes], dts, mu, g, mass)
                for name in _LINE_NAMES:
                    values[name][batch, direction] = line[name]
            if turns is not None:
                for column, angle in enumerate(turns):
                    turned = [turned_axes(first, second, angle)[0] for first, second in axes]
                    line = _line_results(turned, dts, mu, g, mass)
                    for name in azimuth:
                        azimuth[name][batch, column] = line[name]
            bar.update(len(batch))
    return _cube(pairs, mu, values, turns, azimuth, mass, g, rtol)


def _pair_coordinates(pairs: Sequence[RecordPair]) -> dict:
    """Coordinates along ``pair``: the components, event, station, separation and peak accelerations."""
    def meta(pair: RecordPair, field: str) -> str:
        return getattr(pair.first.meta, field) or getattr(pair.second.meta, field)

    axes = [pair.horizontal() for pair in pairs]
    return {
        "first_component": ("pair", [pair.first.meta.component or pair.first.meta.record_id for pair in pairs],
                            {"long_name": "the first component (axis 1)"}),
        "second_component": ("pair", [pair.second.meta.component or pair.second.meta.record_id for pair in pairs],
                             {"long_name": "the second component (axis 2 is a quarter turn from axis 1 towards it)"}),
        "event": ("pair", [meta(pair, "event") for pair in pairs], {"long_name": "earthquake"}),
        "station": ("pair", [meta(pair, "station") for pair in pairs], {"long_name": "recording station"}),
        "separation": ("pair", [pair.separation for pair in pairs],
                       {"units": "degree", "long_name": "angle from the first component to the second"}),
        "dt": ("pair", [pair.dt for pair in pairs], {"units": "s", "long_name": "time step"}),
        "pga_first": ("pair", [float(np.max(np.abs(first))) for first, _ in axes],
                      {"units": "m s-2", "long_name": "peak ground acceleration along axis 1"}),
        "pga_second": ("pair", [float(np.max(np.abs(second))) for _, second in axes],
                       {"units": "m s-2", "long_name": "peak ground acceleration along axis 2"}),
        "pga_plane": ("pair", [float(np.max(np.hypot(first, second))) for first, second in axes],
                      {"units": "m s-2", "long_name": "peak magnitude of the horizontal ground acceleration vector"}),
    }


def _cube(pairs, mu, values, turns, azimuth, mass, g, rtol) -> xr.Dataset:
    """The sweep's dataset, with units, coordinates and provenance (xarray imported here: ``solve --pair``, which
    needs :func:`components_alone` only, starts without it)."""
    import xarray as xr

    balance = values["kinetic_energy_final"] + values["energy_dissipated"] - values["energy_input"]
    cube = xr.Dataset(
        {name: (("pair", "direction", "mu"), data, {"units": VARIABLES[name][0], "long_name": VARIABLES[name][1]})
         for name, data in values.items()},
        coords={"pair": ("pair", [pair.name for pair in pairs]), "direction": ("direction", list(DIRECTIONS), {
                    "long_name": "plane: both components at once; first, second: that component alone (1-D)"}),
                "mu": ("mu", mu, {"units": "1", "long_name": "friction ratio"}), **_pair_coordinates(pairs)},
    )
    cube["balance_residual"] = (("pair", "direction", "mu"), balance, {
        "units": "J", "long_name": "E_k - E_k(0) + E_df - E_I at the end of the record (the ledger; E_k(0) = 0)"})
    if turns is not None:
        cube = cube.assign_coords(angle=("angle", turns, {"units": "degree",
                                                          "long_name": "turn of the axes, from axis 1 towards axis 2"}))
        for name, data in azimuth.items():
            units = VARIABLES[name][0]
            cube[f"{name}_rotd100"] = (("pair", "mu"), np.max(data, axis=1), {
                "units": units, "long_name": f"largest over the azimuths of the 1-D {name.replace('_', ' ')}"})
            cube[f"{name}_rotd50"] = (("pair", "mu"), np.median(data, axis=1), {
                "units": units, "long_name": f"median over the azimuths of the 1-D {name.replace('_', ' ')}"})
        best = grid_maximum_index(azimuth["energy_dissipated"])
        cube["mu_max_azimuth"] = (("pair", "angle"), np.where(best >= 0, mu[np.maximum(best, 0)], np.nan),
                                  {"units": "1", "long_name": "friction ratio of largest 1-D E_df at each azimuth"})
        cube["energy_dissipated_max_azimuth"] = (("pair", "angle"), np.nanmax(azimuth["energy_dissipated"], axis=2),
                                                 {"units": "J", "long_name": "largest 1-D E_df at each azimuth"})
    cube.attrs.update(Conventions=CF_CONVENTIONS, model="planar", mass=mass, g=g, rtol=rtol,
                      method="exact (planar: DOP853 in three regimes; 1-D: event-driven)", **provenance())
    return planar_optimum(cube)


def planar_optimum(cube: xr.Dataset) -> xr.Dataset:
    """``cube`` with, per pair and direction, μ_max on the grid, E_df,max [J] and the stroke there [m].

    ``mu_max``: the grid μ of largest E_df (ties: the smallest); NaN for a
    curve that never slides.  ``peak_displacement_at_mu_max`` and
    ``residual_displacement_at_mu_max``: the block's largest and final
    distance from its start at μ_max.
    """
    energy = cube["energy_dissipated"].values
    best = grid_maximum_index(np.where(energy > 0.0, energy, np.nan))
    found = best >= 0
    index = np.maximum(best, 0)
    mu = cube["mu"].values

    def at_best(name: str) -> np.ndarray:
        return np.where(found, np.take_along_axis(cube[name].values, index[..., None], axis=-1)[..., 0], np.nan)

    return cube.assign(
        mu_max=(("pair", "direction"), np.where(found, mu[index], np.nan),
                {"units": "1", "long_name": "friction ratio of largest dissipated energy on the grid"}),
        energy_dissipated_max=(("pair", "direction"), np.where(found, at_best("energy_dissipated"), 0.0),
                               {"units": "J", "long_name": "largest dissipated energy on the grid"}),
        peak_displacement_at_mu_max=(("pair", "direction"), at_best("peak_displacement"),
                                     {"units": "m", "long_name": "largest distance from the start at mu_max"}),
        residual_displacement_at_mu_max=(("pair", "direction"), at_best("residual_displacement"),
                                         {"units": "m", "long_name": "distance from the start at the end, at mu_max"}),
    )
