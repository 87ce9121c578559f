"""The warm-up that ``make env`` runs leaves numba nothing to compile when the commands run, for every model.

numba caches a kernel per signature (the types and array layouts of its
arguments), so a warm-up helps a command only if it compiled the very
signatures that command passes.  Checked without timing: in a fresh process,
after :func:`stickslip.models.warm_up.warm_up`, running the commands (one
``solve`` for every model and scheme of the registry at least) adds no
signature to any numba kernel of stickslip.  The warm-up is driven by the
registry alone: a model registered with kernels of its own has them compiled
with no line of the warm-up changed.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
from pathlib import Path

import numba
import numpy as np
import pytest
from numba.core import types

from stickslip.errors import StickslipError, StickslipWarning
from stickslip.models import MODELS
from stickslip.models.entry import Model, Scheme
from stickslip.models.parameters import MU
from stickslip.models.result import Result
from stickslip.records.pair import RecordPair
from stickslip.records.vertical import WithVertical
from stickslip.models.warm_up import warm_up

REPO_ROOT = Path(__file__).resolve().parents[1]

#: Run in a fresh process: warm up, note every stickslip kernel's signatures, run the commands given as JSON in
#: argv[1] in-process, and print the kernels, the signatures the commands added, the commands' exit codes and
#: their standard output, and the warm-up's warnings.
SCRIPT = r"""
import contextlib, gc, io, json, sys, warnings

from numba.core.dispatcher import Dispatcher

from stickslip.cli import main
from stickslip.models.warm_up import warm_up


def signatures():
    found = {}
    for candidate in gc.get_objects():
        if isinstance(candidate, Dispatcher) and candidate.py_func.__module__.startswith("stickslip"):
            key = f"{candidate.py_func.__module__}.{candidate.py_func.__qualname__}"
            found.setdefault(key, set()).update(str(signature) for signature in candidate.signatures)
    return found


with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    warm_up()
warmed = signatures()
codes, outputs = [], []
for argv in json.loads(sys.argv[1]):
    stdout = io.StringIO()
    with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(io.StringIO()):
        codes.append(main(argv))
    outputs.append(stdout.getvalue())
added = sorted(f"{key} {signature}" for key, known in signatures().items()
               for signature in known - warmed.get(key, set()))
print(json.dumps({"warmed": {key: sorted(known) for key, known in warmed.items()}, "added": added, "codes": codes,
                  "outputs": outputs, "warnings": [str(warning.message) for warning in caught]}))
"""


def _write_component(path: Path, frequency: float, phase: float) -> None:
    """A 20 s decaying motion [m/s²] every 0.01 s, as a ``time,acc`` CSV."""
    time = np.arange(2000) * 0.01
    acceleration = 4.0 * np.exp(-0.2 * time) * np.sin(2.0 * np.pi * frequency * time + phase)
    np.savetxt(path, np.column_stack([time, acceleration]), delimiter=",", header="time,acc", comments="")


def _solve_options() -> set[str]:
    """The options ``stickslip solve`` takes (read from its ``--help``)."""
    import re

    from stickslip.cli import build_parser

    parser = build_parser()
    commands = next(action for action in parser._actions if isinstance(action, argparse._SubParsersAction))
    return set(re.findall(r"(--[a-z][a-z-]*)", commands.choices["solve"].format_help()))


def example_commands(first: Path, second: Path, vertical: Path) -> list[list[str]]:
    """``solve --json`` of each registered model with each of its schemes (and its vertical, where it takes one), at
    the first of the model's examples the scheme takes that the command line can say: what a new model needs here."""
    known = _solve_options()
    commands = []
    for entry in MODELS.values():
        motion = [first] if "component" in entry.motions else [first, second, "--pair"]
        for scheme in entry.schemes:
            for example in entry.examples:
                parts = [part for name, value in example.items() if value is not False
                         for part in ([f"--{name.replace('_', '-')}"] + ([] if value is True else [str(value)]))]
                if not {part for part in parts if part.startswith("--")} <= known:
                    continue
                parameters, options = entry.split(example)
                try:
                    scheme.check(entry.case(entry.checked(parameters)))
                    scheme.checked_options(options)
                except StickslipError:
                    continue
                command = ["solve", *motion, "--model", entry.name, "--method", scheme.name, *parts, "--json"]
                commands += [command] + ([[*command, "--vertical", vertical]] if entry.vertical else [])
                break
    return commands


