"""Models swept over a coefficient (a friction ratio μ, a yield coefficient k_y): their cube and their design answer.

A :class:`SweptModel` is a model whose sweeps run one coefficient over a
grid (:class:`~stickslip.grids.Grid`, the coefficients of
:data:`stickslip.grids.COEFFICIENTS`) on records of one component, into the
cube of :mod:`stickslip.sweeps` (record × [scaling] × coefficient), and whose
design answer (:mod:`stickslip.optimum`: the coefficient of its objective's
optimum, the most energy dissipated by default, the near-optimal range, the
stroke there) reads a :class:`~stickslip.optimum.Design`, the block over its
grid, which it defines beside the design answer.  The rigid block is one; a model that slides a
block on one component under its own resistance is another with three
methods of its own (:meth:`SweptModel.variables`, :meth:`SweptModel.cube_attrs`,
:meth:`SweptModel.parameters_of`) beside its entry.

The case a swept model builds (:meth:`~stickslip.models.entry.Model.case`)
has ``mass`` [kg], ``g`` [m/s²] and ``inverse``, and these methods:
``at(name, value)`` (the same block with its coefficient at ``value``),
``solved(acceleration)`` (the record as solved), ``slides(motion)`` (whether
the block at rest leaves its stick band on a motion), ``still_reason(motion,
where)`` (why it does not), ``describe_sliding()`` and ``settings()``.  Its
schemes solve a case (``solve``) and, where batched, ``sweep(records, case,
name, values)``: the end results of every record at every value of the
coefficient, by name, in the cube's units.
"""

from __future__ import annotations

import json
from collections.abc import Mapping

import numpy as np

from stickslip.constants import STANDARD_GRAVITY
from stickslip.grids import COEFFICIENTS, Grid
from stickslip.errors import StickslipError
from stickslip.models.entry import Model
from stickslip.optimum import STROKES, Design, end_results
from stickslip.plumbing.files import provenance
from stickslip.records.record import Record
from stickslip.sweeps import CubeLayout, fill_cube, missing_cube
from stickslip.units import CF_CONVENTIONS

def motion_measures(motion, g: float) -> dict:
    """The intensity measures of ``motion`` (gravity ``g`` [m/s²]): a component's, that of the horizontal
    component of a motion with its vertical, and of a pair its stronger component's (the one of larger PGA: the
    "larger horizontal component" of design practice)."""
    from stickslip.measures import intensity_measures
    from stickslip.records.pair import RecordPair
    from stickslip.records.vertical import WithVertical

    motion = motion.horizontal if isinstance(motion, WithVertical) else motion
    if not isinstance(motion, RecordPair):
        return intensity_measures(motion, g=g).as_dict()
    each = [intensity_measures(record, g=g).as_dict() for record in (motion.first, motion.second)]
    return max(each, key=lambda measures: measures["pga"])


def _replayed(solved, grid: Grid, names: list[str]):
    """A cube's solver that hands out the end results ``names`` of ``solved`` (:class:`~stickslip.optimum.Curves`
    on ``grid``) to the versions it is given, in order, as :func:`stickslip.sweeps.fill_cube` asks for them."""
    if not np.array_equal(solved.grid.values, grid.values):
        raise ValueError("the end results solved are on another grid than the cube's")
    values = solved.values(names)
    done = 0

    def solve(versions):
        nonlocal done
        done += len(versions)
        return values[done - len(versions):done]

    return solve


