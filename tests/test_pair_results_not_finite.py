"""A pair of components whose results are not finite is one line and exit code 2, never a traceback.

The pendulum in the plane and the flat block in the plane check their end results as the 1-D solvers do
(:func:`stickslip.checks.checked_finite_results`); a count among them (the slip episodes) that is NaN must reach
that check rather than fail in ``int()`` before it.  A kernel whose integration went beyond double precision
is stood in for by one that returns NaN for every result.  A pair whose acceleration holds NaN (a record built
or processed in Python; the readers refuse such a file) is named as the 1-D solvers name it.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from conftest import assert_one_error_line

import stickslip
from stickslip.errors import StickslipError
from stickslip.models.planar import solver as planar_solver
from stickslip.records.pair import RecordPair
from stickslip.records.record import Record, RecordMeta
from stickslip.solvers import plane


def _diverged(*arguments):
    """A kernel that went beyond double precision: every end result NaN (the slip count too), no give-up time."""
    out = arguments[-1]
    out[:] = math.nan
    return math.nan


@pytest.fixture
def pair_files(tmp_path) -> tuple:
    time = np.arange(0.0, 4.0, 0.01)
    paths = []
    for name, phase in (("STA-000", 0.0), ("STA-090", 1.0)):
        path = tmp_path / f"{name}.txt"
        values = 3.0 * np.sin(2 * np.pi * 1.5 * time + phase)
        path.write_text("\n".join(f"{t:.2f} {value:.9e}" for t, value in zip(time, values)) + "\n")
        paths.append(path)
    return paths


@pytest.mark.parametrize(("model", "module", "patched"), [(("--radius", "2"), plane, "solve_pair_on_surface"),
                                                        ((), planar_solver, "solve_pair")])
def test_results_that_are_not_finite_are_one_line_and_exit_2(run_cli, pair_files, monkeypatch, model, module, patched):
    monkeypatch.setattr(module, patched, _diverged)
    assert_one_error_line(*run_cli("solve", *pair_files, "--pair", "--units", "m/s2", "--mu", "0.1", *model),
                          "STA-000 + STA-090", "results are not finite (")


def _component(values, name: str) -> Record:
    return Record(np.asarray(values, dtype=float), 0.01, RecordMeta(record_id=name, component=name[-3:]))


@pytest.mark.parametrize("parameters", [{"model": "pendulum", "radius": 2.0}, {"model": "planar"}])
def test_a_pair_whose_acceleration_holds_nan_is_named_as_one_component_is(parameters):
    time = np.arange(0.0, 2.0, 0.01)
    first = 3.0 * np.sin(2 * np.pi * 1.5 * time)
    first[50] = np.nan
    pair = RecordPair(_component(first, "STA-000"), _component(3.0 * np.cos(2 * np.pi * time), "STA-090"))
    with pytest.raises(StickslipError, match=r"^000 \+ 090, first component: acceleration contains NaN or infinite "
                                             r"values$"):
        stickslip.solve(pair, mu=0.1, **parameters)
    with pytest.raises(StickslipError, match=r"^STA-000: results are not finite \(pga = nan"):  # its measures first
        stickslip.sweep([pair], model="pendulum", mu=[0.05, 0.1], radius=2.0)
