"""A yield coefficient that varies with the block's downslope displacement: SLAMMER's "varies with displacement".

A :class:`YieldTable` holds pairs (D_i, k_y,i): the accumulated downslope
displacement D_i [m] of the block relative to its base and the yield
coefficient k_y,i [1] (yield acceleration / g) there.  Between pairs k_y is
interpolated linearly in D; past the last pair it keeps the last value.  The
first displacement is 0, where every analysis starts (SLAMMER locks the first
row of its table at 0).  This is the definition of SLAMMER 1.1's help
(``rigorous.html``: "The program linearly interpolates critical-acceleration
values between points. The critical acceleration remains constant at the last
value specified when the last displacement specified is exceeded") and of its
rigid block (``RigidBlock.java``); SLAMMER's table is in cm (or inches), this
one in metres.

The kernels take the table as yield accelerations, (D_i [m], k_y,i·g [m/s²])
(:meth:`YieldTable.thresholds`); :func:`table_value` and
:func:`table_integral` evaluate such a piecewise-linear function and its
integral.  A constant k_y is a table of one pair, (0, k_y).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from stickslip.errors import StickslipError


@dataclass(frozen=True)
class YieldTable:
    """k_y(D): the yield coefficient [1] against the accumulated downslope displacement D [m].

    Attributes
    ----------
    displacement:
        D_i [m]: starts at 0 and increases strictly.
    ky:
        k_y,i [1] at D_i: positive and finite.  Linear in D between pairs,
        constant past the last one.

    Invalid pairs raise :class:`~stickslip.errors.StickslipError` (one line).
    """

    displacement: tuple[float, ...]
    ky: tuple[float, ...]

    def __post_init__(self):
        displacement, ky = checked_pairs(self.displacement, self.ky, "yield table")
        object.__setattr__(self, "displacement", displacement)
        object.__setattr__(self, "ky", ky)

    @classmethod
    def from_pairs(cls, pairs, source: str = "yield table") -> YieldTable:
        """The table of the pairs (D [m], k_y [1]); errors name ``source`` (a file, an option)."""
        pairs = list(pairs)
        if any(len(pair) != 2 for pair in pairs):
            raise StickslipError(f"{source}: expected pairs of displacement D [m] and k_y [1]")
        return cls(*checked_pairs([d for d, _ in pairs], [k for _, k in pairs], source))

    @classmethod
    def read(cls, path: str | Path) -> YieldTable:
        """The table of a text file: one pair a line, displacement D [m] and k_y [1], by blanks or a comma.

        Blank lines and text after ``#`` are ignored.  A missing file or a bad
        line raises :class:`StickslipError` naming the file (and the line).
        """
        try:
            text = Path(path).read_text(encoding="utf-8")
        except FileNotFoundError:
            raise StickslipError(f"{path}: file not found (expected a yield table: lines of D [m] and k_y)") from None
        except (OSError, UnicodeDecodeError) as error:
            raise StickslipError(f"{path}: cannot read the yield table ({error})") from None
        pairs = []
        for number, line in enumerate(text.splitlines(), start=1):
            fields = line.split("#", 1)[0].replace(",", " ").split()
            if not fields:
                continue
            if len(fields) != 2:
                raise StickslipError(f"{path}: line {number}: expected two numbers, displacement D [m] and k_y, "
                                     f"got {line.strip()!r}")
            pairs.append(_numbers(fields, f"{path}: line {number}"))
        if not pairs:
            raise StickslipError(f"{path}: no pairs of displacement D [m] and k_y")
        return cls.from_pairs(pairs, str(path))

    @classmethod
    def parse(cls, text: str, source: str = "yield table") -> YieldTable:
        """The table written inline as ``D:KY`` pairs separated by commas, D [m]: ``"0:0.15,0.1:0.10"``."""
        pairs = []
        for number, pair in enumerate(text.split(","), start=1):
            fields = pair.split(":")
            if len(fields) != 2:
                raise StickslipError(f"{source}: pair {number} {pair.strip()!r} is not D:KY (displacement [m]:k_y)")
            pairs.append(_numbers(fields, f"{source}: pair {number}"))
        return cls.from_pairs(pairs, source)

    def __len__(self) -> int:
        return len(self.displacement)

    def at(self, displacement):
        """k_y [1] at the downslope displacement(s) D [m] ≥ 0."""
        return np.interp(displacement, self.displacement, self.ky)

    def thresholds(self, g: float) -> tuple[tuple[float, ...], tuple[float, ...]]:
        """(D_i [m], k_y,i·g [m/s²]): the table as the yield accelerations the kernels take, g [m/s²]."""
        return self.displacement, tuple(ky * g for ky in self.ky)

    def parameters(self) -> dict:
        """``{"ky": [k_y,i], "ky_displacement": [D_i]}``: how results record the table (k_y [1], D [m])."""
        return {"ky": list(self.ky), "ky_displacement": list(self.displacement)}

    def describe(self) -> str:
        """One line: ``ky(D) = 0:0.15, 0.1:0.1 (D [m]:ky, linear, constant past the last)``."""
        return describe_pairs(self.displacement, self.ky)


def checked_pairs(displacement, ky, source: str) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """The table's columns as tuples of floats, or StickslipError (one line, ``source`` first) saying what is wrong."""
    try:
        displacement = tuple(float(value) for value in displacement)
        ky = tuple(float(value) for value in ky)
    except (TypeError, ValueError):
        raise StickslipError(f"{source}: displacements [m] and k_y must be numbers") from None
    if len(displacement) != len(ky):
        raise StickslipError(f"{source}: {len(displacement)} displacements but {len(ky)} values of k_y")
    if not displacement:
        raise StickslipError(f"{source}: needs at least one pair of displacement D [m] and k_y")
    for number, (d, k) in enumerate(zip(displacement, ky), start=1):
        if not (math.isfinite(d) and math.isfinite(k)):
            raise StickslipError(f"{source}: pair {number} ({d:g} m, {k:g}) is not finite")
        if not k > 0.0:
            raise StickslipError(f"{source}: pair {number}: k_y must be positive, got {k:g}")
    if displacement[0] != 0.0:
        raise StickslipError(f"{source}: the first displacement must be 0 m (every analysis starts there), "
                             f"got {displacement[0]:g} m")
    for number in range(1, len(displacement)):
        if not displacement[number] > displacement[number - 1]:
            raise StickslipError(f"{source}: displacements must increase strictly: pair {number + 1} has "
                                 f"{displacement[number]:g} m after {displacement[number - 1]:g} m")
    return displacement, ky


