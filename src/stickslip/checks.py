"""Input checks shared by the solvers, the processing steps and :func:`stickslip.solve`.

Each function returns the checked value in the form the numba kernels want
(contiguous float64 arrays, Python floats) and raises
:class:`~stickslip.errors.StickslipError` with the quantity's ``name`` (which
carries its units) when the value is unusable.
"""

from __future__ import annotations

import math

import numpy as np

from stickslip.errors import StickslipError


def checked_acceleration(acceleration, name: str) -> np.ndarray:
    """A ground-acceleration history [m/s²] as a contiguous float64 array.

    It must be 1-D, hold at least 2 samples and contain only finite values.
    """
    values = np.ascontiguousarray(acceleration, dtype=np.float64)
    if values.ndim != 1 or values.size < 2:
        raise StickslipError(f"{name}: expected a 1-D acceleration history with at least 2 samples, got shape {values.shape}")
    if not np.all(np.isfinite(values)):
        raise StickslipError(f"{name}: acceleration contains NaN or infinite values")
    return values


def checked_pair_axes(pair) -> tuple[np.ndarray, np.ndarray]:
    """A :class:`~stickslip.records.pair.RecordPair`'s accelerations on its orthogonal axes [m/s²]
    (its ``horizontal()``) as contiguous float64 arrays, every value finite; else one line naming the component."""
    return tuple(checked_acceleration(axis, f"{pair.name}, {which} component")
                 for axis, which in zip(pair.horizontal(), ("first", "second")))


def checked_positive(value: float, name: str) -> float:
    """``value`` as a float, which must be finite and > 0 (a time step [s], a friction ratio [-], …)."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise StickslipError(f"{name} must be a number, got {value!r}") from None
    if not (math.isfinite(number) and number > 0.0):
        raise StickslipError(f"{name} must be a positive finite number, got {value!r}")
    return number


def whole_count(value: float) -> int | float:
    """A count a kernel returned as a float, as an int; NaN or inf unchanged, for :func:`checked_finite_results` to
    refuse with the other results (``int(nan)`` would raise before it could)."""
    return int(value) if math.isfinite(value) else float(value)


def checked_finite_results(values: dict, where: str) -> dict:
    """``values`` (name -> number) unchanged if every number is finite; else StickslipError naming them.

    Huge accelerations (1e200 g) or extreme time steps can overflow double
    precision in an integration; a result of inf or NaN is refused rather
    than printed or stored.
    """
    bad = [name for name, value in values.items() if not math.isfinite(value)]
    if bad:
        shown = ", ".join(f"{name} = {values[name]}" for name in bad[:4])
        raise StickslipError(
            f"{where}: results are not finite ({shown}): the record's values or time step are beyond what double "
            "precision can integrate; check its units and dt"
        )
    return values