def test_after_the_warm_up_the_commands_compile_nothing(tmp_path):
    first, second, vertical = tmp_path / "wave-000.csv", tmp_path / "wave-090.csv", tmp_path / "wave-UP.csv"
    _write_component(first, 1.5, 0.0)
    _write_component(second, 2.1, 1.0)
    _write_component(vertical, 2.7, 0.5)
    units = ["--units", "m/s2"]
    layer = ["--height", "10", "--vs", "300", "--vs-base", "600"]
    commands = [
        ["solve", first, second, "--pair", "--mu", "0.1", *units],
        ["solve", first, second, "--pair", "--mu", "0.1", "--json", *units],
        ["solve", first, "--ky", "0.1", "--model", "coupled", "--method", "exact", *layer, *units],
        ["solve", first, "--ky", "0.1", "--model", "coupled", "--method", "exact", *layer, "--json", *units],
        ["solve", first, "--ky", "0.1", "--model", "decoupled", *layer, "--equivalent-linear",
         "--reference-strain", "0.05%", "--json", *units],
        ["solve", first, "--ky", "0.1", "--model", "coupled", "--method", "slammer", *layer, "--json", *units],
        ["solve", first, "--ky", "0.1", "--model", "decoupled", "--method", "slammer", *layer, "--json", *units],
        ["optimum", first, second, *units],
        ["optimum", first, "--ky", "0.01:0.5:0.01", *units],
        ["solve", first, "--mu", "0.1", "--json", *units],
        ["solve", first, "--mu", "0.1", "--method", "newmark", "--json", *units],
        ["solve", first, "--ky", "0.1", "--method", "slammer", "--json", *units],
        ["sweep", first, second, "--mu", "0.02:0.3:0.02", "--out", tmp_path / "cube.nc", *units],
        ["sweep", first, second, "--pair", "--mu", "0.05,0.1", "--out", tmp_path / "pairs.nc", *units],
        ["sweep", first, "--ky", "0.05,0.1", "--model", "coupled", *layer, "--out", tmp_path / "layer.nc", *units],
        ["solve", first, "--ky", "0.1", "--inverse", "--json", *units],
        ["solve", first, "--ky", "0.1", "--method", "slammer", "--inverse", "--json", *units],
        ["solve", first, "--mu", "0.1", "--method", "newmark", "--inverse", "--json", *units],
        ["sweep", first, second, "--ky", "0.02:0.3:0.02", "--inverse", "--out", tmp_path / "inverse.nc", *units],
        ["optimum", first, "--ky", "0.01:0.5:0.01", "--inverse", *units],
        ["solve", first, "--ky", "0.1", "--model", "decoupled", *layer, "--inverse", "--json", *units],
        ["solve", first, "--ky", "0.1", "--model", "coupled", "--method", "slammer", *layer, "--inverse", "--json",
         *units],
        ["solve", first, "--mu", "0.1", "--radius", "2", "--json", *units],
        ["solve", first, "--mu", "0.1", "--model", "pendulum", "--json", *units],
        ["solve", first, "--mu", "0.1", "--radius", "2", "--method", "integrated", "--json", *units],
        ["solve", first, "--mu-slow", "0.05", "--mu-fast", "0.1", "--rate", "20", "--radius", "2", "--json", *units],
        ["solve", first, "--mu", "0.1", "--vertical", vertical, "--json", *units],
        ["solve", first, "--mu", "0.1", "--radius", "2", "--vertical", vertical, "--json", *units],
        ["optimum", first, "--model", "pendulum", "--radius", "2", *units],
        ["sweep", first, "--mu", "0.05,0.1", "--vertical", vertical, "--out", tmp_path / "vertical.nc", *units],
        ["solve", first, second, "--pair", "--mu", "0.1", "--radius", "2", "--vertical", vertical, "--json", *units],
        ["sweep", first, second, "--pair", "--mu", "0.05,0.1", "--radius", "2", "--out", tmp_path / "plane.nc",
         *units],
        ["optimum", first, second, "--pair", "--radius", "2", "--vertical", vertical, *units],
        ["estimate", first, "--ky", "0.1", "--mw", "6.5", "--ts", "0.3", "--vs", "300", "--vs-base", "760", *units],
    ]
    commands += [[*command, *units] for command in example_commands(first, second, vertical)]
    argv = json.dumps([[str(part) for part in command] for command in commands])
    result = subprocess.run([sys.executable, "-c", SCRIPT, argv], capture_output=True, text=True, cwd=tmp_path,
                            env={**os.environ, "MPLBACKEND": "Agg"}, timeout=1800)
    assert result.returncode == 0, result.stderr[-3000:]
    outcome = json.loads(result.stdout.splitlines()[-1])
    assert outcome["warnings"] == []
    assert outcome["codes"] == [0] * len(commands)
    assert outcome["added"] == [], "\n".join(outcome["added"])
    # the commands solve every model of the registry with every one of its schemes
    solved = {(document["model"], document["method"]) for output, command in zip(outcome["outputs"], commands)
              if "--json" in command and command[0] == "solve" for document in map(json.loads, output.splitlines())}
    registered = {(entry.name, scheme.name) for entry in MODELS.values() for scheme in entry.schemes}
    assert solved == registered, f"give each model and scheme a solve --json command here: {registered - solved}"
    warmed = {key for key, known in outcome["warmed"].items() if known}
    assert {f"stickslip.{name}" for name in (
        "solvers.plane.record.solve_pair_on_surface", "solvers.plane.record._sweep_kernel",
        "models.rigid.exact.sweep_pairs",
        "models.rigid.exact._single_kernel", "models.rigid.events.history_kernel",
        "models.layer.exact.flexible_exact", "models.layer.exact.average_peak", "models.layer.slammer.coupled_steps",
        "models.rigid.slammer.rigid_block_steps", "models.rigid.newmark._literal_kernel",
        "records.compiled_numbers._convert_kernel")} <= warmed


