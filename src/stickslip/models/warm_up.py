"""Compiling the numba kernels into numba's cache on disk once, at install, so that no command compiles them.

numba compiles a kernel at its first call for the types of its arguments (its
signature: each array's dtype, dimensions and layout, each scalar's type) and,
every kernel of stickslip being ``cache=True``, keeps the machine code on disk:
beside the source with an editable install (``src/stickslip/**/__pycache__/``,
``*.nbi`` index and ``*.nbc`` data files, which ``.gitignore``'s ``__pycache__/``
covers), or under ``NUMBA_CACHE_DIR`` when that is set.  A later process that
calls the kernel with the same signature loads it in a fraction of a second
instead of compiling it for seconds (on a fresh install the first ``stickslip
solve A B --pair`` took 8 to 9 s, benchmarks/README.md, "First calls").

A cache entry serves only the signature it was compiled for, so
:func:`warm_up` names no kernel: it solves a synthetic motion through the
models' entries, as the commands do, for every sliding model of
:data:`stickslip.models.MODELS`, every scheme of it (``entry.schemes``) and
every motion it takes (``entry.motions``, and each with its vertical
component where the model takes one, ``entry.vertical``), at each of the
entry's :attr:`~stickslip.models.entry.Model.examples`; it reads each result
as ``solve`` prints it and, for a scheme with a batched kernel
(``scheme.batched``), sweeps the motion along the example's swept
parameters and reads the sweep's design answer as ``sweep`` and ``optimum``
do.  Whatever the entries pass to the kernels is what gets compiled, and a
new model needs no line here, only its examples.  The record is one sample
longer than :data:`~stickslip.models.rigid.events.PYTHON_SAMPLES`, so that
the rigid block's compiled history kernels are compiled too.  ``make env``
and ``make test`` run it: ``python -m stickslip.cli.warm_up`` (:mod:`stickslip.cli.warm_up`).
"""

from __future__ import annotations

import warnings

import numpy as np

from stickslip.errors import StickslipError, StickslipWarning

#: The synthetic record's time step [s] (the newmark scheme's default step: nothing to resample).
DT = 0.001


def _synthetic_motions(samples: int | None = None) -> dict:
    """Each kind of motion (:data:`~stickslip.models.entry.MOTIONS`), without and with its vertical component, as
    the warm-up solves and sweeps it, by ``(kind, with the vertical)``.

    A horizontal component [m/s²] of a decaying motion (peak about 4 m/s²),
    at rest after a minute, one sample longer than the rigid block's
    plain-Python limit, every :data:`DT`; the pair of it and a second one
    (peak about 3 m/s²); the vertical component beside them peaks at about
    2 m/s², positive up; only its first ``samples`` where given (a model's
    :attr:`~stickslip.models.entry.Model.warm_up_samples`).
    """
    from stickslip.models.rigid import PYTHON_SAMPLES
    from stickslip.records.pair import RecordPair
    from stickslip.records.record import Record, RecordMeta
    from stickslip.records.vertical import WithVertical

    time_ = np.arange(PYTHON_SAMPLES + 1 if samples is None else samples) * DT
    envelope = np.exp(-0.5 * time_)
    first = Record(4.0 * envelope * np.sin(2.0 * np.pi * 1.5 * time_), DT,
                   RecordMeta(record_id="warm-up-000", station="warm-up", component="000"))
    second = Record(3.0 * envelope * np.sin(2.0 * np.pi * 2.1 * time_ + 1.0), DT,
                    RecordMeta(record_id="warm-up-090", station="warm-up", component="090"))
    vertical = Record(2.0 * envelope * np.sin(2.0 * np.pi * 2.7 * time_ + 0.5), DT,
                      RecordMeta(record_id="warm-up-UP", station="warm-up", component="UP"))
    horizontal = {"component": first, "pair": RecordPair(first, second)}
    return {**{(kind, False): motion for kind, motion in horizontal.items()},
            **{(kind, True): WithVertical(motion, vertical, "positive up") for kind, motion in horizontal.items()}}


def _as_printed(result) -> None:
    """Read ``result`` as ``stickslip solve`` prints it (table, notes, further tables, ``--json``'s extras)."""
    result.describe()
    result.scalars()
    result.notes()
    result.notices()
    result.tables()
    result.extras()


def _swept(entry, parameters: dict) -> dict | None:
    """``parameters`` with each swept one (:attr:`~stickslip.models.entry.Parameter.swept`) a grid of two values,
    half its value and its value; None where none is swept."""
    swept = {parameter.name for parameter in entry.parameters if parameter.swept} & set(parameters)
    if not swept:
        return None
    return {name: [0.5 * value, value] if name in swept else value for name, value in parameters.items()}


def warm_up_scheme(entry, scheme, motions: dict) -> None:
    """Solve ``entry``'s examples with ``scheme`` on each motion it takes (with its vertical too, where the model
    takes one), as the commands do; sweep them along their swept parameters where the scheme is batched.

    An example the scheme refuses by its own rules (a slope for a flat-only
    scheme, an option it does not take: a :class:`StickslipError`) is not
    that scheme's; a scheme and motion that none of the examples suits is a
    mistake of the entry's declaration, which a
    :class:`~stickslip.errors.StickslipWarning` names (the kernels then compile
    at their first call; the install goes on).
    """
    from stickslip.optimum import DEFAULT_Q

    for kind in entry.motions:
        for vertical in (False, True) if entry.vertical else (False,):
            motion = motions[kind, vertical]
            solved = 0
            for example in entry.examples:
                try:
                    result = entry.solve(motion, scheme.name, **example)
                except StickslipError:
                    continue
                solved += 1
                _as_printed(result)
                parameters, options = entry.split(example)
                grids = _swept(entry, parameters)
                if scheme.batched and grids is not None:
                    cube = entry.sweep([motion], scheme.name, progress=False,
                                       **({"options": options} if options else {}), **grids)
                    entry.design_answer(cube, [motion], DEFAULT_Q)
            if not solved:
                what = kind + (" with its vertical" if vertical else "")
                warnings.warn(f"the {entry.name} model's scheme {scheme.name} solves none of the model's examples on "
                              f"a {what}, so its kernels compile at their first call: declare one it takes "
                              "(stickslip.models.entry.Model.examples)", StickslipWarning, stacklevel=2)


def _bulk_reading() -> None:
    """The record reader's compiled number conversion (:func:`stickslip.records.readers.read_records`)."""
    from stickslip.records.numbers import compiled_conversion, parse_numbers

    with compiled_conversion():
        parse_numbers("0.125 -0.25\n1.5E-3 2\n", 1, "warm-up")


def warm_up() -> list[str]:
    """Solve every scheme of every sliding model of :data:`stickslip.models.MODELS` on its motions
    (:func:`warm_up_scheme`), and read numbers as the bulk reader does, so that numba compiles (or loads) each
    kernel with the signatures the commands use; the ``model/scheme`` done."""
    from stickslip.models import MODELS

    motions = {None: _synthetic_motions()}
    done = []
    for entry in MODELS.values():
        if entry.warm_up_samples not in motions:
            motions[entry.warm_up_samples] = _synthetic_motions(entry.warm_up_samples)
        for scheme in entry.schemes:
            warm_up_scheme(entry, scheme, motions[entry.warm_up_samples])
            done.append(f"{entry.name}/{scheme.name}")
    _bulk_reading()
    return done

