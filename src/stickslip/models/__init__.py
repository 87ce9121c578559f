"""The sliding-block models and the one route to solve or sweep any of them.

:data:`MODELS` holds one entry per model (:class:`~stickslip.models.entry.Model`),
each declared by its own module (:data:`~stickslip.models.registry.MODEL_MODULES`);
:func:`solve` and :func:`sweep` take a motion (or motions), a model's name
and its parameters, and hand them to the entry.  Without a model's name the
motion and the parameters given choose it (:func:`chosen_model`): the
simplest model that takes that motion and every parameter given.
"""

from __future__ import annotations

from collections.abc import Iterable

from stickslip.errors import StickslipError
from stickslip.models.entry import MOTIONS, Model, Parameter, Scheme
from stickslip.models.registry import MODELS, register

__all__ = ["MODELS", "MOTIONS", "Model", "Parameter", "Scheme", "chosen_model", "motion_kind", "register", "solve",
           "sweep"]


def motion_kind(motion) -> str:
    """The kind of ``motion`` (:data:`~stickslip.models.entry.MOTIONS`): ``"pair"`` for a
    :class:`~stickslip.records.pair.RecordPair`, else ``"component"``."""
    from stickslip.records.pair import RecordPair

    return "pair" if isinstance(motion, RecordPair) else "component"


def chosen_model(kind: str, names: Iterable[str] = (), model: str | None = None) -> Model:
    """The model named ``model``, or the one the motion ``kind`` and the parameter ``names`` given choose.

    Among the models that take the motion and every name that some model
    declares as a parameter (the other names are a scheme's options), the one
    with the fewest parameters: ``mu`` on one component is the rigid block,
    on a pair the planar one.  Two such models with as many parameters
    (decoupled and coupled take the same) are one line asking for the name.
    """
    if model is not None and not isinstance(model, str):
        raise StickslipError(f"model: expected a model's name ({', '.join(MODELS)}), got {model!r}; give the "
                             "parameters by name (mu=0.1)")
    if model is not None:
        entry = MODELS[model]
        if kind not in entry.motions:
            raise StickslipError(f"the {entry.name} model takes {' or '.join(MOTIONS[m] for m in entry.motions)}, "
                                 f"not {MOTIONS[kind]}")
        return entry
    declared = {parameter.name for entry in MODELS.values() for parameter in entry.parameters}
    names = set(names) & declared
    candidates = [entry for entry in MODELS.values() if entry.takes(kind, names)]
    if not candidates:
        takers = [entry for entry in MODELS.values() if kind in entry.motions]
        if not takers:
            raise StickslipError(f"no sliding-block model takes {MOTIONS[kind]}")
        return takers[0]  # its own check names what it does not take
    fewest = min(len(entry.parameters) for entry in candidates)
    simplest = [entry for entry in candidates if len(entry.parameters) == fewest]
    if len(simplest) > 1:
        raise StickslipError(f"{', '.join(sorted(names))} fit the models {' and '.join(e.name for e in simplest)}: "
                             f"give the model's name (model={simplest[0].name!r})")
    return simplest[0]


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
    return chosen_model(motion_kind(motion), parameters, model).solve(motion, method, **parameters)


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
    return chosen_model(motion_kind(motions[0]), keywords, model).sweep(motions, method, **keywords)