@numba.njit
def _line_peak(acceleration, mu):
    """A toy model's kernel: the peak |a| [m/s²] above μ (in m/s², g taken as 1)."""
    return np.max(np.abs(acceleration)) - mu


@numba.njit
def _line_sweep(acceleration, mu):
    """The toy model's batched kernel: :func:`_line_peak` at every μ."""
    return np.max(np.abs(acceleration)) - mu


@numba.njit
def _refused_peak(acceleration, mu):
    """The kernel of a toy model whose one example its scheme refuses (a negative μ)."""
    return np.max(np.abs(acceleration)) - mu


@numba.njit
def _plane_peak(first, second, mu):
    """A toy pair model's kernel: the peak of the horizontal acceleration's size above μ."""
    return np.max(np.sqrt(first * first + second * second)) - mu


@numba.njit
def _vertical_peak(horizontal, vertical, mu):
    """A toy model's kernel for a component with its vertical: the peak |a| above μ times the normal force."""
    return np.max(np.abs(horizontal) - mu * (1.0 + vertical))


class _ToyResult(Result):
    """What a toy scheme returns: one number."""

    def __init__(self, model: str, method: str, excess: float):
        self.model, self.method, self.excess = model, method, excess

    def scalars(self) -> dict:
        return {"excess": self.excess}

    def describe(self) -> str:
        return f"{self.model}, method = {self.method}"


class _ToyScheme(Scheme):
    """A scheme of the toy models: ``solve`` calls ``kernel`` on the motion (``vertical_kernel`` on a component with
    its vertical); a batched one sweeps ``sweeper``."""

    def __init__(self, name: str, kernel, sweeper=None, vertical_kernel=None):
        self.name, self.summary, self.kernel, self.sweeper = name, f"toy scheme {name}", kernel, sweeper
        self.vertical_kernel = vertical_kernel
        self.batched = sweeper is not None

    def solve(self, motion, case, **options):
        if isinstance(motion, WithVertical):
            excess = self.vertical_kernel(motion.acceleration, motion.vertical.acceleration, case["mu"])
        elif isinstance(motion, RecordPair):
            excess = self.kernel(motion.first.acceleration, motion.second.acceleration, case["mu"])
        else:
            excess = self.kernel(motion.acceleration, case["mu"])
        return _ToyResult(case["model"], self.name, float(excess))

    def sweep(self, motions, case, coefficient, values):
        return [self.sweeper(motion.acceleration, np.asarray(values, dtype=float)) for motion in motions]


