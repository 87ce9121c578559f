"""Intensity measures of a ground-motion record (definitions: docs/definitions.md).

All quantities are SI: acceleration [m/s²], velocity [m/s], displacement [m],
time [s], Arias intensity [m/s].  The fixed definitions:

- Arias intensity I_A = π/(2g)·∫a² dt, by the trapezoid rule on the samples.
- Husid curve H(t) = (cumulative I_A up to t) / I_A, dimensionless, at the samples.
- t5, t95: the times where H reaches 0.05 and 0.95, by linear interpolation of
  H between samples (Trifunac and Brady 1975); significant duration
  t_e = t95 − t5.  The whole-sample convention takes instead the first sample
  times where H ≥ 0.05 and H ≥ 0.95.
- RMS acceleration a_rms = sqrt((1/t_e)·∫_{t5}^{t95} a² dt), where the integral
  is the trapezoid cumulative integral of a² interpolated linearly inside a
  step (the same rule that gives H), so that a_rms²·t_e = (2g/π)·0.9·I_A.
- Mean period T_m = Σ C_i²/f_i / Σ C_i² over the Fourier amplitudes C_i with
  0.25 Hz ≤ f_i ≤ 20 Hz (Rathje, Abrahamson and Bray 1998), after the
  processing of SLAMMER: the mean removed, a cosine taper on the first and
  last 5 % of the samples, zeros padded to a power of two.
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields

import numpy as np

from stickslip.checks import checked_finite_results, checked_positive
from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import RecordError
from stickslip.records.process import ground_motion, peak_ground_acceleration, record_name
from stickslip.records.record import Record
from stickslip.units import UNITS

#: Husid fractions that bound the significant duration (Trifunac and Brady 1975).
SIGNIFICANT_FRACTIONS = (0.05, 0.95)

#: Frequency band [Hz] of the mean period (Rathje et al. 1998).
MEAN_PERIOD_BAND = (0.25, 20.0)

#: Fraction of the samples tapered at each end before the Fourier transform of the mean period.
MEAN_PERIOD_TAPER = 0.05


def cumulative_squared_acceleration(acceleration: np.ndarray, dt: float) -> np.ndarray:
    """∫_0^{t_i} a² dt at every sample [m²/s³], by the trapezoid rule with step ``dt`` [s]."""
    squared = np.square(np.asarray(acceleration, dtype=np.float64))
    cumulative = np.zeros_like(squared)
    step = np.add(squared[:-1], squared[1:])
    step *= 0.5 * dt
    np.cumsum(step, out=cumulative[1:])
    return cumulative


def arias_intensity(acceleration: np.ndarray, dt: float, g: float = STANDARD_GRAVITY) -> float:
    """Arias intensity I_A = π/(2g)·∫a² dt [m/s], trapezoid rule.

    ``acceleration`` in m/s², ``dt`` in s, ``g`` in m/s².
    """
    cumulative = cumulative_squared_acceleration(acceleration, dt)
    return float(np.pi / (2.0 * g) * cumulative[-1]) if cumulative.size else 0.0


def husid_curve(acceleration: np.ndarray, dt: float) -> np.ndarray:
    """Husid curve H(t_i) = cumulative I_A / I_A at every sample (dimensionless, 0 to 1).

    ``acceleration`` in m/s², ``dt`` in s.  Raises ``ValueError`` for a record
    with zero Arias intensity, whose Husid curve is undefined.
    """
    cumulative = cumulative_squared_acceleration(acceleration, dt)
    if cumulative.size == 0 or cumulative[-1] <= 0.0:
        raise ValueError("the Husid curve is undefined: the Arias intensity is zero")
    return cumulative / cumulative[-1]


def husid_time(husid: np.ndarray, dt: float, fraction: float, whole_sample: bool = False) -> float:
    """The time [s] at which the Husid curve ``husid`` (sampled at step ``dt`` [s]) reaches ``fraction``.

    With ``whole_sample=False``, H is interpolated linearly between the last
    sample below ``fraction`` and the first at or above it.  With
    ``whole_sample=True``, the time of that first sample with H ≥ ``fraction``.
    """
    index = int(np.searchsorted(husid, fraction, side="left"))
    index = min(index, husid.size - 1)  # guards against H[-1] = 1 − round-off < fraction = 1
    if whole_sample or index == 0:
        return index * dt
    below, above = husid[index - 1], husid[index]
    return float((index - 1 + (fraction - below) / (above - below)) * dt)


def significant_interval(
    acceleration: np.ndarray,
    dt: float,
    fractions: tuple[float, float] = SIGNIFICANT_FRACTIONS,
    whole_sample: bool = False,
) -> tuple[float, float]:
    """(t_low, t_high) [s]: the times at which the Husid curve reaches ``fractions`` (default 5 % and 95 %).

    ``acceleration`` in m/s², ``dt`` in s; see :func:`husid_time` for ``whole_sample``.
    """
    husid = husid_curve(acceleration, dt)
    low, high = fractions
    return husid_time(husid, dt, low, whole_sample), husid_time(husid, dt, high, whole_sample)


def significant_duration(
    acceleration: np.ndarray,
    dt: float,
    fractions: tuple[float, float] = SIGNIFICANT_FRACTIONS,
    whole_sample: bool = False,
) -> float:
    """Significant duration t_e = t95 − t5 [s] (Trifunac and Brady 1975); see :func:`significant_interval`."""
    t_low, t_high = significant_interval(acceleration, dt, fractions, whole_sample)
    return t_high - t_low


def rms_acceleration(acceleration: np.ndarray, dt: float, t_start: float, t_end: float) -> float:
    """Root mean square of the acceleration over [t_start, t_end] [m/s²].

    a_rms = sqrt(∫_{t_start}^{t_end} a² dt / (t_end − t_start)), where the
    integral is the trapezoid cumulative integral of a² (as for the Arias
    intensity) interpolated linearly inside a step.  ``acceleration`` in m/s²,
    ``dt``, ``t_start`` and ``t_end`` in s, with t_end > t_start.
    """
    return window_rms(cumulative_squared_acceleration(acceleration, dt), dt, t_start, t_end)


def window_rms(cumulative: np.ndarray, dt: float, t_start: float, t_end: float) -> float:
    """RMS [m/s²] over [t_start, t_end] [s] from the cumulative ∫a² dt [m²/s³] at steps of ``dt`` [s]."""
    times = np.arange(cumulative.size) * dt
    window_integral = np.interp(t_end, times, cumulative) - np.interp(t_start, times, cumulative)
    return float(np.sqrt(window_integral / (t_end - t_start)))


def mean_period(acceleration: np.ndarray, dt: float, band: tuple[float, float] = MEAN_PERIOD_BAND) -> float:
    """Rathje's mean period T_m = Σ C_i²/f_i / Σ C_i² [s] over the frequencies f_i in ``band`` [Hz].

    C_i are the Fourier amplitudes of the acceleration (m/s², step ``dt`` [s])
    after the mean is removed, the first and last 5 % of the samples are
    tapered by a half cosine and zeros are padded to the next power of two:
    the processing of SLAMMER's ``meanPer``, so that the two programs agree
    to the database's rounding.  NaN when no frequency of the transform lies in
    the band (a record too short or sampled too coarsely).
    """
    values = np.asarray(acceleration, dtype=np.float64)
    values = values - values.mean()
    tapered = int(np.ceil(values.size * MEAN_PERIOD_TAPER))
    if tapered:
        ramp = 0.5 * (1.0 - np.cos(np.pi * np.arange(tapered) / (values.size * MEAN_PERIOD_TAPER)))
        values[:tapered] *= ramp
        values[values.size - tapered:] *= ramp[::-1]
    padded = 1 << max(1, int(np.ceil(np.log2(values.size))))
    squared_amplitude = np.abs(np.fft.rfft(values, n=padded) * dt) ** 2
    frequency = np.fft.rfftfreq(padded, dt)
    inside = (frequency >= band[0]) & (frequency <= band[1])
    if not inside.any():
        return float("nan")
    weights = squared_amplitude[inside]
    return float(np.sum(weights / frequency[inside]) / np.sum(weights))


#: Units of the scalars of :meth:`IntensityMeasures.as_dict`, UDUNITS spelling ("1" for a count).
MEASURE_UNITS = {name: UNITS[name] for name in (
    "pga", "pgv", "pgd", "arias_intensity", "t5", "t95", "significant_duration",
    "significant_duration_samples", "rms_acceleration", "mean_period", "npts", "dt", "duration",
)}

#: What each measure is, in words, for tables read by people (the CLI's, the record report's).
MEASURE_LABELS = {
    "pga": "peak ground acceleration",
    "pgv": "peak ground velocity (no baseline correction)",
    "pgd": "peak ground displacement (no baseline correction)",
    "arias_intensity": "Arias intensity",
    "t5": "t5 (5 % of Arias intensity)",
    "t95": "t95 (95 % of Arias intensity)",
    "significant_duration": "significant duration t95 - t5",
    "significant_duration_samples": "significant duration, whole samples",
    "rms_acceleration": "RMS acceleration over [t5, t95]",
    "mean_period": "mean period T_m (0.25-20 Hz, Rathje et al. 1998)",
    "npts": "number of samples",
    "dt": "time step",
    "duration": "duration (npts - 1)*dt",
}


@dataclass(frozen=True)
class IntensityMeasures:
    """Intensity measures of one record, SI units.

    Attributes
    ----------
    pga:
        Peak ground acceleration max |a| [m/s²].
    pgv:
        Peak ground velocity max |v| [m/s], v integrated from the acceleration
        (see :func:`stickslip.records.process.ground_motion`).
    pgd:
        Peak ground displacement max |u| [m], likewise.
    arias_intensity:
        I_A = π/(2g)·∫a² dt [m/s], trapezoid rule.
    t5, t95:
        Times where the Husid curve reaches 5 % and 95 %, interpolated [s].
    significant_duration:
        t_e = t95 − t5 [s], interpolated.
    significant_duration_samples:
        t_e by the whole-sample convention [s].
    rms_acceleration:
        RMS acceleration over [t5, t95] [m/s²].
    mean_period:
        Rathje's mean period T_m [s] (:func:`mean_period`).
    npts:
        Number of samples.
    dt:
        Time step [s].
    duration:
        t0 = (npts − 1)·dt [s].
    husid:
        The Husid curve at the samples (dimensionless); not in :meth:`as_dict`.
    """

    pga: float
    pgv: float
    pgd: float
    arias_intensity: float
    t5: float
    t95: float
    significant_duration: float
    significant_duration_samples: float
    rms_acceleration: float
    mean_period: float
    npts: int
    dt: float
    duration: float
    husid: np.ndarray = field(repr=False, compare=False)

    def as_dict(self) -> dict[str, float | int]:
        """The scalar measures by name, SI units (the Husid curve left out)."""
        return {f.name: getattr(self, f.name) for f in fields(self) if f.name != "husid"}


def intensity_measures(record: Record, g: float = STANDARD_GRAVITY, *, baseline: str = "none") -> IntensityMeasures:
    """The intensity measures of ``record``, with gravity ``g`` [m/s²].

    PGV and PGD come from the record integrated without baseline correction
    unless ``baseline`` says otherwise (see
    :func:`stickslip.records.process.ground_motion`).  A record with fewer than
    two samples or with zero Arias intensity raises :class:`RecordError`; measures
    that overflow double precision (inf or NaN) raise :class:`StickslipError`.
    """
    g = checked_positive(g, "gravity g")
    if record.npts < 2:
        raise RecordError(record_name(record), f"{record.npts} sample(s): intensity measures need at least 2")
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # overflow is reported, not warned
        return _intensity_measures(record, g, baseline)


def _intensity_measures(record: Record, g: float, baseline: str) -> IntensityMeasures:
    """As :func:`intensity_measures`, with the cumulative integral of a² computed once."""
    acceleration, dt = record.acceleration, record.dt
    cumulative = cumulative_squared_acceleration(acceleration, dt)
    if not cumulative[-1] > 0.0 and not np.isnan(cumulative[-1]):
        raise RecordError(
            record_name(record), "every acceleration is zero: Arias intensity and durations are undefined"
        )
    husid = cumulative / cumulative[-1]
    t5, t95 = (husid_time(husid, dt, fraction) for fraction in SIGNIFICANT_FRACTIONS)
    t5_samples, t95_samples = (husid_time(husid, dt, fraction, whole_sample=True) for fraction in SIGNIFICANT_FRACTIONS)
    motion = ground_motion(record, baseline=baseline)
    husid.setflags(write=False)
    measures = IntensityMeasures(
        pga=peak_ground_acceleration(record),
        pgv=float(np.max(np.abs(motion.velocity))),
        pgd=float(np.max(np.abs(motion.displacement))),
        arias_intensity=float(np.pi / (2.0 * g) * cumulative[-1]),
        t5=t5,
        t95=t95,
        significant_duration=t95 - t5,
        significant_duration_samples=t95_samples - t5_samples,
        rms_acceleration=window_rms(cumulative, dt, t5, t95),
        mean_period=mean_period(acceleration, dt),
        npts=record.npts,
        dt=dt,
        duration=record.duration,
        husid=husid,
    )
    defined_where_finite = {"mean_period"}  # NaN for a record with no frequency in the band
    checked_finite_results({name: value for name, value in measures.as_dict().items()
                            if name not in defined_where_finite}, record_name(record))
    return measures