def describe_pairs(displacement, ky) -> str:
    """``ky(D) = 0:0.15, 0.1:0.1 (D [m]:ky, linear, constant past the last)`` for the columns D_i [m], k_y,i [1]."""
    pairs = ", ".join(f"{d:g}:{k:g}" for d, k in zip(displacement, ky))
    return f"ky(D) = {pairs} (D [m]:ky, linear, constant past the last)"


def _numbers(fields, where: str) -> tuple[float, float]:
    """Two fields as floats, or StickslipError naming ``where`` and the field."""
    try:
        return float(fields[0]), float(fields[1])
    except ValueError:
        raise StickslipError(f"{where}: {':'.join(field.strip() for field in fields)!r} is not two numbers") from None


def table_value(x, points, values):
    """The piecewise-linear function of the table (``points``, ``values``) at x ≥ points[0]; constant past the last.

    A scalar function for the kernels: plain Python on lists or tuples, numba
    on arrays.  With one point it returns ``values[0]`` without arithmetic.
    """
    last = len(points) - 1
    segment = 0
    while segment < last and x > points[segment + 1]:
        segment += 1
    if segment == last:
        return values[last]
    fraction = (x - points[segment]) / (points[segment + 1] - points[segment])
    return values[segment] + (values[segment + 1] - values[segment]) * fraction


def table_integral(x, points, values):
    """∫ from points[0] to x of the table's piecewise-linear function (``x`` an array ≥ points[0]).

    With one point (a constant v) it is v·(x − points[0]), which is v·x bit
    for bit when the table starts at 0.
    """
    points = np.asarray(points, dtype=float)
    values = np.asarray(values, dtype=float)
    widths = np.diff(points)
    slopes = np.append(np.diff(values) / widths, 0.0)
    areas = np.concatenate(([0.0], np.cumsum(0.5 * (values[1:] + values[:-1]) * widths)))
    segment = np.searchsorted(points, x, side="right") - 1
    into = x - points[segment]
    return areas[segment] + into * (values[segment] + 0.5 * slopes[segment] * into)
