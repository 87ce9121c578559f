"""The shape of a sliding-block model: the motion it takes, its parameters, its schemes, how it solves.

A model is one module (or one small subpackage) of :mod:`stickslip.models`
that subclasses :class:`Model` and registers one instance of its subclass
(:func:`stickslip.models.registry.register`); :data:`stickslip.models.registry.MODEL_MODULES`
names the module, one line.  The entry is all that the rest of stickslip
knows of a model:

* the **motion** it takes, from :data:`MOTIONS`: one horizontal component (a
  :class:`~stickslip.records.record.Record`), or a pair of horizontal
  components of one station (a :class:`~stickslip.records.pair.RecordPair`);
* its **parameters**, each a :class:`Parameter` with its unit, default,
  check and help text, from which :func:`stickslip.solve`'s keywords and the
  command line's options come (:mod:`stickslip.models.parameters` declares
  the ones several models share);
* its **schemes**, each a :class:`Scheme` object with a ``solve`` method
  and, where it has a batched kernel, a ``sweep`` method: behaviour, not a
  flag beside a global function;
* its **result** type, derived from :class:`stickslip.models.result.Result`;
* its **examples**, cases that reach every kernel of its schemes, which the
  install solves once so that numba's cache holds them (:mod:`stickslip.models.warm_up`);
* its **objectives**, what "optimal" may mean in its design answer
  (:mod:`stickslip.objectives`: the most energy dissipated by default).

:meth:`Model.solve` and :meth:`Model.sweep` are what :func:`stickslip.solve`
and :func:`stickslip.sweep` call; neither they nor the command line branch on
a model's or a scheme's name.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from stickslip.errors import StickslipError

#: The kinds of ground motion a model may take: name -> what it is.
MOTIONS = {
    "component": "one horizontal component of a record",
    "pair": "the two horizontal components of one station (--pair)",
}


@dataclass(frozen=True)
class Parameter:
    """One parameter of a model: a keyword of :func:`stickslip.solve` and an option of the command line.

    Attributes
    ----------
    name:
        The keyword (``mu``); the option is ``--mu`` (underscores become dashes).
    unit:
        Its unit, UDUNITS spelling (``"1"`` for a dimensionless number, ``"m"``, ``"kg"``).
    help:
        What it is, in one line, with its unit in words where it has one.
    default:
        The value when it is not given; ``None``: none (the model's :meth:`Model.case` decides).
    check:
        ``check(value) -> value``: the value as the model takes it, or a
        :class:`StickslipError` naming the parameter (default: as given).
    kind:
        How the command line reads it (:mod:`stickslip.cli.model_options`):
        ``"number"`` (in :attr:`unit`, or with a unit of the same quantity:
        ``200cm``, ``6%``), ``"acceleration"`` (a number in units of g, or with an
        acceleration unit, as ``--ky 0.15`` and ``--ky 1.47m/s2``), ``"strain"``
        (a percentage with its ``%``), ``"flag"`` or ``"choice"``.
    choices:
        The values a ``"choice"`` takes.
    swept:
        Whether a sweep may take several values of it, as a dimension of its cube.
    excludes:
        Parameters that cannot be given with it (``mu`` excludes ``ky``).
    requires:
        ``(name, value)``: it applies only with the parameter ``name`` given
        (``value`` None) or set to ``value`` (``thrust_angle`` needs
        ``direction`` ``"both"``).
    plural, example:
        How several values are named in a message (``"friction ratios mu"``)
        and a grid of them written out (``"0.05:0.2:0.025"``), for a swept one.
    command_line:
        Whether the command line offers it (False: the library's only, such as
        the flexible schemes' ``ledger`` switch).
    tables:
        Whether it may also vary with the block's accumulated displacement: a
        :class:`~stickslip.models.yield_table.YieldTable` (the command line's
        ``--ky-table`` for ``ky``).
    plausible:
        For a coefficient of g (μ, k_y [1]): the largest value it plausibly
        takes (1: above it the block slides only where the ground acceleration
        passes that many g, which no ground motion reaches, so the number is
        most likely a percentage or in other units).  The command line warns of
        a larger value (:func:`stickslip.cli.model_options.warn_if_implausible`);
        None: no such bound.
    in_sweeps:
        For a parameter that a sweep's grid replaces (``mu_slow``, ``mu_fast``
        of the velocity law: a sweep's grid of ``mu`` is its ``mu_fast``), what
        a sweep takes instead, in words; the command's one line when it is
        given to ``sweep``, ``optimum`` or ``report``.  Empty: a sweep takes it.
    usual:
        For a dimension: ``(low, high, of_what)``, the range [:attr:`unit`]
        it has in practice (``(0.2, 20.0, "friction pendulum surfaces")``).
        The command line warns of a bare positive finite number outside it,
        most likely in other units, naming its readings in them; None: no
        such range.
    """

    name: str
    unit: str
    help: str
    default: Any = None
    check: Callable[[Any], Any] | None = None
    kind: str = "number"
    choices: tuple[str, ...] = ()
    swept: bool = False
    tables: bool = False
    excludes: tuple[str, ...] = ()
    requires: tuple[str, Any] | None = None
    plural: str = ""
    example: str = ""
    command_line: bool = True
    plausible: float | None = None
    usual: tuple[float, float, str] | None = None
    in_sweeps: str = ""

    @property
    def option(self) -> str:
        """The command line's option: ``--thrust-angle`` for ``thrust_angle``."""
        return "--" + self.name.replace("_", "-")

    def checked(self, value):
        """``value`` as the model takes it (:attr:`check`)."""
        return value if self.check is None else self.check(value)


class Scheme:
    """One way of integrating a model: :meth:`solve` one case and, with a batched kernel, :meth:`sweep` many.

    Subclasses set :attr:`name` and :attr:`summary` and implement
    :meth:`solve`; a scheme with a batched kernel sets :attr:`batched` and
    implements :meth:`sweep`.  ``case`` is what the model's :meth:`Model.case`
    built from the checked parameters.
    """

    #: The name users give: ``method="exact"``, ``--method exact``.
    name: str
    #: What it is, in one line (the command line's help, the docs).
    summary: str
    #: Whether it has a batched kernel (:meth:`sweep`) that sweeps use instead of one solve per case.
    batched: bool = False

    @property
    def options(self) -> dict:
        """The scheme's own options and their defaults (``{"time_step": 0.001}`` [s]; ``None``: from the record)."""
        return {}

    def solve(self, motion, case, **options):
        """The :class:`~stickslip.models.result.Result` of one case on one motion."""
        raise NotImplementedError

    def check(self, case) -> None:
        """Refuse, in one line, a case the scheme cannot solve; it solves every case by default."""

    def run_options(self, given: Mapping | None, case) -> dict:
        """The options a solve of ``case`` runs with: the defaults that are set, then the ``given`` ones (checked)."""
        return self.with_defaults(self.checked_options(given))

    def sweep(self, motions, case, coefficient: str, values, **options):
        """The end results of every motion at every ``values`` [1] of the swept ``coefficient``, at once, with the
        scheme's ``options`` that are set (as :meth:`solve` takes them).

        Only a :attr:`batched` scheme has it; the model's entry says what it holds.
        """
        raise NotImplementedError(f"the {self.name} scheme has no batched kernel")

    def checked_options(self, given: Mapping | None) -> dict:
        """The options ``given`` (not the defaults), checked: one the scheme does not take is one clear line."""
        given = {name: value for name, value in dict(given or {}).items() if value is not None}
        defaults = self.options
        unknown = sorted(set(given) - set(defaults))
        if unknown:
            raise StickslipError(f"solver {self.name!r} does not accept option(s) {', '.join(unknown)}; "
                                 f"it accepts: {', '.join(defaults) or 'none'}")
        return given

    def with_defaults(self, given: Mapping) -> dict:
        """The options a solve runs with: the defaults that are set, then ``given``."""
        merged = {**self.options, **given}
        return {name: value for name, value in merged.items() if value is not None}


class Model:
    """One sliding-block model's entry: what it takes and how it is solved.

    Subclasses set the class attributes and may override :meth:`case`
    (parameters that depend on each other), :meth:`solve` and :meth:`sweep`.
    """

    #: The name users give: ``model="coupled"``, ``--model coupled``.
    name: str = ""
    #: What it is, in one line.
    summary: str = ""
    #: The motions it takes (:data:`MOTIONS`), the first being the one it is chosen for by default.
    motions: tuple[str, ...] = ("component",)
    #: Whether it takes the vertical ground motion beside them (:class:`~stickslip.records.vertical.WithVertical`).
    vertical: bool = False
    #: Its parameters, in the order its help lists them.
    parameters: tuple[Parameter, ...] = ()
    #: Its schemes, the default first.
    schemes: tuple[Scheme, ...] = ()
    #: Its result type (a subclass of :class:`stickslip.models.result.Result`).
    result: type = object
    #: Whether its sweep scales the records along a dimension of its cube (``scale`` or ``target_pga``).
    scaled_sweeps: bool = False
    #: Whether it has a design answer over a grid of a swept coefficient (:meth:`design`, :mod:`stickslip.optimum`).
    designs: bool = False
    #: Cases that together reach every kernel of its schemes, each the keywords of one :meth:`solve` (parameters
    #: and scheme options; a scheme that refuses one by its rules skips it): what ``make env`` compiles, solving
    #: each with every scheme on every motion it takes (:mod:`stickslip.models.warm_up`).
    examples: tuple[Mapping[str, Any], ...] = ()
    #: The length [samples] of the synthetic motion the warm-up solves those examples on: long enough to reach every
    #: compiled path of its schemes (a path chosen by the record's length needs a longer motion), short enough that
    #: the solves themselves cost little beside the compilation.
    warm_up_samples: int = 4_000
    #: Whether ``stickslip report --pair`` gives a pair of components the pair report (the block in the plane beside
    #: each component alone, :mod:`stickslip.reports.pair_report`) rather than the record report's page for the pair.
    pair_report: bool = False
    #: What "optimal" may mean in its design answer, by name (:data:`stickslip.objectives.OBJECTIVES`), its default
    #: first: the most energy dissipated, the paper's, unless the model says otherwise.
    objectives: tuple[str, ...] = ("energy",)

    def objective(self, name: str | None = None, option: str = "objective"):
        """The :class:`~stickslip.objectives.Objective` ``name`` among :attr:`objectives` (the default when None);
        another is one line naming ``option``."""
        from stickslip.objectives import objective_named

        return objective_named(self.objectives[0] if name is None else name, self.objectives, self.name, option)

    def parameter(self, name: str) -> Parameter:
        """The declaration of the parameter ``name``."""
        for parameter in self.parameters:
            if parameter.name == name:
                return parameter
        raise StickslipError(f"the {self.name} model takes no parameter {name!r}; it takes: "
                             f"{', '.join(p.name for p in self.parameters)}")

    def takes(self, motion: str, names: Sequence[str] = (), vertical: bool = False) -> bool:
        """Whether it takes the motion ``motion`` (:data:`MOTIONS`; with its ``vertical`` component) and every
        parameter of ``names``."""
        declared = {parameter.name for parameter in self.parameters}
        return motion in self.motions and (self.vertical or not vertical) and set(names) <= declared

    def scheme(self, method: str | None = None) -> Scheme:
        """The scheme ``method`` (the default when None); another name is one line naming the model's own."""
        if method is None:
            return self.schemes[0]
        for scheme in self.schemes:
            if scheme.name == method:
                return scheme
        raise StickslipError(f"the {self.name} model is solved by method {', '.join(self.scheme_names)}, "
                             f"not {method!r}")

    @property
    def scheme_names(self) -> tuple[str, ...]:
        """The names of its schemes, the default first."""
        return tuple(scheme.name for scheme in self.schemes)

    @functools.cached_property
    def declared(self) -> dict[str, Parameter]:
        """Its parameters by name (a model's parameters are fixed once it is registered)."""
        return {parameter.name: parameter for parameter in self.parameters}

    @functools.cached_property
    def defaults(self) -> dict[str, Any]:
        """Each parameter's value when it is not given, by name."""
        return {name: parameter.default for name, parameter in self.declared.items()}

    def checked(self, given: Mapping[str, Any]) -> dict:
        """The given parameters checked one by one (:meth:`Parameter.checked`), defaults filled in."""
        declared = self.declared
        if not given.keys() <= declared.keys():
            unknown = sorted(given.keys() - declared.keys())
            raise StickslipError(f"the {self.name} model does not take {', '.join(unknown)}; it takes: "
                                 f"{', '.join(sorted(declared))} (a scheme's options, such as rtol, go in options=)")
        values = dict(self.defaults)
        values.update({name: declared[name].checked(value) for name, value in given.items() if value is not None})
        return values

    def case(self, parameters: Mapping[str, Any]):
        """What the schemes solve, from the checked parameters (default: the parameters themselves)."""
        return dict(parameters)

    def split(self, keywords: Mapping[str, Any]) -> tuple[dict, dict]:
        """``keywords`` split into the model's parameters and the rest, the scheme's options.

        A keyword that another model declares as a parameter but this one does
        not is one line naming the ones this model takes.
        """
        declared = self.declared
        if keywords.keys() <= declared.keys():  # the usual call: no scheme option, no stray keyword
            return dict(keywords), {}
        from stickslip.models.registry import MODELS

        elsewhere = {parameter.name for entry in MODELS.values() for parameter in entry.parameters} - declared.keys()
        foreign = sorted(name for name, value in keywords.items() if name in elsewhere and value is not None)
        if foreign:
            raise StickslipError(f"the {self.name} model ({self.summary}) does not take {', '.join(foreign)}; it "
                                 f"takes: {', '.join(sorted(declared))}")
        return ({name: value for name, value in keywords.items() if name in declared},
                {name: value for name, value in keywords.items() if name not in declared and name not in elsewhere})

    def solve(self, motion, method: str | None = None, **keywords):
        """Solve one case on ``motion``: the scheme ``method`` on :meth:`case` of the checked parameters.

        ``keywords`` are the model's parameters and, besides them, the scheme's options.
        """
        scheme = self.scheme(method)
        parameters, options = self.split(keywords)
        case = self.case(self.checked(parameters))
        return scheme.solve(motion, case, **scheme.checked_options(options))

    def sweep(self, motions, method: str | None = None, **keywords):
        """Every motion over the grids among ``keywords`` (lists of swept parameters), into one cube."""
        raise StickslipError(f"the {self.name} model has no sweep")

    def design(self, grid, method: str | None = None, options: Mapping | None = None, **parameters):
        """The block of ``parameters`` over ``grid`` as :mod:`stickslip.optimum` reads it (where :attr:`designs`)."""
        raise StickslipError(f"the {self.name} model has no design answer over a grid")

    def design_answer(self, cube, motions, q: float, reference: float | None = None):
        """``cube`` of :meth:`sweep` with the design answer of each motion (where :attr:`designs`; else as it is)."""
        return cube

    #: The parameter its design chart runs over beside the grid's friction ratio (the friction pendulum's and the
    #: isolated building's surface ``radius``, the damper's ``mass_ratio``: :meth:`design_chart`), for ``optimum
    #: --chart`` and the record report; "": it draws none.
    chart_over: str = ""
    #: The values of :attr:`chart_over` its design chart runs over when none are given, what that parameter is in
    #: words without its unit (the chart's axis, the command line's help), and the chart's title.
    chart_values: tuple[float, ...] = ()
    chart_long_name: str = ""
    chart_title: str = ""

    def design_chart(self, motions, values, mu, progress: bool = False, objective: str | None = None, **parameters):
        """The statistics over ``motions`` of its design chart over ``values`` of :attr:`chart_over` (None: the
        model's own) and the friction ratios ``mu`` [1] for the ``objective`` named (None: its default), with its
        other ``parameters`` (where :attr:`chart_over`)."""
        raise StickslipError(f"the {self.name} model draws no design chart")

    def chart_quantities(self, objective: str | None = None) -> tuple[str, str]:
        """What its design chart (:meth:`design_chart`) draws for the ``objective`` named (None: its default), each
        in words with its units as people read them: the quantity in colours and the one in lines ("" where it
        draws none), the two whose level steps ``--chart-levels`` gives."""
        raise StickslipError(f"the {self.name} model draws no design chart")

    #: What its ``mass`` parameter [kg] is the mass of, in the header of ``optimum``'s table ("block 1 kg").
    mass_of: str = "block"
    #: The columns of ``optimum``'s table of :meth:`motion_notes`, note name -> (heading, second heading line), and
    #: the line under the table that says what they are (``{c}``: the swept coefficient's name); none by default.
    motion_note_columns: Mapping[str, tuple[str, str]] = {}
    motion_note_text: str = ""

    def motion_notes(self, motion, g: float) -> dict[str, float | int]:
        """What the model notes of ``motion`` alone (gravity ``g`` [m/s²]), the same at every value of a grid, by
        name (units of :data:`stickslip.units.UNITS`): none by default."""
        return {}

    #: For a model whose sweep gives its design answer per direction (the block in the plane and under each
    #: component alone) rather than per record (:attr:`designs`): the columns of ``optimum``'s table of
    #: :meth:`answers`, result name -> (heading, units); empty: none.
    answer_columns: Mapping[str, tuple[str, str]] = {}

    def answers(self, cube, motions, q: float, reference: float, min_points: int, options=None) -> list[dict]:
        """Per motion of a :meth:`sweep` cube, the design answer of each direction (where :attr:`answer_columns`)."""
        raise StickslipError(f"the {self.name} model has no design answer per direction")
