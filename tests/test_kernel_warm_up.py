"""The warm-up that ``make env`` runs leaves numba nothing to compile when the commands run.

numba caches a kernel per signature (the types and array layouts of its
arguments), so a warm-up helps a command only if it compiled the very
signatures that command passes.  Checked without timing: in a fresh process,
after :func:`stickslip.solvers.warm_up.warm_up`, running the commands adds no
signature to any numba kernel of stickslip.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np

REPO_ROOT = Path(__file__).resolve().parents[1]

#: Run in a fresh process: warm up, note every stickslip kernel's signatures, run the commands given as JSON in
#: argv[1] in-process, and print the kernels, the signatures the commands added and the commands' exit codes.
SCRIPT = r"""
import contextlib, gc, io, json, sys
from pathlib import Path

from numba.core.dispatcher import Dispatcher

from stickslip.cli import main
from stickslip.solvers.warm_up import warm_up


def signatures():
    found = {}
    for candidate in gc.get_objects():
        if isinstance(candidate, Dispatcher) and candidate.py_func.__module__.startswith("stickslip"):
            code = candidate.py_func.__code__
            key = f"{Path(code.co_filename).name}:{code.co_name}:{code.co_firstlineno}"
            found.setdefault(key, set()).update(str(signature) for signature in candidate.signatures)
    return found


warm_up()
warmed = signatures()
codes = []
with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
    for argv in json.loads(sys.argv[1]):
        codes.append(main(argv))
added = sorted(f"{key} {signature}" for key, known in signatures().items()
               for signature in known - warmed.get(key, set()))
print(json.dumps({"warmed": {key: sorted(known) for key, known in warmed.items()}, "added": added, "codes": codes}))
"""


def _write_component(path: Path, frequency: float, phase: float) -> None:
    """A 20 s decaying motion [m/s²] every 0.01 s, as a ``time,acc`` CSV."""
    time = np.arange(2000) * 0.01
    acceleration = 4.0 * np.exp(-0.2 * time) * np.sin(2.0 * np.pi * frequency * time + phase)
    np.savetxt(path, np.column_stack([time, acceleration]), delimiter=",", header="time,acc", comments="")


def test_after_the_warm_up_the_commands_compile_nothing(tmp_path):
    first, second = tmp_path / "wave-000.csv", tmp_path / "wave-090.csv"
    _write_component(first, 1.5, 0.0)
    _write_component(second, 2.1, 1.0)
    units = ["--units", "m/s2"]
    layer = ["--height", "10", "--vs", "300", "--vs-base", "600"]
    commands = [
        ["solve", first, second, "--pair", "--mu", "0.1", *units],
        ["solve", first, "--ky", "0.1", "--model", "coupled", "--method", "exact", *layer, *units],
        ["solve", first, "--ky", "0.1", "--model", "decoupled", *layer, "--equivalent-linear",
         "--reference-strain", "0.05%", "--json", *units],
        ["solve", first, "--ky", "0.1", "--model", "coupled", "--method", "slammer", *layer, *units],
        ["optimum", first, second, *units],
        ["optimum", first, "--ky", "0.01:0.5:0.01", *units],
        ["solve", first, "--mu", "0.1", "--method", "newmark", *units],
        ["solve", first, "--ky", "0.1", "--method", "slammer", *units],
        ["sweep", first, second, "--mu", "0.02:0.3:0.02", "--out", tmp_path / "cube.nc", *units],
        ["sweep", first, second, "--pair", "--mu", "0.05,0.1", "--out", tmp_path / "pairs.nc", *units],
        ["sweep", first, "--ky", "0.05,0.1", "--model", "coupled", *layer, "--out", tmp_path / "layer.nc", *units],
    ]
    argv = json.dumps([[str(part) for part in command] for command in commands])
    result = subprocess.run([sys.executable, "-c", SCRIPT, argv], capture_output=True, text=True, cwd=tmp_path,
                            env={**os.environ, "MPLBACKEND": "Agg"}, timeout=1800)
    assert result.returncode == 0, result.stderr[-3000:]
    outcome = json.loads(result.stdout.splitlines()[-1])
    assert outcome["codes"] == [0] * len(commands)
    assert outcome["added"] == []
    warmed = {key.split(":")[0] + ":" + key.split(":")[1] for key, known in outcome["warmed"].items() if known}
    assert {"planar_kernel.py:solve_pair", "planar_kernel.py:sweep_pairs", "exact.py:_sweep_kernel",
            "exact.py:_single_kernel", "events.py:history_kernel", "layer_exact.py:flexible_exact",
            "layer_exact.py:average_peak", "layer_slammer.py:coupled_steps", "slammer.py:rigid_block_steps",
            "newmark.py:_literal_kernel", "compiled_numbers.py:_convert_kernel"} <= warmed


def test_the_environment_and_the_test_environment_are_warmed_up():
    """``make env`` and ``make test`` run the warm-up after installing stickslip (a dry run of both stamps)."""
    for stamp in (".venv/.installed-runtime", ".venv/.installed-test"):
        dry_run = subprocess.run(["make", "-n", "-B", stamp], capture_output=True, text=True, cwd=REPO_ROOT,
                                 check=True).stdout
        install = dry_run.index("pip install --quiet --python .venv/bin/python --no-deps --no-build-isolation -e .")
        assert dry_run.index("-m stickslip.solvers.warm_up") > install, stamp
