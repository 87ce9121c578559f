"""The package's dependencies point downward, and a coefficient is asked of its table, never named in a branch.

The studies (``stickslip.studies``) are the workflow's steps: the library
(models, records, reports, the command line, ...) never imports them, so that
what a study computes with lives below it and a report reads what a study
wrote.  A swept coefficient's kind (μ or k_y) is data, ``grids.COEFFICIENTS``:
no module but that table compares a name with ``"mu"`` or ``"ky"``.
"""

from __future__ import annotations

import ast
from pathlib import Path

import stickslip

PACKAGE = Path(stickslip.__file__).resolve().parent
#: The coefficient names that only the coefficient table may compare with.
COEFFICIENT_NAMES = {"mu", "ky"}
#: (modules, a package or module they never import): a lower layer never reaches up to a higher one.
NEVER = (
    ("solvers/", "stickslip.models"),  # what several models share knows none of them
    ("optimum.py", "stickslip.models"),  # the design answer reads the design it is given; the models call it
    ("units.py", "stickslip.plumbing"),  # the units table writes no file; a study does
    ("grids.py", "stickslip.models"),  # a grid is values
)


def modules(folder: Path = PACKAGE) -> dict[str, ast.Module]:
    """Every module of the package under ``folder``, by its path relative to the package, parsed."""
    return {path.relative_to(folder).as_posix(): ast.parse(path.read_text(encoding="utf-8"))
            for path in sorted(folder.rglob("*.py"))}


def imports_of(tree: ast.Module, prefix: str) -> list[int]:
    """The lines of ``tree`` that import a module named ``prefix`` or under it (at any depth of the code)."""
    lines = []
    for node in ast.walk(tree):
        names = ([alias.name for alias in node.names] if isinstance(node, ast.Import)
                 else [node.module or ""] if isinstance(node, ast.ImportFrom) else [])
        if any(name == prefix or name.startswith(prefix + ".") for name in names):
            lines.append(node.lineno)
    return sorted(lines)


def comparisons_with(tree: ast.Module, constants: set[str]) -> list[int]:
    """The lines of ``tree`` that compare (``==``, ``!=``, ``in``, ``not in``) something with one of ``constants``."""
    lines = []
    for node in ast.walk(tree):
        if not (isinstance(node, ast.Compare)
                and any(isinstance(op, (ast.Eq, ast.NotEq, ast.In, ast.NotIn)) for op in node.ops)):
            continue
        sides = [node.left, *node.comparators]
        values = [side.value for side in sides if isinstance(side, ast.Constant)]
        values += [item.value for side in sides if isinstance(side, (ast.Tuple, ast.List, ast.Set))
                   for item in side.elts if isinstance(item, ast.Constant)]
        if constants & {value for value in values if isinstance(value, str)}:
            lines.append(node.lineno)
    return sorted(lines)


def test_the_library_never_imports_the_studies():
    found = {path: lines for path, tree in modules().items()
             if not path.startswith("studies/") and (lines := imports_of(tree, "stickslip.studies"))}
    assert found == {}


def test_no_lower_layer_imports_a_higher_one():
    found = {(path, higher): lines for lower, higher in NEVER for path, tree in modules().items()
             if path.startswith(lower) and (lines := imports_of(tree, higher))}
    assert found == {}


def test_only_the_coefficient_table_compares_a_name_with_mu_or_ky():
    found = {path: lines for path, tree in modules().items()
             if path != "grids.py" and (lines := comparisons_with(tree, COEFFICIENT_NAMES))}
    assert found == {}


def test_the_checks_find_what_they_look_for():
    tree = ast.parse("import stickslip.studies.mu_max\n"
                     "def f(c, name):\n"
                     "    from stickslip.studies import timestep\n"
                     "    from stickslip.studiesx import other\n"
                     "    if c == 'ky' or name in ('mu', 'g'):\n"
                     "        return 'mu' != name, c == 'mux'\n")
    assert imports_of(tree, "stickslip.studies") == [1, 3]
    assert comparisons_with(tree, COEFFICIENT_NAMES) == [5, 5, 6]
