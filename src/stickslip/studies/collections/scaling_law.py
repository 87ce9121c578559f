"""The scaling law of the sliding block, checked on records: E_df(k·μ; k·a) = k²·E_df(μ; a).

Scale a ground motion a(t) by k > 0 and the friction ratio by the same k:
the equation of motion ü = −a_g − μ·g·sign(u̇) (and the stick condition
|a_g| ≤ μ·g) is multiplied through by k, so the relative motion u(t) scales
by k, the friction force m·μ·g by k, and the energy dissipated
E_df = ∫ m·μ·g·|u̇| dt by k².  Hence the energy curve of the scaled record is
the original one stretched by k in μ and by k² in energy, and its maximum
sits at μ_max(k·a) = k·μ_max(a): **μ_max is exactly proportional to PGA for
a given record shape**, which is the trend of the paper's Table 8 (one record
scaled to four PGAs).

:func:`scaling_law_rows` checks it with the exact solver on stored records:
the largest relative difference between E_df(k·μ; k·a) and k²·E_df(μ; a)
over the grid, and the ratio μ_max(k·a) / (k·μ_max(a)) of the continuous
maxima.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from stickslip.collections.store import read_record_store
from stickslip.plumbing.files import write_csv_atomic
from stickslip.records.process import scale as scale_record
from stickslip.models.rigid import RIGID
from stickslip.optimum import refine_mu_max
from stickslip.grids import Grid, grid_values

#: Records of the store the law is checked on (the first ones that could be read and slide on the grid).
RECORDS_CHECKED = 5

#: Columns of the law's table.
COLUMNS = ["record", "factor", "max_relative_energy_difference", "mu_max", "mu_max_scaled", "mu_max_ratio"]


def scaling_law_rows(store_path: str | Path, mu, factors: list[float], g: float) -> list[dict]:
    """One row per (record, factor k): the largest relative energy difference and the μ_max ratio.

    A record that never slides on the grid (E_df = 0 at every μ: no μ_max) is
    passed over; the law is checked on the first :data:`RECORDS_CHECKED` others.
    """
    grid = Grid("mu", grid_values(mu))
    records = (row.record for row in read_record_store(store_path) if row.record is not None)
    rows = []
    checked = 0
    for record in records:
        design = RIGID.design(grid, mass=1.0, g=g)
        energy = design.curves([record])["energy_dissipated"][0]
        if not energy.any():
            continue
        checked += 1
        if checked > RECORDS_CHECKED:
            break
        mu_max = refine_mu_max(record, design, energy).argument
        for factor in factors:
            scaled = scale_record(record, factor)
            scaled_design = design.with_values(factor * grid.values)
            scaled_energy = scaled_design.curves([scaled])["energy_dissipated"][0]
            expected = factor ** 2 * energy
            moving = expected > 0
            difference = np.abs(scaled_energy[moving] - expected[moving]) / expected[moving]
            scaled_mu_max = refine_mu_max(scaled, scaled_design, scaled_energy).argument
            rows.append({"record": str(record.meta.record_id), "factor": factor,
                         "max_relative_energy_difference": float(difference.max()) if difference.size else 0.0,
                         "mu_max": mu_max, "mu_max_scaled": scaled_mu_max,
                         "mu_max_ratio": scaled_mu_max / (factor * mu_max)})
    return rows


def write_scaling_law(store_path: str | Path, law_path: str | Path, mu, factors: list[float], g: float) -> Path:
    """:func:`scaling_law_rows` written as CSV to ``law_path``."""
    return write_csv_atomic(law_path, scaling_law_rows(store_path, mu, factors, g), COLUMNS)
