"""Compiling kernels with numba so that they call each other compiled, and the event engine on a model's phase functions."""

from __future__ import annotations

import functools
import sys
import types


def bound_functions(module, names, *, bound=None, owner=None, wrap=None) -> dict:
    """Copies of the functions of ``module`` named in ``names``, by name, whose globals are the module's with the
    names of ``bound`` (a dict) its values and ``names`` the copies themselves, each passed through ``wrap``.

    With ``owner`` (a module) the copies belong to it: their ``__module__`` is
    its name and their code its file, so that numba keeps their machine code
    beside the owner's (one cache per owner of the same function) and compiles
    them again when the owner's file changes.  numba does not look at the
    files of the functions a kernel calls: after an edit of ``module`` alone,
    clear the owners' ``__pycache__`` (a fresh clone has none).
    """
    namespace = dict(vars(module))
    namespace.update(bound or {})
    if owner is not None:
        namespace["__name__"] = owner.__name__
    for name in names:
        function = namespace[name]
        code = function.__code__ if owner is None else function.__code__.replace(co_filename=owner.__file__)
        copy = types.FunctionType(code, namespace, name, function.__defaults__, function.__closure__)
        namespace[name] = copy if wrap is None else wrap(copy)
    return {name: namespace[name] for name in names}


def compiled_kernels(module, names, *, bound=None, owner=None, inlined=(), **options) -> dict:
    """``numba.njit(**options)`` of each function of ``module`` named in ``names``, by name.

    Each is compiled from a copy of the function (:func:`bound_functions`):
    numba resolves a kernel's globals when it compiles it, so the kernels call
    each other, and the bound functions, compiled while the module's own
    functions stay plain Python.  The names in ``inlined`` are compiled into
    each caller (``inline="always"``): a phase function of the event engine
    called once an interval costs a call that passes its tuples otherwise.
    """
    import numba

    def compiled(function):
        return numba.njit(**options, **({"inline": "always"} if function.__name__ in inlined else {}))(function)

    return bound_functions(module, names, bound=bound, owner=owner, wrap=compiled)


@functools.cache
def engine_pieces() -> dict:
    """The shared pieces of :mod:`stickslip.solvers.events` (its ``PIECES``), compiled once, by name."""
    from stickslip.solvers import events

    return compiled_kernels(events, events.PIECES, cache=True)


def interval_engine(owner_name: str, **phase_functions):
    """:func:`stickslip.solvers.events.interval_state` compiled on a model's ``band``, ``slide_edge``,
    ``stop_time`` and ``slid`` (compiled with ``inline="always"``), for the module ``owner_name``."""
    from stickslip.solvers import events

    return compiled_kernels(events, ("interval_state",), bound={**engine_pieces(), **phase_functions},
                            owner=sys.modules[owner_name], cache=True)["interval_state"]


def record_engine(owner_name: str, **phase_functions):
    """:func:`stickslip.solvers.events.record_state` compiled on a model's phase functions, for the module ``owner_name``.

    ``phase_functions`` are the model's compiled ``hold_band``, ``held_over``,
    ``slid_through`` and ``crossed``, and ``holding`` where the engine's
    (the state's phase s, its third number, is 0) does not do; compiled with
    ``inline="always"``, they cost the loop no call.  The loop is compiled
    without numba's reference counting (``_nrt=False``): each inlined phase
    function takes the record's tuple of arrays anew, and counting those
    references cost two atomic operations per array and interval, a quarter of
    the rigid block's μ sweep's time; the loop makes no array, and the caller holds the
    record's.
    """
    from stickslip.solvers import events

    names = ("record_state",) if "holding" in phase_functions else ("holding", "record_state")
    return compiled_kernels(events, names, bound={**engine_pieces(), **phase_functions},
                            owner=sys.modules[owner_name], inlined=("holding",), cache=True, _nrt=False)["record_state"]


def sweep_engine(owner_name: str, solved_pair):
    """:func:`stickslip.solvers.events.sweep_pairs` compiled, in parallel, on a model's ``solved_pair``."""
    import numba

    from stickslip.solvers import events

    return compiled_kernels(events, ("sweep_pairs",),
                            bound={**engine_pieces(), "solved_pair": solved_pair, "prange": numba.prange},
                            owner=sys.modules[owner_name], cache=True, parallel=True)["sweep_pairs"]