class SweptModel(Model):
    """A model swept over a coefficient of :data:`~stickslip.grids.COEFFICIENTS`, with a design answer.

    A subclass provides :meth:`variables`, :meth:`cube_attrs` and
    :meth:`parameters_of` beside its entry's declarations.
    """

    scaled_sweeps = True
    designs = True
    #: The cube's variables that count something (integers, -1 where unknown).
    counts: tuple[str, ...] = ("n_slip_episodes",)
    #: Further response curves its design answer reports beside the energy, stroke and residual displacement:
    #: name -> (units, long name, short label) (:data:`stickslip.optimum.Demand`); none by default.
    demands: Mapping = {}
    #: Its end results that are the stroke (largest |x|) and the displacement at the end, which the design answer
    #: reports and the ``displacement`` objective reads (:data:`stickslip.optimum.STROKES`: the block's relative to
    #: its base).
    strokes: tuple[str, str] = STROKES

    def variables(self, case) -> dict[str, dict[str, str]]:
        """The cube's end results for ``case``, name -> CF attributes (units, long_name), in order."""
        raise NotImplementedError

    def cube_variables(self, case, motions) -> dict[str, dict[str, str]]:
        """The cube's end results for ``case`` on ``motions`` (records, or pairs or motions with their vertical, as
        the model takes them): :meth:`variables` whatever the motions, unless the model has more to say of some."""
        return self.variables(case)

    def cube_attrs(self, case, scheme, run_options: Mapping) -> dict:
        """The cube attributes that describe the block ``case`` and its scheme (read back by :meth:`parameters_of`)."""
        raise NotImplementedError

    def parameters_of(self, cube) -> tuple[str, dict, dict]:
        """``(method, options, parameters)`` a cube of :meth:`sweep` was swept with, but its coefficient."""
        raise NotImplementedError

    def grid_coords(self, grid: Grid, case) -> dict:
        """More coordinates along the grid: name -> (values, CF attributes); none by default."""
        return {}

    def setup(self, method=None, options=None, **parameters):
        """The grid, the block at its first value, the scheme and the options it runs with, of a sweep's parameters.

        The swept coefficient is given as a list of values [1]; every parameter is
        checked as a solve checks it, the combination by the model's own :meth:`case`.
        """
        given = {name: parameters.pop(name, None) for name in COEFFICIENTS if name in {p.name for p in self.parameters}}
        named = [name for name, values in given.items() if values is not None]
        if len(named) != 1:  # the model's own check says what is wrong with the combination, else this line does
            self.case(self.checked({**parameters, **{name: 1.0 for name in named}}))
            raise StickslipError(f"a sweep of the {self.name} model takes the values of one swept coefficient, "
                                 f"{' or '.join(f'{name}=' for name in given)}; got {len(named) or 'none'}")
        grid = Grid(named[0], given[named[0]])
        case = self.case(self.checked({**parameters, grid.name: float(grid.values[0])}))
        scheme = self.scheme(method)
        scheme.check(case)
        return grid, case, scheme, scheme.run_options(options, case)

    def layout(self, grid: Grid, case, scheme, run_options: Mapping, scale=None, target_pga=None,
               config=None, motions=()) -> CubeLayout:
        """The cube's layout for the block ``case`` on ``motions`` over ``grid``, solved by ``scheme`` with
        ``run_options``."""
        attrs = {"title": grid.coefficient.title, "Conventions": CF_CONVENTIONS, **provenance(), "model": self.name,
                 "solver": scheme.name, **self.cube_attrs(case, scheme, run_options),
                 "scaling": "factor" if scale is not None else "target_pga" if target_pga is not None else "none",
                 "config": json.dumps(dict(config or {}), sort_keys=True, default=str)}
        return CubeLayout(grid, self.cube_variables(case, motions), attrs, case.g, scale, target_pga,
                          self.grid_coords(grid, case), counts=self.counts)

    def sweep(self, records, method=None, *, scale=None, target_pga=None, progress: bool = False, config=None,
              measures=None, options=None, solved=None, **parameters):
        """Every record (scaled by ``scale`` [1] or to ``target_pga`` [m/s²]) over a grid of the coefficient; one cube.

        ``parameters`` are the model's, the swept coefficient a list of values
        [1]; ``options`` the scheme's (the cube records every option the solver
        ran with); ``config`` settings recorded in the cube's ``config``
        attribute (JSON); ``measures`` the records' intensity measures when known
        (:func:`stickslip.sweeps.fill_cube`); ``solved`` the end results of every
        version of every record, in order, on the same grid, when a design answer
        has solved them already (its :class:`~stickslip.optimum.Curves`, of a
        design :meth:`~stickslip.optimum.Design.with_results` the cube's variables), so that none is
        solved again.  A pair of components or a motion with its vertical (a model that takes them) is swept as
        given, with no scaling dimension, and measured by :func:`motion_measures`.  Returns the cube, dimensions ``(record, [scale or
        target_pga,] coefficient)``.
        """
        records = list(records)
        if any(not isinstance(record, Record) for record in records):
            if scale is not None or target_pga is not None:
                raise StickslipError("a sweep of pairs of components, or of motions with their vertical, takes no "
                                     "scaling dimension: scale all components alike first (--scale with one factor)")
            if measures is None:
                measures = [motion_measures(record, parameters.get("g") or STANDARD_GRAVITY) for record in records]
        grid, case, scheme, run_options = self.setup(method, options, **parameters)
        layout = self.layout(grid, case, scheme, run_options, scale, target_pga, config, records)
        given = scheme.checked_options(options)

        def solve(versions):
            return end_results(versions, case, scheme, grid, given, list(layout.variables))

        if solved is not None:
            solve = _replayed(solved, grid, list(layout.variables))
        return fill_cube(records, layout, solve, batched=scheme.batched, measures=measures, progress=progress)

    def missing_cube(self, record_id: str, status: str, method=None, *, scale=None, target_pga=None, config=None,
                     options=None, **parameters):
        """The cube of a record that could not be swept, laid out as :meth:`sweep` lays it out, NaN, with ``status``."""
        grid, case, scheme, run_options = self.setup(method, options, **parameters)
        return missing_cube(record_id, status, self.layout(grid, case, scheme, run_options, scale, target_pga, config))

    def design(self, grid: Grid, method=None, options=None, objective: str | None = None, **parameters) -> Design:
        """The block of ``parameters`` over ``grid``, as :mod:`stickslip.optimum` reads it (:class:`~stickslip.optimum.Design`), with
        the ``objective`` named (default: the model's first)."""
        case = self.case(self.checked({**parameters, grid.name: float(grid.values[0])}))
        scheme = self.scheme(method)
        scheme.check(case)
        return Design(grid, case, scheme, scheme.checked_options(options), self.demands, self.objective(objective),
                      self.strokes)

    def design_of(self, cube, objective: str | None = None) -> Design:
        """The :meth:`design` a cube of :meth:`sweep` was swept with, from its coordinates and attributes, with the
        ``objective`` named (default: the cube's ``objective`` attribute, else the model's first)."""
        from stickslip.sweeps import cube_grid

        method, options, parameters = self.parameters_of(cube)
        return self.design(cube_grid(cube), method, options, objective or cube.attrs.get("objective"), **parameters)

    def design_chart(self, motions, values, mu, progress: bool = False, objective: str | None = None, **parameters):
        """The median, 84th percentile and (over :data:`~stickslip.models.design_chart.MEAN_RECORDS` or more) mean
        over ``motions`` of the ``objective``'s quantity (default: the model's first objective's) and of the stroke
        (:attr:`strokes`), over the ``values`` of :attr:`~stickslip.models.entry.Model.chart_over` (None:
        :attr:`chart_values`) and the friction ratios ``mu`` [1], one sweep per value
        (:func:`~stickslip.models.design_chart.stacked_sweeps`).

        The statistics' attributes name the quantity contoured in colour (``filled``), the one in lines
        (``lines``: the ``stroke``; none when the objective's quantity is the stroke), the ``objective`` (its
        ``objective_summary``, and ``objective_larger``: 1 where a larger value is better), the chart's ``title``
        and the model's ``mass`` [kg], which the energies [J] are of.
        """
        from stickslip.grids import positive_increasing
        from stickslip.models.design_chart import chart_statistics, stacked_sweeps
        from stickslip.units import readable_units

        if not self.chart_over:
            return super().design_chart(motions, values, mu, progress, **parameters)
        chosen = self.objective(objective)
        unit = self.parameter(self.chart_over).unit
        what = f"values of the {self.chart_long_name} [{readable_units(unit)}]"
        values = positive_increasing(self.chart_values if values is None else values, what)
        method = parameters.pop("method", None)
        first = self.checked({**parameters, "mu": float(np.min(mu)), self.chart_over: float(values[0])})
        filled, variables = self._chart_variables(chosen)
        chart = stacked_sweeps(self.name, motions, self.chart_over, values, mu, variables, what, progress=progress,
                               method=method, **parameters)
        chart[self.chart_over].attrs.update(units=unit, long_name=self.chart_long_name)
        statistics = chart_statistics(chart)
        statistics.attrs.update(title=self.chart_title, filled=filled, stroke=self.strokes[0],
                                lines="" if filled == self.strokes[0] else self.strokes[0], objective=chosen.name,
                                objective_summary=chosen.summary, objective_larger=int(chosen.larger),
                                mass=first["mass"])
        return statistics

    def chart_quantities(self, objective: str | None = None) -> tuple[str, str]:
        """The ``objective``'s quantity (default: the model's first objective's) in colours and the stroke
        (:attr:`strokes`) in lines, or "" for the lines where the objective's quantity is the stroke, each with its
        units; from the entry's declarations alone, so that the command line's help imports no solver."""
        from stickslip.units import readable_units

        if not self.chart_over:
            return super().chart_quantities(objective)
        variables = self._chart_variables(self.objective(objective))[1]
        quantities = [f"{long_name} [{readable_units(units)}]" for units, long_name in variables.values()]
        return quantities[0], quantities[1] if len(quantities) > 1 else ""

    def _chart_variables(self, chosen) -> tuple[str, dict[str, tuple[str, str]]]:
        """The end result its design chart fills for the objective ``chosen`` and the chart's variables, name ->
        (units, long name): that one first, then the stroke where it is another; the units those the entry
        declares (a demand's, a stroke's as the rigid block's counterpart's, else the units table's)."""
        from stickslip.units import UNITS

        counterparts = dict(zip(self.strokes, STROKES))
        filled = {stroke: own for own, stroke in counterparts.items()}.get(chosen.curve, chosen.curve)

        def units(name: str) -> str:
            return self.demands[name][0] if name in self.demands else UNITS[counterparts.get(name, name)]

        return filled, {name: (units(name), chosen.quantity if name == filled else name.replace("_", " "))
                        for name in dict.fromkeys((filled, self.strokes[0]))}

    def design_answer(self, cube, motions, q: float, reference: float | None = None, objective: str | None = None):
        """``cube`` with each record's μ_max (k_y,max), near-optimal range, stroke … (:func:`stickslip.optimum.cube_with_optimum`)
        for the ``objective`` named (default: the model's first)."""
        from stickslip.optimum import cube_with_optimum

        return cube_with_optimum(cube, motions, self.design_of(cube, objective), q, reference)
