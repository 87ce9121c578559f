"""Study ``mass``: the dissipated energy per unit mass E_df/m does not depend on the block mass.

The mass cancels from the equation of motion (Eq. 1) and E_df = μ·m·g·(path),
so E_df/m against μ must be the same for every mass: the paper's remark that
the shape and maxima of its Fig. 21 do not change with the vertical load.
The sweep stage computes ``mass_study.records`` on the fine μ grid for each of
``mass_study.masses`` [kg] (the gathered cube ``results/sweeps/mass.nc``, over
mass, record and μ); :func:`write_mass_check` writes ``mass_check.csv``: per
record, the largest relative spread of E_df/m [J/kg] across the masses, μ_max
for each mass, and whether they agree.

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
from stickslip.plumbing.files import write_csv_atomic
from stickslip.sweeps import available, missing_records, read_cube

#: Relative spread of E_df/m across masses accepted as "the same" (round-off).
SAME_TOLERANCE = 1e-12

#: What the check shows, written beside it.
CHECK_NOTE = ("solvers work per unit mass: this checks the sweep's handling of m; "
              "the physical check (m in the model) is the OpenSees test")


def check_rows(cube: xr.Dataset) -> list[dict]:
    """Per record: relative spread of E_df/m across masses and μ_max for each mass."""
    missing = missing_records(cube)
    cube = available(cube)
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


def write_mass_check(cube_path, check_path) -> Path:
    """``mass_check.csv`` from the gathered mass cube."""
    return write_csv_atomic(check_path, check_rows(read_cube(cube_path)))
