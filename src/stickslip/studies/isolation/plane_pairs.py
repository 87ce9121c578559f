"""The isolated building in the plane on the SLAMMER library's station pairs, against each component alone.

The one-story building of :mod:`stickslip.studies.isolation.with_vertical` (its T, R and μ: the settings'
``vertical`` part) under both horizontal components of each of the planar study's station pairs at once (the
pair padded as :func:`~stickslip.studies.planar.sweep.record_pair` pads it), by the isolated model's integrated
scheme (DOP853 to 1e-10); the library has no vertical, so N = W.  The answers are the plane's vector magnitudes
(:data:`ANSWERS`).  Against each component alone in one direction (the per-component study's ``isolation.nc``,
solved exactly, at the same T, R and μ): per pair, the plane's peak isolator displacement, drift and floor
acceleration over the larger of its two components' (:data:`COMPARED`).

Steps of ``workflow/rules/isolation.smk``: :func:`write_plane_pair_chunk_cube`, one job per share of the pairs
(the ``vertical`` part's ``chunks``, shared by their samples: :func:`pair_shares`) and period;
:func:`write_plane_pair_tables` gathers them (``isolation_plane_pairs.nc``: pair × period × radius × mu),
writes one row per pair, T, R and μ (``isolation_plane_pairs.csv``, with the pair's rupture distance and whether
it is near-fault) and the statistics of the ratios over the pairs, near-fault, far-field and all
(``isolation_plane_pairs_summary.csv``).  Without the library there is no chunk and the tables are empty.
"""

from __future__ import annotations

import math
import time
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np
import xarray as xr

from stickslip.collections.store import read_record_store
from stickslip.plumbing.files import read_csv_rows, write_csv_atomic
from stickslip.studies.isolation.near_far import distance_group
from stickslip.studies.isolation.sweep import building_attrs, gather_isolation_study, grid_coordinates
from stickslip.studies.isolation.tables import statistics
from stickslip.studies.isolation.with_vertical import ANSWERS as VERTICAL_ANSWERS
from stickslip.studies.isolation.with_vertical import solved_answers, vertical_settings
from stickslip.sweeps import read_cube, write_cube

#: The answers in the plane without the vertical (no lift-off): name -> (units, long name).
ANSWERS = {name: value for name, value in VERTICAL_ANSWERS.items() if name != "liftoff_time"}
#: The answers compared with the per-component study's, each the same quantity in one direction there.
COMPARED = ("peak_isolator_displacement", "peak_drift", "peak_floor_acceleration")
#: The groups of pairs of the summary by their rupture distance (``all``: every pair).
GROUPS = ("near-fault", "far-field", "all")
#: A pair's group in the tables, by its :func:`~stickslip.studies.isolation.near_far.distance_group` ("": unknown).
GROUP_NAMES = {"near": "near-fault", "far": "far-field", "unknown": ""}

ROW_FIELDS = ["pair", "first", "second", "rupture_distance", "distance_group", "period", "radius", "mu", *ANSWERS,
              *(f"{name}_{side}" for name in COMPARED for side in ("first", "second")),
              *(f"{name}_ratio" for name in COMPARED)]
SUMMARY_FIELDS = ["period", "radius", "mu", "group", "quantity", "pairs", "median", "p16", "p84"]


def pair_shares(rows: Sequence[Mapping], count: int) -> list[list[Mapping]]:
    """The rows of ``pairs.csv`` whose two records were read (status ``ok``) in ``count`` shares of about as many
    samples each (a pair's padded length; the longest first into the share of fewest samples so far), each share
    in the file's order."""
    found = [row for row in rows if row["status"] == "ok"]
    lengths = [max(int(row["npts_first"]), int(row["npts_second"])) for row in found]
    shares: list[list[int]] = [[] for _ in range(count)]
    loads = [0] * count
    for index in sorted(range(len(found)), key=lambda item: -lengths[item]):
        lightest = loads.index(min(loads))
        shares[lightest].append(index)
        loads[lightest] += lengths[index]
    return [[found[index] for index in sorted(share)] for share in shares]


def share_pairs(pairs_path: str | Path, store_paths: Sequence[str | Path], share: int,
                count: int) -> list[tuple[Mapping, object]]:
    """(the row of ``pairs.csv``, the padded :class:`~stickslip.records.pair.RecordPair`) of each pair of share
    ``share`` of ``count`` (:func:`pair_shares`)."""
    from stickslip.studies.planar.sweep import record_pair

    rows = pair_shares(read_csv_rows(pairs_path), count)[share]
    if not rows:
        return []
    stored = {item.record_id: item for path in store_paths for item in read_record_store(path)}
    return [(row, record_pair(row, stored)) for row in rows]


