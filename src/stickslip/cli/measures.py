"""``stickslip measures PATH...``: the intensity measures of record files, SI units.

``--g`` [m/s²] converts values in g and enters the Arias intensity; the
output states it.  A vertical component gets a note on stderr and, with
``--json``, its ``vertical`` field says why it is taken as one.
"""

from __future__ import annotations

import json
from pathlib import Path

from stickslip.cli.record_options import (
    add_gravity_option,
    add_keep_going_option,
    add_record_options,
    read_records_from_args,
)
from stickslip.measures import MEASURE_LABELS, MEASURE_UNITS, intensity_measures
from stickslip.records.components import vertical_component
from stickslip.records.process import record_name
from stickslip.units import UNITS, readable_units

#: Keys of the ``--json`` object, in order (SI units).
JSON_KEYS = (
    "pga", "pgv", "pgd", "arias_intensity", "t5", "t95",
    "significant_duration", "rms_acceleration", "mean_period", "npts", "dt", "duration",
)

def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "measures",
        help="intensity measures of record files (PGA, PGV, PGD, Arias, significant duration, RMS)",
        description=(
            "Read ground-motion records (formats may mix) and print the intensity measures of each in SI units. "
            "Definitions: docs/definitions.md (g = 9.81 m/s2 unless --g says otherwise)."
        ),
    )
    parser.add_argument("paths", type=Path, nargs="+", metavar="path", help="record files")
    add_record_options(parser)
    add_keep_going_option(parser)
    add_gravity_option(parser)
    parser.add_argument("--json", action="store_true",
                        help="print one JSON object per file and line (the record id, its source file, 'vertical': why "
                        "it is a vertical component or null, g, the measures in SI units, named in its 'units' object, "
                        "UDUNITS spelling) instead of a table")
    parser.set_defaults(func=run)


def format_table(values: dict[str, float | int]) -> str:
    """The measures as an aligned three-column table: label, value, units (:data:`MEASURE_LABELS`' order)."""
    width = max(map(len, MEASURE_LABELS.values()))
    lines = []
    for key, label in MEASURE_LABELS.items():
        value = values[key]
        shown = f"{value:d}" if isinstance(value, int) else f"{value:.6g}"
        lines.append(f"{label:<{width}}  {shown:>12}  {readable_units(MEASURE_UNITS[key])}")
    return "\n".join(lines)


def json_document(record, values: dict[str, float | int], g: float) -> dict:
    """The ``--json`` object of one record: its id and source file, whether it is vertical, g [m/s²], the measures
    (SI) and their units."""
    # JSON has no NaN: a mean period undefined for a short record is null
    measures = {key: None if values[key] != values[key] else values[key] for key in JSON_KEYS}
    return {"record": record.meta.record_id, "source": record.meta.source, "vertical": vertical_component(record.meta),
            "g": g, **measures, "units": {"g": UNITS["gravity"], **{key: MEASURE_UNITS[key] for key in JSON_KEYS}}}


def run(args) -> int:
    records = read_records_from_args(args.paths, args)
    for number, record in enumerate(records):
        values = intensity_measures(record, g=args.g).as_dict()
        if args.json:
            print(json.dumps(json_document(record, values, args.g), allow_nan=False))
        else:
            stored = f"stored record of {record.meta.source}, " if record.meta.stored_in else ""
            print(("\n" if number else "") + f"{record_name(record)}  ({stored}{record.meta.format}, "
                  f"{record.meta.units} -> SI, g = {args.g:g} m/s2)")
            print(format_table(values))
    return 0
