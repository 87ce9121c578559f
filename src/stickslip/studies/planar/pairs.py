"""The station pairs of a collection study: which two horizontal components of one station slide the block in the plane.

A collection's members are single components (the SLAMMER library's rows:
``TAK-000``, ``CHY028-N``, ``PAR-L``).  :func:`form_pairs` groups them by
event and station prefix, the component id without its direction suffix
(:func:`component_direction`): ``TAK-000``/``TAK-090`` → ``TAK``,
``CHY028-N``/``CHY028-W`` → ``CHY028``, ``PAR-L``/``PAR-T`` → ``PAR``.  A group
of exactly two horizontal components with the same time step is a pair; every
other member is listed as unpaired with its reason (:data:`REASONS`): a
single component, more than two, directions that cannot be related (an
azimuth and a longitudinal/transverse name), components closer than
:data:`~stickslip.records.pair.MIN_SEPARATION` degrees or different time steps.

How the two components are taken (``docs/planar.md`` states it for the study):

- azimuths (``-000``, ``-N``): the first component is the one from which the
  other lies clockwise within (0°, 180°]; components that are not a right
  angle apart (the SLAMMER library's Landers LCN 260/345, 85°) are resolved
  onto orthogonal axes by :meth:`~stickslip.records.pair.RecordPair.horizontal`;
- longitudinal and transverse (``-L``/``-T``, ``-LN``/``-TR``, ``-L1``/``-T1``):
  the L component first, and the two taken as orthogonal (their azimuths are
  not known);
- lengths: the components are taken to start together; the shorter one is
  padded with zeros at its end (:meth:`~stickslip.records.pair.RecordPair.padded`),
  which is the ground at rest after it ends.  The study's table gives the
  number of samples added.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping

from stickslip.records.components import component_direction
from stickslip.records.pair import MIN_SEPARATION

#: Kinds of unpaired member, and what the report calls each.
REASONS = {
    "no direction": "component id names no horizontal direction",
    "single": "the only horizontal component of its station among the study's records",
    "more than two": "more than two horizontal components of one station",
    "unrelated directions": "one azimuth and one longitudinal/transverse component: their angle is unknown",
    "too close": f"the components are closer than {MIN_SEPARATION:g} degrees (or more than "
                 f"{180 - MIN_SEPARATION:g} apart): they cannot be resolved onto orthogonal axes",
    "different dt": "the two components have different time steps",
    "not read": "a component could not be read",
}

def _separation(first: float, second: float) -> float:
    """The angle from azimuth ``first`` to ``second``, clockwise, in [0, 360)."""
    return (second - first) % 360.0


def _ordered(members: list[dict], kinds: list[tuple]) -> tuple[list[dict], float | None, str | None]:
    """The two members in pair order, the separation [degrees] (None: taken as orthogonal), and why not a pair."""
    (_, kind_a, azimuth_a), (_, kind_b, azimuth_b) = kinds
    if kind_a == kind_b == "azimuth":
        separation = _separation(azimuth_a, azimuth_b)
        if separation > 180.0:
            members, separation = members[::-1], 360.0 - separation
        if not MIN_SEPARATION <= separation <= 180.0 - MIN_SEPARATION:
            return members, separation, "too close"
        return members, separation, None
    if {kind_a, kind_b} == {"longitudinal", "transverse"}:
        return (members if kind_a == "longitudinal" else members[::-1]), None, None
    return members, None, "unrelated directions"


def form_pairs(members: Iterable[Mapping]) -> tuple[list[dict], list[dict]]:
    """The station pairs of ``members`` and the members left unpaired, each with its reason.

    Each member is a mapping with ``id``, ``event``, ``record`` (the component
    id, e.g. ``TAK-090``; the id when empty), ``dt`` [s] and optionally
    ``station`` and ``rupture_distance`` [km].  Returns (pairs, unpaired):

    - a pair: ``pair`` (``event/STATION``), ``first``, ``second`` (member ids),
      ``first_component``, ``second_component``, ``event``, ``station_key``,
      ``station``, ``dt``, ``rupture_distance``, ``separation`` [degrees; 90 when
      taken as orthogonal], ``orthogonal`` and ``directions`` (how the axes
      were taken);
    - an unpaired member: ``id``, ``event``, ``component``, ``group`` (a key of
      :data:`REASONS`) and ``reason``.

    Pairs come in the order of their first member in ``members``.
    """
    members = [dict(member) for member in members]
    groups: dict[tuple[str, str], list[tuple[dict, tuple]]] = {}
    unpaired = []
    for member in members:
        component = str(member.get("record") or member["id"])
        found = component_direction(component)
        if found is None:
            unpaired.append(_unpaired(member, component, "no direction", f"{component}: {REASONS['no direction']}"))
            continue
        groups.setdefault((str(member["event"]), found[0]), []).append((member, found))
    pairs = []
    for (event, key), group in groups.items():
        components = [str(member.get("record") or member["id"]) for member, _ in group]
        if len(group) == 1:
            unpaired.append(_unpaired(group[0][0], components[0], "single",
                                      f"no other horizontal component of station {key} in {event} among the "
                                      "study's records"))
            continue
        if len(group) > 2:
            for (member, _), component in zip(group, components):
                unpaired.append(_unpaired(member, component, "more than two",
                                          f"station {key} in {event} has {len(group)}: {', '.join(components)}"))
            continue
        ordered, separation, problem = _ordered([member for member, _ in group], [found for _, found in group])
        dts = [float(member["dt"]) for member in ordered]
        if problem is None and abs(dts[0] - dts[1]) > 1e-9 * max(dts):
            problem = "different dt"
        if problem is not None:
            detail = (f"{separation:g} degrees apart" if problem == "too close" else
                      f"dt {dts[0]:g} s and {dts[1]:g} s" if problem == "different dt" else " and ".join(components))
            for member, component in zip(ordered, [str(m.get("record") or m["id"]) for m in ordered]):
                unpaired.append(_unpaired(member, component, problem, f"{REASONS[problem]} ({detail})"))
            continue
        first, second = ordered
        orthogonal = separation is None or abs(separation - 90.0) <= 1e-6
        pairs.append({
            "pair": f"{event}/{key}", "first": first["id"], "second": second["id"],
            "first_component": str(first.get("record") or first["id"]),
            "second_component": str(second.get("record") or second["id"]),
            "event": event, "station_key": key, "station": str(first.get("station") or ""),
            "dt": dts[0], "rupture_distance": first.get("rupture_distance", ""),
            "separation": 90.0 if separation is None else separation, "orthogonal": orthogonal,
            "directions": ("longitudinal and transverse, taken as orthogonal" if separation is None else
                           "azimuths, orthogonal" if orthogonal else
                           f"azimuths {separation:g} degrees apart, resolved onto orthogonal axes"),
        })
    order = {member["id"]: index for index, member in enumerate(members)}
    pairs.sort(key=lambda pair: min(order[pair["first"]], order[pair["second"]]))
    unpaired.sort(key=lambda row: order[row["id"]])
    return pairs, unpaired


def _unpaired(member: Mapping, component: str, group: str, reason: str) -> dict:
    return {"id": member["id"], "event": str(member["event"]), "component": component, "group": group,
            "reason": reason}


def collection_members(table, ids: Iterable[str]) -> list[dict]:
    """The members ``ids`` of a collection's table (:data:`stickslip.collections.collection.COLUMNS`) as mappings."""
    columns = ("event", "record", "station", "dt", "rupture_distance")
    rows = []
    for record_id in ids:
        values = table.loc[record_id]
        row = {"id": record_id}
        for column in columns:
            value = values.get(column, "") if hasattr(values, "get") else ""
            row[column] = "" if value is None or (isinstance(value, float) and value != value) else value
        rows.append(row)
    return rows


def pair_chunks(pairs: list[dict], chunk_size: int) -> list[list[dict]]:
    """The pairs in the fewest chunks of at most ``chunk_size``, each as large as the first (as the records' chunks)."""
    if not pairs:
        return []
    chunks = -(-len(pairs) // chunk_size)
    size = -(-len(pairs) // chunks)
    return [pairs[start:start + size] for start in range(0, len(pairs), size)]
