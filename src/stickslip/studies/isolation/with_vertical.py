"""The isolated building in the plane on the three-component stations, with and without the vertical.

The one-story building of :mod:`stickslip.studies.isolation.response` (fixed-base period T [s], m_s/m_b,
damping ratio ζ) on a friction pendulum of radius R [m] and Coulomb friction μ [1], under both horizontal
components of a station at once (``H1`` and ``H2`` as a pair, the shorter padded with zeros), solved twice by the
isolated model's integrated scheme (DOP853 to a relative tolerance of 1e-10, ``stickslip.solve(...,
method="integrated")``): without the vertical (N = W) and with it (N = W·(1 + a_v/g), lift-off where N
vanishes; the vertical's sense read from its PEER label, or ``untold_positive`` where the label does not tell,
as :func:`~stickslip.studies.vertical.records.station_motion` takes it).  The same scheme both times, so that the
only difference is the vertical.

The answers (:data:`ANSWERS`) are the plane's: vector magnitudes over the samples.  Per station, T, R and μ,
the ratio with / without the vertical of each but the lift-off time (:data:`RATIOS`; 0 without the vertical).

Steps of ``workflow/rules/isolation.smk``: :func:`write_vertical_chunk_cube`, one job per period and chunk of
stations (:func:`station_chunks`: the manifest's stations shared by their number of samples), an empty cube
without the records; :func:`write_vertical_tables` gathers them (``isolation_vertical.nc``: record × period ×
radius × mu × vertical) and writes the ratios per station (``isolation_vertical_ratios.csv``) and their
statistics over the stations (``isolation_vertical_summary.csv``).
"""

from __future__ import annotations

import time
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np
import xarray as xr

from stickslip.errors import StickslipError
from stickslip.grids import grid_values, positive_increasing
from stickslip.plumbing.files import write_csv_atomic
from stickslip.studies.isolation.response import TOTAL_MASS
from stickslip.studies.isolation.sweep import building_attrs, gather_isolation_study, grid_coordinates
from stickslip.studies.isolation.tables import statistics
from stickslip.sweeps import read_cube, write_cube

#: The answers in the plane, each a result's scalar: name -> (units, long name).
ANSWERS = {
    "peak_isolator_displacement": ("m", "peak |isolator displacement vector u_b| relative to the ground"),
    "peak_drift": ("m", "peak |story drift vector|"),
    "peak_floor_acceleration": ("m s-2", "peak |absolute floor acceleration vector|"),
    "base_shear_coefficient": ("1", "peak |isolator force vector| over the weight, V_b/W"),
    "energy_dissipated": ("J", "energy dissipated by friction E_df at the end of the record, building of 1 kg"),
    "liftoff_time": ("s", "total time the isolator is lifted off its surface (N <= 0)"),
}
#: The answers compared with / without the vertical (the lift-off time is 0 without it).
RATIOS = tuple(name for name in ANSWERS if name != "liftoff_time")
#: The two motions of a station: its horizontal pair alone, and with its vertical.
VERTICAL = ("without", "with")
#: The station variants of :func:`~stickslip.studies.vertical.records.station_motion`, per entry of :data:`VERTICAL`.
VARIANTS = {"without": "none", "with": "recorded"}

RATIO_FIELDS = ["station", "period", "radius", "mu", *(f"{name}_{which}" for name in ANSWERS for which in VERTICAL
                                                       if (name, which) != ("liftoff_time", "without")),
                *(f"{name}_ratio" for name in RATIOS)]
SUMMARY_FIELDS = ["period", "radius", "mu", "quantity", "stations", "median", "p16", "p84"]


