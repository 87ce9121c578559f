"""Closed forms for a rigid Coulomb block on a harmonically moving base.

Base displacement u_g(t) = u_g0·sin(ω·t), ω = 2π·f0 (the paper's §2.2.1, after
López et al. 2004).  The normalized friction f_f = μ·g / (u_g0·ω²) (Eq. 3) sets
the regime:

* f_f ≥ 1: the base acceleration never exceeds μ·g, the block never slips;
* threshold ≤ f_f < 1: stick-slip, with threshold = 1/√(1 + π²/4) ≈ 0.5370 (Eq. 4);
* f_f < threshold: permanent sliding in steady state.

Energy per cycle in steady permanent sliding (derivation).  The block's
absolute acceleration is a square wave ±μ·g, so its absolute velocity is a
triangle wave of amplitude V = μ·g·π/(2ω), reversing when it meets the base
velocity: u_g0·ω·cos θ_r = −V at the reversal phase θ_r, i.e.
cos θ_r = −π·f_f/2.  Over the half cycle between reversals the block's own
displacement is zero (the triangle wave averages out), so the relative
displacement changes by −Δu_g = 2·u_g0·sin θ_r; the relative amplitude is
X = u_g0·√(1 − (π·f_f/2)²).  Friction dissipates μ·m·g per metre of the path
4·X per cycle:

    E = 4·μ·m·g·X = 4·m·u_g0²·ω²·f_f·√(1 − (π·f_f/2)²)   [J].

The reversal needs |ü_g| ≥ μ·g there, sin θ_r ≥ f_f, which is Eq. 4 again.
d/df_f [f_f²·(1 − π²·f_f²/4)] = 0 gives the maximum at f_f = √2/π (Eq. 5), hence
μ_max = (√2/π)·u_g0·ω²/g (Eq. 6).
"""

from __future__ import annotations

import math

import numpy as np

from stickslip.errors import StickslipError
from stickslip.records.record import Record, RecordMeta
from stickslip.checks import checked_positive

#: f_f below which the block slides permanently in steady state (Eq. 4) [-].
PERMANENT_SLIP_THRESHOLD = 1.0 / math.sqrt(1.0 + math.pi**2 / 4.0)

#: f_f of maximum dissipated energy per cycle (Eq. 5) [-].
F_F_MAX = math.sqrt(2.0) / math.pi


def _angular_frequency(frequency: float) -> float:
    return 2.0 * math.pi * frequency


def normalized_friction(mu: float, displacement_amplitude: float, frequency: float, g: float) -> float:
    """f_f = μ·g / (u_g0·(2π·f0)²) (Eq. 3) [-].

    Parameters
    ----------
    mu:
        Friction ratio [-].
    displacement_amplitude:
        Base displacement amplitude u_g0 [m].
    frequency:
        Base frequency f0 [Hz].
    g:
        Gravitational acceleration [m/s²].
    """
    return mu * g / (displacement_amplitude * _angular_frequency(frequency) ** 2)


def regime(f_f: float) -> str:
    """The steady-state regime for normalized friction ``f_f`` [-].

    ``"no_slip"`` (f_f ≥ 1), ``"stick_slip"`` (threshold ≤ f_f < 1) or
    ``"permanent_slip"`` (f_f < threshold, Eq. 4).
    """
    if f_f >= 1.0:
        return "no_slip"
    if f_f >= PERMANENT_SLIP_THRESHOLD:
        return "stick_slip"
    return "permanent_slip"


def mu_max(displacement_amplitude: float, frequency: float, g: float) -> float:
    """Friction ratio of maximum energy dissipation per cycle (Eq. 6) [-].

    Parameters
    ----------
    displacement_amplitude:
        Base displacement amplitude u_g0 [m].
    frequency:
        Base frequency f0 [Hz].
    g:
        Gravitational acceleration [m/s²].
    """
    return F_F_MAX * displacement_amplitude * _angular_frequency(frequency) ** 2 / g


def energy_per_cycle(mu: float, displacement_amplitude: float, frequency: float, mass: float, g: float) -> float:
    """Energy dissipated by friction per cycle of steady permanent sliding [J].

    E = 4·m·u_g0²·ω²·f_f·√(1 − (π·f_f/2)²) (derived in the module docstring).

    Parameters
    ----------
    mu:
        Friction ratio [-]; must give f_f below the permanent-slip threshold.
    displacement_amplitude:
        Base displacement amplitude u_g0 [m].
    frequency:
        Base frequency f0 [Hz].
    mass:
        Block mass [kg].
    g:
        Gravitational acceleration [m/s²].
    """
    f_f = normalized_friction(mu, displacement_amplitude, frequency, g)
    if not 0.0 < f_f < PERMANENT_SLIP_THRESHOLD:
        raise StickslipError(
            f"energy_per_cycle: f_f = {f_f:.4g} is outside the permanent-slip range "
            f"0 < f_f < {PERMANENT_SLIP_THRESHOLD:.4f}, where the closed form holds"
        )
    omega = _angular_frequency(frequency)
    return 4.0 * mass * displacement_amplitude**2 * omega**2 * f_f * math.sqrt(1.0 - (math.pi * f_f / 2.0) ** 2)


def harmonic_record(
    displacement_amplitude: float,
    frequency: float,
    duration: float,
    dt: float,
    ramp_cycles: float = 0.0,
) -> Record:
    """A sampled harmonic base acceleration ü_g(t) = −u_g0·ω²·sin(ω·t)·e(t) as a Record.

    The envelope e(t) is 1 without a ramp.  With ``ramp_cycles`` = n > 0 it rises
    smoothly over the first n cycles, e(t) = sin²(π·t/(2·T_r)) for t < T_r = n/f0,
    and is 1 afterwards (continuous with a continuous slope).

    Parameters
    ----------
    displacement_amplitude:
        Base displacement amplitude u_g0 [m].
    frequency:
        Base frequency f0 [Hz].
    duration:
        Record duration [s]; the last sample is at the largest multiple of dt not beyond it.
    dt:
        Sample interval [s].
    ramp_cycles:
        Number of cycles of the amplitude ramp [-] (0: none).
    """
    for name, value in (("displacement_amplitude [m]", displacement_amplitude), ("frequency [Hz]", frequency),
                        ("duration [s]", duration), ("dt [s]", dt)):
        checked_positive(value, f"harmonic_record: {name}")
    if not (math.isfinite(ramp_cycles) and ramp_cycles >= 0.0):
        raise StickslipError(f"harmonic_record: ramp_cycles must be ≥ 0, got {ramp_cycles!r}")
    omega = _angular_frequency(frequency)
    time = np.arange(int(math.floor(duration / dt + 1e-9)) + 1) * dt
    envelope = np.ones_like(time)
    if ramp_cycles > 0.0:
        ramp_time = ramp_cycles / frequency
        rising = time < ramp_time
        envelope[rising] = np.sin(0.5 * math.pi * time[rising] / ramp_time) ** 2
    acceleration = -displacement_amplitude * omega**2 * np.sin(omega * time) * envelope
    record_id = f"harmonic_{displacement_amplitude * 1e3:g}mm_{frequency:g}Hz_{duration:g}s"
    meta = RecordMeta(record_id=record_id, event="harmonic base motion", source="stickslip.solvers.harmonic", units="m/s2",
                      format="synthetic")
    return Record(acceleration=acceleration, dt=dt, meta=meta)
