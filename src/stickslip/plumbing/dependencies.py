"""Which of stickslip's source files a piece of code depends on, read from its imports.

The workflow makes each rule depend on the library files its step uses, so
that editing ``reports/plots.py`` reruns only the reports and editing a solver reruns
the sweeps and what follows, but nothing else.  The dependencies are found
statically: every ``import stickslip…`` and ``from stickslip… import …`` in
the code (at any depth, so imports inside functions count), every string that
names a ``stickslip.`` module (the solver registry names its modules so), and
the ``__init__.py`` of every package on the way, followed transitively.  The
package's own ``__init__.py`` is the exception: its table of lazily imported
public names imports nothing when a submodule is imported.

Each source text is parsed once per process (:func:`imported_modules` keeps
its answers, keyed by the text itself, so an edited file is parsed afresh):
the workflow asks for the dependencies of some fifty steps whose imports
overlap, and parsing the same modules for each of them made building the
workflow's job graph take some 20 s.
"""

from __future__ import annotations

import ast
import json
import re
from collections.abc import Iterable
from functools import cache
from pathlib import Path

#: A string constant that names one of stickslip's modules.
_MODULE_NAME = re.compile(r"^stickslip(\.[A-Za-z_][A-Za-z0-9_]*)+$")

#: ``src/`` of the checkout (the folder that holds the ``stickslip`` package).
SOURCE_ROOT = Path(__file__).resolve().parents[2]


@cache
def imported_modules(code: str, follow_names: bool = True) -> frozenset[str]:
    """The stickslip modules (and names that may be modules) that ``code`` imports, or names when ``follow_names``."""
    found = set()
    for node in ast.walk(ast.parse(code)):
        if isinstance(node, ast.Import):
            found.update(alias.name for alias in node.names if alias.name.split(".")[0] == "stickslip")
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            if node.module.split(".")[0] == "stickslip":
                found.add(node.module)
                found.update(f"{node.module}.{alias.name}" for alias in node.names)
        elif follow_names and isinstance(node, ast.Constant) and isinstance(node.value, str):
            module = node.value.split(":")[0]
            if _MODULE_NAME.match(module):
                found.add(module)
    return frozenset(found)


def code_of(path: str | Path) -> str:
    """The Python code of a ``.py`` file, or of the code cells of a Jupyter notebook."""
    path = Path(path)
    text = path.read_text(encoding="utf-8")
    if path.suffix != ".ipynb":
        return text
    cells = json.loads(text)["cells"]
    lines = ["".join(cell["source"]) for cell in cells if cell["cell_type"] == "code"]
    return "\n".join(line for cell in lines for line in cell.splitlines() if not line.lstrip().startswith(("%", "!")))


def module_file(name: str, source_root: Path = SOURCE_ROOT) -> Path | None:
    """The file of module ``name`` under ``source_root``, or None when ``name`` is not a module there."""
    path = source_root.joinpath(*name.split("."))
    if (path / "__init__.py").is_file():
        return path / "__init__.py"
    if path.with_suffix(".py").is_file():
        return path.with_suffix(".py")
    return None


def library_sources(modules: Iterable[str] = (), files: Iterable[str | Path] = (),
                    source_root: Path = SOURCE_ROOT) -> list[str]:
    """The stickslip source files that ``modules`` and the code in ``files`` depend on, sorted.

    ``modules`` are module names (``"stickslip.studies.mu_max"``) or
    ``"module:function"`` step names; ``files`` are scripts or notebooks.
    """
    pending = [module.split(":")[0] for module in modules]
    for path in files:
        pending.extend(imported_modules(code_of(path)))
    seen: dict[str, Path] = {}
    while pending:
        name = pending.pop()
        if name in seen:
            continue
        path = module_file(name, source_root)
        if path is None:
            continue
        seen[name] = path
        parts = name.split(".")
        pending.extend(".".join(parts[:k]) for k in range(1, len(parts)))
        pending.extend(imported_modules(path.read_text(encoding="utf-8"), follow_names=name != "stickslip"))
    return sorted(str(path) for path in seen.values())
