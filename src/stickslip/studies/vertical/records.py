"""The three-component records of the vertical-motion study: acquired from a folder, each file checked by its SHA-256.

Fifteen near-fault stations of the PEER NGA-West2 database, each with its two
horizontal components (``H1``, ``H2``) and its vertical (``UP``), as listed
with their SHA-256 in the package's ``stickslip/data/three_component.csv``
(docs/studies.md, "The vertical ground motion on sliders and pendulums").
The files are never part of the repository: the workflow reads them from a
folder (``vertical_study.records_dir``, or ``STICKSLIP_THREE_COMPONENT_DIR``),
laid out as the manifest's ``file`` column says (``<set>/<PEER file name>``).
A file that is absent, or whose SHA-256 is not the manifest's, keeps its
row in the store with the reason, and its station is left out of the study.

The motions of a station (:func:`station_motion`): one horizontal component
(``H1``, ``H2``) or both (``plane``), without the vertical (``none``), with
it as recorded (``recorded``: its sense read from its PEER label, ``UP`` or
``DWN``, or taken as ``untold_positive`` where the label does not say, as
the Tabas files' ``V1``), or with it reversed (``reversed``: a_v → −a_v, the
other sense, so that the two bound the sign).  The shorter component is
padded with zeros at its end (the components of a set differ by a few
samples; Gazli's by up to 96).
"""

from __future__ import annotations

import csv
import importlib.resources
from dataclasses import replace
from pathlib import Path

from stickslip.collections.store import StoredRecord, read_record_store, write_record_store
from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import RecordError, StickslipError
from stickslip.plumbing.files import write_csv_atomic
from stickslip.records.pair import RecordPair
from stickslip.records.readers import read_file_bytes, read_record_bytes, sha256_hex
from stickslip.records.record import Record
from stickslip.records.vertical import WithVertical, vertical_sense

#: The components of a set, as the manifest names them.
COMPONENTS = ("H1", "H2", "UP")

#: The directions a study can slide in: one horizontal component, or both in the plane.
DIRECTIONS = ("H1", "H2", "plane")

#: The vertical variants: without the vertical, with it as recorded, with it reversed.
VARIANTS = ("none", "recorded", "reversed")

#: Environment variable naming the folder of the three-component records.
FOLDER_ENV = "STICKSLIP_THREE_COMPONENT_DIR"

#: Where the records come from, for a reader who has not got them.
HOW_TO_GET = ("copy the fifteen PEER NGA-West2 three-component sets listed with their SHA-256 in "
              "stickslip/data/three_component.csv (from https://ngawest2.berkeley.edu, or the public repositories "
              f"named there) into a folder, and set {FOLDER_ENV} or vertical_study.records_dir to it")


def manifest_rows() -> list[dict[str, str]]:
    """The package's list of the three-component files: set, component, file, sha256, event, year, station, dt [s], npts."""
    resource = importlib.resources.files("stickslip").joinpath("data", "three_component.csv")
    with resource.open("r", encoding="utf-8", newline="") as handle:
        return list(csv.DictReader(handle))


def set_names() -> list[str]:
    """The sets (stations) of the manifest, in its order."""
    return list(dict.fromkeys(row["set"] for row in manifest_rows()))


def folder_files(folder: str | Path | None) -> list[Path]:
    """The manifest's files present in ``folder`` (none when it is None or absent)."""
    if not folder or not Path(folder).is_dir():
        return []
    return [Path(folder) / row["file"] for row in manifest_rows() if (Path(folder) / row["file"]).is_file()]


def missing_message(folder: str | Path | None) -> str:
    """One sentence: the records were not available, and how to get them."""
    where = f"in {folder}" if folder else "(no folder configured)"
    return f"The three-component records were not available {where}: {HOW_TO_GET}."


def stored_id(set_name: str, component: str) -> str:
    """The id of a set's component in the store: ``<set>.<component>``."""
    return f"{set_name}.{component}"


def acquired_row(folder: Path, entry: dict[str, str], g: float) -> StoredRecord:
    """One manifest file read from ``folder`` and checked against its SHA-256: ok, missing or rejected."""
    record_id = stored_id(entry["set"], entry["component"])
    path = folder / entry["file"]
    if not path.is_file():
        return StoredRecord(record_id, None, "missing", f"{entry['file']} is not in {folder}")
    data = read_file_bytes(path)
    found = sha256_hex(data)
    if found != entry["sha256"]:
        return StoredRecord(record_id, None, "rejected",
                            f"{path}: SHA-256 {found} is not the manifest's {entry['sha256']} (another version of "
                            "the file)")
    try:
        record = read_record_bytes(data, str(path), g=g)
    except RecordError as error:
        return StoredRecord(record_id, None, "rejected", str(error))
    return StoredRecord(record_id, record, "ok")


