"""What ``stickslip solve A B --pair`` and ``stickslip optimum A B`` import before they answer: neither xarray nor
scipy.integrate.

Every command is a fresh process that pays for each module it imports: xarray
(with pandas) and scipy.integrate cost about 0.4 and 0.5 s of a start on the
2-core machine, as much as loading numba's cached kernels (benchmarks/README.md,
"First calls").  The pair's answer needs neither: the cube's module imports
xarray where it builds a cube, and the planar kernel reads SciPy's Dormand–Prince
coefficients from their file.  Nor does the design answer's table: the cubes'
machinery (:mod:`stickslip.sweeps`) imports xarray where it builds, reads or
gathers a cube.
"""

from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
from scipy.integrate._ivp import dop853_coefficients

from stickslip.solvers import dop853

SCRIPT = r"""
import contextlib, io, json, sys
from stickslip.cli import main

with contextlib.redirect_stdout(io.StringIO()):
    code = main(sys.argv[1:])
print(json.dumps({"code": code, "imported": sorted({"xarray", "pandas", "scipy.integrate"} & set(sys.modules))}))
"""


def _components(folder) -> list[str]:
    """Two 15 s decaying motions [m/s²] every 0.01 s, as ``time,acc`` CSV files; their paths."""
    time = np.arange(1500) * 0.01
    paths = []
    for name, frequency in (("wave-000.csv", 1.5), ("wave-090.csv", 2.1)):
        path = folder / name
        acceleration = 4.0 * np.exp(-0.2 * time) * np.sin(2.0 * np.pi * frequency * time)
        np.savetxt(path, np.column_stack([time, acceleration]), delimiter=",", header="time,acc", comments="")
        paths.append(str(path))
    return paths


def _imported(*arguments: str) -> dict:
    """The exit code of ``stickslip ARGUMENTS`` in a fresh process and which of the heavy modules it imported."""
    result = subprocess.run([sys.executable, "-c", SCRIPT, *arguments, "--units", "m/s2"], capture_output=True,
                            text=True, check=True)
    return json.loads(result.stdout.splitlines()[-1])


def test_solving_a_pair_imports_neither_xarray_nor_scipy_integrate(tmp_path):
    assert _imported("solve", *_components(tmp_path), "--pair", "--mu", "0.1") == {"code": 0, "imported": []}


def test_the_design_answer_s_table_imports_neither_xarray_nor_scipy_integrate(tmp_path):
    paths = _components(tmp_path)
    assert _imported("optimum", *paths) == {"code": 0, "imported": []}
    assert _imported("optimum", paths[0], "--ky", "0.01:0.5:0.01") == {"code": 0, "imported": []}


def test_the_integrating_kernels_tableau_is_scipy_s():
    for name in ("A", "B", "E3", "E5"):
        ours, theirs = getattr(dop853, name), getattr(dop853_coefficients, name)
        np.testing.assert_array_equal(ours, theirs[:12, :12] if name == "A" else theirs, err_msg=name)
    assert dop853.A.flags.c_contiguous and dop853.A.shape == (12, 12)
