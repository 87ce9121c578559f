"""The paper's studies, each producing tables under ``results/``.

Every study module provides ``run(config: dict, out_dir: pathlib.Path) ->
list[pathlib.Path]``: it computes with the library, writes its files
atomically under the results folder ``out_dir`` (tables in ``out_dir/tables``,
cubes in ``out_dir/sweeps``) and returns their paths.  ``config`` is the parsed
``config/config.yaml`` (see :func:`stickslip.config.load_config`).
"""

from __future__ import annotations

import importlib
from types import ModuleType

#: Study name -> module that implements it.
STUDIES: dict[str, str] = {
    "table5": "stickslip.studies.table5",
    "table4": "stickslip.studies.table4",
    "table6": "stickslip.studies.table6",
    "table8": "stickslip.studies.table8",
    "mass": "stickslip.studies.mass",
    "timestep": "stickslip.studies.timestep",
}


def study_module(name: str) -> ModuleType:
    """The module implementing study ``name``."""
    from stickslip.errors import StickslipError

    if name not in STUDIES:
        raise StickslipError(f"unknown study {name!r}; known: {', '.join(sorted(STUDIES))}")
    return importlib.import_module(STUDIES[name])
