"""What resists a sliding block: one threshold per sliding direction and a constant body force.

Every solver works per unit mass on an axis x along the sliding surface; x is
the block's displacement relative to the base [m] and a(t) = ü_g the base
acceleration along +x [m/s²].  A positive a drives the block towards −x
relative to the base (its inertia lags behind), so on a slope **−x is
downslope** and the record's positive direction points upslope: SLAMMER's
"normal polarity", in which positive accelerations above k_y·g drive
downslope sliding.

With b a constant body acceleration along +x (the along-slope component of
gravity) and e(t) = a(t) − b, the block

* sticks while −T₊ ≤ e ≤ T₋;
* slides in the direction s = ±1 (ẋ ≷ 0) with ẍ = −e − s·T_s,
  T_s = T₊ for s = +1 and T₋ for s = −1;
* stops when ẋ = 0, and then sticks or slides the other way.

A :class:`Resistance` holds T₊, T₋ and b [m/s²]; its constructors build the
variants from what engineers specify:

========================  ===========================  ==========  ====================
variant                   T₊ (towards +x, upslope)     T₋          b
========================  ===========================  ==========  ====================
:meth:`friction` (flat)   μ·g                          μ·g         0
:meth:`one_way`           +∞ (never)                   k_y·g       0
:meth:`two_way`           k_y·g + g·sin β              same        −g·sin β
========================  ===========================  ==========  ====================

:meth:`two_way` is SLAMMER's "downslope and upslope" rigid block at a thrust
angle β: the block slides downslope when a > k_y·g and upslope when
a < −(k_y·g + 2·g·sin β).  For a block with friction coefficient μ on a plane
inclined at β, shaken along the plane, it is exact with k_y = μ·cos β − sin β
(docs/solvers.md derives it).  The motion depends only on the two ground
accelerations that bound the stick band, :attr:`Resistance.upper` = b + T₋ and
:attr:`Resistance.lower` = b − T₊; b splits the work between dissipation
(E_df = Σ T_s·|Δx|) and the body force (W_b = b·x).

A new variant with constant thresholds is one more constructor here; the
kernels take the plain floats (T₊, T₋, b) of :meth:`Resistance.thresholds`.

:meth:`one_way` also takes a :class:`~stickslip.models.yield_table.YieldTable`,
a k_y that varies with the accumulated downslope displacement D: T₋(D) =
k_y(D)·g, linear between the table's pairs and constant past the last.  Only
the schemes that declare it solve such a block (the registry's
:attr:`~stickslip.models.rigid.scheme.Scheme.yield_table`); they read it from
:meth:`Resistance.downslope_thresholds`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from stickslip.checks import checked_positive
from stickslip.errors import StickslipError
from stickslip.grids import COEFFICIENTS
from stickslip.models.yield_table import YieldTable, describe_pairs, table_integral

#: The sliding directions of a yield coefficient k_y: downslope only, or both ways.
DIRECTIONS = ("down", "both")


@dataclass(frozen=True)
class Resistance:
    """Thresholds of sliding and the constant body acceleration, per unit mass [m/s²].

    Attributes
    ----------
    positive:
        T₊ > 0, the resisting acceleration while sliding towards +x (upslope);
        ``math.inf`` when the block never slides that way.
    negative:
        T₋ > 0, the resisting acceleration while sliding towards −x (downslope), finite.
    body:
        b, a constant body acceleration on the block along +x (gravity's
        along-slope component, −g·sin β); 0 on a flat surface.
    parameters:
        How it was specified, e.g. ``{"mu": 0.1}`` or ``{"ky": 0.15,
        "direction": "both", "thrust_angle": 10.0}`` (angles in degrees);
        written as attributes of results.  Not compared.  A yield table gives
        ``{"ky": [k_y,i], "ky_displacement": [D_i], "direction": "down"}``.
    threshold_table:
        ``(D_i [m], T₋,i [m/s²])`` when T₋ varies with the accumulated
        downslope displacement (:meth:`one_way` of a
        :class:`~stickslip.models.yield_table.YieldTable`), T₋,0 =
        ``negative``; None when T₋ is constant.
    """

    positive: float
    negative: float
    body: float = 0.0
    parameters: dict = field(default_factory=dict, compare=False)
    threshold_table: tuple[tuple[float, ...], tuple[float, ...]] | None = None

    def __post_init__(self):
        finite_body = math.isfinite(self.body)
        if not (self.positive > 0.0 and 0.0 < self.negative < math.inf and finite_body):
            raise StickslipError(
                f"resistance: expected thresholds T+ > 0 (may be inf), 0 < T- < inf and a finite body "
                f"acceleration, got T+ = {self.positive!r}, T- = {self.negative!r}, b = {self.body!r} m/s2"
            )

    @property
    def flat(self) -> bool:
        """Whether it is flat friction: the same threshold both ways and no body acceleration."""
        return self.positive == self.negative and self.body == 0.0

    @classmethod
    def friction(cls, mu: float, g: float) -> Resistance:
        """A flat surface with Coulomb friction ratio ``mu`` [-] under gravity ``g`` [m/s²]: T₊ = T₋ = μ·g, b = 0."""
        mu = checked_positive(mu, "friction ratio mu")
        limit = mu * checked_positive(g, "gravity g [m/s2]")
        return cls(limit, limit, 0.0, {"mu": mu})

    @classmethod
    def one_way(cls, ky: float | YieldTable, g: float) -> Resistance:
        """Newmark's rigid block: slides downslope (−x) past k_y·g [m/s²], never upslope.

        ``ky`` is the yield coefficient k_y [-] (yield acceleration / g), or a
        :class:`~stickslip.models.yield_table.YieldTable` of k_y against the
        accumulated downslope displacement [m] (a table of one pair is its
        constant k_y); ``g`` [m/s²].
        """
        if isinstance(ky, YieldTable) and len(ky) == 1:
            ky = ky.ky[0]
        if isinstance(ky, YieldTable):
            points, thresholds = ky.thresholds(checked_positive(g, "gravity g [m/s2]"))
            return cls(math.inf, thresholds[0], 0.0, {**ky.parameters(), "direction": "down"},
                       threshold_table=(points, thresholds))
        ky = checked_positive(ky, "yield coefficient ky")
        return cls(math.inf, ky * checked_positive(g, "gravity g [m/s2]"), 0.0, {"ky": ky, "direction": "down"})

    @classmethod
    def two_way(cls, ky: float, g: float, thrust_angle: float = 0.0) -> Resistance:
        """SLAMMER's two-way rigid block at a thrust angle β [degrees, 0 to 90].

        Downslope (−x) past k_y·g, upslope past k_y·g + 2·g·sin β: T₊ = T₋ =
        k_y·g + g·sin β, b = −g·sin β.  β = 0 is flat friction with μ = k_y.
        """
        if isinstance(ky, YieldTable):
            raise StickslipError("a yield table (ky varying with displacement) applies to one-way (downslope) "
                                 "sliding, not to direction 'both'")
        ky = checked_positive(ky, "yield coefficient ky")
        g = checked_positive(g, "gravity g [m/s2]")
        angle = _checked_angle(thrust_angle)
        along_slope = g * math.sin(math.radians(angle))
        limit = ky * g + along_slope
        return cls(limit, limit, -along_slope, {"ky": ky, "direction": "both", "thrust_angle": angle})

    @classmethod
    def from_options(
        cls,
        g: float,
        mu: float | None = None,
        ky: float | None = None,
        direction: str | None = None,
        thrust_angle: float | None = None,
    ) -> Resistance:
        """The resistance that :func:`stickslip.solve` and :func:`stickslip.sweep` are given.

        Exactly one of ``mu`` (flat friction) and ``ky`` (a yield coefficient;
        ``direction`` ``"down"`` by default, or ``"both"`` with an optional
        ``thrust_angle`` [degrees]; a :class:`~stickslip.models.yield_table.YieldTable`
        for one-way sliding).
        """
        check_options(mu is not None, ky is not None, direction, thrust_angle)
        if mu is not None:
            return cls.friction(mu, g)
        if direction == "both":
            return cls.two_way(ky, g, 0.0 if thrust_angle is None else thrust_angle)
        return cls.one_way(ky, g)

    @property
    def upper(self) -> float:
        """b + T₋ [m/s²]: above this ground acceleration the block slides towards −x (downslope)."""
        return self.body + self.negative

    @property
    def lower(self) -> float:
        """b − T₊ [m/s²]: below this ground acceleration it slides towards +x (−inf: never)."""
        return self.body - self.positive

    @property
    def coefficient(self) -> str | None:
        """The swept coefficient it was given by (:data:`stickslip.grids.COEFFICIENTS`: ``mu`` or ``ky``), or None."""
        return next((name for name in COEFFICIENTS if name in self.parameters), None)

    @property
    def value(self) -> str:
        """Its coefficient and value, ``mu = 0.1`` (a yield table: the table's line)."""
        if self.threshold_table is not None:
            return describe_pairs(self.parameters["ky_displacement"], self.parameters["ky"])
        if self.coefficient is None:
            return self.describe()
        return f"{self.coefficient} = {self.parameters[self.coefficient]:g}"

    @property
    def on_slope(self) -> bool:
        """Whether it was given as a yield coefficient of a block on a slope (so that "downslope" has a meaning)."""
        return self.coefficient is not None and COEFFICIENTS[self.coefficient].slope

    def thresholds(self) -> tuple[float, float, float]:
        """(T₊, T₋, b) [m/s²], the floats the kernels take."""
        return self.positive, self.negative, self.body

    def downslope_thresholds(self) -> tuple[tuple[float, ...], tuple[float, ...]]:
        """(D_i [m], T₋,i [m/s²]): T₋ against the accumulated downslope displacement; ``((0.0,), (T₋,))`` if constant."""
        return self.threshold_table or ((0.0,), (self.negative,))

    def downslope_work(self, path):
        """∫ T₋ dD [J/kg] over a downslope path D [m] (an array) from D = 0: T₋·D for a constant T₋."""
        return table_integral(path, *self.downslope_thresholds())

    def describe(self, g: float | None = None) -> str:
        """One line such as ``mu = 0.1`` or ``ky = 0.15, two-way, thrust angle 10 deg``.

        With ``g`` [m/s²], a yield coefficient also shows its yield acceleration:
        ``ky = 0.15 (k_y*g = 1.472 m/s2), one-way (downslope)``.
        """
        if not self.parameters:
            return f"T+ = {self.positive:g}, T- = {self.negative:g}, b = {self.body:g} m/s2"
        if not self.on_slope:
            return f"{self.coefficient} = {self.parameters[self.coefficient]:g}"
        if self.threshold_table is not None:
            return describe_pairs(self.parameters["ky_displacement"], self.parameters["ky"]) + ", one-way (downslope)"
        ky = self.parameters["ky"]
        text = f"ky = {ky:g}" + ("" if g is None else f" (k_y*g = {ky * g:.4g} m/s2)")
        if self.parameters["direction"] == "down":
            return text + ", one-way (downslope)"
        return text + f", two-way, thrust angle {self.parameters['thrust_angle']:g} deg"


def check_options(has_mu: bool, has_ky: bool, direction: str | None, thrust_angle: float | None) -> None:
    """Refuse combinations of the resistance options that mean nothing (StickslipError, one line)."""
    if has_mu and has_ky:
        raise StickslipError("give either a friction ratio mu or a yield coefficient ky, not both")
    if not (has_mu or has_ky):
        raise StickslipError("give a friction ratio mu or a yield coefficient ky")
    if has_mu and (direction is not None or thrust_angle is not None):
        raise StickslipError("direction and thrust_angle apply to a yield coefficient ky, not to a friction ratio mu")
    if direction is not None and direction not in DIRECTIONS:
        raise StickslipError(f"direction must be one of {', '.join(DIRECTIONS)}, got {direction!r}")
    if thrust_angle is not None and direction != "both":
        raise StickslipError("thrust_angle applies to two-way sliding (direction 'both') only")


def _checked_angle(angle: float) -> float:
    """A thrust angle [degrees] in [0, 90], as SLAMMER accepts it."""
    try:
        value = float(angle)
    except (TypeError, ValueError):
        raise StickslipError(f"thrust angle [degrees] must be a number, got {angle!r}") from None
    if not 0.0 <= value <= 90.0:
        raise StickslipError(f"thrust angle [degrees] must be between 0 and 90, got {angle!r}")
    return value