def plane_pair_cube(pairs: Sequence[tuple[Mapping, object]], settings: Mapping, period: float,
                    g: float) -> xr.Dataset:
    """Every pair of ``pairs`` (:func:`share_pairs`) in the plane at the fixed-base period ``period`` [s] and every
    R × μ of ``settings``' ``vertical`` part (:func:`~stickslip.studies.isolation.with_vertical.vertical_settings`),
    gravity ``g`` [m/s²]."""
    grid = vertical_settings(settings)
    radii, mu = grid["radii"], grid["mu"]
    values = {name: np.full((len(pairs), 1, radii.size, mu.size), np.nan) for name in ANSWERS}
    for i, (row, pair) in enumerate(pairs):
        started = time.perf_counter()
        for r, radius in enumerate(radii):
            for m, value in enumerate(mu):
                found = solved_answers(pair, period, radius, value, grid["mass_ratio"], grid["damping_ratio"], g)
                for name in ANSWERS:
                    values[name][i, 0, r, m] = found[name]
        print(f"{row['pair']}, T = {period:g} s: {radii.size} R x {mu.size} mu, {pair.first.npts} samples, in "
              f"{time.perf_counter() - started:.2f} s", flush=True)
    dims = ("record", "period", "radius", "mu")
    distances = [float(row["rupture_distance"]) if row["rupture_distance"] else math.nan for row, _ in pairs]
    return xr.Dataset(
        {name: (dims, values[name], {"units": units, "long_name": text}) for name, (units, text) in ANSWERS.items()},
        coords={"record": ("record", np.asarray([row["pair"] for row, _ in pairs], dtype=object),
                           {"long_name": "station pair (event/station)"}),
                "first": ("record", np.asarray([row["first"] for row, _ in pairs], dtype=object),
                          {"long_name": "the first component's record id"}),
                "second": ("record", np.asarray([row["second"] for row, _ in pairs], dtype=object),
                           {"long_name": "the second component's record id"}),
                "rupture_distance": ("record", np.asarray(distances, dtype=float),
                                     {"units": "km", "long_name": "closest distance to the rupture (NaN: not known)"}),
                **grid_coordinates(period, radii, mu)},
        attrs={"title": "a one-story building on friction pendulums in the plane on the SLAMMER library's pairs",
               "scheme": "integrated (DOP853, rtol 1e-10), no vertical", **building_attrs(grid, g)})


def write_plane_pair_chunk_cube(pairs_path: str | Path, store_paths: Sequence[str | Path], cube_path: str | Path,
                                chunk: int, settings: Mapping, period: float, g: float) -> Path:
    """The cube of the pairs of share ``chunk`` of the settings' ``vertical`` ``chunks`` (:func:`pair_shares`) at
    ``period`` [s]."""
    pairs = share_pairs(pairs_path, store_paths, int(chunk), vertical_settings(settings)["chunks"])
    return write_cube(plane_pair_cube(pairs, settings, period, g), cube_path)


def _alone(components, record: str, period: float, radius: float, mu: float, name: str) -> float:
    """``name`` of the component ``record`` alone at (T, R, μ) in the per-component study's cube, NaN where the
    cube has not that component or that cell."""
    if components is None or record not in components.indexes["record"]:
        return math.nan
    try:
        return float(components[name].sel(record=record, period=period, radius=radius, mu=mu))
    except KeyError:
        return math.nan


def pair_rows(cube, components, near_fault_km: float) -> list[dict]:
    """One row per pair, T, R and μ of the gathered cube (:data:`ROW_FIELDS`): the plane's answers, each of
    :data:`COMPARED` of each component alone (``components``, the per-component study's cube, or None) and the
    plane's over the larger of the two."""
    rows = []
    for i, pair in enumerate(cube.record.values):
        distance = float(cube.rupture_distance.values[i])
        first, second = str(cube["first"].values[i]), str(cube["second"].values[i])
        group = GROUP_NAMES[distance_group(distance, near_fault_km)]
        for period in cube.period.values:
            for radius in cube.radius.values:
                for mu in cube.mu.values:
                    cell = cube.isel(record=i).sel(period=period, radius=radius, mu=mu)
                    row = {"pair": str(pair), "first": first, "second": second, "rupture_distance": distance,
                           "distance_group": group, "period": float(period), "radius": float(radius),
                           "mu": float(mu),
                           **{name: float(cell[name]) for name in ANSWERS}}
                    for name in COMPARED:
                        alone = [_alone(components, record, period, radius, mu, name) for record in (first, second)]
                        row[f"{name}_first"], row[f"{name}_second"] = alone
                        with np.errstate(divide="ignore", invalid="ignore"):
                            row[f"{name}_ratio"] = float(np.float64(row[name]) / np.max(alone))
                    rows.append(row)
    return rows


def summary_rows(rows: Sequence[Mapping]) -> list[dict]:
    """Per T, R, μ, group of :data:`GROUPS` and ratio of :data:`COMPARED`: the number of pairs with a finite ratio,
    the median and the 16th and 84th percentiles
    (:func:`~stickslip.studies.isolation.tables.statistics`)."""
    cells: dict[tuple, list[Mapping]] = {}
    for row in rows:
        cells.setdefault((row["period"], row["radius"], row["mu"]), []).append(row)
    found = []
    for (period, radius, mu), members in sorted(cells.items()):
        for group in GROUPS:
            chosen = [row for row in members if group == "all" or row["distance_group"] == group]
            for name in COMPARED:
                counted = statistics([row[f"{name}_ratio"] for row in chosen])
                found.append({"period": period, "radius": radius, "mu": mu, "group": group,
                              "quantity": f"{name}_ratio", "pairs": counted.pop("records"), **counted})
    return found


def write_plane_pair_tables(cube_paths: Sequence[str | Path], components_path: str | Path,
                            study_path: str | Path, rows_path: str | Path, summary_path: str | Path, periods: int,
                            near_fault_km: float) -> list[str]:
    """The jobs' cubes gathered (each group of ``periods`` consecutive ones the periods of one share of pairs) into
    ``isolation_plane_pairs.nc``, the rows per pair against the per-component study's cube ``components_path`` and
    their statistics (CSV); without a cube (no library) an empty cube and tables with their header only."""
    if cube_paths:
        gather_isolation_study(cube_paths, study_path, periods)
        rows = pair_rows(read_cube(study_path), read_cube(components_path), near_fault_km)
    else:
        write_cube(xr.Dataset(attrs={"title": "no SLAMMER library: no station pair"}), study_path)
        rows = []
    write_csv_atomic(rows_path, rows, ROW_FIELDS)
    write_csv_atomic(summary_path, summary_rows(rows), SUMMARY_FIELDS)
    return [str(Path(path)) for path in (study_path, rows_path, summary_path)]