def vertical_settings(settings: Mapping) -> dict:
    """``isolation_study``'s ``vertical`` part checked, as arrays: periods T [s], radii R [m], mu [1], the number
    of chunks of stations; with the building's mass ratio and damping ratio of ``settings``."""
    part = settings["vertical"]
    chunks = part["chunks"]
    if not (isinstance(chunks, int) and chunks >= 1):
        raise StickslipError(f"isolation_study.vertical.chunks must be a whole number of at least 1, got {chunks!r}")
    return {"periods": positive_increasing(part["periods"], "isolation_study.vertical.periods"),
            "radii": positive_increasing(part["radii"], "isolation_study.vertical.radii"),
            "mu": grid_values(part["mu"], "isolation_study.vertical.mu"), "chunks": chunks,
            "mass_ratio": float(settings["mass_ratio"]), "damping_ratio": float(settings["damping_ratio"])}


def station_chunks(count: int) -> list[list[str]]:
    """The manifest's stations in ``count`` chunks of about as many samples each (the largest station first into
    the chunk of fewest samples so far), each chunk in the manifest's order."""
    from stickslip.studies.vertical.records import manifest_rows

    samples: dict[str, int] = {}
    for row in manifest_rows():
        if row["component"] == "H1":
            samples[row["set"]] = int(row["npts"])
    order = list(samples)
    chunks: list[list[str]] = [[] for _ in range(count)]
    loads = [0] * count
    for name in sorted(order, key=lambda item: -samples[item]):
        lightest = loads.index(min(loads))
        chunks[lightest].append(name)
        loads[lightest] += samples[name]
    return [sorted(chunk, key=order.index) for chunk in chunks]


def solved_answers(motion, period: float, radius: float, mu: float, mass_ratio: float, damping_ratio: float,
                   g: float) -> dict[str, float]:
    """:data:`ANSWERS` of the one-story building on ``motion`` (a pair, or a pair with its vertical), solved by the
    integrated scheme: fixed-base period ``period`` [s], radius ``radius`` [m], friction ``mu`` [1], m_s/m_b
    ``mass_ratio``, damping ratio ``damping_ratio`` [1], gravity ``g`` [m/s²]; E_df of a building of
    :data:`~stickslip.studies.isolation.response.TOTAL_MASS`."""
    from stickslip.models import solve

    scalars = solve(motion, model="isolated", method="integrated", superstructure_period=period, stories=1,
                    mass_ratio=mass_ratio, superstructure_damping=damping_ratio, radius=radius, mu=mu,
                    mass=TOTAL_MASS, g=g).scalars()
    return {name: float(scalars[name]) for name in ANSWERS}


def vertical_cube(stations: Mapping[str, Mapping], settings: Mapping, period: float, g: float,
                  untold_positive: str | None) -> xr.Dataset:
    """Every station of ``stations`` (set -> its ``H1``, ``H2`` and ``UP`` records) at the fixed-base period
    ``period`` [s] and every R × μ of ``settings`` (:func:`vertical_settings`), without and with the vertical."""
    from stickslip.studies.vertical.records import station_motion

    grid = vertical_settings(settings)
    radii, mu = grid["radii"], grid["mu"]
    values = {name: np.full((len(stations), 1, radii.size, mu.size, len(VERTICAL)), np.nan) for name in ANSWERS}
    for i, (name, station) in enumerate(stations.items()):
        started = time.perf_counter()
        for v, which in enumerate(VERTICAL):
            motion = station_motion(station, "plane", VARIANTS[which], untold_positive)
            for r, radius in enumerate(radii):
                for m, value in enumerate(mu):
                    found = solved_answers(motion, period, radius, value, grid["mass_ratio"], grid["damping_ratio"],
                                           g)
                    for answer, number in found.items():
                        values[answer][i, 0, r, m, v] = number
        print(f"{name}, T = {period:g} s: {radii.size} R x {mu.size} mu x {len(VERTICAL)} in "
              f"{time.perf_counter() - started:.2f} s", flush=True)
    dims = ("record", "period", "radius", "mu", "vertical")
    return xr.Dataset(
        {name: (dims, values[name], {"units": units, "long_name": text}) for name, (units, text) in ANSWERS.items()},
        coords={"record": ("record", np.asarray(list(stations), dtype=object),
                           {"long_name": "three-component station (set)"}),
                **grid_coordinates(period, radii, mu),
                "vertical": ("vertical", np.asarray(VERTICAL, dtype=object),
                             {"long_name": "the horizontal pair alone, or with the station's vertical"})},
        attrs={"title": "a one-story building on friction pendulums in the plane, with and without the vertical",
               "scheme": "integrated (DOP853, rtol 1e-10) both times",
               "untold_vertical_positive": untold_positive or "", **building_attrs(grid, g)})


