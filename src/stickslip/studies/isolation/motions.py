"""The horizontal components the isolation study runs on, each in one direction.

Two sources, read where other studies left them (no record file is opened here):

- the SLAMMER library's station pairs (the planar study's ``pairs.csv`` with status ``ok``, their components in
  the collection study's record stores): both components of each pair, each alone;
- the fifteen three-component stations (the vertical study's store, :func:`stickslip.studies.vertical.records.stations`):
  each station's ``H1`` and ``H2``.

Each component is a :class:`Component`: the record and what the tables say of it.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

from stickslip.collections.store import read_record_store
from stickslip.plumbing.files import read_csv_rows
from stickslip.records.record import Record

#: The libraries of the study, as its tables name them.
LIBRARIES = ("slammer", "three_component")


@dataclass(frozen=True)
class Component:
    """One horizontal component and what the study's tables say of it."""

    record_id: str
    """Its id: the collection's member id (``TAK-090``'s row), or ``<set>.H1`` for a three-component station."""
    library: str
    """``slammer`` or ``three_component``."""
    station: str
    """``event/STATION`` of a SLAMMER pair, or the three-component set's name."""
    component: str
    """The component's name (``TAK-090``, ``H1``)."""
    rupture_distance: float
    """Closest distance to the rupture [km]; NaN where the source does not give it."""
    record: Record
    """The ground acceleration [m/s²] and its time step [s]."""


def pair_components(pairs_path: str | Path, store_paths: Sequence[str | Path], chunk: str) -> list[Component]:
    """Both components of each pair of ``chunk`` in ``pairs.csv`` whose two records were read (status ``ok``)."""
    rows = [row for row in read_csv_rows(pairs_path) if row["chunk"] == chunk and row["status"] == "ok"]
    if not rows:
        return []
    stored = {item.record_id: item for path in store_paths for item in read_record_store(path)}
    components = []
    for row in rows:
        distance = float(row["rupture_distance"]) if row["rupture_distance"] else math.nan
        for side in ("first", "second"):
            components.append(Component(row[side], "slammer", row["pair"], row[f"{side}_component"], distance,
                                        stored[row[side]].record))
    return components


def three_component_components(store_path: str | Path | None) -> tuple[list[Component], dict[str, str]]:
    """``H1`` and ``H2`` of each station stored ``ok`` (none without a store), and the stations left out, with why."""
    from stickslip.studies.vertical.records import stations, stored_id

    if store_path is None:
        return [], {}
    found, left_out = stations(store_path)
    components = [Component(stored_id(name, direction), "three_component", name, direction, math.nan,
                            station[direction])
                  for name, station in found.items() for direction in ("H1", "H2")]
    return components, left_out


def described(components: Sequence[Component]) -> Mapping[str, list]:
    """The components' descriptions as columns: record id, library, station, component, rupture distance [km]."""
    return {"record": [item.record_id for item in components], "library": [item.library for item in components],
            "station": [item.station for item in components], "component": [item.component for item in components],
            "rupture_distance": [item.rupture_distance for item in components]}
