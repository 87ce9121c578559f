"""Harmonic base motion: E_df of the shaking-table cases under each reading of "u_g0 = 30 mm" (the paper's Table 4).

The paper gives m = 5.10 kg, μ = 0.10 and "u_g0 = 30 mm" at 2 Hz and 1 Hz
for 5 s and 15 s, but says neither whether 30 mm is the amplitude or the
stroke (peak to peak, amplitude 15 mm) nor how the motion was ramped up.
:func:`write_harmonic_energies` solves (exact solver) every case of the
configuration's ``harmonic.cases`` under every combination of
``displacement_amplitudes`` [m] and ``ramp_cycles`` and writes
``harmonic_energy.csv`` (E_df [J] per case and reading).
:func:`write_harmonic_comparison` sets it beside the paper's model column:

- ``table4_readings.csv``: each reading's E_df, the paper's value, the relative
  difference, and the RMS relative difference of the reading over the cases;
- ``table4_comparison.csv``: the best reading (smallest RMS relative
  difference) against the paper, cell by cell.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from stickslip.plumbing.files import read_csv_rows, write_csv_atomic
from stickslip.reference import paper_tables
from stickslip.solvers.harmonic import harmonic_record
from stickslip.studies.compare import compare_cells, relative_difference, write_comparison
from stickslip.models import sweep


def energy_rows(settings: dict, mass: float, g: float) -> list[dict]:
    """E_df [J] of every harmonic case under every (amplitude, ramp) reading."""
    rows = []
    for amplitude in settings["displacement_amplitudes"]:
        for ramp in settings["ramp_cycles"]:
            for case in settings["cases"]:
                record = harmonic_record(amplitude, case["frequency"], case["duration"], settings["dt"], ramp)
                cube = sweep([record], mu=[settings["mu"]], mass=mass, g=g)
                rows.append({"reading": f"amplitude {amplitude * 1e3:g} mm, ramp {ramp:g} cycles",
                             "displacement_amplitude": amplitude, "ramp_cycles": ramp, "row": case["name"],
                             "frequency": case["frequency"], "duration": case["duration"], "mu": settings["mu"],
                             "energy_dissipated": float(cube.energy_dissipated.item())})
    return rows


def reading_rows(energy_rows: list[dict[str, str]]) -> list[dict]:
    """The energies beside the paper's model column, with each reading's RMS relative difference."""
    paper = {row["name"]: row for row in paper_tables()["table4_harmonic_model"]["rows"]}
    rows = []
    for row in energy_rows:
        printed = paper.get(row["row"], {}).get("energy_dissipated")
        ours = float(row["energy_dissipated"])
        rows.append({**row, "energy_dissipated": ours, "paper_energy_dissipated": printed if printed else "",
                     "relative_difference": relative_difference(ours, printed) if printed else float("nan")})
    for reading in dict.fromkeys(row["reading"] for row in rows):
        mine = [row for row in rows if row["reading"] == reading]
        rms = float(np.sqrt(np.nanmean([row["relative_difference"] ** 2 for row in mine])))
        for row in mine:
            row["reading_rms_relative_difference"] = rms
    return rows


def write_harmonic_energies(energy_path: str | Path, settings: dict, mass: float, g: float) -> Path:
    """``harmonic_energy.csv``: E_df [J] of every case and reading (block mass [kg], gravity [m/s²])."""
    return write_csv_atomic(energy_path, energy_rows(settings, mass, g))


def write_harmonic_comparison(energy_path, readings_path, comparison_path, tolerances: dict) -> list[Path]:
    """``table4_readings.csv`` and ``table4_comparison.csv`` from ``harmonic_energy.csv``."""
    rows = reading_rows(read_csv_rows(energy_path))
    best = min(rows, key=lambda row: row["reading_rms_relative_difference"])["reading"]
    ours = {row["row"]: row for row in rows if row["reading"] == best}
    paper = {row["name"]: row for row in paper_tables()["table4_harmonic_model"]["rows"]}
    cells = compare_cells("table4", ours, paper, ["energy_dissipated"], tolerances,
                          notes={"energy_dissipated": f"best reading: {best}"})
    return [write_csv_atomic(readings_path, rows), write_comparison(comparison_path, cells)]