def write_vertical_chunk_cube(cube_path: str | Path, settings: Mapping, period: float, g: float, chunk: int,
                              untold_positive: str | None, store_path: str | Path | None = None) -> Path:
    """The cube of the stations of chunk ``chunk`` (:func:`station_chunks`) stored ``ok`` in ``store_path`` at
    ``period`` [s] (no station without a store); the chunk's stations left out, with why, in ``left_out``."""
    from stickslip.studies.vertical.records import stations

    names = station_chunks(vertical_settings(settings)["chunks"])[int(chunk)]
    found, left_out = stations(store_path) if store_path is not None else ({}, {})
    cube = vertical_cube({name: found[name] for name in names if name in found}, settings, period, g,
                         untold_positive)
    cube.attrs["left_out"] = "; ".join(f"{name}: {why}" for name, why in left_out.items() if name in names)
    return write_cube(cube, cube_path)


def ratio_rows(cube) -> list[dict]:
    """One row per station, T, R and μ of the gathered cube (:data:`RATIO_FIELDS`): each answer without and with the
    vertical, and the ratios with / without."""
    rows = []
    for station in cube.record.values:
        for period in cube.period.values:
            for radius in cube.radius.values:
                for mu in cube.mu.values:
                    cell = cube.sel(record=station, period=period, radius=radius, mu=mu)
                    row = {"station": str(station), "period": float(period), "radius": float(radius), "mu": float(mu)}
                    for name in ANSWERS:
                        for which in VERTICAL:
                            if (name, which) != ("liftoff_time", "without"):
                                row[f"{name}_{which}"] = float(cell[name].sel(vertical=which))
                    with np.errstate(divide="ignore", invalid="ignore"):
                        for name in RATIOS:
                            row[f"{name}_ratio"] = float(np.float64(row[f"{name}_with"]) / row[f"{name}_without"])
                    rows.append(row)
    return rows


def summary_rows(rows: Sequence[Mapping]) -> list[dict]:
    """Per T, R, μ and ratio (and the lift-off time with the vertical [s]): the median and the 16th and 84th
    percentiles over the stations (:func:`~stickslip.studies.isolation.tables.statistics`)."""
    cells: dict[tuple, list[Mapping]] = {}
    for row in rows:
        cells.setdefault((row["period"], row["radius"], row["mu"]), []).append(row)
    found = []
    for (period, radius, mu), members in sorted(cells.items()):
        for quantity in (*(f"{name}_ratio" for name in RATIOS), "liftoff_time_with"):
            counted = statistics([row[quantity] for row in members])
            found.append({"period": period, "radius": radius, "mu": mu, "quantity": quantity,
                          "stations": counted.pop("records"), **counted})
    return found


def write_vertical_tables(cube_paths: Sequence[str | Path], study_path: str | Path, ratios_path: str | Path,
                          summary_path: str | Path, periods: int) -> list[str]:
    """The jobs' cubes gathered (each group of ``periods`` consecutive ones the periods of one chunk of stations)
    into ``isolation_vertical.nc``, the ratios per station and their statistics over the stations (CSV)."""
    gather_isolation_study(cube_paths, study_path, periods)
    rows = ratio_rows(read_cube(study_path))
    write_csv_atomic(ratios_path, rows, RATIO_FIELDS)
    write_csv_atomic(summary_path, summary_rows(rows), SUMMARY_FIELDS)
    return [str(Path(path)) for path in (study_path, ratios_path, summary_path)]
