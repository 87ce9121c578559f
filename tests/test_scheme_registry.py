"""The solver schemes are registry entries: a toy scheme, one module and one line, flows through solve, sweep,
the μ_max refinement and the command line, and its rules are the entry's."""

from __future__ import annotations

import sys
import types

import numpy as np
import pytest

from stickslip.errors import StickslipError
from stickslip.records.record import Record, RecordMeta
from stickslip.solution import solve
from stickslip.solvers import exact_scheme, registry
from stickslip.sweeps import sweep

G = 9.81


def _toy_history(acceleration, dt, resistance, *, label: str = "toy"):
    """The exact scheme's history under another name, with an option of its own."""
    return exact_scheme.sliding_history(acceleration, dt, resistance)


@pytest.fixture
def toy(monkeypatch):
    """A flat-only scheme ``toy`` without a batched kernel, registered in a temporary registry."""
    module = types.ModuleType("toy_scheme")
    module.sliding_history = _toy_history
    module.SCHEME = registry.Scheme("toy", "a toy for the registry's test", _toy_history, flat_only=True)
    monkeypatch.setitem(sys.modules, "toy_scheme", module)
    monkeypatch.setitem(registry.SCHEME_MODULES, "toy", "toy_scheme")
    return module.SCHEME


@pytest.fixture
def record():
    time = np.arange(0.0, 8.0, 0.01)
    return Record(3.0 * np.sin(2 * np.pi * 1.3 * time) * np.exp(-0.3 * time), 0.01, RecordMeta(record_id="wave"))


def test_a_new_scheme_is_one_module_and_one_line(toy, record):
    assert registry.scheme("toy") is toy and toy.option_defaults == {"label": "toy"}
    assert registry.schemes_with_option("label") == ["toy"]
    ours, reference = solve(record, mu=0.1, method="toy"), solve(record, mu=0.1)
    assert ours.method == "toy" and ours.solver_options == {"label": "toy"}
    assert ours.energy_dissipated == reference.energy_dissipated > 0
    mu = [0.05, 0.1, 0.2]
    cube, batched = sweep([record], mu=mu, method="toy", progress=False), sweep([record], mu=mu, progress=False)
    np.testing.assert_allclose(cube.energy_dissipated.values, batched.energy_dissipated.values, rtol=1e-12)
    assert cube.attrs["solver"] == "toy"


def test_the_entry_s_rules_are_checked_once_for_every_caller(toy, record):
    message = r"toy \(a toy for the registry's test\) solves flat friction only, not .*; use method exact or slammer"
    with pytest.raises(StickslipError, match=message):
        solve(record, ky=0.1, method="toy")
    with pytest.raises(StickslipError, match=message):
        sweep([record], ky=[0.1, 0.2], method="toy", progress=False)
    with pytest.raises(StickslipError, match="solver 'toy' does not accept option\\(s\\) time_step; it accepts: label"):
        solve(record, mu=0.1, method="toy", time_step=0.001)
    with pytest.raises(StickslipError, match="unknown solver method 'toys'; known: exact, newmark, slammer, toy"):
        solve(record, mu=0.1, method="toys")


def test_the_command_line_offers_the_new_scheme(toy, run_cli, tmp_path):
    path = tmp_path / "wave.txt"
    time = np.arange(0.0, 8.0, 0.01)
    path.write_text("\n".join(f"{t:.2f} {0.3 * np.sin(2 * np.pi * 1.3 * t):.6f}" for t in time) + "\n",
                    encoding="ascii")
    code, out, err = run_cli("solve", path, "--mu", "0.1", "--units", "g", "--method", "toy", "--json")
    assert code == 0, err
    assert '"method": "toy"' in out and '"label": "toy"' in out
    code, out, err = run_cli("solve", path, "--mu", "0.1", "--units", "g", "--method", "toy", "--time-step", "0.001")
    assert code == 2 and err.strip() == ("stickslip: error: --time-step applies to --method newmark only (toy follows "
                                         "the record's samples)")


def test_inverse_polarity_options_reach_solve_and_sweep_alike(record):
    inverse = solve(record, ky=0.05, method="slammer", inverse=True)
    assert inverse.solver_options == {"skip_zero_samples": False}
    cube = sweep([record], ky=[0.05, 0.1], method="slammer", inverse=True, progress=False)
    assert cube.downslope_displacement.values[0, 0] == pytest.approx(inverse.downslope_displacement, rel=1e-12)
