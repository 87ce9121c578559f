"""The codes' elastic response spectra: spectral acceleration S_a(T) [g] over the period T [s].

Each spectrum is a callable ``spectrum(periods, damping=0.05)`` returning
S_a [g] at each period, for the damping ratio ``damping`` [1]:

- :class:`AsceTwoPeriod`: ASCE 7-22 §11.4.6 (Fig. 11.4-1), here on the MCE_R
  parameters S_MS, S_M1 [g] and T_L [s] as Chapter 17 uses them:
  S_MS (0.4 + 0.6 T/T_0) below T_0 = 0.2 T_S, S_MS up to T_S = S_M1/S_MS,
  S_M1/T up to T_L, S_M1 T_L/T² beyond;
- :class:`MultiPeriodTable`: a user's multi-period spectrum (ASCE 7-22
  §11.4.5.1 gives one at 22 periods), linear between its rows;
- :class:`AashtoThreePoint`: AASHTO's spectrum from A_s, S_DS, S_D1 [g]
  (AASHTO Guide Specifications for LRFD Seismic Bridge Design §3.4.1,
  used by the Guide Specifications for Seismic Isolation Design §7.1):
  A_s + (S_DS − A_s) T/T_0 below T_0 = 0.2 T_S, S_DS up to T_S = S_D1/S_DS,
  S_D1/T beyond;
- :class:`Eurocode8`: EN 1998-1 §3.2.2.2 Eqs. 3.2-3.5, type 1 or 2, ground
  type A-E (Tables 3.2 and 3.3: S, T_B, T_C, T_D) or the user's own values,
  a_g [g] the design ground acceleration on ground type A.

Damping: EN's η (:func:`~stickslip.codes.damping.eurocode_damping_correction`)
enters its equations where they have it; the ASCE and AASHTO spectra are
divided by their B (:func:`~stickslip.codes.damping.asce_damping_coefficient`,
:func:`~stickslip.codes.damping.aashto_damping_coefficient`) from T_0 on, and
run linear from the undamped S_a(0) to S_a(T_0)/B below T_0, as EN's
spectrum does from a_g S to its plateau (the codes use B only in their
displacement formulas, at periods far above T_0).
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from stickslip.codes.damping import aashto_damping_coefficient, asce_damping_coefficient, eurocode_damping_correction
from stickslip.errors import StickslipError

#: EN 1998-1 Tables 3.2 (type 1) and 3.3 (type 2): ground type -> (S, T_B [s], T_C [s], T_D [s]).
EUROCODE_GROUND_TYPES = {
    1: {"A": (1.0, 0.15, 0.4, 2.0), "B": (1.2, 0.15, 0.5, 2.0), "C": (1.15, 0.20, 0.6, 2.0),
        "D": (1.35, 0.20, 0.8, 2.0), "E": (1.4, 0.15, 0.5, 2.0)},
    2: {"A": (1.0, 0.05, 0.25, 1.2), "B": (1.35, 0.05, 0.25, 1.2), "C": (1.5, 0.10, 0.25, 1.2),
        "D": (1.8, 0.10, 0.30, 1.2), "E": (1.6, 0.05, 0.25, 1.2)},
}


def _positive(value: float, name: str) -> float:
    if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0.0):
        raise StickslipError(f"{name} {value!r}: expected a positive number")
    return float(value)


def _periods(periods) -> np.ndarray:
    values = np.asarray(periods, dtype=float)
    if not np.all(np.isfinite(values) & (values >= 0.0)):
        raise StickslipError("spectrum periods: each must be a finite number >= 0 [s]")
    return values


def _three_branches(periods: np.ndarray, zero: float, plateau: float, one_second: float, long_period: float,
                    factor: float) -> np.ndarray:
    """S_a [g]: linear from ``zero`` at T = 0 to ``plateau``/factor at T_0 = 0.2 T_S, ``plateau``/factor to T_S =
    ``one_second``/``plateau``, ``one_second``/(factor T) to ``long_period``, ``one_second`` T_L/(factor T²) beyond."""
    corner = one_second / plateau
    start = 0.2 * corner
    values = np.where(periods < start, zero + (plateau / factor - zero) * periods / start, plateau / factor)
    with np.errstate(divide="ignore"):
        values = np.where(periods > corner, one_second / (factor * periods), values)
        return np.where(periods > long_period, one_second * long_period / (factor * periods**2), values)


@dataclass(frozen=True)
class AsceTwoPeriod:
    """ASCE 7-22's two-period MCE_R spectrum from S_MS, S_M1 [g] and T_L [s] (module docstring)."""

    sms: float
    sm1: float
    tl: float

    def __post_init__(self) -> None:
        for name, value in (("S_MS [g]", self.sms), ("S_M1 [g]", self.sm1), ("T_L [s]", self.tl)):
            _positive(value, name)

    name = "ASCE 7-22 two-period MCE_R spectrum (§11.4.6)"

    def __call__(self, periods, damping: float = 0.05) -> np.ndarray:
        return _three_branches(_periods(periods), 0.4 * self.sms, self.sms, self.sm1, self.tl,
                               asce_damping_coefficient(damping))


