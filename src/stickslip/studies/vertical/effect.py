"""How much the vertical ground motion changes a slider's and a pendulum's response: the study's tables.

From the study's cube (:mod:`stickslip.studies.vertical.sweep`), one row per
station, direction, radius R [m] and vertical variant (:func:`case_rows`):
μ_max (maximised continuously) [1], E_df,max [J], and at the grid's μ_max and at
the reference μ the displacement demand (largest |u|) [m], the residual
displacement [m] and the peak base shear coefficient V/W [1]; the time the
slider spent lifted off (g + a_v ≤ 0) [s].

The vertical's effect (:func:`change_rows`): each variant with the vertical
(``recorded``, ``reversed``) against the same case without it (``none``):
ratios of E_df,max, of the displacement demand and of V/W [1], and differences
of μ_max [1] and of the residual displacement [m]. A ratio whose denominator
is zero (a case without sliding) is left empty.  Over the stations
(:func:`summary_rows`): the median, the smallest and the largest of each, per
direction (and over the directions), radius and variant.  Lift-off per station (:func:`liftoff_rows`):
it depends on the vertical alone, not on the direction, radius or μ.
"""

from __future__ import annotations

import json
import math
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from stickslip.plumbing.files import provenance, write_csv_atomic, write_text_atomic
from stickslip.studies.vertical.records import missing_message
from stickslip.units import UNITS

#: The responses of a case, as :func:`case_rows` names them: column -> (where the cube holds it: ``"optimum"`` per
#: station, ``"reference"`` at the reference μ; its variable).  Units: :data:`stickslip.units.UNITS`.
CASE_SOURCES = {
    "mu_max": ("optimum", "mu_max_continuous"),
    "mu_max_at_grid_edge": ("optimum", "mu_max_at_grid_edge"),
    "energy_dissipated_max": ("optimum", "energy_dissipated_max_continuous"),
    "peak_relative_displacement_at_mu_max": ("optimum", "peak_relative_displacement_at_mu_max"),
    "residual_displacement_at_mu_max": ("optimum", "residual_displacement_at_mu_max"),
    "peak_base_shear_at_mu_max": ("optimum", "peak_base_shear_at_mu_max"),
    "energy_dissipated_reference": ("reference", "energy_dissipated"),
    "peak_relative_displacement_at_reference": ("reference", "peak_relative_displacement"),
    "residual_displacement_at_reference": ("reference", "residual_displacement"),
    "peak_base_shear_at_reference": ("reference", "peak_base_shear"),
    "liftoff_time": ("reference", "liftoff_time"),
    "vertical_down_peak": ("optimum", "vertical_down_peak"),
    "vertical_pga": ("optimum", "vertical_pga"),
}
CASE_COLUMNS = tuple(CASE_SOURCES)

#: The vertical's effect: column -> (how: "ratio" or "difference", the case column it compares); units: UNITS.
CHANGES = {
    "energy_ratio": ("ratio", "energy_dissipated_max"),
    "mu_max_change": ("difference", "mu_max"),
    "peak_displacement_ratio": ("ratio", "peak_relative_displacement_at_mu_max"),
    "residual_displacement_change": ("difference", "residual_displacement_at_mu_max"),
    "base_shear_ratio": ("ratio", "peak_base_shear_at_mu_max"),
    "energy_ratio_at_reference": ("ratio", "energy_dissipated_reference"),
    "peak_displacement_ratio_at_reference": ("ratio", "peak_relative_displacement_at_reference"),
    "residual_displacement_change_at_reference": ("difference", "residual_displacement_at_reference"),
    "base_shear_ratio_at_reference": ("ratio", "peak_base_shear_at_reference"),
}

#: What identifies a case, beside its vertical variant.
KEYS = ("direction", "radius", "record")

CASE_FIELDS = [*KEYS[:2], "vertical", KEYS[2], "vertical_sense", "optimum_status", *CASE_COLUMNS]
CHANGE_FIELDS = [*KEYS[:2], "vertical", KEYS[2], *CHANGES]
LIFTOFF_FIELDS = ["record", "vertical", "vertical_sense", "liftoff_time", "vertical_down_peak", "vertical_pga"]
SUMMARY_FIELDS = ["direction", "radius", "vertical", "quantity", "units", "records", "median", "min", "max"]


def case_rows(cube) -> list[dict]:
    """One row per direction, radius [m], vertical variant and station of the study's cube (:data:`CASE_COLUMNS`)."""
    reference = float(cube.attrs["reference_mu"])
    at_reference = cube.sel(mu=reference, method="nearest")
    if not math.isclose(float(at_reference.mu), reference, rel_tol=1e-9):
        raise ValueError(f"the reference mu {reference:g} is not on the study's grid")
    rows = []
    for direction in cube.direction.values:
        for radius in cube.radius.values:
            for variant in cube.vertical.values:
                where = {"direction": direction, "radius": radius, "vertical": variant}
                case = cube.sel(where)
                held = {"optimum": case, "reference": at_reference.sel(where)}
                columns = {name: held[at][variable].values for name, (at, variable) in CASE_SOURCES.items()}
                for index, record in enumerate(cube.record.values):
                    rows.append({"direction": str(direction), "radius": radius_text(radius), "vertical": str(variant),
                                 "record": str(record), "vertical_sense": str(case.vertical_sense.values[index]),
                                 "optimum_status": str(case.optimum_status.values[index]),
                                 **{name: float(values[index]) for name, values in columns.items()}})
    return rows


