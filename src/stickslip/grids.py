"""What a sweep varies: friction ratios μ of a flat surface or yield coefficients k_y of a block on a slope.

A :class:`Grid` holds the swept values [1] of one coefficient, checked
(:func:`positive_increasing`, :func:`checked_range`).  The kind of value is
data, :data:`COEFFICIENTS`: its name names the cube's dimension and every
per-record result (``mu_max`` or ``ky_max``, :mod:`stickslip.optimum`), and
its words name it in text.  How the block slides at each value is its
model's (:mod:`stickslip.models`).

This module imports neither xarray nor numba, so that ``stickslip optimum`` starts fast.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field

import numpy as np

from stickslip.errors import StickslipError


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
    level:
        How the acceleration at which the block starts to slide is written (``mu*g``).
    grid:
        What a grid of it is called in a message (``"friction grid"``).
    heading:
        What a grid of it is called at the head of ``stickslip optimum``'s table (``"friction grid"``).
    reference:
        The value [1] whose E_df and efficiency the design answer reports when none is given
        (:mod:`stickslip.optimum`).
    default_grid:
        The grid ``stickslip optimum`` sweeps when none is given, ``{"start", "stop", "step"}`` [1]; None: it
        must be given.
    slope:
        Whether it places the block on a slope, so that its results include the
        permanent downslope displacement (SLAMMER's number).
    """

    name: str
    symbol: str
    noun: str
    plural: str
    long_name: str
    energy: str
    level: str
    grid: str
    heading: str
    reference: float
    default_grid: Mapping[str, float] | None = field(default=None, compare=False)
    slope: bool = False

    @property
    def title(self) -> str:
        """The title of a cube that sweeps it: ``stickslip friction-ratio sweep``."""
        return f"stickslip {self.noun.replace(' ', '-')} sweep"


#: The reference friction ratio [1]: the paper's recommended μ.
REFERENCE_MU = 0.10

#: The coefficients a grid may sweep, by name.  The reference k_y is μ's, 0.1, so that a two-way yield grid at
#: thrust angle 0 (flat friction with μ = k_y) gives the friction grid's answer, and a value inside the range of
#: yield coefficients engineers use (0.02 to 0.4).  The friction grid when none is given is the collection
#: study's: μ from 0.0025 to 1.0 in steps of 0.0025 (400 values).  Up to 1 because μ·g beyond a record's PGA
#: dissipates nothing, and few records exceed 1 g; steps of 0.0025 resolve μ_max well enough for the continuous
#: search that follows, and keep a record's sweep far below a second.  A yield grid has none: which yield
#: accelerations matter depends on the slope.
COEFFICIENTS = {
    "mu": Coefficient("mu", "μ", "friction ratio", "friction ratios", "friction ratio (Coulomb coefficient)",
                      "energy dissipated by friction", "mu*g", "friction grid", "friction grid", REFERENCE_MU,
                      {"start": 0.0025, "stop": 1.0, "step": 0.0025}),
    "ky": Coefficient("ky", "k_y", "yield coefficient", "yield coefficients", "yield coefficient k_y (yield acceleration / g)",
                      "energy dissipated by the resisting force", "ky*g", "yield grid", "yield-coefficient grid",
                      REFERENCE_MU, slope=True),
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
    """The values [1] of one swept coefficient (:data:`COEFFICIENTS`): positive, finite, strictly increasing.

    How the block slides at each value (gravity, the sliding direction, the
    polarity) is the model's, not the grid's: a sweep holds its model's
    parameters beside its grid.

    Parameters
    ----------
    name:
        The coefficient: ``"mu"`` (friction ratios) or ``"ky"`` (yield coefficients).
    values:
        Its values [1].
    """

    def __init__(self, name: str, values):
        if name not in COEFFICIENTS:
            raise StickslipError(f"a grid sweeps one of {', '.join(COEFFICIENTS)}, not {name!r}")
        self.name = name
        self.values = positive_increasing(values, f"{COEFFICIENTS[name].plural} {name}")

    @classmethod
    def of(cls, **given) -> Grid:
        """The grid of the one coefficient given among ``given`` (``Grid.of(mu=[0.05, 0.1], ky=None)``)."""
        names = [name for name in COEFFICIENTS if given.get(name) is not None]
        if len(names) != 1:
            raise StickslipError(f"give the values of one swept coefficient ({' or '.join(COEFFICIENTS)}), got "
                                 f"{', '.join(names) or 'none'}")
        return cls(names[0], given[names[0]])

    @property
    def coefficient(self) -> Coefficient:
        """What the grid sweeps (:data:`COEFFICIENTS`)."""
        return COEFFICIENTS[self.name]

    def with_values(self, values) -> Grid:
        """A grid of the same coefficient at other ``values`` [1]."""
        return Grid(self.name, values)

    def __repr__(self) -> str:
        return f"Grid({self.name!r}, {self.values.size} values from {self.values[0]:g} to {self.values[-1]:g})"


def grid_dimension(dims) -> str:
    """The name of the swept coefficient among a cube's dimensions ``dims`` (:data:`COEFFICIENTS`)."""
    for name in COEFFICIENTS:
        if name in dims:
            return name
    raise StickslipError(f"no swept coefficient ({', '.join(COEFFICIENTS)}) among the dimensions {', '.join(dims)}")
