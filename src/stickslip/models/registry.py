"""The one registry of sliding-block models: each model's module registers its entry when imported.

:data:`MODEL_MODULES` names the modules, one line each; :data:`MODELS` maps
a model's name to its entry (a :class:`~stickslip.models.entry.Model`),
importing the modules on first use, so that the command line starts without
any kernel: an entry imports its numerical code only when it solves.
As xarray's backends do, the behaviour is a method of the registered object
and each module registers itself (:func:`register`); as xarray finds the
backends of other packages, an installed package adds its models through
the entry points of :data:`ENTRY_POINTS`, each naming a module that
registers its model when imported, after stickslip's own.
"""

from __future__ import annotations

import importlib
import importlib.metadata
from collections.abc import Iterator, Mapping

from stickslip.errors import StickslipError

#: The modules that define the sliding-block models, in the order the command line lists them and in which
#: :func:`stickslip.models.chosen_model` tries them: the first that takes the parameters given is chosen.
#: A new model is its module and one line here.
MODEL_MODULES = (
    "stickslip.models.rigid",
    "stickslip.models.layer",
    "stickslip.models.planar",
    "stickslip.models.pendulum",
    "stickslip.models.spring",
    "stickslip.models.isolated",
    "stickslip.models.friction_tmd",
)


#: The entry-point group of the models of other installed packages: each entry point names a module that
#: registers its model on import (``[project.entry-points."stickslip.models"]`` ``mymodel = "mypackage.mymodel"``).
ENTRY_POINTS = "stickslip.models"


class Registry(Mapping):
    """Model name -> entry, filled by :func:`register` as :data:`MODEL_MODULES`, then the modules of
    :data:`ENTRY_POINTS`, are imported on first use."""

    def __init__(self):
        self._entries: dict = {}
        self._loaded = False

    def _load(self) -> None:
        if not self._loaded:
            self._loaded = True
            for module in MODEL_MODULES:
                importlib.import_module(module)
            for point in importlib.metadata.entry_points(group=ENTRY_POINTS):
                point.load()

    def register(self, entry) -> None:
        """Add ``entry`` (a :class:`~stickslip.models.entry.Model`) under its name; a second one of a name is a bug.

        The entries stay in the order of :data:`MODEL_MODULES` (then of registration), whichever module is
        imported first.
        """
        if entry.name in self._entries:
            raise ValueError(f"a sliding-block model named {entry.name!r} is registered twice")
        self._entries[entry.name] = entry
        rank = {module: index for index, module in enumerate(MODEL_MODULES)}
        ordered = sorted(self._entries.items(), key=lambda item: rank.get(type(item[1]).__module__, len(rank)))
        self._entries = dict(ordered)

    def __getitem__(self, name: str):
        self._load()
        if name not in self._entries:
            raise StickslipError(f"unknown sliding-block model {name!r}; known: {', '.join(self._entries)}")
        return self._entries[name]

    def __contains__(self, name) -> bool:
        self._load()
        return name in self._entries

    def __iter__(self) -> Iterator[str]:
        self._load()
        return iter(self._entries)

    def __len__(self) -> int:
        self._load()
        return len(self._entries)


#: Every sliding-block model, by name.
MODELS = Registry()


def public_names(package: str, names: Mapping[str, str]):
    """The module-level ``__getattr__`` (PEP 562) of a model's ``package`` that gives its public ``names`` (name ->
    the package's module that defines it): what outside the package may use of a model beside its entry, each
    imported when first asked for, so that importing the package (the registry does) imports no kernel."""

    def __getattr__(name: str):
        if name not in names:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        return getattr(importlib.import_module(f"{package}.{names[name]}"), name)

    return __getattr__


def register(entry):
    """Register ``entry`` in :data:`MODELS` (a model module calls it once, on import); returns it."""
    MODELS.register(entry)
    return entry
