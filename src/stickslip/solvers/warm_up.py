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
:func:`warm_up` names no kernel: it solves a synthetic two-component record
through the functions the commands call, for every scheme of every sliding
model of :data:`stickslip.solvers.flexible.MODELS` (:data:`SOLVES`, the one
table to change when a model or a scheme's entry point changes), and whatever
those functions pass to the kernels is what gets compiled.  The record is one
sample longer than :data:`~stickslip.solvers.events.PYTHON_SAMPLES`, so that
the rigid block's compiled history kernels are compiled too.  ``make env``
and ``make test`` run it: ``python -m stickslip.solvers.warm_up``.
"""

from __future__ import annotations

import sys
import time

import numpy as np

from stickslip.constants import STANDARD_GRAVITY

#: The synthetic record's time step [s] (the newmark scheme's default step: nothing to resample).
DT = 0.001

#: The friction ratios and the yield coefficient [1] solved.
MU, KY = (0.05, 0.1), 0.1


def _rigid(method: str, record, pair) -> None:
    """The rigid block as ``solve`` and ``sweep`` solve it: flat and one-way, each reading of a scheme, the batched
    kernel and its one-case form (the μ_max refinement)."""
    from stickslip.solution import solve
    from stickslip.solvers import exact, newmark, registry

    entry = registry.scheme(method)
    for options in ([{"reading": reading} for reading in newmark.READINGS] if method == "newmark" else [{}]):
        solve(record, mu=MU[1], method=method, **options)
    if not entry.flat_only:
        solve(record, ky=KY, method=method)
    if entry.batched:
        exact.sweep_scalars([record.acceleration, pair.second.acceleration], [record.dt, pair.second.dt],
                            np.array(MU), STANDARD_GRAVITY)
        exact.record_scalars(record.acceleration, record.dt, MU[1], STANDARD_GRAVITY)


def _layer(model: str):
    """The flexible block ``model`` as ``solve_flexible`` (and the flexible sweep) solves it: an equivalent-linear
    layer, with the energy ledger and without."""
    def solve_model(method: str, record, pair) -> None:
        from stickslip.solvers.flexible import solve_flexible
        from stickslip.solvers.layer import Layer

        layer = Layer(10.0, 300.0, 600.0, soil_model="equivalent-linear")
        for ledger in (True, False):
            solve_flexible(record, KY, layer, model, method, ledger=ledger)

    return solve_model


def _planar(method: str, record, pair) -> None:
    """Sliding in the plane as ``solve --pair`` and ``sweep --pair`` solve it (the 1-D components by the rigid
    block's batched kernel)."""
    from stickslip.planar_sweeps import components_alone, planar_sweep
    from stickslip.solution import solve

    solve(pair, mu=MU[1], method=method)
    components_alone(pair, MU[1])
    planar_sweep([pair], list(MU), progress=False)


#: How the commands solve each sliding model of :data:`~stickslip.solvers.flexible.MODELS`, by name:
#: ``solve(method, record, pair)`` for each of the model's schemes.
SOLVES = {"rigid": _rigid, "decoupled": _layer("decoupled"), "coupled": _layer("coupled"), "planar": _planar}


def _synthetic_pair():
    """Two horizontal components [m/s²] of a decaying motion (peaks about 4 and 3 m/s²), at rest after a minute,
    one sample longer than the rigid block's plain-Python limit, every :data:`DT`."""
    from stickslip.records.pair import RecordPair
    from stickslip.records.record import Record, RecordMeta
    from stickslip.solvers.events import PYTHON_SAMPLES

    time_ = np.arange(PYTHON_SAMPLES + 1) * DT
    envelope = np.exp(-0.5 * time_)
    first = Record(4.0 * envelope * np.sin(2.0 * np.pi * 1.5 * time_), DT,
                   RecordMeta(record_id="warm-up-000", station="warm-up", component="000"))
    second = Record(3.0 * envelope * np.sin(2.0 * np.pi * 2.1 * time_ + 1.0), DT,
                    RecordMeta(record_id="warm-up-090", station="warm-up", component="090"))
    return first, RecordPair(first, second)


def _bulk_reading() -> None:
    """The record reader's compiled number conversion (:func:`stickslip.records.readers.read_records`)."""
    from stickslip.records.numbers import compiled_conversion, parse_numbers

    with compiled_conversion():
        parse_numbers("0.125 -0.25\n1.5E-3 2\n", 1, "warm-up")


def warm_up() -> list[str]:
    """Solve every scheme of every sliding model once (:data:`SOLVES`), and read numbers as the bulk reader does,
    so that numba compiles (or loads) each kernel with the signatures the commands use; the ``model/scheme`` done."""
    from stickslip.solvers.flexible import MODELS

    record, pair = _synthetic_pair()
    done = []
    for name, model in MODELS.items():
        for method in model.schemes:
            SOLVES[name](method, record, pair)
            done.append(f"{name}/{method}")
    _bulk_reading()
    return done


def main() -> int:
    """``python -m stickslip.solvers.warm_up``: warm up, and say what and in how long."""
    start = time.perf_counter()
    done = warm_up()
    print(f"numba kernels compiled or loaded for {', '.join(done)} and the bulk reader in "
          f"{time.perf_counter() - start:.0f} s", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
