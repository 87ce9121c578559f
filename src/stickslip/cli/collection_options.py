"""Command-line options that choose a record collection and filter its records (``records list``, ``records fetch``)."""

from __future__ import annotations

from pathlib import Path

from stickslip.cli.accelerations import in_units_of_g
from stickslip.cli.quantities import of_unit, quantity_type
from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import StickslipError


def add_collection_options(parser) -> None:
    """``--collection``, ``--folder``, ``--metadata`` and the record filters."""
    parser.add_argument("--collection", choices=("slammer", "pyslammer", "folder"), default=None,
                        help="a record collection instead of the manifest (docs/collections.md)")
    parser.add_argument("--folder", type=Path, default=None,
                        help="slammer: a copy of the SLAMMER library (default STICKSLIP_SLAMMER_DIR); "
                             "folder: the folder of .AT2 files")
    parser.add_argument("--metadata", type=Path, default=None,
                        help="folder: a CSV table of more columns (file, mw, rupture_distance, ...; format, dt, units)")
    parser.add_argument("--dt", type=quantity_type(of_unit("s"), "--dt"), default=None,
                        help="folder: time step [s] of the files that state none and that no manifest knows (or "
                             "with its unit, 5ms)")
    parser.add_argument("--units", default=None,
                        help="folder: units (g, m/s2 or cm/s2) of the files that state none and that no manifest knows")
    filters = parser.add_argument_group("record filters (a record without the value is left out)")
    filters.add_argument("--min-rupture-distance", type=quantity_type(of_unit("km"), "--min-rupture-distance"),
                         metavar="KM", help="rupture distance at least KM [km] (or with its unit, 500m)")
    filters.add_argument("--max-rupture-distance", type=quantity_type(of_unit("km"), "--max-rupture-distance"),
                         metavar="KM", help="rupture distance at most KM [km] (or with its unit, 500m)")
    filters.add_argument("--min-magnitude", type=float, metavar="MW", help="moment magnitude at least MW")
    filters.add_argument("--max-magnitude", type=float, metavar="MW", help="moment magnitude at most MW")
    filters.add_argument("--min-pga", metavar="PGA",
                         help="listed PGA at least PGA [g] (0.3, the same as 0.3g), or with its unit (2.94m/s2)")
    filters.add_argument("--event", action="append", default=[], metavar="TEXT",
                         help="event name contains TEXT (case-insensitive; repeat for several)")
    filters.add_argument("--site-class", action="append", default=[], metavar="A-E",
                         choices=list("ABCDEabcde"), help="Geomatrix site class (repeat for several)")


def min_pga_in_g(text: str | None) -> float | None:
    """``--min-pga`` in g, from ``"0.3"`` or ``"0.3g"`` (g) or ``"2.94m/s2"`` (divided by the standard 9.81 m/s²)."""
    return None if text is None else in_units_of_g(text, STANDARD_GRAVITY, "--min-pga", "0.3")


def collection_from_args(args):
    """The collection the options name, restricted by the filters."""
    from stickslip.collections import RecordFilter, load_collection

    record_filter = RecordFilter(
        min_rupture_distance=args.min_rupture_distance, max_rupture_distance=args.max_rupture_distance,
        min_magnitude=args.min_magnitude, max_magnitude=args.max_magnitude, min_pga=min_pga_in_g(args.min_pga),
        events=tuple(args.event), site_classes=tuple(args.site_class),
    )
    if args.collection != "folder" and (args.dt is not None or args.units is not None):
        raise StickslipError(f"--dt and --units are for a folder collection, not --collection {args.collection}")
    collection = load_collection(args.collection, args.folder, args.metadata, args.dt, args.units)
    return collection.select(record_filter), record_filter
