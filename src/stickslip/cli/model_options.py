"""The sliding-block model, its scheme and its parameters on the command line, from the models' declarations.

Every option here comes from a declaration (:mod:`stickslip.models`):
``--model`` (the registry's names), ``--method`` (the schemes of its
models), the scheme options of :data:`SCHEME_OPTIONS`, and one option per
parameter of every model (:class:`~stickslip.models.entry.Parameter`), read
by its kind:

* ``number``: a number in the parameter's unit (``--height 20``), or with a
  unit of the same quantity (``--height 2000cm``, ``--mu 6%``, ``--mass 5100g``:
  :func:`stickslip.cli.quantities.of_unit`);
* ``acceleration``: a bare number in units of g, or a number with an
  acceleration unit (``--ky 0.15``, ``--ky 1.47m/s2``: :mod:`stickslip.cli.accelerations`);
  one that may vary with displacement also has ``--{name}-table``;
* ``strain``: a percentage with its unit (``--reference-strain 0.05%``; a bare
  number is refused, since pySLAMMER's decimal strain 0.0005 is 0.05 %);
* ``flag`` (``--inverse``) and ``choice`` (``--direction both``).

A value above the largest its declaration calls plausible (``plausible``: a
friction ratio or yield coefficient above 1), or a bare number outside its
usual range (``usual``: ``--radius 200``), gets a warning that names the
readings a user more likely meant (:func:`warn_if_implausible`; a bare
``--ky 15``: 15 g, or 0.0153 g in cm/s²; ``--radius 200``: 2 m in cm), one for
each value of a list or grid.

In ``sweep``, ``optimum`` and ``report`` a swept parameter takes a grid:
``START:STOP:STEP`` (STOP included when it lies on the grid), a comma list, or
``--{name}-list`` with the values one by one.  Without ``--model`` the
motion and the parameters given choose the model
(:func:`stickslip.models.chosen_model`); a parameter given that the model
does not take is one line naming the models that take it.
"""

from __future__ import annotations

import argparse
import re
import warnings

import numpy as np

from stickslip.cli.accelerations import in_units_of_g, number_and_unit
from stickslip.cli.quantities import grid_part, of_unit, parse_quantity, quantity_type, read_gravity, warn_if_unusual
from stickslip.errors import StickslipError, StickslipWarning
from stickslip.grids import COEFFICIENTS
from stickslip.models import MODELS, MOTIONS, AmbiguousModel, chosen_model
from stickslip.models.parameters import GRAVITY

#: The scheme options the command line offers: name -> (type, help).
SCHEME_OPTIONS = {
    "time_step": (quantity_type(of_unit("s"), "--time-step"),
                  "integration step [s] of a scheme that takes one (newmark: default 0.001; or with its unit, 1ms)"),
}

#: What each kind of parameter is written as, for its help's metavar.
METAVARS = {"number": "X", "acceleration": "A", "strain": "PERCENT", "choice": None, "flag": None}


def offered_parameters() -> dict:
    """Every parameter the command line offers, by name: (its declaration, the names of the models that take it)."""
    offered: dict = {}
    for entry in MODELS.values():
        for parameter in entry.parameters:
            if parameter.command_line:
                offered.setdefault(parameter.name, (parameter, []))[1].append(entry.name)
    return offered


def _option(name: str) -> str:
    return "--" + name.replace("_", "-")


