"""Study ``mass``: the dissipated energy per unit mass E_df/m does not depend on the block mass.

The mass cancels from the equation of motion (Eq. 1) and E_df = μ·m·g·(path),
so E_df/m against μ must be the same for every mass: the paper's remark that
the shape and maxima of its Fig. 21 do not change with the vertical load.
Sweeps ``mass_study.records`` on the fine μ grid of ``table6.fine_mu`` for each
of ``mass_study.masses`` [kg] and writes under ``out_dir``:

- ``sweeps/mass.nc``: the cube over (mass, record, μ);
- ``tables/mass_check.csv``: per record, the largest relative spread of
  E_df/m [J/kg] across the masses, μ_max for each mass, and whether they agree.

stickslip's solvers work per unit mass, so this study checks how the sweep
carries the mass through (energies scale with m, nothing else does), not the
physics: for that, ``tests/test_opensees_oracle.py`` solves the block in
OpenSees, where m enters the model, for m = 1, 5.1 and 50 kg.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from stickslip.analysis import mu_max_on_grid
from stickslip.constants import STANDARD_GRAVITY
from stickslip.io import write_csv_atomic
from stickslip.studies.records import load_study_records
from stickslip.studies.table6 import fine_grid
from stickslip.sweeps import sweep, write_cube

#: Relative spread of E_df/m across masses accepted as "the same" (round-off).
SAME_TOLERANCE = 1e-12

#: What the check shows, written beside it.
CHECK_NOTE = ("solvers work per unit mass: this checks the sweep's handling of m; "
              "the physical check (m in the model) is the OpenSees test")


def mass_cube(records: list, mu, masses, g: float) -> xr.Dataset:
    """Sweeps for each mass [kg], stacked along a ``mass`` dimension."""
    cubes = [sweep(records, mu, mass=mass, g=g, config={"study": "mass"}) for mass in masses]
    cube = xr.concat(cubes, dim=xr.Variable("mass", np.asarray(masses, dtype=float),
                                           attrs={"units": "kg", "long_name": "block mass"}),
                     combine_attrs="drop_conflicts")
    cube["energy_dissipated_per_mass"] = (cube.energy_dissipated / cube.mass).assign_attrs(
        units="J kg-1", long_name="energy dissipated by friction per unit block mass")
    return cube


def check_rows(cube: xr.Dataset, missing: dict) -> list[dict]:
    """Per record: relative spread of E_df/m across masses and μ_max for each mass."""
    per_mass = cube.energy_dissipated_per_mass
    spread = (per_mass.max("mass") - per_mass.min("mass")) / np.abs(per_mass).max("mass")
    rows = []
    for record_id in cube.record.values:
        largest = float(spread.sel(record=record_id).max())
        mu_max = mu_max_on_grid(per_mass.sel(record=record_id)).values
        rows.append({"record": record_id, "masses": " ".join(f"{m:g}" for m in cube.mass.values),
                     "max_relative_spread": largest, "mu_max_per_mass": " ".join(f"{m:g}" for m in mu_max),
                     "tolerance": SAME_TOLERANCE,
                     "status": "same" if largest <= SAME_TOLERANCE and np.all(mu_max == mu_max[0]) else "DIFFERENT",
                     "note": CHECK_NOTE})
    rows += [{"record": record_id, "status": status} for record_id, status in missing.items()]
    return rows


def run(config: dict, out_dir: Path) -> list[Path]:
    """Run the mass study; write the cube and the check under ``out_dir``; return their paths."""
    out_dir = Path(out_dir)
    settings = config["mass_study"]
    records, missing = load_study_records(config, list(settings["records"]))
    cube = mass_cube(list(records.values()), fine_grid(config["table6"]["fine_mu"]), settings["masses"],
                     config.get("gravity", STANDARD_GRAVITY))
    return [
        write_cube(cube, out_dir / "sweeps" / "mass.nc"),
        write_csv_atomic(out_dir / "tables" / "mass_check.csv", check_rows(cube, missing)),
    ]
