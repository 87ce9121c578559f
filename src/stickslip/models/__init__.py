"""The sliding-block models and the one route to solve or sweep any of them.

:data:`MODELS` holds one entry per model (:class:`~stickslip.models.entry.Model`),
each declared by its own module (:data:`~stickslip.models.registry.MODEL_MODULES`);
:func:`solve` and :func:`sweep` take a motion (or motions), a model's name
and its parameters, and hand them to the entry.  Without a model's name the
motion and the parameters given choose it (:func:`chosen_model`): the
simplest model that takes that motion and every parameter given.
"""

from __future__ import annotations

import functools
from collections.abc import Iterable

from stickslip.errors import StickslipError
from stickslip.models.entry import MOTIONS, Model, Parameter, Scheme
from stickslip.models.registry import MODELS, register

__all__ = ["MODELS", "MOTIONS", "AmbiguousModel", "Model", "Parameter", "Scheme", "chosen_model", "design_of", "motion_kind", "register",
           "solve", "sweep", "with_optimum"]


class AmbiguousModel(StickslipError):
    """Several models with the same parameters take a motion and the parameters given: the model must be named."""

    def __init__(self, message: str, models):
        super().__init__(message)
        self.models = list(models)


@functools.cache
def _motion_types() -> tuple[type, type]:
    """:class:`~stickslip.records.pair.RecordPair` and :class:`~stickslip.records.vertical.WithVertical`, imported
    when the first motion is solved (they import NumPy, which the command line's options do without)."""
    from stickslip.records.pair import RecordPair
    from stickslip.records.vertical import WithVertical

    return RecordPair, WithVertical


def motion_kind(motion) -> tuple[str, bool]:
    """The kind of ``motion`` (:data:`~stickslip.models.entry.MOTIONS`: ``"pair"`` for a
    :class:`~stickslip.records.pair.RecordPair`, else ``"component"``) and whether it comes with its vertical
    (:class:`~stickslip.records.vertical.WithVertical`)."""
    RecordPair, WithVertical = _motion_types()
    vertical = isinstance(motion, WithVertical)
    horizontal = motion.horizontal if vertical else motion
    return ("pair" if isinstance(horizontal, RecordPair) else "component"), vertical


def chosen_model(kind: str, names: Iterable[str] = (), model: str | None = None, vertical: bool = False) -> Model:
    """The model named ``model``, or the one the motion ``kind`` and the parameter ``names`` given choose.

    Among the models that take the motion (with its ``vertical`` component
    where it has one) and every name that some model declares as a parameter
    (the other names are a scheme's options), the first registered
    (:data:`~stickslip.models.registry.MODEL_MODULES`): ``mu`` on one component
    is the rigid block, on a pair the planar one, with a vertical or a
    ``radius`` the pendulum.  When the first shares its parameters with another
    (decoupled and coupled), one line asks for the name.
    """
    if model is not None and not isinstance(model, str):
        raise StickslipError(f"model: expected a model's name ({', '.join(MODELS)}), got {model!r}; give the "
                             "parameters by name (mu=0.1)")
    if model is not None:
        entry = MODELS[model]
        if kind not in entry.motions:
            raise StickslipError(f"the {entry.name} model takes {' or '.join(MOTIONS[m] for m in entry.motions)}, "
                                 f"not {MOTIONS[kind]}")
        if vertical and not entry.vertical:
            raise StickslipError(f"the {entry.name} model takes no vertical ground motion")
        return entry
    declared = {parameter.name for entry in MODELS.values() for parameter in entry.parameters}
    names = set(names) & declared
    candidates = [entry for entry in MODELS.values() if entry.takes(kind, names, vertical)]
    if not candidates:
        if not any(entry.takes(kind, (), vertical) for entry in MODELS.values()):
            raise StickslipError(f"no sliding-block model takes {MOTIONS[kind]}"
                                 + (" with its vertical component" if vertical else ""))
        takers = [entry for entry in MODELS.values() if entry.takes(kind, (), vertical)]
        if len(takers) == 1:
            return takers[0]  # its own check names what it does not take
        raise StickslipError(_no_one_model(kind, names, vertical))
    first = candidates[0]
    alike = [entry for entry in candidates if {p.name for p in entry.parameters} == {p.name for p in first.parameters}]
    if len(alike) > 1:
        raise AmbiguousModel(f"{', '.join(sorted(names))} fit the models {' and '.join(e.name for e in alike)}: "
                             f"give the model's name (model={alike[0].name!r})", alike)
    return first