def add_model_options(parser: argparse.ArgumentParser, grids: bool = False) -> None:
    """Add ``--model``, ``--method``, the scheme options and every model parameter's option to ``parser``.

    ``grids``: a swept parameter takes a grid (``sweep``, ``optimum``), with ``--{name}-list`` beside it.
    """
    parser.add_argument("--model", choices=tuple(MODELS), default=None,
                        help="sliding-block model: " + "; ".join(f"{name}: {entry.summary}"
                                                                  for name, entry in MODELS.items())
                             + " (default: chosen by --pair and the parameters given)")
    methods = list(dict.fromkeys(scheme.name for entry in MODELS.values() for scheme in entry.schemes))
    parser.add_argument("--method", choices=methods, default=None,
                        help="solver scheme (default: the model's first, exact; docs/solvers.md): "
                             + "; ".join(f"{entry.name}: {', '.join(entry.scheme_names)}"
                                         for entry in MODELS.values()))
    for name, (kind, text) in SCHEME_OPTIONS.items():
        parser.add_argument(_option(name), type=kind, default=None, help=text)
    group = parser.add_argument_group("the models' parameters (each names the models that take it)")
    for name, (parameter, models) in offered_parameters().items():
        text = f"{parameter.help}{written_as(parameter)} ({', '.join(models)})".replace("%", "%%")  # argparse: %
        option = _option(name)
        target = group
        if parameter.kind == "flag":
            target.add_argument(option, action="store_true", default=None, help=text)
        elif parameter.kind == "choice":
            target.add_argument(option, choices=parameter.choices, default=None, help=text)
        elif grids and parameter.swept:
            target.add_argument(option, default=None, metavar="START:STOP:STEP",
                                help=f"{text}; a grid: START:STOP:STEP (STOP included), or a comma list")
            target.add_argument(f"{option}-list", nargs="+", default=None, metavar=METAVARS[parameter.kind],
                                help=f"explicit values of {name}, one by one")
        else:
            target.add_argument(option, default=None, metavar=METAVARS[parameter.kind], help=text)
        if parameter.tables and not grids:
            symbol = COEFFICIENTS[name].symbol if name in COEFFICIENTS else name
            target.add_argument(f"{option}-table", default=None, metavar="TABLE",
                                help=f"{symbol} varying with the block's accumulated downslope displacement D "
                                     "(SLAMMER's 'varies with displacement', D in m, not cm): a text file of lines "
                                     f"'D {name}' (D [m], {symbol} [-]; blanks or a comma between, # comments) or the "
                                     f"pairs inline, D:{name.upper()},D:{name.upper()} (0:0.15,0.1:0.10); the first D "
                                     f"is 0 and D increases, {symbol} > 0; linear between pairs, constant past the "
                                     f"last; one-way, --method slammer (a single pair is a constant {symbol}, any "
                                     f"method); instead of {option}")


def written_as(parameter) -> str:
    """What a number parameter's help adds on how its value is written: ``; or with its unit (200cm, 0.2m)``."""
    if parameter.kind != "number":
        return ""
    if parameter.unit == "1":
        return "; or a percentage (6%)"
    units = [spelling for spelling in of_unit(parameter.unit).factors if spelling is not None][1:]
    return f"; or with its unit ({', '.join(units)})" if units else ""


def given_parameters(args: argparse.Namespace) -> list[str]:
    """The names of the parameters whose options were given (a value, a list, a table or a flag)."""
    given = []
    for name, (parameter, _) in offered_parameters().items():
        spellings = (name, f"{name}_list", f"{name}_table")
        if any(getattr(args, spelling, None) not in (None, False) for spelling in spellings):
            given.append(name)
    return given


def model_from_args(args: argparse.Namespace, motion: str):
    """The model of ``--model``, or the one the motion and the options choose (see :func:`chosen_from_args`)."""
    return chosen_from_args(args, motion, getattr(args, "vertical", None) is not None)


def chosen_from_args(args: argparse.Namespace, motion: str, vertical: bool = False):
    """The model of ``--model``, or the one the motion (``"component"`` or ``"pair"``) and the options choose.

    An option of a parameter the model does not take is one line naming the
    models that take it, and one that applies only with another option (its
    declaration's ``requires``) without it is one line naming that option.
    """
    given = given_parameters(args)
    offered = offered_parameters()
    for name in given:
        excluded = [other for other in offered[name][0].excludes if other in given]
        if excluded:
            raise StickslipError(f"argument {_option(name)}: not allowed with argument {_option(excluded[0])}")
    if args.model is None:
        for name in given:
            if not any(MODELS[model].takes(motion, [name], vertical) for model in offered[name][1]):
                raise StickslipError(_not_with_motion(name, offered[name][1], motion, vertical))
    try:
        entry = chosen_model(motion, given, args.model, vertical)
    except AmbiguousModel as error:  # name the options that only these models take
        takers = [model.name for model in error.models]
        others = {p.name for name, model in MODELS.items() if name not in takers for p in model.parameters}
        telling = [_option(name) for name in given if name not in others] or [_option(name) for name in given]
        verb = "applies" if len(telling) == 1 else "apply"
        raise StickslipError(f"{', '.join(telling)} {verb} to --model {' or '.join(takers)}: give --model") from None
    except StickslipError as error:
        raise StickslipError(f"--model {args.model}: {error}" if args.model else str(error)) from None
    for name in given:
        if not entry.takes(motion, [name]):
            models = [model for model in offered[name][1] if motion in MODELS[model].motions]
            which = f"; it applies to --model {' or '.join(models)}" if models else ""
            raise StickslipError(f"{_option(name)} does not apply to the {entry.name} model ({entry.summary}){which}")
        required = offered[name][0].requires
        if required is not None:
            other, value = required
            if value is None and other not in given:
                raise StickslipError(f"{_option(name)} applies with {_option(other)} only")
            if value is not None and getattr(args, other, None) != value:
                shown = _option(other) + ("" if value is True else f" {value}")
                raise StickslipError(f"{_option(name)} applies to {shown} only")
    if args.method is not None:
        try:
            entry.scheme(args.method)
        except StickslipError as error:
            raise StickslipError(f"--method {args.method}: {error}") from None
    return entry


