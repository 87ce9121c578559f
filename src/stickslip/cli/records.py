"""``stickslip records list | validate | fetch``: the record manifest, file checks and acquisition."""

from __future__ import annotations

from pathlib import Path

from stickslip.cli.collection_options import add_collection_options, collection_from_args
from stickslip.cli.record_options import add_gravity_option, add_record_options, read_record_from_args
from stickslip.records.components import vertical_component


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "records",
        help="list the known records, validate record files, fetch records as NetCDF",
        description="Ground-motion records: the manifest shipped with stickslip (stickslip/data/records.yaml), file validation and acquisition.",
    )
    actions = parser.add_subparsers(dest="records_command", required=True, metavar="ACTION")

    listing = actions.add_parser("list", help="table of the manifest's (or a collection's) records and where each is")
    listing.add_argument("--records-dir", type=Path, default=None, help="local records folder")
    add_collection_options(listing)
    listing.set_defaults(func=run_list)

    validate = actions.add_parser("validate", help="read record files (formats may be mixed) and check them")
    validate.add_argument("paths", type=Path, nargs="+", metavar="PATH", help="record files")
    add_record_options(validate, check_choices=False)
    add_gravity_option(validate)
    validate.set_defaults(func=run_validate)

    fetch = actions.add_parser(
        "fetch", help="acquire records and write them as NetCDF {id}.nc; with --collection slammer, download "
                      "the library's files (checked) into a SLAMMER folder")
    fetch.add_argument("ids", nargs="*", metavar="ID",
                       help="record ids (default: the paper's eight records, or the filtered collection)")
    fetch.add_argument("--records-dir", type=Path, default=None, help="local records folder")
    fetch.add_argument("--out-dir", type=Path, default=Path("results/records"),
                       help="output folder: one NetCDF file {id}.nc per record, which every command reads as a record")
    fetch.add_argument("--cache-dir", type=Path, default=None, help="download cache folder")
    fetch.add_argument("--accept-unknown", action="store_true", help="accept files whose SHA-256 is not known")
    fetch.add_argument("--no-download", action="store_true", help="do not try the download mirror")
    add_gravity_option(fetch)
    add_collection_options(fetch)
    fetch.set_defaults(func=run_fetch)


def run_list(args) -> int:
    if args.collection:
        return run_list_collection(args)
    from stickslip.records.acquire import available_source, resolve_records_dir
    from stickslip.records.manifest import load_manifest

    folder = resolve_records_dir(args.records_dir)
    rows = [
        (entry.id, f"{entry.event} {entry.year}", entry.station or "-", entry.component or "-", available_source(entry, folder))
        for entry in load_manifest().values()
    ]
    header = ("id", "event", "station", "comp", "available")
    widths = [max(len(row[column]) for row in [header, *rows]) for column in range(len(header))]
    for row in [header, *rows]:
        print("  ".join(cell.ljust(width) for cell, width in zip(row, widths)).rstrip())
    return 0


def run_validate(args) -> int:
    """Print npts, dt, PGA and what is known of each file (a vertical component says so); check the measures of
    known versions. Exit 1 on a mismatch.  A PGA in doubt in the units assumed is a warning (the reader's)."""
    from stickslip.measures import intensity_measures
    from stickslip.records.manifest import EXPECTED_MEASURES, load_manifest

    manifest = load_manifest()
    mismatches = 0
    for path in args.paths:
        record = read_record_from_args(path, args, manifest)
        measures = intensity_measures(record, g=args.g).as_dict()
        pga = measures["pga"]
        print(
            f"{path}: {record.meta.format}, npts={record.npts}, dt={record.dt:g} s, "
            f"duration={record.duration:g} s, PGA={pga:.4g} m/s2 ({pga / args.g:.4g} g, g = {args.g:g} m/s2)"
        )
        meta = record.meta
        described = "; ".join(f"{name} {value}" for name, value in
                              (("event", meta.event), ("station", meta.station), ("component", meta.component)) if value)
        vertical = vertical_component(meta)
        stored = f"; stored in {meta.stored_in} (from {meta.source})" if meta.stored_in else ""
        print(f"  record {meta.record_id}: {described or 'no event, station or component known'}"
              f"{f'; a vertical component ({vertical})' if vertical else ''}; "
              f"dt {'given' if meta.dt_source == 'given' else f'from {meta.dt_source}'}, values in {meta.units}{stored}")
        entry = manifest.get(record.meta.record_id)
        if entry is None or entry.version_for(record.meta.sha256) is None:
            print("  no published measures to check it against (none in stickslip's record manifest for this file; "
                  "as for any file of your own)")
            continue
        for name, expected in entry.expected.items():
            ok = expected.accepts(measures[name])
            mismatches += not ok
            print(
                f"  {name} = {measures[name]:.5g} {EXPECTED_MEASURES[name]}, expected {expected.value:.5g} "
                f"(rtol {expected.rtol:g}) [{entry.id}]: {'ok' if ok else 'MISMATCH'}"
            )
    return 1 if mismatches else 0


