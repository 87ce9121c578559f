"""Processing of ground-motion records: resampling, scaling, padding, integration.

Every function that changes a record returns a new :class:`~stickslip.records.record.Record`
made with :meth:`Record.derive`, so the step is appended to ``meta.processing``.
The ground acceleration is taken as linear between samples throughout (the
paper interpolates linearly to Δt = 0.001 s), and the integrals below are exact
for such a signal.  Units are SI: time [s], acceleration [m/s²], velocity
[m/s], displacement [m].
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from stickslip.checks import checked_positive
from stickslip.errors import RecordError, StickslipError
from stickslip.records.record import Record

#: Relative tolerance for deciding that a time falls on a grid point.
_GRID_TOLERANCE = 1e-9

#: Baseline corrections that :func:`ground_motion` knows.
BASELINES = ("none", "polynomial")


def record_name(record: Record) -> str:
    """How error messages name a record: the file read (a stored record's NetCDF file, else its source file), else
    its id, else ``"record"``."""
    return record.meta.stored_in or record.meta.source or record.meta.record_id or "record"


def _grid_steps(span: float, dt: float) -> int:
    """Number of whole steps of ``dt`` [s] that fit in ``span`` [s], counting a near-fit as a fit."""
    steps = span / dt
    nearest = round(steps)
    if abs(steps - nearest) <= _GRID_TOLERANCE * max(1.0, steps):
        return int(nearest)
    return int(math.floor(steps))


def resample(record: Record, dt: float) -> Record:
    """Linear interpolation onto a uniform grid of step ``dt`` [s].

    The new grid runs from 0 to the last original sample time
    t_end = (npts − 1)·record.dt.  The last grid point is t_end itself when
    t_end is a whole number of new steps (within a relative 1e-9, to absorb
    round-off such as 0.02 / 0.001); otherwise the grid stops at the last
    multiple of ``dt`` before t_end and the tail shorter than ``dt`` is
    dropped (the record is not extended and not extrapolated).

    Because the acceleration is linear between samples, resampling changes
    nothing about the signal: every new value lies on the original
    piecewise-linear history, and when ``record.dt / dt`` is an integer the
    original samples are kept (to round-off).  Integrals computed by the
    trapezoid rule on the new grid (for example the Arias intensity, which
    integrates a²) do change slightly, since a² is not linear between samples.
    """
    dt = checked_positive(dt, "resampling time step dt [s]")
    steps = _grid_steps(record.duration, dt)
    # Positions on the original sample index axis; the last one is clamped to
    # the last sample so that a near-fit end point is the last sample exactly.
    positions = np.minimum(np.arange(steps + 1) * (dt / record.dt), record.npts - 1)
    acceleration = np.interp(positions, np.arange(record.npts), record.acceleration)
    return record.derive(acceleration, dt=dt, step=f"resample linear dt={dt:g} s")


def scale(record: Record, factor: float) -> Record:
    """The record with every acceleration multiplied by ``factor`` (dimensionless, finite, not zero).

    A negative factor flips the sign of the record and is allowed; zero would
    leave no motion at all and is an error.
    """
    factor = float(factor)
    if not math.isfinite(factor):
        raise StickslipError(f"scale factor must be a finite number, got {factor!r}")
    if factor == 0.0:
        raise StickslipError("scale factor must not be zero (it would leave no ground motion); a negative factor flips the sign")
    return record.derive(_scaled(record, factor), step=f"scale {factor:g}")


def inverse_polarity(record: Record) -> Record:
    """The record with its sign flipped (SLAMMER's "inverse polarity"), the step recorded as ``inverse polarity``."""
    return record.derive(-record.acceleration, step="inverse polarity")


def _scaled(record: Record, factor: float) -> np.ndarray:
    """The accelerations times ``factor`` [m/s²], which must stay finite."""
    with np.errstate(over="ignore"):
        acceleration = record.acceleration * factor
    if not np.all(np.isfinite(acceleration)):
        raise RecordError(
            record_name(record), f"scaling by {factor:g} overflows double precision (accelerations become infinite)"
        )
    return acceleration


def peak_ground_acceleration(record: Record) -> float:
    """PGA = max |a| over the samples [m/s²] (exact for a signal linear between samples).

    Of a pair of horizontal components (or a motion with its vertical), the
    peak of the horizontal vector's magnitude (its ``peak_acceleration``).
    """
    if not isinstance(record, Record):
        return record.peak_acceleration()
    return float(np.max(np.abs(record.acceleration))) if record.npts else 0.0


def scale_to_pga(record: Record, target_pga: float) -> Record:
    """The record scaled so that its PGA equals ``target_pga`` [m/s²]."""
    target_pga = checked_positive(target_pga, "target PGA [m/s²]")
    pga = peak_ground_acceleration(record)
    if pga == 0.0:
        raise RecordError(record_name(record), "cannot scale to a PGA: every acceleration is zero")
    factor = target_pga / pga
    return record.derive(_scaled(record, factor), step=f"scale {factor:g} to PGA {target_pga:g} m/s2")


def scaled_versions(record: Record, factors=None, target_pgas=None) -> list[Record]:
    """The versions of ``record`` a sweep solves: itself, or one per scale factor [1] or per target PGA [m/s²].

    A pair of components, or a motion with its vertical, is solved as given.
    """
    if not isinstance(record, Record) and (factors is not None or target_pgas is not None):
        raise StickslipError(f"{record.name}: a pair of components, or a motion with its vertical, is solved as "
                             "given: it takes no scaling dimension (scale all its components alike first)")
    if factors is not None:
        return [scale(record, factor) for factor in factors]
    if target_pgas is not None:
        return [scale_to_pga(record, pga) for pga in target_pgas]
    return [record]


def pad_to_duration(record: Record, duration: float) -> Record:
    """The record with zeros appended so that its duration (npts − 1)·dt reaches ``duration`` [s].

    The new duration is the first multiple of dt that is not shorter than
    ``duration`` (a near-fit within a relative 1e-9 counts as a fit).  A
    ``duration`` shorter than the record's own is an error: padding never
    truncates.
    """
    duration = checked_positive(duration, "padded duration [s]")
    if duration < record.duration * (1.0 - _GRID_TOLERANCE):
        raise RecordError(
            record_name(record),
            f"cannot pad to {duration:g} s: the record already lasts {record.duration:g} s",
        )
    steps = _grid_steps(duration, record.dt)
    if steps * record.dt < duration * (1.0 - _GRID_TOLERANCE):
        steps += 1
    extra = max(steps + 1 - record.npts, 0)
    acceleration = np.concatenate([record.acceleration, np.zeros(extra)])
    return record.derive(acceleration, step=f"pad zeros to {steps * record.dt:g} s")


@dataclass(frozen=True)
class GroundMotion:
    """Ground acceleration, velocity and displacement at the record's samples.

    Attributes
    ----------
    acceleration:
        Ground acceleration [m/s²] (baseline-corrected when a correction was asked for).
    velocity:
        Ground velocity [m/s], zero at t = 0.
    displacement:
        Ground displacement [m], zero at t = 0.
    baseline:
        The correction applied: ``"none"`` or ``"polynomial degree N"``.
    """

    acceleration: np.ndarray
    velocity: np.ndarray
    displacement: np.ndarray
    baseline: str


def integrate_linear_acceleration(acceleration: np.ndarray, dt: float) -> tuple[np.ndarray, np.ndarray]:
    """Velocity [m/s] and displacement [m] at the samples of an acceleration [m/s²] linear between samples.

    Starting from rest at t = 0, with a step of ``dt`` [s]:
    v_{i+1} = v_i + dt·(a_i + a_{i+1})/2 (trapezoid, exact) and
    u_{i+1} = u_i + v_i·dt + dt²·(2a_i + a_{i+1})/6 (the exact cubic integral).
    """
    acceleration = np.asarray(acceleration, dtype=np.float64)
    velocity = np.zeros_like(acceleration)
    displacement = np.zeros_like(acceleration)
    if acceleration.size > 1:
        a_now, a_next = acceleration[:-1], acceleration[1:]
        # in place, with the operations of 0.5·dt·(a_i + a_{i+1}) and v_i·dt + dt·dt·(2a_i + a_{i+1})/6 in order
        step = np.add(a_now, a_next)
        step *= 0.5 * dt
        np.cumsum(step, out=velocity[1:])
        step = np.multiply(a_now, 2.0, out=step)
        step += a_next
        step *= dt * dt
        step /= 6.0
        step += np.multiply(velocity[:-1], dt)
        np.cumsum(step, out=displacement[1:])
    return velocity, displacement


def _polynomial_baseline(
    displacement: np.ndarray, velocity: np.ndarray, dt: float, degree: int
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Baseline b(t) = Σ_{k=2..degree} c_k (t/t_end)^k and its first two time derivatives at the samples.

    The coefficients make b(t_end) = u(t_end) and ḃ(t_end) = u̇(t_end); when
    degree > 3, the remaining freedom is a least-squares fit of b to the
    displacement u at all samples.  Returns (b [m], ḃ [m/s], b̈ [m/s²]).
    """
    npts = displacement.size
    t_end = (npts - 1) * dt
    s = np.arange(npts) / (npts - 1)  # normalised time t / t_end
    powers = np.arange(2, degree + 1)
    basis = s[:, None] ** powers  # (npts, degree - 1)
    constraints = np.vstack([np.ones(powers.size), powers.astype(np.float64)])
    targets = np.array([displacement[-1], velocity[-1] * t_end])
    # Equality-constrained least squares, solved through its KKT system.
    kkt = np.block([[basis.T @ basis, constraints.T], [constraints, np.zeros((2, 2))]])
    rhs = np.concatenate([basis.T @ displacement, targets])
    coefficients = np.linalg.solve(kkt, rhs)[: powers.size]
    value = basis @ coefficients
    slope = (s[:, None] ** (powers - 1)) @ (coefficients * powers) / t_end
    curvature = (s[:, None] ** (powers - 2)) @ (coefficients * powers * (powers - 1)) / t_end**2
    return value, slope, curvature


def ground_motion(record: Record, baseline: str = "none", degree: int = 3) -> GroundMotion:
    """Ground velocity [m/s] and displacement [m] at the samples, optionally baseline-corrected.

    Integration (:func:`integrate_linear_acceleration`) is exact for an
    acceleration linear between samples, starting from rest (u = u̇ = 0 at t = 0).

    ``baseline="none"`` (default): the record's acceleration integrated as it
    is.  Velocity and displacement may drift at the end of the record.

    ``baseline="polynomial"``: a correction in the spirit of Yang et al.
    (2006) and of the paper's own processing of its shaking-table records
    (a third-order polynomial baseline with null displacement at both ends).
    Exactly: a polynomial b(t) = Σ_{k=2..degree} c_k·(t/t0)^k is subtracted
    from the displacement u, its derivative ḃ from the velocity and b̈ from
    the acceleration.  Having no constant or linear term, b keeps the start at
    rest (u = u̇ = 0 at t = 0); its coefficients are chosen so that the
    corrected record ends at rest with no drift (u = u̇ = 0 at t = t0).  With
    ``degree=3`` (default) these four conditions fix b completely; with a
    higher degree the extra coefficients are a least-squares fit of b to the
    uncorrected displacement.  For degree 3, b̈ is linear in t, so the
    corrected acceleration is still linear between samples and integrating it
    again gives the corrected velocity and displacement exactly.

    The solvers use the UNcorrected acceleration unless the user asks for a
    corrected one (``ground_motion(record, "polynomial").acceleration``).
    """
    if baseline not in BASELINES:
        raise StickslipError(f"unknown baseline correction {baseline!r}; known: {', '.join(BASELINES)}")
    velocity, displacement = integrate_linear_acceleration(record.acceleration, record.dt)
    if baseline == "none":
        return GroundMotion(record.acceleration, velocity, displacement, baseline="none")
    if isinstance(degree, bool) or not isinstance(degree, (int, np.integer)) or not 3 <= degree <= 9:
        raise StickslipError(f"baseline polynomial degree must be an integer from 3 to 9, got {degree!r}")
    if record.npts < degree:
        raise RecordError(
            record_name(record), f"{record.npts} samples are too few for a degree-{degree} baseline"
        )
    value, slope, curvature = _polynomial_baseline(displacement, velocity, record.dt, int(degree))
    return GroundMotion(
        acceleration=record.acceleration - curvature,
        velocity=velocity - slope,
        displacement=displacement - value,
        baseline=f"polynomial degree {degree}",
    )