def _no_one_model(kind: str, names: set[str], vertical: bool) -> str:
    """Why no model takes the parameter ``names`` together on the motion ``kind``: whose each name is."""
    motion = MOTIONS[kind] + (" with its vertical component" if vertical else "")
    takers = [entry for entry in MODELS.values() if entry.takes(kind, (), vertical)]
    owners = []
    for name in sorted(names):
        own = [entry.name for entry in takers if entry.takes(kind, (name,), vertical)]
        if len(own) == len(takers):
            continue  # every model of this motion takes it: not the trouble
        if own:
            owners.append(f"{name}= is the {' and '.join(own)} model" + ("s'" if len(own) > 1 else "'s"))
        else:
            elsewhere = [f"{entry.name} model's, on {' or '.join(MOTIONS[m] for m in entry.motions)}"
                         for entry in MODELS.values() if name in {p.name for p in entry.parameters}]
            owners.append(f"{name}= is the {' and the '.join(elsewhere)}")
    return f"no one model takes {', '.join(f'{name}=' for name in sorted(names))} on {motion}: {'; '.join(owners)}"


def solve(motion, model: str | None = None, method: str | None = None, **parameters):
    """Solve one sliding block on ``motion``: one case of one model.

    Parameters
    ----------
    motion:
        A :class:`~stickslip.records.record.Record` (ground acceleration [m/s²],
        linear between samples; a positive value drives the block towards −x,
        downslope) or a :class:`~stickslip.records.pair.RecordPair` of two
        horizontal components.
    model:
        The model's name (:data:`MODELS`: ``"rigid"``, ``"decoupled"``,
        ``"coupled"``, ``"planar"`` …); default: chosen by the motion and the
        parameters (:func:`chosen_model`).
    method:
        The scheme (the model's default when None: ``"exact"``).
    parameters:
        The model's parameters (its entry's :attr:`~stickslip.models.entry.Model.parameters`,
        each with its unit: ``mu`` [1], ``ky`` [1], ``mass`` [kg], ``g`` [m/s²],
        ``height`` [m] …) and the scheme's options (``time_step`` [s] for
        ``newmark``).

    Returns
    -------
    The model's result, a :class:`~stickslip.models.result.Result`.  A parameter
    or option the model or scheme does not take, a value out of range, work
    whose memory estimate exceeds :func:`stickslip.limits.memory_limit` and
    results that are not finite raise :class:`StickslipError`.
    """
    kind, vertical = motion_kind(motion)
    return chosen_model(kind, parameters, model, vertical).solve(motion, method, **parameters)


def sweep(motions, model: str | None = None, method: str | None = None, **keywords):
    """Solve every motion over grids of a model's swept parameters; one labelled cube (:class:`xarray.Dataset`).

    ``motions`` are records (or record pairs); ``keywords`` are the model's
    parameters, a list of values for a swept one (``mu=[0.05, 0.1]``,
    ``ky=[...]``, ``height=[...]``), and what the model's sweep takes besides
    (``scale`` or ``target_pga`` [m/s²], ``progress``, ``config``, the scheme's
    ``options``; see each model's ``sweep``).
    """
    motions = list(motions)
    if not motions:
        raise StickslipError("a sweep needs at least one record")
    kind, vertical = motion_kind(motions[0])
    return chosen_model(kind, keywords, model, vertical).sweep(motions, method, **keywords)


def with_optimum(cube, records, q: float | None = None, reference: float | None = None):
    """``cube`` of :func:`sweep` with each record's design answer: μ_max (k_y,max), near-optimal range, stroke …

    The model the cube was swept with (its ``model`` attribute; a cube
    without one is the rigid block's) answers (:meth:`~stickslip.models.entry.Model.design_answer`);
    ``records`` are the unscaled records given to the sweep, ``q`` the
    near-optimal fraction (default :data:`stickslip.optimum.DEFAULT_Q`) and
    ``reference`` [1] the value of the grid's coefficient whose E_df and
    efficiency are reported (:func:`stickslip.optimum.cube_with_optimum`).
    """
    from stickslip.optimum import DEFAULT_Q

    return _designing_model(cube).design_answer(cube, records, DEFAULT_Q if q is None else q, reference)


def design_of(cube):
    """The block ``cube`` of :func:`sweep` was swept with, over the cube's grid, as :mod:`stickslip.optimum` reads it.

    Its model's ``design_of`` (:meth:`stickslip.models.swept.SweptModel.design_of`): mass [kg], gravity
    [m/s²], how the block slides, the scheme and its options, the grid [1], the model's demands; the model
    is the cube's, as for :func:`with_optimum`.
    """
    return _designing_model(cube).design_of(cube)


def _designing_model(cube) -> Model:
    """The model ``cube`` was swept with (its ``model`` attribute; a cube without one is the rigid block's), which
    must have a design answer over a grid; else one line."""
    entry = MODELS[cube.attrs.get("model", "rigid")]
    if not entry.designs:
        raise StickslipError(f"the {entry.name} model has no design answer over a grid")
    return entry
