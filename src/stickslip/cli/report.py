"""``stickslip report PATH --out report.html``: a record's report as one HTML page, without code.

Several files give one page each: ``stickslip report A.AT2 B.AT2 --out pages/``
writes ``pages/<record id>.html`` for each, every file read and every option
checked before the first page is rendered.

The page (:func:`stickslip.reports.record_report.render_record_report`,
``notebooks/record_report.ipynb``) gives the design answer of
:mod:`stickslip.optimum` (μ_max on the grid and continuous, the near-optimal
range, the stroke and residual displacement at μ_max and at the range's
ends, the efficiency of the reference μ: the numbers ``stickslip optimum``
prints for the record with the same grid, q and reference μ) with its
figures, the intensity measures, the acceleration history and the response
at one μ; its figures are embedded, so the one file is the whole report.  The record and the options are checked before
the notebook starts, so a mistake is one line and exit code 2.
"""

from __future__ import annotations

from pathlib import Path

from stickslip.cli.grid_options import (
    DEFAULT_MU_TEXT,
    add_optimum_options,
    check_optimum_options,
    parse_mu_bounds,
)
from stickslip.cli.pair_options import add_pair_options, pairs_from_args
from stickslip.cli.record_options import add_record_options, read_records_from_args, record_files
from stickslip.constants import PAPER_BLOCK_MASS, STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.plumbing.files import check_output_dir, check_output_path, write_text_atomic
from stickslip.records.process import record_name
from stickslip.optimum import DEFAULT_Q, DEFAULT_REFERENCE


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "report",
        help="write a record's report (the design answer, measures, figures) as one HTML page",
        description=(
            "Render the record report (notebooks/record_report.ipynb, with papermill) for one record file and "
            "write it as one self-contained HTML page without code: mu_max, the near-optimal range, the stroke "
            "and residual displacement, the efficiency of the reference mu (the numbers 'stickslip optimum' "
            "prints for the record, with the same options), the intensity measures and figures."
        ),
    )
    parser.add_argument("paths", type=Path, nargs="+", metavar="PATH",
                        help="record files (formats may mix): one page each")
    parser.add_argument("--mu", default=DEFAULT_MU_TEXT, metavar="START:STOP:STEP",
                        help="friction ratios of the sweep, STOP included, at least three (default "
                             f"{DEFAULT_MU_TEXT}, the grid of 'stickslip optimum')")
    add_optimum_options(parser)
    parser.add_argument("--mu-case", type=float, default=DEFAULT_REFERENCE["mu"],
                        help="friction ratio of the response figure (default %(default)s)")
    parser.add_argument("--mass", type=float, default=PAPER_BLOCK_MASS, help="block mass [kg] (default %(default)s)")
    parser.add_argument("--g", type=float, default=STANDARD_GRAVITY, help="gravity [m/s2] (default %(default)s)")
    add_pair_options(parser)
    add_record_options(parser)
    parser.add_argument("--out", type=Path, required=True,
                        help="the HTML page to write; with several files, the folder for one page per record "
                             "(<record id>.html)")
    parser.set_defaults(func=run)


def run(args) -> int:
    from stickslip.reports.record_report import check_positive, render_record_report

    if args.pad and not args.pair:
        raise StickslipError("--pad applies with --pair (two components of one station)")
    if "," in args.mu:
        raise StickslipError(f"--mu {args.mu!r}: the report sweeps a START:STOP:STEP range (0.0025:1:0.0025), "
                             "not a list")
    start, stop, step = parse_mu_bounds(args.mu, min_values=3)  # the notebook builds the grid by range_values
    reference = check_optimum_options(args)
    for option in ("mu_case", "mass", "g"):
        check_positive(getattr(args, option), f"--{option.replace('_', '-')}")
    if args.pair:
        return run_pairs(args, start, stop, step)
    paths = record_files(args.paths)
    if len(paths) == 1:
        check_output_path(args.out, "the HTML report")
    elif args.out.exists() and not args.out.is_dir():
        raise StickslipError(f"{args.out}: {len(paths)} records give one page each: --out must be a folder")
    else:
        check_output_dir(args.out, "the HTML reports")
    records = read_records_from_args(paths, args)  # a bad file or option stops here, before any notebook starts
    pages = ({paths[0]: args.out} if len(paths) == 1 else
             {path: args.out / f"{record.meta.record_id}.html" for path, record in zip(paths, records)})
    for path, page_path in pages.items():
        page = render_record_report({
            "record": str(path.resolve()), "format": args.format, "dt": args.dt, "units": args.units,
            "mu_start": start, "mu_stop": stop, "mu_step": step,
            "near_optimal_fraction": args.q, "reference_mu": reference, "mu_case": args.mu_case,
            "mass": args.mass, "g": args.g,
        })
        write_text_atomic(page_path, page)
        print(page_path)
    return 0


def run_pairs(args, start: float, stop: float, step: float) -> int:
    """``report --pair``: one page per pair of components (the block in the plane beside each component alone)."""
    from stickslip.reports.pair_report import render_pair_report

    if args.reference_mu is not None or args.q != DEFAULT_Q:
        raise StickslipError("--reference-mu and --q apply to a record's report, not to a pair's (--pair)")
    pairs = pairs_from_args(args)  # a bad file, a mismatched pair or an option stops here, before any notebook starts
    if len(pairs) == 1:
        check_output_path(args.out, "the HTML report")
        pages = [(pairs[0], args.out)]
    else:
        if args.out.exists() and not args.out.is_dir():
            raise StickslipError(f"{args.out}: {len(pairs)} pairs give one page each: --out must be a folder")
        check_output_dir(args.out, "the HTML reports")
        pages = [(pair, args.out / f"{Path(pair.first.meta.source).stem}_{Path(pair.second.meta.source).stem}.html")
                 for pair in pairs]
    for pair, page_path in pages:
        page = render_pair_report({
            "first": str(Path(record_name(pair.first)).resolve()), "second": str(Path(record_name(pair.second)).resolve()),
            "pad": args.pad, "any_pair": args.any_pair, "format": args.format, "dt": args.dt, "units": args.units,
            "mu_start": start, "mu_stop": stop, "mu_step": step, "mu_case": args.mu_case, "mass": args.mass,
            "g": args.g,
        })
        write_text_atomic(page_path, page)
        print(page_path)
    return 0