def run_list_collection(args) -> int:
    """The filtered collection as a table: id, event, record, Mw, rupture distance, Vs30, site class, PGA, here."""
    collection, record_filter = collection_from_args(args)
    here = set(collection.local_ids())

    def cell(value, digits: str) -> str:
        return "-" if value != value or value is None or value == "" else format(value, digits)

    rows = [(record_id, str(row["event"]), str(row["record"]), cell(row["mw"], ".1f"),
             cell(row["rupture_distance"], ".1f"), cell(row["vs30"], ".0f"), cell(row["site_class"], "s"),
             cell(row["listed_pga"], ".3f"), "yes" if record_id in here else "no")
            for record_id, row in collection.table.iterrows()]
    header = ("id", "event", "record", "Mw", "R_rup[km]", "Vs30[m/s]", "class", "PGA[g]", "here")
    widths = [max(len(row[column]) for row in [header, *rows]) for column in range(len(header))]
    for row in [header, *rows]:
        print("  ".join(cell.ljust(width) for cell, width in zip(row, widths)).rstrip())
    unreadable = {record_id: reason for record_id, reason in collection.table.get("unreadable", {}).items() if reason}
    for record_id, reason in unreadable.items():
        print(f"  {collection.table.at[record_id, 'file']}: cannot be read: {reason}")
    for skipped in collection.skipped:
        print(f"  {skipped.file}: skipped, not a record file: {skipped.reason}")
    counted = f"; {len(here) - len(unreadable)} readable, {len(unreadable)} not (above)" if unreadable else ""
    others = len(collection.skipped)
    if others:
        counted += f"; {others} other file{'s' if others != 1 else ''} skipped (above)"
    print(f"{len(rows)} records of the {collection.kind} collection ({record_filter.describe()}); "
          f"{len(here)} here{f' in {collection.folder}' if collection.folder else ''}{counted}")
    return 0


def run_fetch_collection(args) -> int:
    """Gather the selected SLAMMER library files in ``out_dir`` (SLAMMER's layout), each checked by its SHA-256.

    A file already in ``out_dir`` is kept, one in the ``--folder`` library is
    copied, any other is downloaded from the source repository; then
    ``out_dir`` can serve as the collection study's folder.
    """
    from stickslip.collections import Collection
    from stickslip.errors import StickslipError
    from stickslip.plumbing.files import atomic_path

    if args.collection != "slammer":
        raise StickslipError(f"--collection {args.collection}: only the slammer collection can be fetched")
    collection, _ = collection_from_args(args)
    ids = args.ids or collection.ids
    unknown = [record_id for record_id in ids if record_id not in collection.table.index]
    if unknown:
        raise StickslipError(f"unknown record id(s) of the slammer collection: {', '.join(unknown[:5])}")
    target = Collection("slammer", collection.table, args.out_dir)
    for record_id in ids:
        if target.local_file(record_id) is None:
            data, _ = collection.file_bytes(record_id, download=not args.no_download, cache_dir=args.cache_dir)
            with atomic_path(args.out_dir / "records" / collection.table.at[record_id, "file"]) as tmp:
                tmp.write_bytes(data)
        target.read(record_id, g=args.g)  # the copy is checked like any file of the library
        print(target.local_file(record_id))
    return 0


def run_fetch(args) -> int:
    """Acquire each record and write ``{out_dir}/{id}.nc``; unavailable default records are stored as missing."""
    if args.collection:
        return run_fetch_collection(args)
    from stickslip.plumbing.files import check_output_dir, check_output_path
    from stickslip.records.acquire import store_record
    from stickslip.records.manifest import load_manifest
    from stickslip.reference import paper_record_ids

    check_output_dir(args.out_dir, "the records")
    for record_id in args.ids:
        check_output_path(args.out_dir / f"{record_id}.nc", "the record")
    manifest = load_manifest()
    options = {"records_dir": args.records_dir, "manifest": manifest, "accept_unknown": args.accept_unknown,
               "cache_dir": args.cache_dir, "download": not args.no_download, "g": args.g}
    ids = args.ids or paper_record_ids()
    for record_id in ids:  # a record named on the command line must be found; a default one may be missing
        print(store_record(record_id, args.out_dir / f"{record_id}.nc", missing_ok=not args.ids, **options))
    return 0