def store_three_component(folder, store_path, inventory_path, g: float = STANDARD_GRAVITY) -> list[str]:
    """The workflow's acquisition: every manifest file of ``folder`` checked and stored in one record store.

    Writes the store (:func:`stickslip.collections.store.write_record_store`,
    accelerations in m/s² with ``g`` [m/s²]) and an inventory (CSV: set,
    component, status, reason, dt [s], npts, pga [g], and for the vertical
    which way its file's positive axis points and how that was told).
    """
    if not folder_files(folder):
        raise StickslipError(missing_message(folder))
    folder = Path(folder)
    rows = [acquired_row(folder, entry, g) for entry in manifest_rows()]
    write_record_store(rows, store_path, {"title": "three-component PEER records of the vertical-motion study",
                                          "records_folder": str(folder)})
    inventory = []
    for entry, row in zip(manifest_rows(), rows):
        record = row.record
        told = vertical_sense(record) if record is not None and entry["component"] == "UP" else None
        inventory.append({
            "set": entry["set"], "component": entry["component"], "file": entry["file"], "status": row.status,
            "reason": row.reason, "dt": record.dt if record else "", "npts": record.npts if record else "",
            "pga_g": float(abs(record.acceleration).max() / g) if record else "",
            "vertical_sense": "" if entry["component"] != "UP" else (f"{told[0]} ({told[1]})" if told else "untold"),
        })
    write_csv_atomic(inventory_path, inventory)
    return [str(store_path), str(inventory_path)]


def stations(store_path) -> tuple[dict[str, dict[str, Record]], dict[str, str]]:
    """The stations whose three components were stored ``ok``: set -> {H1, H2, UP}; and set -> why not, for the rest.

    Each component's ``meta.record_id`` is its set's name (the study's ``record`` dimension).
    """
    by_set: dict[str, dict[str, StoredRecord]] = {}
    for row in read_record_store(store_path):
        set_name, component = row.record_id.rsplit(".", 1)
        by_set.setdefault(set_name, {})[component] = row
    found, left_out = {}, {}
    for set_name, rows in by_set.items():
        bad = [f"{component}: {row.status} ({row.reason})" for component, row in rows.items() if row.status != "ok"]
        if bad or set(rows) != set(COMPONENTS):
            left_out[set_name] = "; ".join(bad) or "a component is not in the store"
            continue
        found[set_name] = {component: replace(row.record, meta=replace(row.record.meta, record_id=set_name))
                           for component, row in rows.items()}
    return found, left_out


def station_motion(station: dict[str, Record], direction: str, variant: str, untold_positive: str | None = None):
    """The motion of one station: ``direction`` (``H1``, ``H2``, ``plane``) with the vertical ``variant``.

    ``none`` gives the horizontal motion alone (a :class:`Record`, or a
    :class:`RecordPair` for the plane), the others a :class:`WithVertical`
    (a_v positive up): ``recorded`` reads the vertical's sense from its label,
    or takes ``untold_positive`` (``"up"``, ``"down"``) where the label does
    not tell; ``reversed`` is the same motion with a_v → −a_v.  Components of
    unequal lengths are padded with zeros at their ends.
    """
    if direction not in DIRECTIONS:
        raise StickslipError(f"vertical_study.directions: {direction!r} is not one of {', '.join(DIRECTIONS)}")
    if variant not in VARIANTS:
        raise StickslipError(f"vertical_study.variants: {variant!r} is not one of {', '.join(VARIANTS)}")
    horizontal = (RecordPair.padded(station["H1"], station["H2"]) if direction == "plane"
                  else station[direction])
    positive = None if vertical_sense(station["UP"]) is not None else untold_positive
    motion = WithVertical.of(horizontal, station["UP"], positive=positive, pad=True)
    if variant == "none":
        return motion.horizontal
    if variant == "reversed":
        return reversed_vertical(motion)
    return motion


def reversed_vertical(motion: WithVertical) -> WithVertical:
    """``motion`` with its vertical acceleration reversed, a_v → −a_v [m/s²] (the other sense of the file)."""
    vertical = motion.vertical.derive(-motion.vertical.acceleration, step="vertical reversed")
    return WithVertical(motion.horizontal, vertical, f"{motion.sense}, then reversed")
