"""The design answer of a sweep, per record: the coefficient of maximum dissipation, the near-optimal range, the stroke there.

The one definition of each per-record result, used by ``stickslip optimum``,
the cubes of ``stickslip sweep``, the workflow's Tables 6 and 7
(:mod:`stickslip.studies.mu_max`), the collection study
(:mod:`stickslip.studies.collections.sweep`) and the record report
(``stickslip report``).  A sweep varies one coefficient c over a grid
c_1 < … < c_n (:class:`stickslip.grids.Grid`): the friction ratio μ of a flat
surface, or the yield coefficient k_y of a block on a slope (one-way or
two-way, either polarity).  The coefficient's name names the results: with
c = ``mu`` (``ky`` for a yield grid), for each record (or scaled version of one):

``mu_max``, ``energy_dissipated_max`` [J]
    the grid value of largest dissipated energy E_df and E_df there
    (:func:`stickslip.analysis.mu_max_on_grid`; ties go to the smallest value);
``mu_max_at_grid_edge``
    1 when it is c_1 or c_n (the true maximum may lie outside the grid), else 0;
``mu_max_continuous``, ``energy_dissipated_max_continuous`` [J]
    the maximum of E_df(c) found continuously between the neighbours of the
    grid's best point (:func:`refine_mu_max`), with the sweep's solver;
``mu_low``, ``mu_high``, ``contiguous``
    the near-optimal range {c : E_df ≥ q·E_df,max} on the grid
    (:func:`stickslip.analysis.near_optimal_range`), and 1 when every grid
    value between its ends qualifies;
``mu_low_at_grid_edge``, ``mu_high_at_grid_edge``
    1 when ``mu_low`` is c_1 (``mu_high`` is c_n): the range may reach beyond
    the grid, and its end and the range's largest values are bounds
    (:func:`range_bounds`), else 0;
``energy_dissipated_reference`` [J], ``efficiency`` [1]
    E_df at the reference value c_ref (the coefficient's ``reference``, :data:`stickslip.grids.COEFFICIENTS`), and
    E_df(c_ref) / E_df,max,continuous;
``peak_relative_displacement_at_*``, ``residual_displacement_at_*`` [m]
    the stroke (largest |x|, x the block's displacement relative to the base)
    and the residual displacement x at the end of the record, at ``mu_max``,
    ``mu_low`` and ``mu_high``; a ``ky`` grid adds ``downslope_displacement_at_*``
    = −x at the end (SLAMMER's permanent displacement, positive downslope);
``largest_stroke``, ``mu_at_largest_stroke``, ``largest_residual_displacement``, ``mu_at_largest_residual_displacement``
    the design quantities: the largest stroke [m] and the residual
    displacement of largest magnitude [m] at any grid value of the whole
    near-optimal range (from ``mu_low`` to ``mu_high``, gaps included: a
    device chosen anywhere in the range must accommodate them), and the
    value where each occurs; a ``ky`` grid adds ``largest_downslope_displacement``
    = −``largest_residual_displacement``;
``<demand>_at_*``, ``largest_<demand>``, ``mu_at_largest_<demand>``
    the same for each further demand the model's design declares (its
    ``demands``: the friction pendulum's peak base shear coefficient V/W [1]);
``optimum_status``
    ``"ok"``; ``"never slides: …"`` for a record whose block slides at no
    value of the grid (E_df = 0 everywhere: its ground acceleration never
    leaves the stick band of the grid's first value,
    :meth:`Design.still_reason` says how), which then has no
    optimum, range, stroke or efficiency (NaN; its E_df,max is 0 J); or
    ``"not solved"`` for a record that could not be swept (missing, rejected).

A grid too coarse for a record's range (a weak record's μ_max ≈ 0.0066 on a
grid of steps of 0.0025 has a range of two grid values) is refined around
that range by :func:`refine_for_ranges`, until the range holds at least
:data:`MIN_RANGE_POINTS` grid values; a grid whose edge cuts a record's range
(``--mu 0.01:0.2:0.005`` for a range from 0.008) is first extended beyond that
edge by :func:`extend_for_ranges`, down towards 0 and up, until the range ends
inside it (:func:`grid_for_ranges` does both): ``stickslip optimum`` and the
record report do so, and say where (:class:`GridExtension`,
:class:`RangeRefinement`); the sweeps of the workflow keep their grids, and
their ``mu_low_at_grid_edge`` and ``mu_high_at_grid_edge`` say where a range is cut.

What a model's block over its grid is to the design answer is a
:class:`Design` (its case, scheme, objective and demands), defined here beside
the answer that reads it; a model's entry builds it
(:meth:`~stickslip.models.swept.SweptModel.design`).

Everything here works on NumPy arrays; only :func:`cube_with_optimum`,
:func:`optimum_variables` and :func:`curves_of`, which read and write cubes, use xarray.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace

import numpy as np

from stickslip.analysis import (
    Maximum,
    grid_maximum_index,
    mu_max_on_grid,
    mu_max_on_grid_edge,
    near_optimal_range,
    refine_maximum,
)
from stickslip.checks import checked_finite_results
from stickslip.errors import StickslipError
from stickslip.grids import COEFFICIENTS, Grid, grid_dimension
from stickslip.limits import check_memory
from stickslip.objectives import ENERGY, Objective
from stickslip.records.process import record_name
from stickslip.records.record import Record
from stickslip.units import UNITS

#: The friction grid of ``stickslip optimum`` when none is given [1]: the friction ratio's declaration's
#: (:data:`stickslip.grids.COEFFICIENTS`).
DEFAULT_MU = COEFFICIENTS["mu"].default_grid

#: The near-optimal fraction q [1] (the workflow's, ``mu_max.near_optimal_fraction``).
DEFAULT_Q = 0.95

#: The fewest grid values that the near-optimal range of any record holds in ``stickslip optimum`` and the record
#: report (their ``--range-points``): a grid with fewer there is refined around the range (:func:`refine_for_ranges`).
#: Ten places the range's ends to a tenth of its width.
MIN_RANGE_POINTS = 10

#: Rounds of refinement at most, each dividing the cells around a range by up to :data:`_SUBDIVISIONS`' largest.
MAX_REFINEMENTS = 6

#: Rounds of extension at most (:func:`extend_for_ranges`): each adds at least the range's width beyond the grid's
#: edge, so that the span added grows geometrically (and below the grid's spacing, each round halves the first value).
MAX_EXTENSIONS = 8

#: The most values one round of extension adds on one side of the grid.
MAX_EXTENSION_VALUES = 400

#: How :func:`range_bounds` marks a result that is a bound: the true value is at most (``≤``) or at least (``≥``)
#: the one given, or (``?``) may lie either side of it.
AT_MOST, AT_LEAST, EITHER_SIDE = "≤", "≥", "?"

#: Factors a grid cell around a range is divided by (the smallest that is fine enough): the values added stay
#: short decimals (steps of 0.0025 become 0.00125, 0.0005, 0.00025, ...).
_SUBDIVISIONS = (2, 5, 10, 20, 50, 100, 200, 500, 1000)


#: The per-record results of every grid: name -> (units, long_name), with {c} for the coefficient's name,
#: {noun} for what it is called and {energy} for what E_df is (:data:`stickslip.grids.COEFFICIENTS`).
_TEMPLATES: dict[str, tuple[str, str]] = {
    "{c}_max": ("1", "{noun} of maximum energy dissipated, on the grid"),
    "energy_dissipated_max": ("J", "maximum {energy} on the grid"),
    "{c}_max_at_grid_edge": ("1", "1 where {c}_max is the grid's first or last point, else 0"),
    "{c}_max_continuous": ("1", "{noun} of maximum energy dissipated, maximised continuously"),
    "energy_dissipated_max_continuous": ("J", "maximum {energy}, continuous in {c}"),
    "{c}_low": ("1", "smallest grid {c} with energy dissipated >= q times the maximum"),
    "{c}_high": ("1", "largest grid {c} with energy dissipated >= q times the maximum"),
    "contiguous": ("1", "1 where every grid {c} between {c}_low and {c}_high qualifies, else 0"),
    "{c}_low_at_grid_edge": ("1", "1 where {c}_low is the grid's first point (the range may reach below the grid), "
                                  "else 0"),
    "{c}_high_at_grid_edge": ("1", "1 where {c}_high is the grid's last point (the range may reach above the grid), "
                                   "else 0"),
    "energy_dissipated_reference": ("J", "{energy} at the reference {noun}"),
    "efficiency": ("1", "energy dissipated at the reference {noun} over the continuous maximum"),
    "peak_relative_displacement_at_{c}_max": ("m", "stroke: largest |block displacement relative to the base| at {c}_max"),
    "residual_displacement_at_{c}_max": ("m", "block displacement relative to the base at the end, at {c}_max"),
    "peak_relative_displacement_at_{c}_low": ("m", "stroke: largest |block displacement relative to the base| at {c}_low"),
    "peak_relative_displacement_at_{c}_high": ("m", "stroke: largest |block displacement relative to the base| at {c}_high"),
    "residual_displacement_at_{c}_low": ("m", "block displacement relative to the base at the end, at {c}_low"),
    "residual_displacement_at_{c}_high": ("m", "block displacement relative to the base at the end, at {c}_high"),
    "largest_stroke": ("m", "largest stroke (|block displacement relative to the base|) at any grid {c} of the "
                            "near-optimal range"),
    "{c}_at_largest_stroke": ("1", "{noun} of the near-optimal range where the stroke is largest"),
    "largest_residual_displacement": ("m", "residual displacement of largest magnitude at any grid {c} of the "
                                           "near-optimal range"),
    "{c}_at_largest_residual_displacement": ("1", "{noun} of the near-optimal range where the residual displacement "
                                                  "is largest"),
}

#: What a yield grid adds: the permanent downslope displacement at the optimum and the range's ends.
_SLOPE_TEMPLATES: dict[str, tuple[str, str]] = {
    **{f"downslope_displacement_at_{{c}}_{at}": ("m", f"permanent displacement downslope at the end (SLAMMER's; "
                                                     f"negative if upslope), at {{c}}_{at}")
       for at in ("max", "low", "high")},
    "largest_downslope_displacement": ("m", "permanent downslope displacement of largest magnitude at any grid {c} "
                                            "of the near-optimal range"),
}

#: A further demand of a model's design: (units, long name, short label for a table's heading).
Demand = tuple[str, str, str]

#: The places on the grid where the displacements are reported.
_AT = ("max", "low", "high")


def results_of(name: str, demands: Mapping[str, Demand] | None = None) -> dict[str, tuple[str, str]]:
    """The per-record results of a grid of the coefficient ``name`` (``"mu"`` or ``"ky"``): name -> (units, long_name).

    ``demands`` are a model's further response curves (a design's ``demands``), each reported at the optimum,
    at the range's ends and at its largest in the range.
    """
    coefficient = COEFFICIENTS[name]
    templates = {**_TEMPLATES, **(_SLOPE_TEMPLATES if coefficient.slope else {})}
    for demand, (units, long_name, _) in (demands or {}).items():
        templates.update({f"{demand}_at_{{c}}_{at}": (units, f"{long_name} at {{c}}_{at}") for at in _AT})
        templates[f"largest_{demand}"] = (units, f"largest {long_name} at any grid {{c}} of the near-optimal range")
        templates[f"{{c}}_at_largest_{demand}"] = ("1", f"{{noun}} of the near-optimal range where the {long_name} is "
                                                       "largest")
    return {template.format(c=name): (units, long_name.format(c=name, noun=coefficient.noun, energy=coefficient.energy))
            for template, (units, long_name) in templates.items()}


#: Per-record results of a friction grid: name -> (units, long_name).
RESULTS: dict[str, tuple[str, str]] = results_of("mu")

#: The text variable that says whether a record has an optimum.
STATUS = "optimum_status"

#: ``optimum_status`` of a record that could not be swept (missing or rejected).
NOT_SOLVED = "not solved"

#: How the ``optimum_status`` of a record whose block slides at no value of the grid starts.
NEVER_SLIDES = "never slides"

#: The response curves a sweep gives and the optimum reads, by their names in :class:`Curves`.
_CURVES = ("energy_dissipated", "peak_relative_displacement", "residual_displacement")

#: The end results that are a model's stroke (its largest |x|) and its displacement at the end, as the sliding-block
#: models name them; a model whose slider is another (a damper's stroke on its floor) declares its own names
#: (:attr:`stickslip.models.swept.SweptModel.strokes`), read into :class:`Curves`' two.
STROKES = ("peak_relative_displacement", "residual_displacement")



@dataclass(frozen=True)
class Curves:
    """The response of n cases (records, or scaled versions of them) over a grid.

    Attributes
    ----------
    grid:
        The swept coefficient (:class:`stickslip.grids.Grid`): its values [1],
        increasing, shape (n_values,), and how the block slides.
    energy_dissipated:
        E_df [J], shape (n, n_values).
    peak_relative_displacement:
        Largest |x| [m], shape (n, n_values).
    residual_displacement:
        x at the end of the record [m], shape (n, n_values).
    demands:
        The model's further response curves by name (the pendulum's ``peak_base_shear`` V/W [1]), (n, n_values)
        each; none by default.
    objective:
        What is optimal (:mod:`stickslip.objectives`; default the most E_df).
    others:
        Further end results by name, (n, n_values) each, solved with the curves for a cube of them (the
        design's ``extra``), so that the cube needs no second sweep; none by default.
    """

    grid: Grid
    energy_dissipated: np.ndarray
    peak_relative_displacement: np.ndarray
    residual_displacement: np.ndarray
    demands: Mapping[str, np.ndarray] = field(default_factory=dict)
    objective: Objective = ENERGY
    others: Mapping[str, np.ndarray] = field(default_factory=dict)

    def values(self, names: Sequence[str]) -> np.ndarray:
        """The end results ``names`` (curves, demands or others), shape (n, n_values, len(names))."""
        found = {**{name: getattr(self, name) for name in _CURVES}, **self.demands, **self.others}
        return np.stack([found[name] for name in names], axis=-1)

    @property
    def merit(self) -> np.ndarray:
        """The :attr:`objective`'s merit of every case at every value, (n, n_values): the larger, the better."""
        curve = self.objective.curve
        return self.objective.merit(self.demands[curve] if curve in self.demands else getattr(self, curve))

    def rows(self, cases) -> Curves:
        """The curves of the cases ``cases`` (an index or a slice of the first axis)."""
        return Curves(self.grid, *(getattr(self, name)[cases] for name in _CURVES),
                      {name: values[cases] for name, values in self.demands.items()}, self.objective,
                      {name: values[cases] for name, values in self.others.items()})


def end_results(records: Sequence[Record], case, scheme, grid: Grid, options: Mapping, names) -> np.ndarray:
    """The end results ``names`` of every record at every grid value, shape (records, values, names), cube units.

    A batched scheme solves all at once (its ``sweep``), another case by case;
    both with the ``options`` given (those set).
    """
    if scheme.batched:
        found = scheme.sweep(list(records), case, grid.name, grid.values,
                             **{name: value for name, value in options.items() if value is not None})
        return np.stack([np.asarray(found[name], dtype=float) for name in names], axis=-1)
    values = np.empty((len(records), grid.values.size, len(names)))
    for i, record in enumerate(records):
        for j, value in enumerate(grid.values):
            scalars = scheme.solve(record, case.at(grid.name, value), **options).scalars()
            values[i, j] = [scalars[name] for name in names]
    return values


@dataclass(frozen=True)
class Design:
    """A block over a grid of its coefficient, solved by one scheme, as :mod:`stickslip.optimum` reads it.

    Attributes
    ----------
    grid:
        The swept coefficient and its values [1].
    case:
        The block at the grid's first value (its model's case).
    scheme:
        The scheme that solves it.
    options:
        The scheme's options, as given.
    demands:
        The model's further response curves the design answer reports (:attr:`SweptModel.demands`).
    objective:
        What is optimal (:mod:`stickslip.objectives`): one of the model's :attr:`Model.objectives`.
    strokes:
        The model's names of its stroke and its displacement at the end (:data:`STROKES`).
    extra:
        Further end results solved with the curves (the cube's other variables, :meth:`with_results`), so that
        a cube of the design answer's grid needs no second sweep (:meth:`SweptModel.sweep`'s ``solved``).
    """

    grid: Grid
    case: object
    scheme: object
    options: Mapping = field(default_factory=dict)
    demands: Mapping = field(default_factory=dict)
    objective: Objective = ENERGY
    strokes: tuple[str, str] = STROKES
    extra: tuple[str, ...] = ()

    @property
    def mass(self) -> float:
        """Block mass [kg]."""
        return self.case.mass

    @property
    def g(self) -> float:
        """Gravity [m/s²]."""
        return self.case.g

    def with_values(self, values) -> Design:
        """The same block over other ``values`` [1] of its coefficient."""
        return replace(self, grid=self.grid.with_values(values))

    def with_results(self, names: Sequence[str]) -> Design:
        """The same design, solving the end results ``names`` [cube units] beside its curves."""
        return replace(self, extra=tuple(name for name in names if name not in (*_CURVES, *self.demands)))

    def curves(self, versions: Sequence[Record]) -> dict[str, np.ndarray]:
        """E_df [J], the stroke (largest |x|) [m], x at the end [m] (under the names of :data:`_CURVES` and the
        model's own, :attr:`strokes`), the :attr:`demands` and the :attr:`extra` end results of each record over the
        grid, (n, values) each."""
        names = ("energy_dissipated", *self.strokes, *self.demands, *self.extra)
        check_memory(len(versions) * self.grid.values.size * len(names) * 8 * 4,
                     f"{len(versions)} record(s) x {self.grid.values.size:,} {self.grid.coefficient.plural}")
        values = end_results(versions, self.case, self.scheme, self.grid, self.options, names)
        found = {name: values[..., index] for index, name in enumerate(names)}
        return {**found, **{curve: found[name] for curve, name in zip(_CURVES[1:], self.strokes)}}

    def energy(self, version: Record, values) -> np.ndarray:
        """E_df [J] of ``version`` at each of ``values`` [1] of the coefficient."""
        return self.with_values(np.atleast_1d(np.asarray(values, dtype=float))).curves([version])["energy_dissipated"][0]

    def merit(self, version: Record, values) -> np.ndarray:
        """The :attr:`objective`'s merit of ``version`` at each of ``values`` [1] of the coefficient (E_df [J] for the
        most energy)."""
        if self.objective == ENERGY:
            return self.energy(version, values)
        curves = self.with_values(np.atleast_1d(np.asarray(values, dtype=float))).curves([version])
        return self.objective.merit(curves[self.objective.curve][0])

    def first_still(self, version: Record) -> int:
        """Index of the first grid value from which on the block never slides on ``version`` (size: none).

        Both levels of the stick band move away from zero as the coefficient
        grows, so the values without sliding are a tail of the grid.
        """
        low, high = 0, self.grid.values.size
        while low < high:  # bisection over the grid: slides, then still
            middle = (low + high) // 2
            if self.case.at(self.grid.name, self.grid.values[middle]).slides(version):
                low = middle + 1
            else:
                high = middle
        return low

    def still_reason(self, version: Record, index: int = 0) -> str:
        """Why the block does not slide on ``version`` at ``grid.values[index]``: the record's extremes and the levels."""
        value = float(self.grid.values[index])
        name = self.grid.name
        smallest_of_several = index == 0 and self.grid.values.size > 1
        where = f"the grid's smallest {name}, {value:g}" if smallest_of_several else f"{name} = {value:g}"
        return self.case.at(name, value).still_reason(version, where)

    def describe(self) -> str:
        """How the block slides, in words, where it is not flat friction on a record as given ("" where it is)."""
        return self.case.describe_sliding()

    def settings(self) -> dict:
        """What the block is, JSON-ready (its model's parameters but the coefficient), the scheme and its options
        as given (``time_step`` [s])."""
        return {**self.case.settings(), "method": self.scheme.name, **self.options}

    def settings_units(self) -> dict:
        """The units of :meth:`settings`' numbers."""
        return {**self.case.settings_units(), **{name: UNITS[name] for name in self.options if name in UNITS}}


def solve_curves(versions: Sequence[Record], design) -> Curves:
    """The :class:`Curves` of ``versions`` (acceleration in m/s²) over the grid of ``design``, from its model.

    ``design`` is a model's block over its swept coefficient (the rigid
    block's :class:`Design`, from
    :meth:`~stickslip.models.rigid.RigidModel.design`): what
    :func:`stickslip.sweep` computes, without building a cube (and without
    importing xarray).
    """
    curves = design.curves(versions)
    for index, version in enumerate(versions):
        largest = {name: float(np.max(np.abs(values[index]))) for name, values in curves.items()}
        checked_finite_results(largest, f"{record_name(version)} (sweep)")
    return Curves(design.grid, *(curves[name] for name in _CURVES), {name: curves[name] for name in design.demands},
                  design.objective, {name: curves[name] for name in design.extra})


def range_sizes(curves: Curves, q: float = DEFAULT_Q) -> np.ndarray:
    """How many grid values lie in each case's near-optimal range (0 where the case never slides), shape (n,)."""
    values = curves.grid.values
    low, high, _ = near_optimal_range(curves.merit, values, q=q)
    slides = np.max(curves.energy_dissipated, axis=1) > 0.0
    with np.errstate(invalid="ignore"):
        inside = (values >= np.asarray(low)[:, None]) & (values <= np.asarray(high)[:, None])
    return np.where(slides, inside.sum(axis=1), 0)


@dataclass(frozen=True)
class RangeRefinement:
    """Where the grid was refined for one case so that its near-optimal range holds enough grid values.

    Attributes
    ----------
    case:
        The case's index in the curves (a record, or a scaled version of one).
    start, stop:
        The span refined [1]: the range's ends on the coarser grid and the grid values beyond them.
    step:
        The finest spacing of the refined grid in that span [1].
    added:
        How many values the refinement added in that span.
    before, after:
        Grid values in the case's near-optimal range on the grid as given, and on the refined grid.
    """

    case: int
    start: float
    stop: float
    step: float
    added: int
    before: int
    after: int

    def describe(self, name: str, min_points: int) -> str:
        """The refinement in words, for the grid's coefficient ``name`` (``mu``, ``ky``) and the fewest values asked."""
        short = f", still fewer than {min_points}" if self.after < min_points else ""
        return (f"{self.added} values of {name} added from {self.start:g} to {self.stop:g} (step {self.step:g}): "
                f"its near-optimal range holds {self.after} grid values{short} ({self.before} before)")


def refine_for_ranges(versions: Sequence[Record], curves: Curves, design, q: float = DEFAULT_Q,
                      min_points: int = MIN_RANGE_POINTS) -> tuple[Curves, list[RangeRefinement]]:
    """``curves`` on their grid refined until every case's near-optimal range holds at least ``min_points`` values.

    ``versions`` are the records of the curves (acceleration in m/s²), and
    ``design`` the model's block that gave them (:func:`solve_curves`): it
    solves the values added (its ``with_values``).  Round by round
    (at most :data:`MAX_REFINEMENTS`), every cell of the grid from the grid
    value below a short range's lowest to the one above its highest is
    divided by the smallest factor of :data:`_SUBDIVISIONS` that makes its
    step at most the range's width over ``min_points`` (a range of one value:
    the span's width over twice that), and every case is solved at the new
    values; a range found on a finer grid may be narrower (E_df,max rises
    with the grid's resolution), hence the rounds.  The grid is one for all
    cases, so that they stay comparable.  With ``q`` = 1 the range is μ_max
    alone, and ``min_points`` 0 or 1 asks for nothing: the curves come back
    as they are.  Returns the refined curves and one :class:`RangeRefinement`
    per case that needed it.
    """
    if min_points <= 1 or q >= 1.0:
        return curves, []
    given = curves.grid.values
    before = range_sizes(curves, q)
    spans: dict[int, list[float]] = {}
    for _ in range(MAX_REFINEMENTS):
        short = np.flatnonzero((range_sizes(curves, q) < min_points)
                               & (np.max(curves.energy_dissipated, axis=1) > 0.0))
        if short.size == 0:
            break
        values = curves.grid.values
        low, high, _ = near_optimal_range(curves.merit[short], values, q=q)
        added = []
        for case, lowest, highest in zip(short, np.atleast_1d(low), np.atleast_1d(high)):
            first = max(int(np.searchsorted(values, lowest)) - 1, 0)
            last = min(int(np.searchsorted(values, highest)) + 1, values.size - 1)
            span = values[first:last + 1]
            width = highest - lowest if highest > lowest else (span[-1] - span[0]) / 2.0
            widest = float(np.max(np.diff(span))) if span.size > 1 else 0.0
            if widest == 0.0:
                continue
            target = width / min_points * (1.0 + 1e-9)  # a step equal to the target, as written, is fine enough
            factor = next((factor for factor in _SUBDIVISIONS if widest / factor <= target), _SUBDIVISIONS[-1])
            added.append(np.concatenate([np.linspace(left, right, factor + 1)[1:-1]
                                         for left, right in zip(span[:-1], span[1:])]))
            start, stop = spans.get(int(case), [span[0], span[-1]])
            spans[int(case)] = [min(start, span[0]), max(stop, span[-1])]
        new = np.unique(np.round(np.concatenate(added), 12)) if added else np.empty(0)
        new = new[_distance_to_nearest(new, values) > 1e-12 * values[-1]]  # none already on the grid
        if new.size == 0:
            break
        extra = solve_curves(versions, design.with_values(new))
        curves = _merged(curves, extra)
    after = range_sizes(curves, q)
    values = curves.grid.values
    refinements = []
    for case, (start, stop) in sorted(spans.items()):
        inside = values[(values >= start) & (values <= stop)]
        refinements.append(RangeRefinement(
            case, float(start), float(stop), float(f"{np.min(np.diff(inside)):.12g}"),  # without rounding noise
            int(inside.size - np.count_nonzero((given >= start) & (given <= stop))), int(before[case]),
            int(after[case])))
    return curves, refinements


@dataclass(frozen=True)
class GridExtension:
    """Where the grid was extended beyond one of its edges for one case whose near-optimal range reached it.

    Attributes
    ----------
    case:
        The case's index in the curves (a record, or a scaled version of one).
    side:
        ``"below"`` (towards 0) or ``"above"`` the grid as given.
    start, stop:
        The span of the values added on that side [1].
    step:
        The finest spacing of the values added [1].
    added:
        How many values were added on that side.
    edge:
        The grid's first (below) or last (above) value after the extension [1].
    inside:
        Whether the range's end on that side (``mu_low`` below, ``mu_high`` above) now lies inside the grid; if
        not, the extension stopped (:data:`MAX_EXTENSIONS`) and the range's quantities are bounds
        (:func:`range_bounds`).
    """

    case: int
    side: str
    start: float
    stop: float
    step: float
    added: int
    edge: float
    inside: bool

    def describe(self, name: str) -> str:
        """The extension in words, for the grid's coefficient ``name`` (``mu``, ``ky``)."""
        below = self.side == "below"
        if self.inside:
            outcome = f"its near-optimal range now {'starts' if below else 'ends'} inside the grid"
        else:
            outcome = (f"its near-optimal range still reaches the grid's {'first' if below else 'last'} value, "
                       f"{self.edge:g}, where it is cut: a bound")
        values = (f"1 value of {name} added {self.side} the grid, {self.start:g}" if self.added == 1 else
                  f"{self.added} values of {name} added {self.side} the grid, from {self.start:g} to {self.stop:g} "
                  f"(step {self.step:g})")
        return f"{values}: {outcome}"


def _cut_ranges(curves: Curves, q: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Which cases' near-optimal ranges reach the grid's first value and its last, shape (n,) each, and their
    widths [1] (cases that never slide: neither, width 0).  A range that reaches the last value where the case no
    longer slides there (E_df = 0) is not counted as cut above: every larger coefficient holds it too and gives the
    same answer, so no extension could end it (an objective other than E_df, such as the drift, can stay
    near-optimal there)."""
    values = curves.grid.values
    low, high, _ = near_optimal_range(curves.merit, values, q=q)
    low, high = np.atleast_1d(np.asarray(low, dtype=float)), np.atleast_1d(np.asarray(high, dtype=float))
    slides = np.max(curves.energy_dissipated, axis=1) > 0.0
    slides_at_last = curves.energy_dissipated[:, -1] > 0.0
    with np.errstate(invalid="ignore"):
        return (slides & (low <= values[0]), slides & slides_at_last & (high >= values[-1]),
                np.where(slides, np.nan_to_num(high - low), 0.0))


def _beyond(values: np.ndarray, side: str, width: float) -> np.ndarray:
    """The values [1] that extend the increasing grid ``values`` on ``side`` by about ``width`` [1], at the grid's
    spacing at that edge: below, only positive ones (a first value within one step of 0 is halved instead)."""
    if side == "above":
        step = float(values[-1] - values[-2]) if values.size > 1 else float(values[-1])
    else:
        step = float(values[1] - values[0]) if values.size > 1 else float(values[0]) / 2.0
    count = int(min(max(np.ceil(width / step - 1e-9), 1), MAX_EXTENSION_VALUES))
    offsets = step * np.arange(1, count + 1)
    if side == "above":
        return np.round(values[-1] + offsets, 12)
    below = np.round(values[0] - offsets, 12)
    below = below[below > 0.0]
    return below[::-1] if below.size else np.array([np.round(values[0] / 2.0, 12)])


def extend_for_ranges(versions: Sequence[Record], curves: Curves, design, q: float = DEFAULT_Q,
                      rounds: int | None = None) -> tuple[Curves, list[GridExtension]]:
    """``curves`` on their grid extended beyond its edges until no case's near-optimal range reaches an edge.

    ``versions`` are the records of the curves (acceleration in m/s²), and
    ``design`` the model's block that gave them (:func:`solve_curves`): it
    solves the values added.  Round by round (at most ``rounds``, by default
    :data:`MAX_EXTENSIONS`), where a
    case's range reaches the grid's first value, values are added below it at
    the grid's spacing there, over the widest such range's width (at least one
    step, at most :data:`MAX_EXTENSION_VALUES`), only positive ones: a first
    value within one step of 0 is halved; where a range reaches the last value,
    the same above it, unless the case no longer slides at the last value
    (:func:`_cut_ranges`).  E_df vanishes as the coefficient goes to 0 and beyond
    PGA/g, so every range of E_df ends inside a grid extended far enough.  The grid is
    one for all cases, so that they stay comparable.  Returns the extended
    curves and one :class:`GridExtension` per case and side extended.
    """
    given = curves.grid.values
    extended: dict[tuple[int, str], None] = {}
    for _ in range(MAX_EXTENSIONS if rounds is None else rounds):
        below, above, width = _cut_ranges(curves, q)
        new = []
        for side, cut in (("below", below), ("above", above)):
            if cut.any():
                new.append(_beyond(curves.grid.values, side, float(np.max(width[cut]))))
                extended.update({(int(case), side): None for case in np.flatnonzero(cut)})
        if not new:
            break
        curves = _merged(curves, solve_curves(versions, design.with_values(np.concatenate(new))))
    if not extended:
        return curves, []
    values = curves.grid.values
    below, above, _ = _cut_ranges(curves, q)
    extensions = []
    for case, side in sorted(extended):
        added = values[values < given[0]] if side == "below" else values[values > given[-1]]
        beside = np.concatenate([added, given[:1]]) if side == "below" else np.concatenate([given[-1:], added])
        extensions.append(GridExtension(
            case, side, float(added[0]), float(added[-1]), float(f"{np.min(np.diff(beside)):.12g}"), int(added.size),
            float(values[0] if side == "below" else values[-1]), not bool((below if side == "below" else above)[case])))
    return curves, extensions


def grid_for_ranges(versions: Sequence[Record], curves: Curves, design, q: float = DEFAULT_Q,
                    min_points: int = MIN_RANGE_POINTS) -> tuple[Curves, list[GridExtension], list[RangeRefinement]]:
    """``curves`` on the grid the design answer needs: extended beyond any edge a near-optimal range reaches
    (:func:`extend_for_ranges`), then refined where a range holds fewer than ``min_points`` values
    (:func:`refine_for_ranges`); with the extensions and the refinements made."""
    curves, extensions = extend_for_ranges(versions, curves, design, q)
    curves, refinements = refine_for_ranges(versions, curves, design, q, min_points)
    return curves, extensions, refinements


def range_bounds(row: Mapping[str, float], name: str = "mu", demands: Sequence[str] = ()) -> dict[str, str]:
    """Which results of one case are bounds, and which way (:data:`AT_MOST`, :data:`AT_LEAST`), where its
    near-optimal range reaches the grid's edge (``{name}_low_at_grid_edge``, ``{name}_high_at_grid_edge``).

    ``row`` maps the results of a grid of ``name`` (``"mu"``, ``"ky"``) to
    their values; ``demands`` are the model's further demands.  A range cut
    below has ``{name}_low`` at most the value given; cut above,
    ``{name}_high`` at least; either way its largest values (the stroke, the
    residual and downslope displacements, each demand, and the count
    ``grid_values_in_range`` where the row has it) are at least the values
    given in magnitude (a negative displacement: at most), and the value
    where each occurs lies below (``≤``), above (``≥``) or, cut on both
    sides, either side (``?``) of the value given.  Nothing for a range
    inside the grid.
    """
    below, above = row.get(f"{name}_low_at_grid_edge") == 1.0, row.get(f"{name}_high_at_grid_edge") == 1.0
    if not (below or above):
        return {}
    bounds = {f"{name}_low": AT_MOST} if below else {}
    if above:
        bounds[f"{name}_high"] = AT_LEAST
    where = EITHER_SIDE if below and above else AT_MOST if below else AT_LEAST
    largest = ["stroke", "residual_displacement", *demands]
    for quantity in largest:
        bounds[f"largest_{quantity}"] = AT_MOST if row[f"largest_{quantity}"] < 0.0 else AT_LEAST
        bounds[f"{name}_at_largest_{quantity}"] = where
    if "largest_downslope_displacement" in row:
        bounds["largest_downslope_displacement"] = (AT_MOST if row["largest_downslope_displacement"] < 0.0
                                                    else AT_LEAST)
    if "grid_values_in_range" in row:
        bounds["grid_values_in_range"] = AT_LEAST
    return bounds


def _distance_to_nearest(points: np.ndarray, values: np.ndarray) -> np.ndarray:
    """The distance of each of ``points`` to the nearest of the increasing ``values`` (same units)."""
    right = np.clip(np.searchsorted(values, points), 1, values.size - 1)
    return np.minimum(np.abs(points - values[right - 1]), np.abs(points - values[right]))


def _merged(curves: Curves, extra: Curves) -> Curves:
    """The :class:`Curves` of ``curves`` and ``extra`` (the same cases and demands at other values of the
    coefficient), in order."""
    values = np.concatenate([curves.grid.values, extra.grid.values])
    order = np.argsort(values)

    def merged(first: np.ndarray, second: np.ndarray) -> np.ndarray:
        return np.concatenate([first, second], axis=1)[:, order]

    return Curves(curves.grid.with_values(values[order]),
                  *(merged(getattr(curves, name), getattr(extra, name)) for name in _CURVES),
                  {name: merged(demand, extra.demands[name]) for name, demand in curves.demands.items()},
                  curves.objective, {name: merged(other, extra.others[name]) for name, other in curves.others.items()})


def grid_results(curves: Curves, q: float = DEFAULT_Q) -> dict[str, np.ndarray]:
    """The per-record results (:func:`results_of`) that the grid alone gives, each of shape (n,).

    The optimum is the largest merit of the curves' objective (the most E_df by
    default), ``energy_dissipated_max`` E_df there.  A case whose block never
    slides (E_df = 0 at every value) gets NaN for every coefficient, flag and
    displacement, and 0 J for E_df,max.
    """
    energy, merit, values, c = curves.energy_dissipated, curves.merit, curves.grid.values, curves.grid.name
    rows = np.arange(energy.shape[0])
    most = grid_maximum_index(energy)
    slides = np.where(most >= 0, energy[rows, np.maximum(most, 0)], np.nan) > 0.0
    best = grid_maximum_index(merit)
    maximum = np.where(best >= 0, energy[rows, np.maximum(best, 0)], np.nan)

    def where_slides(found) -> np.ndarray:
        return np.where(slides, np.asarray(found, dtype=float), np.nan)

    low, high, contiguous = (where_slides(found) for found in near_optimal_range(merit, values, q=q))
    results = {
        f"{c}_max": where_slides(mu_max_on_grid(merit, values)),
        "energy_dissipated_max": maximum,
        f"{c}_max_at_grid_edge": where_slides(mu_max_on_grid_edge(merit, values)),
        f"{c}_low": low,
        f"{c}_high": high,
        "contiguous": contiguous,
        f"{c}_low_at_grid_edge": where_slides(low == values[0]),
        f"{c}_high_at_grid_edge": where_slides(high == values[-1]),
    }
    columns = {f"{c}_max": np.maximum(best, 0)}
    for end, found in ((f"{c}_low", low), (f"{c}_high", high)):
        columns[end] = np.minimum(np.searchsorted(values, np.where(slides, found, values[0])), values.size - 1)
    for name, curve in (("peak_relative_displacement", curves.peak_relative_displacement),
                        ("residual_displacement", curves.residual_displacement), *curves.demands.items()):
        for at, column in columns.items():
            results[f"{name}_at_{at}"] = where_slides(curve[rows, column])
    results.update(largest_in_range(curves, low, high))
    if curves.grid.coefficient.slope:  # SLAMMER's permanent displacement, positive downslope (-x), as the cube's
        for at in _AT:
            results[f"downslope_displacement_at_{c}_{at}"] = -results[f"residual_displacement_at_{c}_{at}"]
        results["largest_downslope_displacement"] = -results["largest_residual_displacement"]
    return results


def largest_in_range(curves: Curves, low: np.ndarray, high: np.ndarray) -> dict[str, np.ndarray]:
    """The largest stroke [m] and residual displacement [m] (by magnitude, signed) between ``low`` and ``high``.

    Over every grid value from ``low`` to ``high`` [1] of each case (NaN where
    the case has no range), with the value where each occurs: the design
    quantities of the near-optimal range, which its ends and its optimum can
    understate.
    """
    values, c = curves.grid.values, curves.grid.name
    rows = np.arange(curves.energy_dissipated.shape[0])
    has_range = ~np.isnan(low)
    with np.errstate(invalid="ignore"):
        inside = (values >= low[:, None]) & (values <= high[:, None])
    results = {}
    for name, curve in (("largest_stroke", curves.peak_relative_displacement),
                        ("largest_residual_displacement", curves.residual_displacement),
                        *((f"largest_{demand}", values) for demand, values in curves.demands.items())):
        at = np.argmax(np.where(inside, np.abs(curve), -np.inf), axis=1)
        results[name] = np.where(has_range, curve[rows, at], np.nan)
        results[f"{c}_at_{name}"] = np.where(has_range, values[at], np.nan)
    return results


#: The percentiles over records of :func:`statistics_over_records` [%]: the median and the 84th (the median
#: times e^σ of a lognormal demand, the "median plus one standard deviation" of design practice).
PERCENTILES = (50.0, 84.0)

#: The responses :func:`statistics_over_records` summarises beside a model's demands: name -> (units, label).
SUMMARISED = {"energy_dissipated": ("J", "E_df"), "peak_relative_displacement": ("m", "stroke"),
              "residual_magnitude": ("m", "|residual|")}


def statistics_over_records(curves: Curves, percentiles: Sequence[float] = PERCENTILES,
                            included: Sequence[bool] | None = None) -> dict[str, np.ndarray]:
    """The ``percentiles`` [%] over the cases of each response at each grid value: name -> (percentiles, values).

    The responses are E_df [J], the stroke [m], the residual displacement's
    magnitude |x at the end| [m] (``residual_magnitude``) and each of the
    curves' demands (the pendulum's V/W [1]); NumPy's linear interpolation
    between order statistics, cases with NaN (not solved) left out.
    ``included`` says which cases enter (one boolean each; all by default):
    the callers leave the vertical components out
    (:func:`stickslip.records.verticals_apart.verticals_apart`).
    """
    if included is not None:
        curves = curves.rows(np.asarray(included, dtype=bool))
    responses = {"energy_dissipated": curves.energy_dissipated,
                 "peak_relative_displacement": curves.peak_relative_displacement,
                 "residual_magnitude": np.abs(curves.residual_displacement), **curves.demands}
    with np.errstate(invalid="ignore"):
        return {name: np.nanpercentile(values, list(percentiles), axis=0) for name, values in responses.items()}


def never_slides_status(record: Record, design) -> str:
    """The ``optimum_status`` of a record (acceleration in m/s²) whose block slides at no value of the grid."""
    return f"{NEVER_SLIDES}: E_df = 0 at every {design.grid.name} of the grid; {design.still_reason(record, 0)}"


def refine_mu_max(record: Record, design, merit_on_grid=None, xatol: float = 1e-6) -> Maximum:
    """The continuous friction ratio μ_max (or yield coefficient k_y,max) that maximises the merit of ``record``.

    The merit of the ``design``'s objective (by default the dissipated energy
    E_df [J]) is evaluated on its grid (or taken from ``merit_on_grid``), then
    every cell that could hold a larger value is resampled, round by round,
    down to a spacing of ``xatol`` (:func:`stickslip.analysis.refine_maximum`;
    a batched kernel evaluates each round at once).  Returns
    :class:`~stickslip.analysis.Maximum` with ``argument`` = μ_max or k_y,max
    [1] and ``value`` = the merit there (E_df,max [J] by default).
    """
    return refine_maximum(lambda value: float(design.merit(record, [value])[0]), design.grid.values, merit_on_grid,
                          xatol=xatol, on_points=lambda points: design.merit(record, points))


def optimum(versions: Sequence[Record], curves: Curves, design, q: float = DEFAULT_Q,
            reference: float | None = None, xatol: float = 1e-6) -> tuple[dict[str, np.ndarray], list[str]]:
    """Every per-record result (:func:`results_of` the curves' grid) and the ``optimum_status`` of each case.

    ``versions`` are the records the curves belong to, in the same order, as
    given (acceleration in m/s²); ``design`` is the model's block that gave the
    curves (:func:`solve_curves`), which computes the continuous maximum of
    its objective's merit (to ``xatol`` [1] in the coefficient,
    :func:`refine_mu_max`) and the energy at the ``reference`` value [1] of
    the grid's coefficient (default: its declaration's, :data:`stickslip.grids.COEFFICIENTS`).  The
    efficiency is the merit at the reference over the continuous maximum's.
    Returns (name -> array of shape (n,), statuses).
    """
    grid = curves.grid
    if len(versions) != curves.energy_dissipated.shape[0]:
        raise StickslipError(f"{len(versions)} records for {curves.energy_dissipated.shape[0]} response curves")
    reference = grid.coefficient.reference if reference is None else reference
    c = grid.name
    results = grid_results(curves, q)
    n = len(versions)
    of_energy = design.objective == ENERGY  # the merit is E_df itself
    merit = curves.merit
    continuous, continuous_energy = np.full(n, np.nan), results["energy_dissipated_max"].copy()
    best = grid_maximum_index(merit)
    continuous_merit = np.where(best >= 0, merit[np.arange(n), np.maximum(best, 0)], np.nan)
    reference_energy, reference_merit, statuses = np.empty(n), np.empty(n), []
    for index, version in enumerate(versions):
        reference_energy[index] = design.energy(version, [reference])[0]
        reference_merit[index] = reference_energy[index] if of_energy else design.merit(version, [reference])[0]
        if np.isnan(results[f"{c}_max"][index]):
            statuses.append(never_slides_status(version, design))
            continue
        if grid.values.size >= 2:
            found = refine_mu_max(version, design, merit[index], xatol)
            continuous[index], continuous_merit[index] = found.argument, found.value
            continuous_energy[index] = found.value if of_energy else design.energy(version, [found.argument])[0]
        else:  # one value: nothing to refine between
            continuous[index] = results[f"{c}_max"][index]
        statuses.append("ok")
    results.update({
        f"{c}_max_continuous": continuous,
        "energy_dissipated_max_continuous": continuous_energy,
        "energy_dissipated_reference": reference_energy,
        "efficiency": np.divide(reference_merit, continuous_merit, out=np.full(n, np.nan),
                                where=np.isfinite(continuous_merit) & (continuous_merit > 0)),
    })
    return {name: results[name] for name in results_of(c, design.demands)}, statuses


def checked_q(q: float, name: str = "q") -> float:
    """The near-optimal fraction ``q``, which must be in (0, 1]; else one line naming the option ``name``."""
    if not 0.0 < q <= 1.0:  # NaN fails too
        raise StickslipError(f"{name} {q:g}: the near-optimal fraction must be in (0, 1], such as {DEFAULT_Q:g}")
    return float(q)


def checked_reference(value: float, coefficient: str = "mu", name: str = "reference") -> float:
    """The reference value [1] of the ``coefficient`` (``"mu"`` or ``"ky"``), positive and finite; else one line."""
    if not (math.isfinite(value) and value > 0.0):
        raise StickslipError(f"{name} {value:g}: a {COEFFICIENTS[coefficient].noun} must be a positive number")
    return float(value)


def attributes(q: float, reference: float, name: str = "mu", objective: Objective = ENERGY) -> dict[str, object]:
    """The cube attributes that say how the per-record results were defined: q and the reference value, with units,
    and the objective (:mod:`stickslip.objectives`) by name."""
    return {"near_optimal_fraction": float(q), "near_optimal_fraction_units": "1",
            f"reference_{name}": float(reference), f"reference_{name}_units": "1", "objective": objective.name}


def optimum_variables(cube, results: Mapping[str, np.ndarray], statuses: Sequence[str], q: float,
                      reference: float, demands: Mapping[str, Demand] | None = None, objective: Objective = ENERGY):
    """``cube`` with the per-record ``results`` and statuses (flat, record-major) as variables, and q, the reference
    and the ``objective``.

    The variables have the cube's dimensions without the grid's (``mu`` or
    ``ky``): ``record`` and the scaling dimension if any; their long names
    say what the objective makes of them.
    """
    name = grid_dimension(cube.dims)
    template = cube.energy_dissipated.isel({name: 0}, drop=True)
    shape, dims = template.shape, template.dims

    def variable(values, attrs):
        return (dims, np.asarray(values).reshape(shape), attrs)

    noun = COEFFICIENTS[name].noun
    long_names = {template.format(c=name): long_name.format(c=name, noun=noun)
                  for template, long_name in objective.long_names.items()}
    variables = {result: variable(results[result], {"units": units, "long_name": long_names.get(result, long_name)})
                 for result, (units, long_name) in results_of(name, demands).items()}
    variables[STATUS] = variable(np.array(list(statuses), dtype=object),
                                 {"long_name": f"ok, '{NEVER_SLIDES}: ...' or '{NOT_SOLVED}'"})
    return cube.assign(variables).assign_attrs(attributes(q, reference, name, objective))


def curves_of(cube, demands: Sequence[str] = (), objective: Objective = ENERGY,
              strokes: Sequence[str] = STROKES) -> Curves:
    """The :class:`Curves` of every case of ``cube`` (record-major, then the scaling dimension), with the
    further response curves ``demands`` of its model's design, for the ``objective``; ``strokes``: the cube's
    names of the stroke and the displacement at the end (:attr:`Design.strokes`)."""
    from stickslip.sweeps import cube_grid

    grid = cube_grid(cube)

    def flat(name):
        values = cube[name].transpose(..., grid.name).values
        return values.reshape(-1, values.shape[-1])

    return Curves(grid, *(flat(name) for name in ("energy_dissipated", *strokes)),
                  {name: flat(name) for name in demands}, objective)


def cube_with_optimum(cube, records: Sequence[Record], design, q: float = DEFAULT_Q, reference: float | None = None,
                      xatol: float = 1e-6):
    """``cube`` (of :func:`stickslip.sweep` or a model's ``missing_cube``) with the per-record results.

    ``records`` are the unscaled records of the cube's ``ok`` records, as
    given to the sweep, found by their id; a record whose status is not
    ``ok`` gets NaN and ``"not solved"``.  ``design`` is the block the cube
    was swept with (its model's ``design_of(cube)``: mass, gravity, how it
    slides, polarity, solver and grid); ``reference`` is the value of the
    grid's coefficient whose E_df and efficiency are reported (default
    its declaration's, :data:`stickslip.grids.COEFFICIENTS`); ``xatol`` [1] the tolerance of the continuous
    maximum (:func:`refine_mu_max`).  :func:`stickslip.with_optimum` finds the
    design of any model's cube.
    """
    from stickslip.records.process import scaled_versions

    by_id = {record.meta.record_id: record for record in records}
    scale = cube["scale"].values if "scale" in cube.dims else None
    target_pga = cube["target_pga"].values if "target_pga" in cube.dims else None
    curves = curves_of(cube, tuple(design.demands), design.objective, design.strokes)
    grid = curves.grid
    reference = grid.coefficient.reference if reference is None else reference
    per_record = curves.energy_dissipated.shape[0] // cube.sizes["record"]
    names = results_of(grid.name, design.demands)
    results = {name: np.full(curves.energy_dissipated.shape[0], np.nan) for name in names}
    statuses = [NOT_SOLVED] * curves.energy_dissipated.shape[0]
    for index, (record_id, status) in enumerate(zip(cube.record.values, cube.status.values)):
        if status != "ok":
            continue
        if record_id not in by_id:
            raise StickslipError(f"no record given for {record_id!r} of the cube")
        cases = slice(index * per_record, (index + 1) * per_record)
        versions = scaled_versions(by_id[record_id], scale, target_pga)
        found, found_statuses = optimum(versions, curves.rows(cases), design, q, reference, xatol)
        for name, values in found.items():
            results[name][cases] = values
        statuses[cases] = found_statuses
    return optimum_variables(cube, results, statuses, q, reference, design.demands, design.objective)
