"""The package's dependencies point downward, a model is known by its declaration, and a coefficient is asked of its
table, never named in a branch.

The package is in layers (:data:`LAYERS`, bottom first): what everything
uses (errors, units, grids, the objectives, file plumbing); the records and
what is measured on them; the shared numerics (solvers, the sweep's cube, the
design answer); the models; what is built on models (design codes,
simplified estimates, collections); the reports; and on top the command line
and the studies (the workflow's steps).  No module imports from a layer above
its own.  The studies (``stickslip.studies``) are the workflow's steps: the
rest of the library never imports them, so that what a study computes with
lives below it and a report reads what a study wrote.

A model is its package's public names (``stickslip.models.rigid``) and its
entry in the registry: no module outside a model's package imports a module
inside it (``stickslip.models.rigid.response``), and no module outside
``models/`` compares a model's name (``entry.name != "pendulum"``): what the
command line and the reports ask of a model, the model declares.

A swept coefficient's kind (μ or k_y) is data, ``grids.COEFFICIENTS``:
no module but that table compares a name with ``"mu"`` or ``"ky"``.
"""

from __future__ import annotations

import ast
import functools
from pathlib import Path

import stickslip
from stickslip.models import MODELS

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


#: The package's layers, bottom first: each names the top-level modules and subpackages in it.  A module may import
#: from its own layer and the ones below, never from one above.
LAYERS = (
    {"errors", "constants", "units", "checks", "limits", "grids", "objectives", "plumbing"},
    {"records", "measures", "response_spectrum", "spectra", "analysis", "reference"},
    {"solvers", "sweeps", "optimum"},
    {"models"},
    {"codes", "estimates", "collections", "slope_displacements"},
    {"reports"},
    {"cli", "studies", "__main__", "__init__"},
)

#: The modules of ``models/`` that every model shares (the contract and the registry), which are no model's
#: internals.
SHARED_MODEL_MODULES = {"entry", "registry", "result", "swept", "parameters", "yield_table", "warm_up", "spring",
                        "design_chart"}

#: The names that hold a model's name where one is compared (``entry.name``, ``model``, ``attrs["model"]``).
MODEL_NAME_HOLDERS = {"name", "model", "model_name"}


def layer_of(path: str) -> int:
    """The layer (:data:`LAYERS`) of the module at ``path``, relative to the package (``models/rigid/exact.py``)."""
    top = path.split("/")[0].removesuffix(".py")
    return next(index for index, layer in enumerate(LAYERS) if top in layer)


@functools.cache
def modules(folder: Path = PACKAGE) -> dict[str, ast.Module]:
    """Every module of the package under ``folder``, by its path relative to the package, parsed (once per run: the
    checks only read the trees)."""
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


