"""Study ``table4``: the harmonic rows of the paper's Table 4 (model column), under each reading of "u_g0 = 30 mm".

The paper gives m = 5.10 kg, μ = 0.10 and "u_g0 = 30 mm" at 2 Hz and 1 Hz
for 5 s and 15 s, but says neither whether 30 mm is the amplitude or the
stroke (peak to peak, amplitude 15 mm) nor how the motion was ramped up.
This study solves (exact solver) every combination of
``table4.displacement_amplitudes`` [m] and ``table4.ramp_cycles`` and writes
under ``out_dir``:

- ``tables/table4_readings.csv``: E_df [J] per row and reading, the paper's
  model value, the relative difference, and the RMS relative difference of
  each reading over the four rows;
- ``tables/table4_comparison.csv``: the best reading (smallest RMS relative
  difference) against the paper, cell by cell.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from stickslip.constants import PAPER_BLOCK_MASS, STANDARD_GRAVITY
from stickslip.io import write_csv_atomic
from stickslip.reference import paper_tables
from stickslip.solvers.harmonic import harmonic_record
from stickslip.studies.compare import compare_cells, relative_difference, write_comparison
from stickslip.sweeps import sweep


def reading_rows(settings: dict, mass: float, g: float) -> list[dict]:
    """E_df [J] of every paper row under every (amplitude, ramp) reading."""
    rows = []
    for amplitude in settings["displacement_amplitudes"]:
        for ramp in settings["ramp_cycles"]:
            for paper in paper_tables()["table4_harmonic_model"]["rows"]:
                record = harmonic_record(amplitude, paper["frequency"], paper["duration"], settings["dt"], ramp)
                cube = sweep([record], [settings["mu"]], mass=mass, g=g)
                ours = float(cube.energy_dissipated.item())
                rows.append({"reading": f"amplitude {amplitude * 1e3:g} mm, ramp {ramp:g} cycles",
                             "displacement_amplitude": amplitude, "ramp_cycles": ramp, "row": paper["name"],
                             "frequency": paper["frequency"], "duration": paper["duration"],
                             "energy_dissipated": ours, "paper_energy_dissipated": paper["energy_dissipated"],
                             "relative_difference": relative_difference(ours, paper["energy_dissipated"])})
    for reading in {row["reading"] for row in rows}:
        mine = [row for row in rows if row["reading"] == reading]
        rms = float(np.sqrt(np.mean([row["relative_difference"] ** 2 for row in mine])))
        for row in mine:
            row["reading_rms_relative_difference"] = rms
    return rows


def run(config: dict, out_dir: Path) -> list[Path]:
    """Run the harmonic readings; write the tables under ``out_dir``; return their paths."""
    out_dir = Path(out_dir)
    rows = reading_rows(config["table4"], config.get("block_mass", PAPER_BLOCK_MASS),
                        config.get("gravity", STANDARD_GRAVITY))
    best = min(rows, key=lambda row: row["reading_rms_relative_difference"])["reading"]
    ours = {row["row"]: row for row in rows if row["reading"] == best}
    paper = {row["name"]: row for row in paper_tables()["table4_harmonic_model"]["rows"]}
    cells = compare_cells("table4", ours, paper, ["energy_dissipated"], config["comparison_tolerance"],
                          notes={"energy_dissipated": f"best reading: {best}"})
    tables = out_dir / "tables"
    return [
        write_csv_atomic(tables / "table4_readings.csv", rows),
        write_comparison(tables / "table4_comparison.csv", cells),
    ]
