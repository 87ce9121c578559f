"""The codes' equivalent-linear displacement of a friction pendulum from a record's own spectrum, beside the exact one.

A code (ASCE 7-22 Ch. 17, AASHTO's isolation guide, EN 1998-2) designs a
friction pendulum of radius R [m] and friction μ [1] by the fixed point
D = g S_a(T_eff(D), β_eff(D)) T_eff(D)²/(4π²) of
:func:`stickslip.codes.friction_pendulum.fixed_point`.  Here the target
spectrum is the record's own: S_a(T, β) = SD₅(T) (2π/T)²/(g B(β)), SD₅ the
record's 5 %-damped spectral displacement [m] and B the code's damping
reduction (ASCE's B_M, AASHTO's B_L, EN's 1/η), so that D is the code's
estimate for that very record, and D_exact/D_code measures the
equivalent-linear method alone, not a spectrum's fit to records.

- In one direction, SD₅ is the component's own spectrum (``psa``).
- In the plane, SD₅ is RotD100 (:mod:`stickslip.spectra`): the pendulum's
  plane demand is the slider's largest distance from the surface's centre,
  max_t |u(t)|, whose linear analogue is the oscillator's vector peak
  max_t sqrt(u₁² + u₂²) = RotD100; and ASCE 7-22 §11.4 and §17.3 define the
  MCE_R and scale pairs in the maximum direction.

The spectrum of a motion is computed once, on the log-spaced period grid
``periods`` [s] (:data:`DEFAULT_PERIODS`), and interpolated linearly in
(ln T, ln SD) at the fixed point's T_eff; a T_eff off the grid is reported,
not extrapolated.  The exact answer is the largest |u| [m] of the pendulum
(:func:`stickslip.sweep`, ``model="pendulum"``), with the vertical where the
motion has one (the code's D ignores it).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from stickslip.codes.damping import aashto_damping_coefficient, asce_damping_coefficient, eurocode_damping_correction
from scipy.optimize import brentq

from stickslip.codes.friction_pendulum import Procedure, aashto, asce7_22, effective_damping, effective_period, \
    en1998_2, fixed_point, spectral_displacement
from stickslip.errors import StickslipError
from stickslip.response_spectrum import relative_displacements
from stickslip.spectra import checked_periods

#: Periods of a record's spectrum unless given [s]: 60 from 0.1 s to 6 s, log-spaced (R ≤ 8.9 m: 2π sqrt(R/g) ≤ 6 s).
DEFAULT_PERIODS = np.geomspace(0.1, 6.0, 60)

#: Each code's procedure and its damping reduction B(β) [1], the factor that divides the 5 % spectrum.
CODES: dict[str, tuple[Callable[..., Procedure], Callable[[float], float]]] = {
    "asce7_22": (asce7_22, asce_damping_coefficient),
    "aashto": (aashto, aashto_damping_coefficient),
    "en1998_2": (en1998_2, lambda damping: 1.0 / eurocode_damping_correction(damping)),
}


@dataclass(frozen=True)
class RecordSpectrum:
    """A record's 5 %-damped spectrum as a code's target: ``spectrum(periods, damping)`` -> S_a [g].

    ``periods`` [s] and ``displacements`` SD₅ [m] on the grid; ``reduction`` B(β) [1] divides it at damping β;
    ``g`` [m/s²] turns the pseudo-acceleration into g; ``logs`` holds (ln T, ln SD), between which it interpolates.
    """

    periods: np.ndarray
    displacements: np.ndarray
    g: float
    reduction: Callable[[float], float]
    name: str = "the record's own 5 %-damped spectrum"

    def __post_init__(self) -> None:
        if not np.all(np.isfinite(self.displacements) & (self.displacements > 0.0)):
            raise StickslipError(f"{self.name}: each spectral displacement must be positive [m]")
        object.__setattr__(self, "logs", (np.log(self.periods), np.log(self.displacements)))

    def __call__(self, periods, damping: float = 0.05) -> np.ndarray:
        periods = np.asarray(periods, dtype=float)
        low, high = self.periods[0], self.periods[-1]
        if periods.min() < low or periods.max() > high:
            outside = periods[(periods < low) | (periods > high)][0]
            raise StickslipError(f"{self.name}: T_eff = {outside:.4g} s is outside its periods {low:g}-{high:g} s")
        displacement = np.exp(np.interp(np.log(periods), *self.logs))
        return (2.0 * np.pi / periods) ** 2 * displacement / (self.g * self.reduction(damping))


def motion_displacement_spectra(motion, periods=DEFAULT_PERIODS, damping: float = 0.05) -> dict[str, np.ndarray]:
    """SD [m] at ``periods`` [s]: of one component (``psa``), or of a pair each component's (``first``, ``second``)
    and ``rotd100`` (on the pair's orthogonal axes), from one pass of the oscillators (a pair's RotD50, the costly
    part of :func:`stickslip.spectra.pair_spectra`, is not needed here)."""
    from stickslip.records.pair import RecordPair

    periods = checked_periods(periods)
    if not isinstance(motion, RecordPair):
        responses = relative_displacements(motion.acceleration[None, :], motion.dt, periods, damping)
        return {"psa": np.array([np.max(np.abs(response)) for response in responses])}
    first, axis = motion.horizontal()
    rows = [first, axis] if motion.orthogonal else [first, axis, motion.second.acceleration]
    values = {name: np.empty(periods.size) for name in ("first", "second", "rotd100")}
    for index, response in enumerate(relative_displacements(np.stack(rows), motion.dt, periods, damping)):
        values["first"][index], values["second"][index] = np.max(np.abs(response[0])), np.max(np.abs(response[-1]))
        values["rotd100"][index] = np.max(np.hypot(response[0], response[1]))
    return values


@dataclass(frozen=True)
class CodeDisplacement:
    """One code's fixed point on a record's spectrum: D [m], T_eff [s], β_eff [1], B(β_eff) [1], how it was found
    (``iteration`` or ``bracketed``) and how many fixed points the scan found; or NaNs and why none."""

    displacement: float
    period: float
    damping: float
    reduction: float
    method: str = ""
    fixed_points: int = 0
    note: str = ""


#: Steps of the codes' iteration before the fixed point is bracketed instead (where it settles, it does in far
#: fewer; one that has not in this many is cycling about its fixed point).
ITERATIONS = 50

#: D values [m] at which f(D) − D is evaluated to bracket the fixed points where the iteration cycles.
SCAN_POINTS = 150


def bracketed_fixed_point(procedure: Procedure, radius: float, mu: float, g: float) -> tuple[float, int]:
    """The largest root of f(D) − D, f(D) = g S_a(T_eff(D), β_eff(D)) T_eff(D)²/(4π²), and the number of roots.

    A record's spectrum is jagged: where the slope of f at its fixed point is below −1 the codes' plain
    iteration cycles about it.  f(D) − D is scanned on :data:`SCAN_POINTS` log-spaced D [m] from the D at which
    T_eff is the spectrum's shortest period to ten times its largest SD (f(D) < D there unless B < 0.1), and the largest
    sign change from + to − is refined by Brent's method: the first fixed point met coming down from the
    iteration's start D(2π sqrt(R/g), 5 %).
    """
    spectrum = procedure.spectrum
    smallest = mu / ((2.0 * math.pi / spectrum.periods[0]) ** 2 / g - 1.0 / radius) * (1.0 + 1e-9)
    largest = 10.0 * float(np.max(spectrum.displacements))

    def excess(displacement: float) -> float:
        return spectral_displacement(procedure, effective_period(radius, mu, displacement, g),
                                     effective_damping(radius, mu, displacement), g) - displacement

    grid = np.geomspace(smallest, largest, SCAN_POINTS)
    periods = np.minimum(2.0 * np.pi / np.sqrt(g * (1.0 / radius + mu / grid)), spectrum.periods[-1])
    reductions = np.array([spectrum.reduction(beta) for beta in 2.0 / np.pi * mu / (mu + grid / radius)])
    values = np.exp(np.interp(np.log(periods), *spectrum.logs)) / reductions - grid
    crossings = np.flatnonzero((values[:-1] > 0.0) & (values[1:] <= 0.0))
    if crossings.size == 0:
        raise StickslipError(f"{procedure.title}, R = {radius:g} m, mu = {mu:g}: f(D) - D has no root between "
                             f"{smallest:.3g} m and {largest:.3g} m")
    last = crossings[-1]
    return float(brentq(excess, grid[last], grid[last + 1], xtol=1e-14, rtol=1e-12)), int(crossings.size)


def code_displacement(code: str, periods: np.ndarray, displacements: np.ndarray, radius: float, mu: float,
                      g: float) -> CodeDisplacement:
    """``code``'s equivalent-linear D of the pendulum (R [m], μ [1]) with the spectrum SD₅ ``displacements`` [m] at
    ``periods`` [s] as its target (module docstring): the codes' iteration where it settles, else
    :func:`bracketed_fixed_point`; NaNs and the reason where neither finds a D."""
    build, reduction = CODES[code]
    procedure = build(RecordSpectrum(np.asarray(periods, float), np.asarray(displacements, float), g, reduction))
    try:
        displacement, method, count = *fixed_point(procedure, radius, mu, g, ITERATIONS)[:1], "iteration", 1
    except StickslipError:
        try:
            (displacement, count), method = bracketed_fixed_point(procedure, radius, mu, g), "bracketed"
        except StickslipError as error:
            return CodeDisplacement(math.nan, math.nan, math.nan, math.nan, "", 0, str(error))
    damping = effective_damping(radius, mu, displacement)
    return CodeDisplacement(displacement, effective_period(radius, mu, displacement, g), damping, reduction(damping),
                            method, count)


def exact_displacements(motions: Sequence, radii: Sequence[float], mu: Sequence[float], g: float) -> np.ndarray:
    """The pendulum's peak |u| [m] on each motion (records, pairs, or either with a vertical), by (motion, R, μ)."""
    from stickslip.models import sweep

    by_radius = [sweep(list(motions), model="pendulum", mu=list(mu), radius=float(radius), g=g)
                 ["peak_relative_displacement"].transpose("record", "mu").values for radius in radii]
    return np.stack(by_radius, axis=1)
