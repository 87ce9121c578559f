"""Every test function checks something itself: a merge cannot silently empty a test.

A test function passes when its own body holds an ``assert`` statement, a
``pytest.raises``/``pytest.warns``/``pytest.fail`` call, or a call of an
``assert_*`` function (``np.testing.assert_allclose``,
``xr.testing.assert_identical``, or a helper of the suite named so).  Checks
inside other helpers do not count: a test that computes the planned jobs
through a helper that asserts only that Snakemake ran, and ends there, is
the case this catches.
"""

from __future__ import annotations

import ast
from pathlib import Path

TESTS = Path(__file__).resolve().parent

#: ``pytest.<name>(...)`` calls that check something.
CHECKING_PYTEST_CALLS = {"raises", "warns", "fail", "deprecated_call"}


def checks_something(function: ast.FunctionDef | ast.AsyncFunctionDef) -> bool:
    """Whether the body of ``function`` holds a check (see the module's docstring)."""
    for node in ast.walk(function):
        if isinstance(node, ast.Assert):
            return True
        if not isinstance(node, ast.Call):
            continue
        name = node.func.attr if isinstance(node.func, ast.Attribute) else getattr(node.func, "id", "")
        if name.startswith("assert_"):
            return True
        if (isinstance(node.func, ast.Attribute) and isinstance(node.func.value, ast.Name)
                and node.func.value.id == "pytest" and name in CHECKING_PYTEST_CALLS):
            return True
    return False


def unchecked_tests(folder: Path = TESTS) -> list[str]:
    """``file::test`` of every test function (module level or in a class) of ``folder`` that checks nothing."""
    found = []
    for path in sorted(folder.glob("test_*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in tree.body:
            functions = node.body if isinstance(node, ast.ClassDef) else [node]
            for function in functions:
                if (isinstance(function, (ast.FunctionDef, ast.AsyncFunctionDef)) and function.name.startswith("test_")
                        and not checks_something(function)):
                    found.append(f"{path.name}::{function.name}")
    return found


def test_every_test_function_checks_something():
    assert unchecked_tests() == []


def test_the_check_finds_tests_that_check_nothing(tmp_path):
    (tmp_path / "test_sample.py").write_text(
        "import pytest\n"
        "def planned(result):\n    assert result is not None\n    return {'a': 1}\n"
        "def test_planned_jobs_and_nothing_more():\n    jobs = planned(0)\n"
        "def test_asserts():\n    assert 1 + 1 == 2\n"
        "def test_raises():\n    with pytest.raises(ValueError):\n        int('x')\n"
        "def test_numpy():\n    import numpy as np\n    np.testing.assert_array_equal([1], [1])\n"
        "class TestGroup:\n    def test_nothing(self):\n        pass\n"
    )
    assert unchecked_tests(tmp_path) == ["test_sample.py::test_planned_jobs_and_nothing_more",
                                         "test_sample.py::test_nothing"]