#: What the motion options ask for, as a message names it.
ASKED = {"pair": ("--pair", "the two horizontal components of one station, solved in the plane"),
         "vertical": ("--vertical", "the vertical ground motion in the normal force")}


def _not_with_motion(name: str, owners: list[str], motion: str, vertical: bool) -> str:
    """Why the option of parameter ``name`` (declared by the models ``owners``) does not apply with the motion asked
    for (``--pair``, ``--vertical``): what those options solve and which models, and where the option applies."""
    asked = [ASKED[what] for what, on in (("pair", motion == "pair"), ("vertical", vertical)) if on]
    takers = [entry.name for entry in MODELS.values() if entry.takes(motion, (), vertical)]
    options = " and ".join(option for option, _ in asked)
    meaning = " with ".join(text for _, text in asked)
    solved = f"{meaning}: --model {' or '.join(takers)}" if takers else meaning
    first = MODELS[owners[0]]
    where = [f"on {MOTIONS[first.motions[0]]}"] if motion not in first.motions else []
    where += ["without --vertical"] if vertical and not first.vertical else []
    return (f"{_option(name)} does not apply with {options} ({solved}); it applies to --model {' or '.join(owners)}"
            + (f", {' and '.join(where)}" if where else ""))


def gravity(args: argparse.Namespace) -> float:
    """The command's g [m/s²]: the ``--g`` given (``9.81``, ``981cm/s2``), else the default; it reads accelerations
    in units of g and converts records stored in g (one g per call).

    The text of ``--g`` is read once (:func:`~stickslip.cli.quantities.read_gravity`:
    a bare number outside 9.7 to 9.9 m/s² gets a warning), and ``args.g`` then
    holds the value [m/s²] (a float is a value already read).
    """
    given = getattr(args, "g", None)
    if given is None:
        return GRAVITY.default
    if not isinstance(given, str):
        return GRAVITY.checked(given)
    args.g = read_gravity(given)
    return args.g


def read_value(parameter, text, g: float, option: str | None = None, doubt: bool = True):
    """One value of ``parameter`` from its option's text, by its kind (``g`` [m/s²] for accelerations).

    A number is read in the parameter's unit, or with a unit of the same
    quantity (``200cm``, ``6%``: :func:`~stickslip.cli.quantities.parse_quantity`).
    ``option`` names the option in messages (default the parameter's own,
    ``--reference-ky`` for a reference value); with ``doubt``, a value beyond
    the parameter's plausible one or outside its usual range gets a warning: a
    bare acceleration with its readings in other units
    (:func:`~stickslip.cli.accelerations.in_units_of_g`), a number by
    :func:`warn_if_implausible`.
    """
    option = option or _option(parameter.name)
    if parameter.kind in ("flag", "choice"):
        return text
    if parameter.kind == "acceleration":
        return in_units_of_g(str(text), g, option, "0.15", largest=parameter.plausible if doubt else None)
    if parameter.kind == "strain":
        return read_strain(str(text), option)
    value, bare = parse_quantity(str(text), option, of_unit(parameter.unit))
    if doubt:
        warn_if_implausible(parameter, value, f"{option} {str(text).strip()}", bare)
    return value


def warn_if_implausible(parameter, value: float, shown: str, bare: bool = True, number: str | None = None) -> None:
    """A warning when ``value`` [1] of a coefficient of g exceeds the largest its declaration calls plausible
    (:attr:`~stickslip.models.entry.Parameter.plausible`): the block would slide only where the ground acceleration
    passes ``value`` g; or when a positive finite dimension lies outside its usual range
    (:attr:`~stickslip.models.entry.Parameter.usual`): a ``bare`` one with its readings in other units
    (:func:`~stickslip.cli.quantities.warn_if_unusual`; ``number`` as written, for one value of a list).  ``shown`` is
    the option as given (``--mu 15``)."""
    if parameter.usual is not None:
        if bare:
            warn_if_unusual(shown, value, of_unit(parameter.unit, parameter.usual), number or f"{value:g}")
        return
    if parameter.plausible is None or not value > parameter.plausible:
        return
    noun = COEFFICIENTS[parameter.name].noun if parameter.name in COEFFICIENTS else parameter.name
    advice = f"; a {noun} is written as a fraction ({value / 100:g} for {value:g} %)" if bare else ""
    warnings.warn(f"{shown}: a {noun} of {value:g}: the block slides only where the ground acceleration passes "
                  f"{value:g} g, which no ground motion reaches{advice}", StickslipWarning, stacklevel=2)