def radius_text(radius: float) -> str:
    """A radius [m] as JSON and tables write it: ``inf`` for the flat surface, else its number."""
    return "inf" if math.isinf(radius) else f"{float(radius):g}"


def compared(how: str, with_vertical: float, without: float) -> float:
    """``with_vertical`` over ``without`` (``"ratio"``; NaN where ``without`` is 0 or either NaN) or their difference."""
    if how == "difference":
        return with_vertical - without
    if without == 0.0 or math.isnan(without) or math.isnan(with_vertical):
        return math.nan
    return with_vertical / without


def change_rows(cases: Sequence[dict]) -> list[dict]:
    """Each case with the vertical against the same direction, radius and station without it (:data:`CHANGES`)."""
    without = {tuple(row[key] for key in KEYS): row for row in cases if row["vertical"] == "none"}
    rows = []
    for row in cases:
        if row["vertical"] == "none":
            continue
        base = without.get(tuple(row[key] for key in KEYS))
        if base is None:
            raise ValueError(f"no case without the vertical for {', '.join(str(row[key]) for key in KEYS)}")
        rows.append({**{key: row[key] for key in (*KEYS, "vertical")},
                     **{name: compared(how, float(row[column]), float(base[column]))
                        for name, (how, column) in CHANGES.items()}})
    return rows


#: The direction of the summary's rows that pool every direction.
ALL_DIRECTIONS = "all"


def summary_rows(changes: Sequence[dict]) -> list[dict]:
    """Per direction, radius and variant, each change's median, smallest and largest over the stations (NaN left out).

    Rows of direction :data:`ALL_DIRECTIONS` pool the directions (one value per station and direction).
    """
    groups: dict[tuple, list[dict]] = {}
    for row in changes:
        groups.setdefault((row["direction"], row["radius"], row["vertical"]), []).append(row)
    if len({row["direction"] for row in changes}) > 1:
        for row in changes:
            groups.setdefault((ALL_DIRECTIONS, row["radius"], row["vertical"]), []).append(row)
    rows = []
    for (direction, radius, variant), members in groups.items():
        for name in CHANGES:
            values = np.array([float(row[name]) for row in members])
            values = values[~np.isnan(values)]
            found = ({"median": float(np.median(values)), "min": float(values.min()), "max": float(values.max())}
                     if values.size else {"median": math.nan, "min": math.nan, "max": math.nan})
            rows.append({"direction": direction, "radius": radius, "vertical": variant, "quantity": name,
                         "units": UNITS[name], "records": int(values.size), **found})
    return rows


def liftoff_rows(cases: Sequence[dict]) -> list[dict]:
    """Per station and variant with the vertical: the time lifted off [s] and the vertical's peaks [g].

    Taken from the first direction and radius: lift-off (g + a_v ≤ 0) depends on the vertical alone.
    """
    first = (cases[0]["direction"], cases[0]["radius"]) if cases else None
    return [{key: row[key] for key in LIFTOFF_FIELDS} for row in cases
            if (row["direction"], row["radius"]) == first and row["vertical"] != "none"]


def write_vertical_tables(cases_path, changes_path, liftoff_path, summary_path, study_path, records_dir=None,
                          cube_path=None, inventory_path=None, settings=None) -> list[str]:
    """The study's tables (CSV) and its description (JSON); without a cube, empty tables and a page's sentence why.

    ``cube_path`` is the study's cube (:func:`stickslip.studies.vertical.sweep.gather_vertical_study`), None when
    the records were not available in ``records_dir``; ``inventory_path`` the acquisition's inventory.
    """
    import xarray as xr

    from stickslip.plumbing.files import read_csv_rows

    document = {"settings": dict(settings or {}), **provenance()}
    if cube_path is None:
        cases = []
        document.update(available=False, message=missing_message(records_dir))
    else:
        cube = xr.load_dataset(cube_path, engine="netcdf4")
        cases = case_rows(cube)
        inventory = read_csv_rows(inventory_path) if inventory_path else []
        document.update(
            available=True, stations=int(cube.sizes["record"]),
            directions=[str(value) for value in cube.direction.values],
            radii_m=[radius_text(value) for value in cube.radius.values],
            variants=[str(value) for value in cube.vertical.values],
            mu=[float(cube.mu.values[0]), float(cube.mu.values[-1]), int(cube.sizes["mu"])],
            reference_mu=float(cube.attrs["reference_mu"]), left_out=cube.attrs.get("left_out", ""),
            mu_max_tolerance=float(cube.attrs["mu_max_tolerance"]),
            grid_edge_cases=int(sum(row["mu_max_at_grid_edge"] == 1.0 for row in cases)),
            files_not_ok=[f"{row['file']}: {row['status']} ({row['reason']})" for row in inventory
                          if row["status"] != "ok"],
        )
    changes = change_rows(cases)
    write_csv_atomic(cases_path, cases, CASE_FIELDS)
    write_csv_atomic(changes_path, changes, CHANGE_FIELDS)
    write_csv_atomic(liftoff_path, liftoff_rows(cases), LIFTOFF_FIELDS)
    write_csv_atomic(summary_path, summary_rows(changes), SUMMARY_FIELDS)
    write_text_atomic(study_path, json.dumps(document, indent=2, default=str) + "\n")
    return [str(Path(path)) for path in (cases_path, changes_path, liftoff_path, summary_path, study_path)]
