"""Study ``timestep``: the effect of the integration step on Algorithm 1 (the paper's §5.2.1, Figs. 18-20).

The paper (ANSYS, Coyote Lake 230) saw "high frequency stuttering" of the
block's acceleration in stick phases at Δt = 0.005 s for μ ≥ 0.125, and none at
0.001 s. This study solves the same record (``config["timestep_study"]``) with

* ``newmark`` — our Algorithm 1, converging reading (the default),
* ``newmark_literal`` — Algorithm 1 read line by line,
* ``exact`` — the event-driven solver, on the record resampled to the same Δt
  (linear resampling does not change its answer; it only gives samples on the
  same grid),

at each time step and friction ratio, and writes (:func:`write_timestep_study`)

``timestep_{record}.nc``
    Time histories, dimensions ``(solver, time_step, mu, time)`` (``solver`` holds the method
    names; not ``method``, which would clash with ``Dataset.sel(method=...)``); ``time`` is
    the grid of the smallest step, and a coarser step's variables are NaN
    between its samples. Variables: block absolute acceleration ü [m/s²],
    relative displacement x [m] and velocity ẋ [m/s], phase (0 stick, ±1
    slide), energy dissipated E_df [J] for the configured block mass, and the
    ground acceleration ü_g [m/s²] on the finest grid.
``timestep_{record}_summary.csv``
    One row per (method, time_step, mu): E_df [J], residual displacement [m],
    the number of stick/slip changes, and two stuttering measures taken over
    the samples where the *exact* block sticks (at the same Δt):
    ``max_abs_acceleration_stick`` = max |ü| [m/s²] and
    ``stick_stutter_rms`` = RMS of ü − ü_g [m/s²] (zero for a block that really
    moves with the base).

When the record is missing, the NetCDF file holds only its status and the
summary one row saying how to obtain the record.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from stickslip.errors import RecordNotFoundError, StickslipError
from stickslip.plumbing.files import provenance, write_csv_atomic
from stickslip.records.netcdf import read_record_netcdf
from stickslip.records.process import resample
from stickslip.records.record import Record
from stickslip.models.rigid import RIGID
from stickslip.sweeps import write_cube
from stickslip.units import CF_CONVENTIONS, UNITS

#: The solvers compared, in the order of the ``solver`` dimension: the rigid model's scheme, its options, and
#: whether it is given the record resampled to the study's time step (the exact scheme, on the same grid as
#: Algorithm 1's steps) or the record with that step as its ``time_step`` option (Algorithm 1, which resamples).
SOLVERS = {
    "exact": ("exact", {}, True),
    "newmark": ("newmark", {"reading": "converging"}, False),
    "newmark_literal": ("newmark", {"reading": "literal"}, False),
}

#: Methods compared, in the order of the ``solver`` dimension.
METHODS = tuple(SOLVERS)

#: Time-history variables: name -> (units, long name).
HISTORY_VARIABLES = {name: (UNITS[name], long_name) for name, long_name in (
    ("block_acceleration", "block absolute acceleration"),
    ("relative_displacement", "block displacement relative to the base"),
    ("relative_velocity", "block velocity relative to the base"),
    ("phase", "0 stick, +1/-1 sliding with positive/negative relative velocity"),
    ("energy_dissipated", "cumulative energy dissipated by friction"),
)}


def solve_case(method: str, acceleration: np.ndarray, dt: float, mu: float, g: float, time_step: float):
    """The :class:`~stickslip.models.rigid.history.SolverHistory` of one case on the grid of step ``time_step`` [s].

    ``method`` is one of :data:`SOLVERS`; ``acceleration`` [m/s²] sampled at ``dt`` [s], ``mu`` [1], ``g`` [m/s²].
    """
    scheme, options, resampled = SOLVERS[method]
    record = Record(acceleration, dt)
    if resampled:
        record = resample(record, time_step)
    else:
        options = {**options, "time_step": time_step}
    return RIGID.solve(record, method=scheme, mu=mu, g=g, **options).history


def stuttering_measures(history, exact_history) -> dict[str, float]:
    """Stick-phase stuttering of ``history`` over the samples where ``exact_history`` sticks.

    Both histories must be on the same grid. Returns the max |ü| [m/s²] and the
    RMS of ü − ü_g [m/s²] over those samples, and the number of phase changes.
    """
    stuck = exact_history.phase == 0
    relative_acceleration = history.relative_acceleration[stuck]
    block_acceleration = history.ground_acceleration[stuck] + relative_acceleration
    sliding = history.phase != 0
    return {
        "max_abs_acceleration_stick": float(np.max(np.abs(block_acceleration))) if stuck.any() else 0.0,
        "stick_stutter_rms": float(np.sqrt(np.mean(relative_acceleration**2))) if stuck.any() else 0.0,
        "phase_changes": int(np.count_nonzero(sliding[1:] != sliding[:-1])),
    }


def write_timestep_study(record_path, cube_path, summary_path, mus, time_steps, mass: float, g: float) -> list[Path]:
    """Solve the stored record for every method, time step [s] and μ; write the NetCDF and the CSV summary.

    ``mass`` is the block mass [kg] and ``g`` the gravity [m/s²].
    """
    record_id = Path(record_path).stem
    try:
        record = read_record_netcdf(record_path)
    except RecordNotFoundError as error:
        status = f"missing: {error}"
        attrs = {"title": f"stickslip time-step study, record {record_id} (missing)", "record_id": record_id,
                 "status": status, **provenance()}
        return [write_cube(xr.Dataset(attrs=attrs), cube_path),
                write_csv_atomic(summary_path, [{"record": record_id, "status": status}])]
    mus = [float(mu) for mu in mus]
    time_steps = sorted(float(step) for step in time_steps)
    finest = time_steps[0]
    n_time = int(round(record.duration / finest * (1 + 1e-12))) + 1
    shape = (len(METHODS), len(time_steps), len(mus), n_time)
    arrays = {name: np.full(shape, np.nan) for name in HISTORY_VARIABLES}
    ground = None
    rows = []
    for k, time_step in enumerate(time_steps):
        stride = int(round(time_step / finest))
        if not np.isclose(stride * finest, time_step, rtol=1e-9):
            raise StickslipError(f"config: timestep_study time step {time_step} is not a multiple of {finest}")
        for j, mu in enumerate(mus):
            histories = {m: solve_case(m, record.acceleration, record.dt, mu, g, time_step) for m in METHODS}
            for i, method in enumerate(METHODS):
                history = histories[method]
                n = history.time.size
                values = {
                    "block_acceleration": history.ground_acceleration + history.relative_acceleration,
                    "relative_displacement": history.relative_displacement,
                    "relative_velocity": history.relative_velocity,
                    "phase": history.phase.astype(float),
                    "energy_dissipated": mass * history.energy_dissipated,
                }
                for name, value in values.items():
                    arrays[name][i, k, j, : (n - 1) * stride + 1 : stride] = value
                if ground is None and stride == 1:
                    ground = history.ground_acceleration
                rows.append(
                    {
                        "record": record_id,
                        "status": "ok",
                        "method": method,
                        "time_step": time_step,
                        "mu": mu,
                        "energy_dissipated": mass * history.energy_dissipated[-1],
                        "residual_displacement": history.relative_displacement[-1],
                        "n_slip_episodes": history.n_slip_episodes,
                        **stuttering_measures(history, histories["exact"]),
                    }
                )
    dims = ("solver", "time_step", "mu", "time")
    data_vars = {
        name: xr.Variable(dims, arrays[name], attrs={"units": units, "long_name": long_name})
        for name, (units, long_name) in HISTORY_VARIABLES.items()
    }
    data_vars["ground_acceleration"] = xr.Variable(
        "time", ground[:n_time], attrs={"units": UNITS["acceleration"], "long_name": "ground acceleration"}
    )
    coords = {
        "solver": xr.Variable("solver", np.array(METHODS, dtype=object), attrs={"long_name": "solver method"}),
        "time_step": xr.Variable("time_step", np.array(time_steps), attrs={"units": UNITS["time_step"], "long_name": "integration step"}),
        "mu": xr.Variable("mu", np.array(mus), attrs={"units": UNITS["mu"], "long_name": "friction ratio"}),
        "time": xr.Variable("time", np.arange(n_time) * finest, attrs={"units": UNITS["time"], "long_name": "time"}),
    }
    attrs = {
        "title": f"stickslip time-step study (paper section 5.2.1), record {record_id}",
        "Conventions": CF_CONVENTIONS,
        **provenance(),
        "record_id": record_id,
        "status": "ok",
        "record_sha256": record.meta.sha256,
        "block_mass": mass,
        "block_mass_units": UNITS["block_mass"],
        "gravity": g,
        "gravity_units": UNITS["gravity"],
    }
    return [write_cube(xr.Dataset(data_vars, coords=coords, attrs=attrs), cube_path),
            write_csv_atomic(summary_path, rows)]