def imported_modules(tree: ast.Module) -> list[tuple[int, str]]:
    """(line, module) of every import of a stickslip module in ``tree``, at any depth of the code: ``from X import y``
    gives ``X.y`` where ``y`` is a module of the package, else ``X``."""
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found += [(node.lineno, alias.name) for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            folder = PACKAGE.parent.joinpath(*node.module.split("."))
            found += [(node.lineno, f"{node.module}.{alias.name}") if (folder / f"{alias.name}.py").exists()
                      or (folder / alias.name / "__init__.py").exists() else (node.lineno, node.module)
                      for alias in node.names]
    return [(line, name) for line, name in found if name == "stickslip" or name.startswith("stickslip.")]


def model_internals(path: str, tree: ast.Module) -> list[tuple[int, str]]:
    """(line, module) of each import in ``tree`` (the module at ``path``) of a module inside a model's package from
    outside that package."""
    found = []
    for line, name in imported_modules(tree):
        parts = name.split(".")
        if len(parts) < 4 or parts[1] != "models" or parts[2] in SHARED_MODEL_MODULES:
            continue
        if not path.startswith(f"models/{parts[2]}/"):
            found.append((line, name))
    return found


def comparisons_with(tree: ast.Module, constants: set[str], holders: set[str] | None = None) -> list[int]:
    """The lines of ``tree`` that compare (``==``, ``!=``, ``in``, ``not in``) something with one of ``constants``;
    with ``holders``, only where the other side is one of those names (``x.name``, ``name``, ``x["name"]``,
    ``x.get("name")``)."""
    lines = []
    for node in ast.walk(tree):
        if not (isinstance(node, ast.Compare)
                and any(isinstance(op, (ast.Eq, ast.NotEq, ast.In, ast.NotIn)) for op in node.ops)):
            continue
        sides = [node.left, *node.comparators]
        if holders is not None and not any(_holds(side, holders) for side in sides):
            continue
        values = [side.value for side in sides if isinstance(side, ast.Constant)]
        values += [item.value for side in sides if isinstance(side, (ast.Tuple, ast.List, ast.Set))
                   for item in side.elts if isinstance(item, ast.Constant)]
        if constants & {value for value in values if isinstance(value, str)}:
            lines.append(node.lineno)
    return sorted(lines)


def _holds(node: ast.expr, holders: set[str]) -> bool:
    """Whether ``node`` reads one of the names ``holders``: ``x.name``, ``name``, ``x["name"]`` or ``x.get("name")``."""
    if isinstance(node, ast.Attribute):
        return node.attr in holders
    if isinstance(node, ast.Name):
        return node.id in holders
    if isinstance(node, ast.Subscript):
        return isinstance(node.slice, ast.Constant) and node.slice.value in holders
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr == "get":
        return bool(node.args) and isinstance(node.args[0], ast.Constant) and node.args[0].value in holders
    return False


def test_the_library_never_imports_the_studies():
    found = {path: lines for path, tree in modules().items()
             if not path.startswith("studies/") and (lines := imports_of(tree, "stickslip.studies"))}
    assert found == {}


def test_no_lower_layer_imports_a_higher_one():
    found = {(path, higher): lines for lower, higher in NEVER for path, tree in modules().items()
             if path.startswith(lower) and (lines := imports_of(tree, higher))}
    assert found == {}


def test_every_module_is_in_a_layer():
    tops = {path.split("/")[0].removesuffix(".py") for path in modules()}
    assert tops == set().union(*LAYERS)


def test_no_module_imports_from_a_layer_above_its_own():
    found = {}
    for path, tree in modules().items():
        own = layer_of(path)
        above = [(line, name) for line, name in imported_modules(tree)
                 if name != "stickslip" and layer_of(name.split(".")[1]) > own]
        if above:
            found[path] = above
    assert found == {}


def test_no_module_imports_a_model_s_internals_from_outside_its_package():
    found = {(path, name) for path, tree in modules().items() for _, name in model_internals(path, tree)}
    assert found == set()


def test_no_module_outside_the_models_compares_a_model_s_name():
    names = set(MODELS)
    found = {path: lines for path, tree in modules().items()
             if not path.startswith("models/") and (lines := comparisons_with(tree, names, MODEL_NAME_HOLDERS))}
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


def test_the_model_checks_find_what_they_look_for():
    tree = ast.parse("from stickslip.models.rigid import response, RIGID\n"
                     "import stickslip.models.pendulum.chart\n"
                     "from stickslip.models.swept import Design\n"
                     "from stickslip.models import MODELS\n"
                     "def f(entry, cube, row):\n"
                     "    if entry.name != 'pendulum' or cube.attrs.get('model') == 'rigid':\n"
                     "        return row['kind'] == 'rigid', model in ('planar',)\n")
    assert model_internals("cli/x.py", tree) == [(1, "stickslip.models.rigid.response"),
                                                 (2, "stickslip.models.pendulum.chart")]
    assert model_internals("models/rigid/x.py", tree) == [(2, "stickslip.models.pendulum.chart")]
    assert comparisons_with(tree, {"rigid", "pendulum", "planar"}, MODEL_NAME_HOLDERS) == [6, 6, 7]
    assert [layer_of(path) for path in ("errors.py", "models/rigid/exact.py", "cli/optimum.py")] == [0, 3, 6]
