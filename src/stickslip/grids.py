"""What a sweep varies: friction ratios μ of a flat surface or yield coefficients k_y of a block on a slope.

A :class:`Grid` holds the swept values [1], gravity g [m/s²] and how the
block slides at each value: a friction ratio μ gives
:meth:`~stickslip.solvers.resistance.Resistance.friction`, a yield
coefficient k_y (yield acceleration / g) gives
:meth:`~stickslip.solvers.resistance.Resistance.one_way` (``direction``
``"down"``, the default) or :meth:`~stickslip.solvers.resistance.Resistance.two_way`
(``"both"``, with a thrust angle [degrees]); ``inverse`` solves the records
with their sign flipped (SLAMMER's inverse polarity).  The kind of value is
data, :data:`COEFFICIENTS`: its name names the cube's dimension and every
per-record result (``mu_max`` or ``ky_max``, :mod:`stickslip.optimum`).

This module imports neither xarray nor numba (the kernels are imported when
a grid is solved), so that ``stickslip optimum`` starts fast.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from stickslip.checks import checked_positive
from stickslip.errors import StickslipError
from stickslip.records.process import peak_ground_acceleration
from stickslip.records.record import Record
from stickslip.solvers.resistance import Resistance, check_options


@dataclass(frozen=True)
class Coefficient:
    """A kind of swept coefficient, dimensionless.

    Attributes
    ----------
    name:
        Its name in a cube (the dimension) and in the per-record results (``mu`` in ``mu_max``).
    symbol:
        How reports write it (μ, k_y).
    noun, plural:
        What one value and several are called in text ("friction ratio").
    long_name:
        The cube coordinate's CF long_name.
    energy:
        What E_df is, in the long names of the results ("energy dissipated by friction").
    """

    name: str
    symbol: str
    noun: str
    plural: str
    long_name: str
    energy: str


#: The coefficients a grid may sweep, by name.
COEFFICIENTS = {
    "mu": Coefficient("mu", "μ", "friction ratio", "friction ratios", "friction ratio (Coulomb coefficient)",
                      "energy dissipated by friction"),
    "ky": Coefficient("ky", "k_y", "yield coefficient", "yield coefficients", "yield coefficient k_y (yield acceleration / g)",
                      "energy dissipated by the resisting force"),
}


#: Most values a ``start:stop:step`` grid may hold (a guard against a mistyped step).
MAX_GRID_VALUES = 1_000_000


def range_values(start: float, stop: float, step: float) -> np.ndarray:
    """The values start, start + step, … up to ``stop`` (included when it lies on the grid, within 1e-9 steps).

    Each value is rounded to 12 decimals, so that 0.1 + 2·0.05 is 0.2; the
    bounds are those :func:`checked_range` accepts.
    """
    count = math.floor((stop - start) / step + 1e-9) + 1
    return np.round(start + step * np.arange(count), 12)


def checked_range(start: float, stop: float, step: float, what: str, quantity: str = "values",
                  min_values: int = 1) -> tuple[float, float, float]:
    """``(start, stop, step)`` of a grid, checked: finite, 0 < start ≤ stop, step > 0, at most :data:`MAX_GRID_VALUES`.

    The one check of a ``start:stop:step`` grid, for the command line and the
    workflow's configuration alike.  ``what`` names the grid in a message
    (``--mu '0.2:0.1:0.01'``, ``fine_mu``), ``quantity`` its values
    (``friction ratios mu``); ``min_values`` is how many values the grid needs.
    """
    if not all(math.isfinite(value) for value in (start, stop, step)) or step <= 0:
        raise StickslipError(f"{what}: STEP must be a positive number, got {step:g}")
    if start <= 0:
        raise StickslipError(f"{what}: {quantity} must be positive, START is {start:g}")
    if not start <= stop:
        raise StickslipError(f"{what}: expected 0 < START <= STOP, got START {start:g} and STOP {stop:g}")
    intervals = (stop - start) / step + 1e-9
    if not intervals < MAX_GRID_VALUES:  # also catches an infinite quotient
        count = f"{math.floor(intervals) + 1:,}" if math.isfinite(intervals) else "infinitely many"
        raise StickslipError(f"{what}: {count} {quantity}; at most {MAX_GRID_VALUES:,} are allowed (use a larger STEP)")
    if math.floor(intervals) + 1 < min_values:
        raise StickslipError(f"{what}: {quantity} from START {start:g} to STOP {stop:g} by STEP {step:g} number "
                             f"{math.floor(intervals) + 1}; at least {min_values} are needed")
    return float(start), float(stop), float(step)


def grid_values(spec, what: str = "grid") -> np.ndarray:
    """The values of a configured grid [1]: a list as given, or ``{start, stop, step}`` by :func:`range_values`.

    Both are checked (:func:`positive_increasing`, :func:`checked_range`); ``what`` names the grid in a message.
    """
    if isinstance(spec, Mapping):
        return range_values(*checked_range(spec["start"], spec["stop"], spec["step"], what))
    return positive_increasing(spec, what)


def positive_increasing(values: Iterable[float], what: str, zero_allowed: bool = False) -> np.ndarray:
    """``values`` as a strictly increasing 1-D float array of positive (or, ``zero_allowed``, non-negative) numbers.

    The one check of a list of grid values; otherwise one clear line naming ``what``.
    """
    try:
        array = np.atleast_1d(np.asarray(values, dtype=float))
    except (TypeError, ValueError):
        raise StickslipError(f"{what}: expected numbers, got {values!r}") from None
    if array.ndim != 1 or array.size == 0:
        raise StickslipError(f"{what}: expected a non-empty list of numbers")
    if not np.all(np.isfinite(array)) or np.any(array < 0 if zero_allowed else array <= 0):
        sign = "non-negative" if zero_allowed else "positive"
        raise StickslipError(f"{what}: every value must be a {sign} finite number, got {array.tolist()}")
    if np.any(np.diff(array) <= 0):
        raise StickslipError(f"{what}: values must be strictly increasing, got {array.tolist()}")
    return array


class Grid:
    """The swept coefficient: friction ratios ``mu`` or yield coefficients ``ky`` [1], and how the block slides.

    Parameters
    ----------
    g:
        Gravitational acceleration [m/s²].
    mu, ky:
        Exactly one: positive, strictly increasing friction ratios or yield coefficients [1].
    direction, thrust_angle:
        With ``ky``: ``"down"`` (default) or ``"both"``, and the thrust angle
        [degrees], as :func:`stickslip.solve` takes them.
    inverse:
        Solve the records with their sign flipped (SLAMMER's inverse polarity).

    Attributes
    ----------
    name, values, g, inverse:
        As given (``name`` is ``"mu"`` or ``"ky"``).
    options:
        ``direction`` and ``thrust_angle`` where given.
    resistances:
        One :class:`~stickslip.solvers.resistance.Resistance` per value of a
        ``ky`` grid; None for a friction grid, which the kernels take as μ and g.
    """

    def __init__(self, g: float, mu=None, ky=None, direction: str | None = None, thrust_angle: float | None = None,
                 inverse: bool = False):
        check_options(mu is not None, ky is not None, direction, thrust_angle)
        self.g = checked_positive(g, "gravity g [m/s²]")
        self.name = "mu" if mu is not None else "ky"
        self.values = positive_increasing(mu if mu is not None else ky, f"{self.coefficient.plural} {self.name}")
        self.options = {key: value for key, value in (("direction", direction), ("thrust_angle", thrust_angle))
                        if value is not None}
        self.inverse = bool(inverse)
        self.resistances = [self.resistance(value) for value in self.values] if self.name == "ky" else None

    @property
    def coefficient(self) -> Coefficient:
        """What the grid sweeps (:data:`COEFFICIENTS`)."""
        return COEFFICIENTS[self.name]

    def resistance(self, value: float) -> Resistance:
        """The resistance of the block at one ``value`` of the coefficient [1]."""
        return Resistance.from_options(self.g, **{self.name: float(value)}, **self.options)

    def sliding(self) -> dict:
        """How the block slides, as the keywords of :func:`stickslip.analysis.energy_dissipated_function`."""
        return {"coefficient": self.name, **self.options, "inverse": self.inverse}

    def solved(self, acceleration: np.ndarray) -> np.ndarray:
        """The ground acceleration [m/s²] as the solver takes it: sign flipped in inverse polarity."""
        return -acceleration if self.inverse else acceleration

    def sweep_scalars(self, accelerations: Sequence[np.ndarray], dts: Sequence[float]) -> np.ndarray:
        """The exact kernel's scalars (n_records, n_values, n_scalars), energies per unit mass [J/kg].

        A friction grid goes to the kernel as μ and g, a ``ky`` grid as its resistances.
        """
        from stickslip.solvers.exact import sweep_scalars

        accelerations = [self.solved(acceleration) for acceleration in accelerations]
        if self.name == "mu":
            return sweep_scalars(accelerations, dts, self.values, self.g)
        return sweep_scalars(accelerations, dts, resistances=self.resistances)

    def first_without_sliding(self, acceleration: np.ndarray) -> int:
        """Index of the first value from which on the block never slides on ``acceleration`` [m/s²] (size: none).

        The block (at rest, sample values linear between samples) slides only
        where the ground acceleration a (sign flipped in inverse polarity)
        rises above the resistance's :attr:`~Resistance.upper` or falls below
        its :attr:`~Resistance.lower`; both move away from zero as the
        coefficient grows, so the values without sliding are a tail of the grid.
        """
        solved = self.solved(np.asarray(acceleration, dtype=float))
        largest, smallest = (float(solved.max()), float(solved.min())) if solved.size else (0.0, 0.0)

        def still(index: int) -> bool:
            resistance = self.resistance(self.values[index])
            return largest <= resistance.upper and smallest >= resistance.lower

        low, high = 0, self.values.size
        while low < high:  # bisection over the grid: still() is False, then True
            middle = (low + high) // 2
            if still(middle):
                high = middle
            else:
                low = middle + 1
        return low

    def describe(self) -> str:
        """How the block slides, in words: ``flat surface`` or ``one-way (downslope only)``, and the polarity."""
        if self.name == "mu":
            text = "flat surface"
        elif self.options.get("direction", "down") == "down":
            text = "one-way (downslope only)"
        else:
            text = f"two-way, thrust angle {self.options.get('thrust_angle', 0.0):g} deg"
        return text + ("; inverse polarity (record sign flipped)" if self.inverse else "")

    def thresholds_text(self) -> tuple[str, str]:
        """How the levels ``upper`` and ``lower`` of its resistance are written: ``("mu*g", "-mu*g")`` and the like."""
        if self.name == "mu":
            return "mu*g", "-mu*g"
        return "ky*g", "-(ky*g + 2 g sin(thrust angle))"


def never_slides_reason(record: Record, grid: Grid, index: int = 0) -> str:
    """Why the block never slides on ``record`` (m/s²) at ``grid.values[index]``: the record's extremes and the levels.

    A friction grid compares the PGA with μ·g; a ``ky`` grid the largest a
    (sign flipped in inverse polarity) with the downslope level k_y·g and,
    two-way, the smallest with the upslope level (the resistance's
    :attr:`~stickslip.solvers.resistance.Resistance.upper` and
    :attr:`~stickslip.solvers.resistance.Resistance.lower`).
    """
    g, value = grid.g, float(grid.values[index])
    smallest_of_several = index == 0 and grid.values.size > 1
    where = f"the grid's smallest {grid.name}, {value:g}" if smallest_of_several else f"{grid.name} = {value:g}"
    resistance = grid.resistance(value)
    upper_text, lower_text = grid.thresholds_text()
    if grid.name == "mu":
        pga = peak_ground_acceleration(record)
        compared = "is at most" if pga <= resistance.upper else "barely exceeds"
        return f"its PGA {pga:.4g} m/s2 ({pga / g:.4g} g) {compared} {upper_text} = {resistance.upper:.4g} m/s2 at {where}"
    solved = grid.solved(record.acceleration)
    largest = float(solved.max())
    which = "a (the record's sign flipped: inverse polarity)" if grid.inverse else "a"
    parts = [f"its largest {which}, {largest:.4g} m/s2 ({largest / g:.4g} g), "
             f"{'is at most' if largest <= resistance.upper else 'barely exceeds'} the downslope level "
             f"{upper_text} = {resistance.upper:.4g} m/s2"]
    if math.isfinite(resistance.lower):
        smallest = float(solved.min())
        parts.append(f"its smallest, {smallest:.4g} m/s2 ({smallest / g:.4g} g), "
                     f"{'is at least' if smallest >= resistance.lower else 'barely falls below'} the upslope level "
                     f"{lower_text} = {resistance.lower:.4g} m/s2")
        return " and ".join(parts) + f" at {where}"
    return parts[0] + f" at {where} (one-way: the block slides only downslope, where a exceeds ky*g)"