@dataclass(frozen=True)
class AashtoThreePoint:
    """AASHTO's spectrum from A_s, S_DS and S_D1 [g] (module docstring); ``damping`` by B_L."""

    a_s: float
    sds: float
    sd1: float

    def __post_init__(self) -> None:
        for name, value in (("A_s [g]", self.a_s), ("S_DS [g]", self.sds), ("S_D1 [g]", self.sd1)):
            _positive(value, name)

    name = "AASHTO three-point spectrum (LRFD Seismic Bridge Design §3.4.1)"

    def __call__(self, periods, damping: float = 0.05) -> np.ndarray:
        return _three_branches(_periods(periods), self.a_s, self.sds, self.sd1, math.inf,
                               aashto_damping_coefficient(damping))


@dataclass(frozen=True)
class Eurocode8:
    """EN 1998-1's elastic spectrum (module docstring): a_g [g], soil factor S [1], corner periods [s]."""

    ag: float
    soil_factor: float
    tb: float
    tc: float
    td: float
    label: str = "user's S, T_B, T_C, T_D"

    def __post_init__(self) -> None:
        for name, value in (("a_g [g]", self.ag), ("S", self.soil_factor), ("T_B [s]", self.tb), ("T_C [s]", self.tc),
                            ("T_D [s]", self.td)):
            _positive(value, name)
        if not self.tb < self.tc < self.td:
            raise StickslipError(f"EN 1998-1 corner periods T_B {self.tb:g} s, T_C {self.tc:g} s, T_D {self.td:g} s: "
                                 "expected T_B < T_C < T_D")

    @classmethod
    def of_ground(cls, ag: float, ground: str, spectrum_type: int = 1) -> Eurocode8:
        """The type 1 or 2 spectrum of ground type A-E (EN 1998-1 Tables 3.2, 3.3) for a_g [g]."""
        if spectrum_type not in EUROCODE_GROUND_TYPES:
            raise StickslipError(f"EN 1998-1 spectrum type {spectrum_type!r}: expected 1 or 2")
        table = EUROCODE_GROUND_TYPES[spectrum_type]
        if str(ground).upper() not in table:
            raise StickslipError(f"EN 1998-1 ground type {ground!r}: expected one of {', '.join(table)} (for S1 and S2, "
                                 "give S, T_B, T_C and T_D from a site study)")
        return cls(ag, *table[str(ground).upper()], label=f"type {spectrum_type}, ground type {str(ground).upper()}")

    @property
    def name(self) -> str:
        return f"EN 1998-1 elastic spectrum ({self.label})"

    def __call__(self, periods, damping: float = 0.05) -> np.ndarray:
        periods, eta = _periods(periods), eurocode_damping_correction(damping)
        peak = self.ag * self.soil_factor
        values = np.where(periods < self.tb, peak * (1.0 + periods / self.tb * (2.5 * eta - 1.0)), 2.5 * peak * eta)
        with np.errstate(divide="ignore"):
            values = np.where(periods > self.tc, 2.5 * peak * eta * self.tc / periods, values)
            return np.where(periods > self.td, 2.5 * peak * eta * self.tc * self.td / periods**2, values)


@dataclass(frozen=True)
class MultiPeriodTable:
    """A spectrum given as a table of periods T [s] and S_a [g] at 5 % damping, linear between its rows; other
    damping by ASCE 7-22's B_M (Table 17.5-1) above the table's first period."""

    periods: tuple[float, ...]
    values: tuple[float, ...]
    source: str = "table"

    def __post_init__(self) -> None:
        periods, values = np.asarray(self.periods, float), np.asarray(self.values, float)
        if periods.size < 2 or periods.shape != values.shape:
            raise StickslipError(f"{self.source}: a multi-period spectrum needs two or more rows of period and S_a")
        if not (np.all(np.isfinite(periods)) and periods[0] >= 0.0 and np.all(np.diff(periods) > 0.0)):
            raise StickslipError(f"{self.source}: the periods must be >= 0 and strictly increasing [s]")
        if not np.all(np.isfinite(values) & (values > 0.0)):
            raise StickslipError(f"{self.source}: each S_a must be a positive number [g]")

    @classmethod
    def from_csv(cls, path: str | Path) -> MultiPeriodTable:
        """Read a CSV file of two columns, period [s] and S_a [g], with or without a header line."""
        path = Path(path)
        try:
            with path.open(newline="", encoding="utf-8-sig") as handle:
                rows = [row for row in csv.reader(handle) if row and any(cell.strip() for cell in row)]
        except OSError as error:
            raise StickslipError(f"{path}: cannot read the spectrum table ({error.strerror or error})") from None
        numbers = []
        for number, row in enumerate(rows, start=1):
            try:
                numbers.append((float(row[0]), float(row[1])))
            except (ValueError, IndexError):
                if number == 1:
                    continue  # a header line
                raise StickslipError(f"{path}: line {number}: expected two numbers, period [s] and S_a [g], "
                                     f"not {','.join(row)!r}") from None
        return cls(tuple(p for p, _ in numbers), tuple(v for _, v in numbers), str(path))

    @property
    def name(self) -> str:
        return f"multi-period spectrum of {self.source}"

    def __call__(self, periods, damping: float = 0.05) -> np.ndarray:
        periods = _periods(periods)
        table = np.asarray(self.periods, float)
        if np.any(periods < table[0]) or np.any(periods > table[-1]):
            raise StickslipError(f"{self.source}: period outside the table's {table[0]:g}-{table[-1]:g} s")
        factor = np.where(periods > table[0], asce_damping_coefficient(damping), 1.0)
        return np.interp(periods, table, np.asarray(self.values, float)) / factor
