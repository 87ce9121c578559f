"""Models swept over a coefficient (a friction ratio μ, a yield coefficient k_y): their cube and their design answer.

A :class:`SweptModel` is a model whose sweeps run one coefficient over a
grid (:class:`~stickslip.grids.Grid`, the coefficients of
:data:`stickslip.grids.COEFFICIENTS`) on records of one component, into the
cube of :mod:`stickslip.sweeps` (record × [scaling] × coefficient), and whose
design answer (:mod:`stickslip.optimum`: the coefficient of most energy
dissipated, the near-optimal range, the stroke there) reads a :class:`Design`,
the block over its grid.  The rigid block is one; a model that slides a
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
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace

import numpy as np

from stickslip.grids import COEFFICIENTS, Grid
from stickslip.errors import StickslipError
from stickslip.limits import check_memory
from stickslip.models.entry import Model
from stickslip.objectives import ENERGY, Objective
from stickslip.plumbing.files import provenance
from stickslip.records.record import Record
from stickslip.sweeps import CubeLayout, fill_cube, missing_cube
from stickslip.units import CF_CONVENTIONS, UNITS

#: The response curves the design answer reads, by name.
CURVES = ("energy_dissipated", "peak_relative_displacement", "residual_displacement")


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
        return replace(self, extra=tuple(name for name in names if name not in (*CURVES, *self.demands)))

    def curves(self, versions: Sequence[Record]) -> dict[str, np.ndarray]:
        """E_df [J], the stroke (largest |x|) [m], x at the end [m], the :attr:`demands` and the :attr:`extra` end
        results of each record over the grid, (n, values) each."""
        names = (*CURVES, *self.demands, *self.extra)
        check_memory(len(versions) * self.grid.values.size * len(names) * 8 * 4,
                     f"{len(versions)} record(s) x {self.grid.values.size:,} {self.grid.coefficient.plural}")
        values = end_results(versions, self.case, self.scheme, self.grid, self.options, names)
        return {name: values[..., index] for index, name in enumerate(names)}

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

    def variables(self, case) -> dict[str, dict[str, str]]:
        """The cube's end results for ``case``, name -> CF attributes (units, long_name), in order."""
        raise NotImplementedError

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
               config=None) -> CubeLayout:
        """The cube's layout for the block ``case`` over ``grid``, solved by ``scheme`` with ``run_options``."""
        attrs = {"title": grid.coefficient.title, "Conventions": CF_CONVENTIONS, **provenance(), "model": self.name,
                 "solver": scheme.name, **self.cube_attrs(case, scheme, run_options),
                 "scaling": "factor" if scale is not None else "target_pga" if target_pga is not None else "none",
                 "config": json.dumps(dict(config or {}), sort_keys=True, default=str)}
        return CubeLayout(grid, self.variables(case), attrs, case.g, scale, target_pga, self.grid_coords(grid, case),
                          counts=self.counts)

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
        design :meth:`Design.with_results` the cube's variables), so that none is
        solved again.  Returns the cube, dimensions ``(record, [scale or
        target_pga,] coefficient)``.
        """
        grid, case, scheme, run_options = self.setup(method, options, **parameters)
        layout = self.layout(grid, case, scheme, run_options, scale, target_pga, config)
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
        """The block of ``parameters`` over ``grid``, as :mod:`stickslip.optimum` reads it (:class:`Design`), with
        the ``objective`` named (default: the model's first)."""
        case = self.case(self.checked({**parameters, grid.name: float(grid.values[0])}))
        scheme = self.scheme(method)
        scheme.check(case)
        return Design(grid, case, scheme, scheme.checked_options(options), self.demands, self.objective(objective))

    def design_of(self, cube, objective: str | None = None) -> Design:
        """The :meth:`design` a cube of :meth:`sweep` was swept with, from its coordinates and attributes, with the
        ``objective`` named (default: the cube's ``objective`` attribute, else the model's first)."""
        from stickslip.sweeps import cube_grid

        method, options, parameters = self.parameters_of(cube)
        return self.design(cube_grid(cube), method, options, objective or cube.attrs.get("objective"), **parameters)

    def design_answer(self, cube, motions, q: float, reference: float | None = None, objective: str | None = None):
        """``cube`` with each record's μ_max (k_y,max), near-optimal range, stroke … (:func:`stickslip.optimum.cube_with_optimum`)
        for the ``objective`` named (default: the model's first)."""
        from stickslip.optimum import cube_with_optimum

        return cube_with_optimum(cube, motions, self.design_of(cube, objective), q, reference)
