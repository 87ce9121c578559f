"""The codes' equivalent-linear displacement against the exact one, per station, direction, R, μ and code.

Two kinds of job write the same table (:data:`CASE_COLUMNS`, one row per
station × direction × vertical × R × μ × code):

- :func:`write_pair_chunk_cases`, one per chunk of the planar study's station
  pairs (``pairs.csv``, the collection's record stores): each pair's two
  components alone (``first``, ``second``) and both in the plane, without a
  vertical (the library has none);
- :func:`write_three_component_cases`, the fifteen three-component stations
  (the vertical study's store) in ``H1``, ``H2`` and the plane, without the
  vertical (``none``) and with it as recorded (``recorded``).

Each row sets the code's D (:func:`~stickslip.studies.code_vs_exact.displacement.code_displacement`,
on the record's own 5 % spectrum: the component's in one direction, RotD100
in the plane) beside the pendulum's exact peak |u| [m]
(:func:`~stickslip.studies.code_vs_exact.displacement.exact_displacements`).  A
motion's spectrum is computed once, on the grid ``periods``, for every R, μ
and code.
"""

from __future__ import annotations

import math
import time
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np

from stickslip.collections.store import read_record_store
from stickslip.plumbing.files import read_csv_rows, write_csv_atomic
from stickslip.studies.code_vs_exact.displacement import CODES, code_displacement, exact_displacements, \
    motion_displacement_spectra
from stickslip.studies.planar.sweep import record_pair

#: Columns of the case tables (units in docs/studies.md): D in m, T_eff in s.
CASE_COLUMNS = ("library", "station", "direction", "component", "vertical", "rupture_distance", "pulse", "radius",
                "mu", "code", "d_exact", "d_code", "t_eff", "beta_eff", "damping_reduction", "ln_ratio",
                "d_code_over_r", "method", "note")

#: The spectrum of each direction: a component's own, or the pair's RotD100 in the plane.
SPECTRUM_OF = {"first": "first", "second": "second", "plane": "rotd100"}

#: What the case tables say of a record's pulse: neither the SLAMMER library's database nor the three-component
#: manifest classifies its records as pulse-like or not.
PULSE_UNKNOWN = "unknown"


def station_cases(stations: Sequence[Mapping], radii: Sequence[float], mu: Sequence[float], g: float,
                  periods) -> list[dict]:
    """The case rows of ``stations``, each a mapping with ``library``, ``station``, ``rupture_distance`` [km] (NaN
    when not known), ``pair`` (its :class:`~stickslip.records.pair.RecordPair`) and ``motions``:
    {(direction, vertical): motion} with direction ``first``, ``second`` or ``plane``."""
    if not stations:
        return []
    spectra = [motion_displacement_spectra(station["pair"], periods) for station in stations]
    groups = sorted({key for station in stations for key in station["motions"]})
    exact = {}
    for key in groups:
        members = [index for index, station in enumerate(stations) if key in station["motions"]]
        started = time.perf_counter()
        values = exact_displacements([stations[index]["motions"][key] for index in members], radii, mu, g)
        exact.update({(index, *key): row for index, row in zip(members, values)})
        print(f"{key[0]}, vertical {key[1]}: {len(members)} stations x {len(radii)} R x {len(mu)} mu in "
              f"{time.perf_counter() - started:.1f} s", flush=True)
    started = time.perf_counter()
    rows, designs = [], {}
    for (index, direction, vertical), peaks in exact.items():
        station = stations[index]
        component = {"first": station["pair"].first, "second": station["pair"].second}.get(direction)
        for (r, radius), (m, friction), code in _cases(radii, mu):
            key = (index, direction, radius, friction, code)
            if key not in designs:
                designs[key] = code_displacement(code, periods, spectra[index][SPECTRUM_OF[direction]], radius,
                                                 friction, g)
            design, d_exact = designs[key], float(peaks[r, m])
            ratio = d_exact / design.displacement if d_exact > 0.0 else math.nan
            rows.append({"library": station["library"], "station": station["station"], "direction": direction,
                         "component": component.meta.component if component is not None else "plane",
                         "vertical": vertical, "rupture_distance": station["rupture_distance"],
                         "pulse": PULSE_UNKNOWN, "radius": radius, "mu": friction, "code": code, "d_exact": d_exact,
                         "d_code": design.displacement, "t_eff": design.period, "beta_eff": design.damping,
                         "damping_reduction": design.reduction, "ln_ratio": math.log(ratio) if ratio > 0 else math.nan,
                         "d_code_over_r": design.displacement / radius, "method": design.method,
                         "note": design.note})
    print(f"{len(designs)} code fixed points in {time.perf_counter() - started:.1f} s", flush=True)
    return rows


def _cases(radii, mu):
    """(index, R), (index, μ), code over the grid."""
    for r, radius in enumerate(radii):
        for m, friction in enumerate(mu):
            for code in CODES:
                yield (r, float(radius)), (m, float(friction)), code


def write_pair_chunk_cases(pairs_path: str | Path, store_paths: Sequence[str | Path], cases_path: str | Path,
                           chunk: str, radii, mu, periods: Mapping, g: float) -> Path:
    """The case table of the chunk's station pairs that were read (``pairs.csv``'s status ``ok``)."""
    rows = [row for row in read_csv_rows(pairs_path) if row["chunk"] == chunk and row["status"] == "ok"]
    stored = {item.record_id: item for path in store_paths for item in read_record_store(path)}
    stations = []
    for row in rows:
        pair = record_pair(row, stored)
        distance = float(row["rupture_distance"]) if row["rupture_distance"] else math.nan
        stations.append({"library": "slammer", "station": row["pair"], "rupture_distance": distance, "pair": pair,
                         "motions": {("first", "none"): pair.first, ("second", "none"): pair.second,
                                     ("plane", "none"): pair}})
    cases = station_cases(stations, radii, mu, g, period_grid(periods))
    return write_csv_atomic(cases_path, cases, list(CASE_COLUMNS))


def write_three_component_cases(cases_path: str | Path, radii, mu, periods: Mapping, g: float,
                                untold_positive: str, store_path: str | Path | None = None) -> Path:
    """The case table of the three-component stations stored ``ok`` in ``store_path`` (none without one)."""
    from stickslip.studies.vertical.records import station_motion, stations as stored_stations

    found = stored_stations(store_path)[0] if store_path else {}
    named = {"first": "H1", "second": "H2", "plane": "plane"}
    stations = [{"library": "three_component", "station": name, "rupture_distance": math.nan,
                 "pair": station_motion(station, "plane", "none", untold_positive),
                 "motions": {(direction, vertical): station_motion(station, named[direction], vertical,
                                                                   untold_positive)
                             for direction in named for vertical in ("none", "recorded")}}
                for name, station in found.items()]
    cases = station_cases(stations, radii, mu, g, period_grid(periods))
    return write_csv_atomic(cases_path, cases, list(CASE_COLUMNS))


def period_grid(periods: Mapping) -> np.ndarray:
    """The spectrum's periods [s]: ``count`` log-spaced from ``shortest`` to ``longest``."""
    return np.geomspace(float(periods["shortest"]), float(periods["longest"]), int(periods["count"]))