class _ToyModel(Model):
    """A toy model of the registry: a friction ratio, its schemes and its examples."""

    parameters = (MU,)

    def __init__(self, name: str, motions: tuple, schemes: tuple, examples: tuple, vertical: bool = False):
        self.name, self.summary, self.motions, self.vertical = name, f"toy {name}", motions, vertical
        self.schemes, self.examples = schemes, examples
        self.swept = []

    def case(self, parameters):
        return {**parameters, "model": self.name}

    def sweep(self, motions, method=None, *, mu=None, progress=False, **rest):
        scheme = self.scheme(method)
        self.swept.append((scheme.name, list(mu)))
        return scheme.sweep(motions, self.case({"mu": mu[0]}), "mu", mu)


@pytest.fixture
def toy_registry(monkeypatch):
    """The registry holding only the models given (the real ones loaded first, so that none registers meanwhile)."""
    list(MODELS)

    def only(*entries):
        monkeypatch.setattr(MODELS, "_entries", {entry.name: entry for entry in entries})

    return only


def test_a_new_model_s_kernels_are_compiled_with_no_change_to_the_warm_up(toy_registry):
    """Every scheme of every registered model, on every motion it takes (with its vertical where the model takes one),
    with the batched kernel swept."""
    line = _ToyModel("toy_line", ("component",), (_ToyScheme("plain", _line_peak),
                                                   _ToyScheme("batched", _line_peak, _line_sweep)), ({"mu": 0.1},))
    plane = _ToyModel("toy_plane", ("pair",), (_ToyScheme("exact", _plane_peak),), ({"mu": 0.1},))
    slider = _ToyModel("toy_slider", ("component",), (_ToyScheme("exact", _line_peak, vertical_kernel=_vertical_peak),),
                       ({"mu": 0.1},), vertical=True)
    toy_registry(line, plane, slider)
    for kernel in (_line_peak, _line_sweep, _plane_peak, _vertical_peak):
        assert kernel.signatures == []
    assert warm_up() == ["toy_line/plain", "toy_line/batched", "toy_plane/exact", "toy_slider/exact"]
    record = types.Array(types.float64, 1, "C", readonly=True)  # a record's samples, which nothing may change
    assert _line_peak.signatures == [(record, types.float64)]
    assert _line_sweep.signatures == [(record, types.Array(types.float64, 1, "C"))]
    assert _plane_peak.signatures == [(record, record, types.float64)]
    assert _vertical_peak.signatures == [(record, record, types.float64)]
    assert line.swept == [("batched", [0.05, 0.1])] and plane.swept == []


def test_a_model_whose_examples_no_scheme_takes_is_named_in_a_warning(toy_registry):
    """An example a scheme refuses is skipped; a scheme that none suits is a mistake of the declaration, named, and
    the warm-up goes on with the other models."""
    refusing = _ToyModel("toy_refusing", ("component",), (_ToyScheme("plain", _refused_peak),), ({"mu": -1.0},))
    line = _ToyModel("toy_line", ("component",), (_ToyScheme("plain", _line_peak),), ({"mu": 0.1},))
    toy_registry(refusing, line)
    with pytest.warns(StickslipWarning) as caught:
        assert warm_up() == ["toy_refusing/plain", "toy_line/plain"]
    assert [str(warning.message) for warning in caught] == [
        "the toy_refusing model's scheme plain solves none of the model's examples on a component, so its kernels "
        "compile at their first call: declare one it takes (stickslip.models.entry.Model.examples)"]
    assert _refused_peak.signatures == [] and len(_line_peak.signatures) == 1


def test_the_environment_and_the_test_environment_are_warmed_up():
    """``make env`` and ``make test`` run the warm-up after installing stickslip (a dry run of both stamps)."""
    for stamp in (".venv/.installed-runtime", ".venv/.installed-test"):
        dry_run = subprocess.run(["make", "-n", "-B", stamp], capture_output=True, text=True, cwd=REPO_ROOT,
                                 check=True).stdout
        install = dry_run.index("pip install --quiet --python .venv/bin/python --no-deps --no-build-isolation -e .")
        assert dry_run.index("-m stickslip.cli.warm_up") > install, stamp
