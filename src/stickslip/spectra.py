"""Elastic response spectra of one component and of a pair of horizontal components.

Every oscillator response comes from :func:`stickslip.response_spectrum.relative_displacements`:
the damped single-degree-of-freedom oscillator (period T [s], damping ratio ξ
[1]) stepped exactly for the record taken linear between its samples.  The
spectral displacement is SD(T) = max_t |u(t)| [m] and the pseudo-spectral
acceleration PSA(T) = ω² SD(T) [m/s²], ω = 2π/T.

A pair's two components a₁, a₂ (on orthogonal axes: :meth:`RecordPair.horizontal`)
give, the oscillator being linear, the response on the axis turned by θ
from axis 1 towards axis 2 as u_θ(t) = u₁(t) cos θ + u₂(t) sin θ.  The
measures of a pair, each a spectral displacement [m] (PSA = ω² times it):

- ``rotd100``: max over θ of max_t |u_θ(t)| = max_t sqrt(u₁² + u₂²), the
  largest peak over all azimuths (Boore 2010), taken exactly from the
  vector's length rather than on an azimuth grid (a 1° grid can miss it by
  at most 1 − cos 0.5° = 3.8e-5 of it);
- ``rotd50``: the median over θ = 0°, 1°, …, 179° of max_t |u_θ(t)| (Boore
  2010; the median of 180 values, the mean of the two middle ones);
- ``geomean``: sqrt(SD₁·SD₂), the geometric mean of the two as-recorded
  components' spectra;
- ``srss``: sqrt(SD₁² + SD₂²), the square root of the sum of their squares
  (the combination by which ASCE 7-05 §17.3.2 scaled a suite of pairs to a
  target spectrum).

Boore, D. M. (2010). Orientation-independent, nongeometric-mean measures of
seismic intensity from two horizontal components of motion. BSSA 100(4),
1830-1835.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from stickslip.errors import StickslipError
from stickslip.checks import checked_acceleration
from stickslip.response_spectrum import DEFAULT_DAMPING, relative_displacements

#: The periods of a spectrum unless given [s]: 100 from 0.01 s to 10 s, evenly spaced in log T.
DEFAULT_PERIODS = np.geomspace(0.01, 10.0, 100)

#: The measures of a pair, in the order outputs list them.
PAIR_MEASURES = ("rotd100", "rotd50", "geomean", "srss")

#: The measure of one component: its own spectrum.
COMPONENT_MEASURE = "psa"

#: The azimuths of RotD50 [degrees]: 0, 1, ..., 179.
ROTATION_ANGLES = np.arange(180.0)

#: How many samples of largest |u| bound the azimuths' peaks from below (:func:`rotated_peaks`).
_CANDIDATES = 256

#: Samples per block when the peaks over the azimuths are taken (bounds the memory to 180 x this many numbers).
_BLOCK = 8192


@dataclass(frozen=True)
class Spectra:
    """Response spectra on one set of periods.

    Attributes
    ----------
    periods:
        Oscillator periods T [s], increasing.
    damping:
        Damping ratio ξ [1].
    displacements:
        Spectral displacement SD [m] of each measure (``psa`` for one
        component; :data:`PAIR_MEASURES` for a pair), one value per period.
    """

    periods: np.ndarray
    damping: float
    displacements: dict[str, np.ndarray]

    @property
    def measures(self) -> tuple[str, ...]:
        """The measures, in order."""
        return tuple(self.displacements)

    def pseudo_acceleration(self, measure: str) -> np.ndarray:
        """PSA = (2π/T)² SD [m/s²] of ``measure``."""
        return (2.0 * np.pi / self.periods) ** 2 * self.displacements[measure]


def checked_periods(periods) -> np.ndarray:
    """``periods`` [s] as a float array, each positive and finite and strictly increasing; one-line errors."""
    values = np.atleast_1d(np.asarray(periods, dtype=float))
    if values.ndim != 1 or values.size == 0:
        raise StickslipError("periods: expected one or more oscillator periods [s]")
    if not np.all(np.isfinite(values) & (values > 0.0)):
        raise StickslipError(f"periods: {', '.join(f'{v:g}' for v in values)}: each must be a positive finite number [s]")
    if np.any(np.diff(values) <= 0.0):
        raise StickslipError(f"periods: {', '.join(f'{v:g}' for v in values)}: expected strictly increasing periods [s]")
    return values


def component_spectra(acceleration, dt: float, periods=DEFAULT_PERIODS, damping: float = DEFAULT_DAMPING) -> Spectra:
    """The spectrum (measure ``psa``) of one component ``acceleration`` [m/s²] sampled every ``dt`` [s]."""
    periods = checked_periods(periods)
    values = checked_acceleration(acceleration, "ground acceleration")[None, :]
    peaks = np.array([np.max(np.abs(response)) for response in relative_displacements(values, dt, periods, damping)])
    return Spectra(periods, float(damping), {COMPONENT_MEASURE: peaks})


def pair_spectra(first, second, dt: float, periods=DEFAULT_PERIODS, damping: float = DEFAULT_DAMPING) -> Spectra:
    """RotD100, RotD50, geometric mean and SRSS (module docstring) of two components on orthogonal axes.

    ``first`` and ``second`` are ground accelerations [m/s²] of equal length, sampled every ``dt`` [s]
    (a :class:`~stickslip.records.pair.RecordPair`'s :meth:`horizontal`).
    """
    periods = checked_periods(periods)
    first, second = checked_acceleration(first, "first component"), checked_acceleration(second, "second component")
    if first.size != second.size:
        raise StickslipError(f"the two components have different lengths ({first.size} and {second.size} samples)")
    values = {measure: np.empty(periods.size) for measure in PAIR_MEASURES}
    for index, (one, other) in enumerate(relative_displacements(np.stack([first, second]), dt, periods, damping)):
        peak_one, peak_other = np.max(np.abs(one)), np.max(np.abs(other))
        values["rotd100"][index] = np.max(np.hypot(one, other))
        values["rotd50"][index] = np.median(rotated_peaks(one, other))
        values["geomean"][index] = np.sqrt(peak_one * peak_other)
        values["srss"][index] = np.hypot(peak_one, peak_other)
    return Spectra(periods, float(damping), values)


def rotated_peaks(first: np.ndarray, second: np.ndarray, angles=ROTATION_ANGLES) -> np.ndarray:
    """max_t |first(t) cos θ + second(t) sin θ| at each azimuth θ of ``angles`` [degrees].

    Exact, on fewer samples: |u_θ(t)| ≤ |u(t)| = sqrt(first² + second²), so a
    sample whose |u| is below a lower bound of every azimuth's peak (their
    peaks over the :data:`_CANDIDATES` samples of largest |u|) is no
    azimuth's peak and is skipped.
    """
    turn = np.radians(np.asarray(angles, dtype=float))
    cosine, sine = np.cos(turn)[:, None], np.sin(turn)[:, None]
    first, second = np.asarray(first, dtype=float), np.asarray(second, dtype=float)
    length = np.hypot(first, second)
    if length.size > _CANDIDATES:
        largest = np.argpartition(length, -_CANDIDATES)[-_CANDIDATES:]
        floor = np.abs(cosine * first[largest] + sine * second[largest]).max(axis=1).min()
        keep = length >= floor
        first, second = first[keep], second[keep]
    peaks = np.zeros(turn.size)
    for start in range(0, len(first), _BLOCK):
        block = np.abs(cosine * first[None, start:start + _BLOCK] + sine * second[None, start:start + _BLOCK])
        np.maximum(peaks, block.max(axis=1), out=peaks)
    return peaks


def motion_spectra(motion, periods=DEFAULT_PERIODS, damping: float = DEFAULT_DAMPING) -> Spectra:
    """The spectra of a :class:`~stickslip.records.record.Record` (``psa``) or of a
    :class:`~stickslip.records.pair.RecordPair` (:data:`PAIR_MEASURES`, on the pair's orthogonal axes)."""
    from stickslip.records.pair import RecordPair

    if isinstance(motion, RecordPair):
        return pair_spectra(*motion.horizontal(), motion.dt, periods, damping)
    return component_spectra(motion.acceleration, motion.dt, periods, damping)
