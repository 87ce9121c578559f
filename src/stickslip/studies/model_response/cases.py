"""Single solved cases behind the paper's Figs. 2, 3, 11-12 and 16 and the model side of Tables 3 and 4.

:func:`write_model_responses` solves, from the configuration's ``model_response`` block:

``fig2_stick_slip``, ``fig2_permanent_slip``
    The exact solver on harmonic base motion (amplitude ``u_g0`` [m], frequency
    ``f0`` [Hz]) at the friction ratios that give the normalized friction f_f of
    Eq. 3 on either side of the threshold of Eq. 4 (``fig2.normalized_friction``).
``fig3_algorithm1``, ``fig3_exact``
    Algorithm 1 (``newmark``, converging reading) at Δt = ``fig3.time_step`` [s]
    and μ = ``fig3.mu`` on ``fig3.record`` (the paper used Mendoza 1985, which
    we do not have), and the exact solver on the same record.
``harmonic_model``, ``seismic_model``
    The exact solver at μ = ``mu`` for the shaking-table cases: harmonic
    ``harmonic`` (u_g0 [m], f0 [Hz], duration [s], dt [s]) and the record
    ``seismic.record`` scaled by ``seismic.scale`` (Kobe KJMA 090 × 0.65).

Each case is written as ``{case}.nc`` in ``responses_dir`` (every history of
:class:`stickslip.models.rigid.response.Response`, SI units, and the case's settings as
attributes: f_f and the closed-form regime for the harmonic cases), or, when its record is missing,
as a file holding only ``status = "missing: …"``.  ``model_responses.csv``
has one row per case: the case's settings, f_f [-] and the closed-form regime
(harmonic cases), the regime the solver shows, residual displacement [m],
E_df, E_I, final E_k [J] and the energy-balance residual [J].
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from stickslip.errors import RecordNotFoundError
from stickslip.plumbing.files import provenance, write_csv_atomic
from stickslip.records.netcdf import read_record_netcdf
from stickslip.records.process import scale
from stickslip.models.rigid import Response
from stickslip.models import solve
from stickslip.solvers.harmonic import harmonic_record, normalized_friction, regime
from stickslip.sweeps import write_cube

#: The cases, in the order of ``model_responses.csv``.
CASES = ("fig2_stick_slip", "fig2_permanent_slip", "fig3_algorithm1", "fig3_exact", "harmonic_model", "seismic_model")


def observed_regime(response: Response) -> str:
    """The regime the solved histories show after the first breakaway.

    ``"no_slip"`` (never slides), ``"permanent_slip"`` (never sticks again
    after it first slides, within the record) or ``"stick_slip"``.
    """
    sliding = np.asarray(response.phase) != 0
    if not sliding.any():
        return "no_slip"
    first = int(np.argmax(sliding))
    return "stick_slip" if not sliding[first:-1].all() else "permanent_slip"


def friction_for(normalized: float, amplitude: float, frequency: float, g: float) -> float:
    """The friction ratio μ [-] that gives normalized friction f_f = ``normalized`` (Eq. 3 solved for μ)."""
    return normalized / normalized_friction(1.0, amplitude, frequency, g)


def _row(case: str, response: Response, **settings) -> dict:
    return {"case": case, "status": "ok", "record": response.record_meta.record_id, "method": response.method,
            "mu": response.mu, **settings, "observed_regime": observed_regime(response),
            **{name: response.scalars()[name] for name in
               ("residual_displacement", "energy_dissipated", "energy_input", "kinetic_energy_final",
                "balance_residual", "sliding_path")}}


def _harmonic_cases(settings: dict, mass: float, g: float) -> dict[str, tuple[Response, dict]]:
    """The Fig. 2 pair and the shaking-table harmonic case."""
    fig2, table = settings["fig2"], settings["harmonic"]
    cases = {}
    for name, f_f in zip(("fig2_stick_slip", "fig2_permanent_slip"), fig2["normalized_friction"]):
        record = harmonic_record(fig2["displacement_amplitude"], fig2["frequency"], fig2["duration"], fig2["dt"])
        mu = friction_for(f_f, fig2["displacement_amplitude"], fig2["frequency"], g)
        cases[name] = (solve(record, mu=mu, mass=mass, g=g),
                       {"displacement_amplitude": fig2["displacement_amplitude"], "frequency": fig2["frequency"]})
    record = harmonic_record(table["displacement_amplitude"], table["frequency"], table["duration"], table["dt"])
    cases["harmonic_model"] = (solve(record, mu=settings["mu"], mass=mass, g=g),
                               {"displacement_amplitude": table["displacement_amplitude"],
                                "frequency": table["frequency"]})
    for response, extra in cases.values():
        extra["normalized_friction"] = normalized_friction(response.mu, extra["displacement_amplitude"],
                                                           extra["frequency"], g)
        extra["closed_form_regime"] = regime(extra["normalized_friction"])
    return cases


def _record_cases(settings: dict, fig3_record_path, seismic_record_path, mass: float, g: float):
    """The Fig. 3 pair and the scaled seismic case: (case -> (response, settings)), (case -> missing status)."""
    cases, missing = {}, {}
    fig3 = settings["fig3"]
    try:
        record = read_record_netcdf(fig3_record_path)
        cases["fig3_algorithm1"] = (solve(record, mu=fig3["mu"], mass=mass, g=g, method="newmark",
                                          time_step=fig3["time_step"]), {"time_step": fig3["time_step"]})
        cases["fig3_exact"] = (solve(record, mu=fig3["mu"], mass=mass, g=g), {})
    except RecordNotFoundError as error:
        missing["fig3_algorithm1"] = missing["fig3_exact"] = (Path(fig3_record_path).stem, f"missing: {error}")
    seismic = settings["seismic"]
    try:
        record = scale(read_record_netcdf(seismic_record_path), seismic["scale"])
        cases["seismic_model"] = (solve(record, mu=settings["mu"], mass=mass, g=g), {"scale": seismic["scale"]})
    except RecordNotFoundError as error:
        missing["seismic_model"] = (Path(seismic_record_path).stem, f"missing: {error}")
    return cases, missing


def write_model_responses(fig3_record_path, seismic_record_path, responses_dir, table_path, settings: dict,
                          mass: float, g: float) -> list[Path]:
    """Solve every case of :data:`CASES`; write ``{case}.nc`` under ``responses_dir`` and ``model_responses.csv``.

    ``mass`` is the block mass [kg], ``g`` gravity [m/s²]; ``settings`` is the
    configuration's ``model_response`` block (see the module docstring).
    """
    responses_dir = Path(responses_dir)
    cases = _harmonic_cases(settings, mass, g)
    record_cases, missing = _record_cases(settings, fig3_record_path, seismic_record_path, mass, g)
    cases.update(record_cases)
    rows, written = [], []
    for case in CASES:
        if case in missing:
            record_id, status = missing[case]
            rows.append({"case": case, "status": status, "record": record_id})
            attrs = {"title": f"stickslip model response {case} (record missing)", "case": case,
                     "record_id": record_id, "status": status, **provenance()}
            written.append(write_cube(xr.Dataset(attrs=attrs), responses_dir / f"{case}.nc"))
            continue
        response, extra = cases[case]
        rows.append(_row(case, response, **extra))
        dataset = response.to_xarray()
        dataset.attrs.update({"case": case, "status": "ok", **extra})
        written.append(write_cube(dataset, responses_dir / f"{case}.nc"))
    fields = list(dict.fromkeys(key for row in rows for key in row))
    return [*written, write_csv_atomic(table_path, rows, fields)]
