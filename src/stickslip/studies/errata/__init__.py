"""Errata of the paper, each found by a computed check (``results/tables/errata.csv``).

One row per check: its id, what it tests, the value found and what it is
compared with (with units), the finding in words, a ``status`` and the
comparison cells a confirmed erratum explains (``explains``, ``table.column``
names, ``;``-separated).  Status is ``confirmed`` (the paper is wrong as
printed), ``not confirmed``, ``unresolved`` (the paper's data allow no
single answer) or ``missing: …`` (an input record is missing).

- **E1** Table 6's RMS column [m/s²] equals the first eight values of Table 4's
  model column [J], cell by cell, in printed order.
- **E2** The energy balance E_k + E_df = E_I with E_k = ½·m·u̇ as printed
  (Eqs. 14 and 17) against ½·m·u̇², on a solved case: the largest
  |E_k − E_k(0) + E_df − E_I| over the record, relative to the largest E_I.
  One row for the harmonic case and one for the seismic case.
- **E3** Table 8's RMS [m/s²] divided by its own scale factors (one record:
  the ratio must be constant), and its unscaled RMS against Table 6's Mendoza RMS.
- **E4** The two readings of Table 4's "u_g0 = 30 mm" (amplitude 30 mm, or a
  30 mm stroke = 15 mm amplitude) against Table 4's harmonic model column, per
  frequency, from ``table4_readings.csv``, with the closed-form f_f (Eq. 3).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from stickslip.plumbing.files import read_csv_rows, write_csv_atomic
from stickslip.reference import paper_tables
from stickslip.solvers.harmonic import normalized_friction

#: |printed − printed| below which two printed 3-decimal values are equal.
PRINTED_EQUAL = 5e-4
#: Largest relative balance residual that counts as closed (round-off of the exact solver).
BALANCE_CLOSED = 1e-6
#: Largest relative spread of RMS/scale factor that counts as one record's scaling (printed to 3 decimals).
SCALING_SPREAD = 0.005
#: Relative RMS difference of a reading over its rows that counts as a fit (Table 4's 10 % tolerance).
READING_FITS = 0.10

FIELDS = ["check", "description", "quantity", "value", "compared_with", "units", "finding", "status", "explains"]


def table6_rms_repeats_table4() -> dict:
    """E1: Table 6's printed RMS column against Table 4's model column (both from paper.yaml)."""
    reference = paper_tables()
    rms = [row["rms_acceleration"] for row in reference["table6_results"]["rows"].values()]
    model = [row["energy_dissipated"] for row in reference["table4_rows"]["rows"]][: len(rms)]
    largest = float(np.max(np.abs(np.subtract(rms, model))))
    equal = int(np.sum(np.abs(np.subtract(rms, model)) < PRINTED_EQUAL))
    text = reference["table6_results"]["text_values"]["chichi_chy080n"]["rms_acceleration"]
    confirmed = equal == len(rms)
    return {"check": "E1", "description": "Table 6's RMS column against the first rows of Table 4's model column",
            "quantity": "largest |Table 6 RMS - Table 4 model E_df| (printed numbers)", "value": largest,
            "compared_with": 0.0, "units": "1",
            "finding": f"{equal} of {len(rms)} cells equal; the text's Chi Chi RMS ({text} m/s2) is not Table 6's "
                       f"({reference['table6_results']['rows']['chichi_chy080n']['rms_acceleration']} m/s2)",
            "status": "confirmed" if confirmed else "not confirmed",
            "explains": "table6.rms_acceleration" if confirmed else ""}


def balance_closure(response_path, case: str) -> dict:
    """E2 on one stored response (:mod:`stickslip.studies.model_response.cases`): ½·m·u̇ against ½·m·u̇²."""
    with xr.open_dataset(response_path, engine="netcdf4") as dataset:
        dataset = dataset.load()
    row = {"check": f"E2 {case}", "description": f"energy balance E_k + E_df = E_I on {case}: "
                                                 "E_k = m*v/2 (Eqs. 14, 17 as printed) against m*v^2/2",
           "quantity": "largest |balance residual| / largest E_I with m*v/2 (value) and m*v^2/2 (compared_with)",
           "units": "1"}
    if dataset.attrs.get("status") != "ok":
        return {**row, "status": dataset.attrs.get("status", "missing"), "finding": "not computed"}
    mass = float(dataset.attrs["mass"])
    velocity = dataset["absolute_velocity"].values
    losses = dataset["energy_dissipated"].values - dataset["energy_input"].values
    scale = float(np.max(np.abs(dataset["energy_input"].values)))
    residuals = {}
    for name, kinetic in (("printed", 0.5 * mass * velocity), ("squared", 0.5 * mass * velocity**2)):
        residuals[name] = float(np.max(np.abs(kinetic - kinetic[0] + losses))) / scale
    confirmed = residuals["squared"] < BALANCE_CLOSED < residuals["printed"]
    return {**row, "value": residuals["printed"], "compared_with": residuals["squared"],
            "finding": f"with m*v^2/2 the balance closes to {residuals['squared']:.1e} of E_I; "
                       f"with m*v/2 (not an energy: kg m/s) it misses by {residuals['printed']:.3g} of E_I",
            "status": "confirmed" if confirmed else "not confirmed", "explains": ""}


def table8_rms_consistency() -> dict:
    """E3: Table 8's RMS against its own scale factors and against Table 6's RMS of the same record."""
    reference = paper_tables()
    table8 = reference["table8_scaling_mendoza"]
    rows = table8["rows"]
    ratios = np.array([row["rms_acceleration"] / row["scale"] for row in rows])
    spread = float(np.ptp(ratios) / np.mean(ratios))
    unscaled = next(row for row in rows if row["scale"] == 1.0)
    table6 = reference["table6_results"]["rows"][table8["record"]]["rms_acceleration"]
    difference = (unscaled["rms_acceleration"] - table6) / table6
    consistent = spread < SCALING_SPREAD
    confirmed = consistent and abs(difference) > READING_FITS
    return {"check": "E3", "description": "Table 8's RMS against its scale factors and against Table 6's RMS "
                                          f"of the same record ({table8['record']})",
            "quantity": "(Table 8 RMS at scale 1 - Table 6 RMS) / Table 6 RMS (value); "
                        "relative spread of Table 8 RMS / scale factor (compared_with)",
            "value": float(difference), "compared_with": spread, "units": "1",
            "finding": f"Table 8's RMS/scale is {np.mean(ratios):.4g} m/s2 within {spread:.2%}, "
                       f"{'consistent' if consistent else 'inconsistent'} with one scaled record; its unscaled RMS "
                       f"{unscaled['rms_acceleration']} m/s2 differs from Table 6's {table6} m/s2 by {difference:+.1%}"
                       " (Table 6's value is Table 4's Kobe model E_df, E1)",
            "status": "confirmed" if confirmed else "not confirmed", "explains": ""}


def harmonic_readings(readings_path, g: float) -> dict:
    """E4: which reading of "30 mm" (amplitude or stroke) the paper's harmonic model column permits, per frequency."""
    rows = [row for row in read_csv_rows(readings_path) if row.get("paper_energy_dissipated")]
    amplitudes = sorted({float(row["displacement_amplitude"]) for row in rows}, reverse=True)
    frequencies = sorted({float(row["frequency"]) for row in rows}, reverse=True)
    parts, fitting = [], []
    for frequency in frequencies:
        fits = set()
        for amplitude in amplitudes:
            mine = [row for row in rows if float(row["displacement_amplitude"]) == amplitude
                    and float(row["frequency"]) == frequency]
            rms = min(float(np.sqrt(np.mean([float(row["relative_difference"]) ** 2 for row in mine
                                             if row["ramp_cycles"] == ramp])))
                      for ramp in {row["ramp_cycles"] for row in mine})
            f_f = normalized_friction(float(mine[0]["mu"]), amplitude, frequency, g)
            if rms <= READING_FITS:
                fits.add(amplitude)
            parts.append(f"{amplitude * 1e3:g} mm at {frequency:g} Hz: RMS difference {rms:.1%}, f_f = {f_f:.2f}"
                         + (" (f_f >= 1: the block cannot slip)" if f_f >= 1 else ""))
        fitting.append(fits)
    common = set.intersection(*fitting) if fitting else set()

    def best(amplitude: float) -> float:
        return min((float(row["reading_rms_relative_difference"]) for row in rows
                    if float(row["displacement_amplitude"]) == amplitude), default=float("nan"))

    return {"check": "E4", "description": "the two readings of Table 4's 'u_g0 = 30 mm' (amplitude 30 mm; stroke "
                                          "30 mm = amplitude 15 mm) against Table 4's harmonic model column",
            "quantity": "RMS relative difference over all harmonic rows of the best reading with the largest "
                        "amplitude (value) and with the smallest (compared_with), amplitudes "
                        + ", ".join(f"{amplitude * 1e3:g} mm" for amplitude in amplitudes),
            "value": best(amplitudes[0]), "compared_with": best(amplitudes[-1]) if len(amplitudes) > 1 else "",
            "units": "1",
            "finding": "; ".join(parts) + (f". The {max(common) * 1e3:g} mm amplitude fits every frequency"
                                           if common else ". No single reading fits every frequency within "
                                           f"{READING_FITS:.0%}"),
            "status": "not confirmed" if common else "unresolved", "explains": ""}


def errata_rows(seismic_path, harmonic_path, readings_path, g: float) -> list[dict]:
    """Every check, in order E1 to E4."""
    return [table6_rms_repeats_table4(), balance_closure(harmonic_path, "harmonic_model"),
            balance_closure(seismic_path, "seismic_model"), table8_rms_consistency(),
            harmonic_readings(readings_path, g)]


def confirmed_errata(rows: list[dict[str, str]]) -> dict[str, str]:
    """``table.column`` -> ``"paper erratum: E… …"`` for every confirmed check that explains it."""
    explained: dict[str, list[str]] = {}
    for row in rows:
        if row["status"] == "confirmed":
            for cell in filter(None, row["explains"].split(";")):
                explained.setdefault(cell.strip(), []).append(row["check"])
    return {cell: f"paper erratum: {', '.join(checks)} (results/tables/errata.csv)" for cell, checks in explained.items()}


def write_errata(seismic_path, harmonic_path, readings_path, errata_path, g: float) -> Path:
    """``errata.csv`` from the stored model responses and ``table4_readings.csv`` (gravity ``g`` [m/s²])."""
    return write_csv_atomic(errata_path, errata_rows(seismic_path, harmonic_path, readings_path, g), FIELDS)