def read_strain(text: str, option: str) -> float:
    """A strain in percent, with its unit: ``"0.05%"``; a bare number is refused (0.0005 is 0.05 % to pySLAMMER)."""
    text = text.strip()
    if not text.endswith("%"):
        raise StickslipError(f"{option} {text!r}: give the strain with its unit, in percent (0.05%); pySLAMMER's "
                             "decimal strain 0.0005 is 0.05%")
    try:
        return float(text.removesuffix("%"))
    except ValueError:
        raise StickslipError(f"{option} {text!r}: expected a strain in percent, such as 0.05%") from None


def read_grid(parameter, args: argparse.Namespace, g: float) -> np.ndarray | None:
    """The values of a swept ``parameter`` from ``--{name}`` (a grid or a comma list) or ``--{name}-list``, each
    read as :func:`read_value` reads one; a warning for each value beyond the plausible or outside the usual range
    (:func:`warn_if_implausible`)."""
    from stickslip.cli.grid_values import parse_values

    option = _option(parameter.name)
    listed = getattr(args, f"{parameter.name}_list", None)
    text = getattr(args, parameter.name, None)
    if listed is not None and text is not None:
        raise StickslipError(f"give {option} or {option}-list, not both")
    if listed is not None:
        from stickslip.grids import positive_increasing

        values = positive_increasing([read_value(parameter, value, g, doubt=False) for value in listed],
                                     f"{option}-list: {parameter.plural or parameter.name}")
        shown, written = f"{option}-list {' '.join(listed)}", listed
    elif text is None:
        return None
    else:
        values = parse_values(str(text), option, parameter.plural or f"values of {parameter.name}",
                              parameter.example or "1:10:1",
                              grid_part(lambda part: read_value(parameter, part, g, doubt=False)))
        shown, written = f"{option} {text}", re.split(r"[,:]", str(text))
    bare = all((number_and_unit(part) or (0.0, "?"))[1] == "" for part in written)
    for value in values:
        warn_if_implausible(parameter, float(value), shown, bare)
    return values


def read_table(text: str, option: str):
    """A :class:`~stickslip.models.yield_table.YieldTable` from a file, or from pairs ``D:KY,D:KY`` inline when no
    such file exists; one-line errors."""
    from pathlib import Path

    from stickslip.models.yield_table import YieldTable

    if ":" in text and not Path(text).exists():
        return YieldTable.parse(text, f"{option} {text!r}")
    return YieldTable.read(text)


def parameters_from_args(args: argparse.Namespace, entry, grids: bool = False) -> dict:
    """The model's parameters given on the command line, each read by its kind; ``grids``: swept ones as grids."""
    g = gravity(args)
    values = {}
    for parameter in entry.parameters:
        if not parameter.command_line:
            continue
        if grids and parameter.in_sweeps and getattr(args, parameter.name, None) is not None:
            raise StickslipError(f"{_option(parameter.name)}: {parameter.in_sweeps}")
        table = getattr(args, f"{parameter.name}_table", None) if parameter.tables else None
        if table is not None:
            if getattr(args, parameter.name, None) is not None:
                raise StickslipError(f"give {_option(parameter.name)} or {_option(parameter.name)}-table, not both")
            values[parameter.name] = read_table(table, _option(parameter.name) + "-table")
        elif grids and parameter.swept:
            found = read_grid(parameter, args, g)
            if found is not None:
                values[parameter.name] = found
        elif parameter is GRAVITY and args.g is not None:
            values[parameter.name] = g
        elif getattr(args, parameter.name, None) is not None:
            text = getattr(args, parameter.name)
            try:
                values[parameter.name] = parameter.checked(read_value(parameter, text, g))
            except StickslipError as error:
                shown = "" if parameter.kind == "flag" else f" {text}"
                message = str(error)
                raise StickslipError(message if message.startswith(_option(parameter.name)) else
                                     f"{_option(parameter.name)}{shown}: {message}") from None
    return values


def scheme_options_from_args(args: argparse.Namespace, entry) -> dict:
    """The scheme options given (``time_step``), refused for a scheme that does not take them."""
    options = {name: getattr(args, name) for name in SCHEME_OPTIONS if getattr(args, name, None) is not None}
    scheme = entry.scheme(args.method)
    for name in options:
        if name not in scheme.options:
            takers = [other.name for model in MODELS.values() for other in model.schemes if name in other.options]
            raise StickslipError(f"{_option(name)} applies to --method {' or '.join(dict.fromkeys(takers))} only "
                                 f"({scheme.name} follows the record's samples)")
    return options
