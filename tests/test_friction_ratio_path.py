"""The friction ratio given to ``stickslip solve`` reaches the solver through few modules, and builds no grid.

A runtime trace: every function of the package whose arguments hold the value
of ``--mu`` (directly, in a mapping or sequence, or as an attribute of an
object) is recorded while the command runs, from the parsed options to the
scheme that calls the compiled kernel (whose own module, not a Python frame,
is counted on top).  A model's route is the command line's option reading, the
model's entry and parameter checks, and the model's own modules: no detour
through a grid, a sweep or a study.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

import stickslip

PACKAGE = Path(stickslip.__file__).resolve().parent
#: A value of μ no other number of the run can equal by chance.
MU = 0.123456789
#: At most this many modules of the package carry μ from the command to the kernel (the kernel's included): the
#: command, cli/quantities.py (a value with its unit, ``--mu 6%``), the option reading, the entry, the check, the
#: rigid model's entry, case, resistance and scheme, the exact scheme and the kernel.
MOST_MODULES = 11


def holds(value, depth: int = 0) -> bool:
    """Whether ``value`` is :data:`MU`, or holds it one level down (mapping, sequence, small array, attributes)."""
    if isinstance(value, float):
        return value == MU
    if depth > 1:
        return False
    if isinstance(value, dict):
        return any(holds(item, depth + 1) for item in value.values())
    if isinstance(value, (list, tuple)):
        return any(holds(item, depth + 1) for item in value[:20])
    if isinstance(value, np.ndarray):
        return value.dtype.kind == "f" and value.size < 1000 and bool(np.any(value == MU))
    attributes = getattr(value, "__dict__", None)
    if isinstance(attributes, dict) and not isinstance(value, type):
        return any(holds(item, depth + 1) for item in attributes.values())
    return False


def modules_carrying_mu(run_cli, *args) -> tuple[list[str], set[str]]:
    """The package's modules whose functions were called with μ in their arguments, in order; and every function called."""
    carrying: list[str] = []
    called: set[str] = set()

    def profile(frame, event, _):
        if event != "call":
            return
        path = Path(frame.f_code.co_filename)
        if PACKAGE not in path.parents:
            return
        module = path.relative_to(PACKAGE).as_posix()
        called.add(f"{module}:{frame.f_code.co_qualname}")
        if module not in carrying and any(holds(value) for value in frame.f_locals.values()):
            carrying.append(module)

    sys.setprofile(profile)
    try:
        code, _, err = run_cli(*args)
    finally:
        sys.setprofile(None)
    assert code == 0, err
    return carrying, called


@pytest.fixture
def record_file(tmp_path, two_tone_record) -> Path:
    """The two-tone record as a two-column text file: time [s], acceleration [g]."""
    path = tmp_path / "two_tone.txt"
    time = np.arange(two_tone_record.npts) * two_tone_record.dt
    np.savetxt(path, np.column_stack([time, two_tone_record.acceleration / 9.80665]), fmt="%.6f")
    return path


def test_mu_reaches_the_rigid_kernel_through_the_options_the_entry_and_the_model_only(run_cli, record_file):
    carrying, called = modules_carrying_mu(run_cli, "solve", record_file, "--units", "g", "--mu", MU)
    # the command's module, which reads --mu as text and hands the parsed value on, and the compiled kernel,
    # which has no Python frame to trace
    route = ["cli/solve.py", *carrying, "models/rigid/exact.py"]
    assert len(set(route)) <= MOST_MODULES, route
    assert carrying[:2] == ["cli/quantities.py", "cli/model_options.py"] and "models/entry.py" in carrying
    assert not {"grids.py", "sweeps.py", "optimum.py"} & set(route), route
    assert not [name for name in called if name.startswith("studies/")]
    assert "grids.py:Grid.__init__" not in called  # no grid rebuilt to say whether the block slides


def test_the_trace_sees_mu_where_it_is(run_cli, record_file):
    """The check can fail: the trace finds μ in the command line's options and in the rigid model."""
    carrying, _ = modules_carrying_mu(run_cli, "solve", record_file, "--units", "g", "--mu", MU)
    assert "cli/model_options.py" in carrying
    assert any(module.startswith("models/rigid/") for module in carrying)
    assert not modules_carrying_mu(run_cli, "solve", record_file, "--units", "g", "--mu", 0.2)[0]
