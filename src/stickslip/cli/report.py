"""``stickslip report PATH --out report.html``: a record's report as one HTML page, without code.

Several files give one page each: ``stickslip report A.AT2 B.AT2 --out pages/``
writes ``pages/<record id>.html`` for each, every file read and every option
checked before the first page is rendered; an ``--out`` that names a page
(``two.html``) for several is refused with the folder form.

The page (:func:`stickslip.reports.record_report.render_record_report`,
``notebooks/record_report.ipynb``) gives the design answer of
:mod:`stickslip.optimum` (μ_max on the grid and continuous, the near-optimal
range, the stroke and residual displacement at μ_max and at the range's
ends, the efficiency of the reference μ: the numbers ``stickslip optimum``
prints for the record with the same grid, q, reference μ and
``--range-points``) with its figures, the intensity measures, the
acceleration history and the response at one μ (the record's μ_max unless
``--mu-case`` says otherwise); its figures are embedded, so the one file is
the whole report.  The record and the options are checked before the
notebook starts, so a mistake is one line and exit code 2.  While it works,
the command writes one line per page on stderr, and the page's path on
stdout when it is written.

With ``--pair``, the files are taken two by two as the horizontal components
of one station: the flat block in the plane gets the pair report
(:func:`stickslip.reports.pair_report.render_pair_report`), the friction
pendulum (``--radius R``, its friction law, ``--vertical``) the record
report's page for the pair (its notebook's ``second``), with the design
chart over R × μ, each component's measures and acceleration, and the
slider's path in the plane.
"""

from __future__ import annotations

import sys
import tempfile
from contextlib import contextmanager
from pathlib import Path

from stickslip.cli.grid_options import (
    DEFAULT_MU_TEXT,
    add_chart_levels_option,
    add_chart_values_options,
    add_optimum_options,
    add_range_points_option,
    check_optimum_options,
    chart_levels_from_args,
    chart_values_from_args,
    checked_range_points,
    refuse_chart_without_model_chart,
)
from stickslip.cli.grid_values import parse_mu_bounds
from stickslip.cli.model_options import (
    add_model_options,
    model_from_args,
    parameters_from_args,
    scheme_options_from_args,
)
from stickslip.cli.pair_options import (
    add_pair_options,
    add_vertical_options,
    motion_kind_from_args,
    motions_from_args,
    pairs_from_args,
)
from stickslip.cli.quantities import of_unit, quantity_type
from stickslip.cli.record_options import add_keep_going_option, add_record_options, record_files
from stickslip.errors import StickslipError
from stickslip.plumbing.files import check_output_dir, check_output_path, write_text_atomic
from stickslip.records.process import record_name


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "report",
        help="write a record's report (the design answer, measures, figures) as one HTML page",
        description=(
            "Render the record report (notebooks/record_report.ipynb, with papermill) for each record file and "
            "write it as one self-contained HTML page without code: mu_max, the near-optimal range, the stroke "
            "and residual displacement, the efficiency of the reference mu (the numbers 'stickslip optimum' "
            "prints for the record, with the same options), the intensity measures and figures, and the block's "
            "response at the record's mu_max. With --pair, the files are taken two by two as the horizontal "
            "components of one station: the pair report (notebooks/pair_report.ipynb) sets the block sliding in "
            "the plane beside each component alone and the turned axes; with --radius R (and --vertical V), the "
            "friction pendulum in the plane gets the record report's page for the pair, with the design chart."
        ),
    )
    parser.add_argument("paths", type=Path, nargs="+", metavar="PATH",
                        help="record files (formats may mix): one page each, or one per pair with --pair")
    add_model_options(parser, grids=True)
    add_optimum_options(parser)
    add_range_points_option(parser)
    parser.add_argument("--mu-case", type=quantity_type(of_unit("1"), "--mu-case"), default=None, metavar="MU",
                        help="friction ratio of the response figures (default: the record's continuous mu_max; "
                             "with --pair, the plane's continuous mu_max); or a percentage (6%%)")
    add_chart_values_options(parser)
    add_chart_levels_option(parser)
    add_pair_options(parser)
    add_vertical_options(parser)
    add_record_options(parser)
    add_keep_going_option(parser)
    parser.add_argument("--out", type=Path, required=True,
                        help="the HTML page to write (report.html); with several pages, the folder for them "
                             "(pages/: <record id>.html for each record, <first>_<second>.html for each pair)")
    parser.set_defaults(func=run)


def run(args) -> int:
    from stickslip.reports.record_report import check_positive, render_record_report

    if args.pad and not args.pair and args.vertical is None:
        raise StickslipError("--pad applies with --pair or --vertical (components of one station)")
    mu_text = args.mu if args.mu is not None else DEFAULT_MU_TEXT
    if args.mu_list is not None:
        raise StickslipError("--mu-list: the report sweeps a START:STOP:STEP range (--mu 0.0025:1:0.0025), not a list")
    if "," in mu_text:
        raise StickslipError(f"--mu {mu_text!r}: the report sweeps a START:STOP:STEP range (0.0025:1:0.0025), "
                             "not a list")
    start, stop, step = parse_mu_bounds(mu_text, min_values=3)  # the notebook builds the grid by range_values
    kind = motion_kind_from_args(args)
    entry = model_from_args(args, kind)
    if not entry.takes(kind, ["mu"]):
        raise StickslipError(f"--model {entry.name}: the report sweeps the friction ratio --mu, which the "
                             f"{entry.name} model ({entry.summary}) does not take; its cube is 'stickslip sweep'")
    parameters = parameters_from_args(args, entry, grids=True)
    parameters.pop("mu", None)  # the report's grid, from START:STOP:STEP
    for name in [parameter.name for parameter in entry.parameters if parameter.swept and parameter.name in parameters]:
        option = "--" + name.replace("_", "-")
        raise StickslipError(f"{option}: the report sweeps the friction ratio --mu; for a grid of {name} give "
                             f"'stickslip optimum {option} ...' or 'stickslip sweep {option} ...'")
    mass, g = entry.checked(parameters)["mass"], entry.checked(parameters)["g"]
    options = scheme_options_from_args(args, entry)
    if options:
        raise StickslipError(f"--{next(iter(options)).replace('_', '-')}: the report solves with the scheme's "
                             "defaults")
    reference = check_optimum_options(args, entry, "mu")
    range_points = checked_range_points(args)
    if args.mu_case is not None:
        check_positive(args.mu_case, "--mu-case")
    entry.scheme(args.method).check(entry.case(entry.checked({**parameters, "mu": args.mu_case or reference})))
    refuse_chart_without_model_chart(args, entry)
    chart_values, chart_levels = chart_values_from_args(args, entry), chart_levels_from_args(args, entry)
    others = {name: value for name, value in parameters.items() if name not in ("mass", "g")}
    if args.pair and entry.pair_report:  # the flat block in the plane (mu, mass, g): the pair report
        return run_pairs(args, start, stop, step, mass, g, reference, range_points)
    if args.pair:  # the friction pendulum in the plane: the record report's page for each pair
        motions = motions_from_args(args, kind)  # a bad file, pair or option stops here, before any notebook starts
        pairs = [motion.horizontal if args.vertical is not None else motion for motion in motions]
        given = len(record_files(args.paths)) // 2
        _check_out(args.out, given, "pairs")
        sources = [_pair_files(pair) for pair in pairs]
        pages = _page_paths(args.out, [_pair_page_name(files) for files in sources], given)
        names = [_pair_label(files) for files in sources]
    else:
        paths = record_files(args.paths)
        _check_out(args.out, len(paths), "records")
        motions = motions_from_args(args, kind)  # a bad file or option stops here, before any notebook starts
        read = [Path(motion.meta.source) for motion in motions]  # all of paths, unless --keep-going left some out
        sources = [(path.resolve(), None) for path in read]
        pages = _page_paths(args.out, [f"{motion.meta.record_id}.html" for motion in motions], len(paths))
        names = [path.name for path in read]
    with _answers(args.out, pages) as answers:
        for number, ((path, second), page_path, name, answer) in enumerate(zip(sources, pages, names, answers),
                                                                          start=1):
            _rendering(number, len(pages), name)
            page = render_record_report({
                "record": str(path), "second": None if second is None else str(second), "any_pair": args.any_pair,
                "format": args.format, "dt": args.dt, "units": args.units,
                "mu_start": start, "mu_stop": stop, "mu_step": step,
                "near_optimal_fraction": args.q, "reference_mu": reference, "range_points": range_points,
                "mu_case": args.mu_case, "mass": mass, "g": g, "model": entry.name, "method": args.method,
                "parameters": others, "chart_values": chart_values,
                "chart_levels": None if chart_levels is None else list(chart_levels),
                "vertical": None if args.vertical is None else str(args.vertical.resolve()),
                "vertical_positive": args.vertical_positive, "any_vertical": args.any_vertical, "pad": args.pad,
                "answer_path": answer,
            })
            write_text_atomic(page_path, page)
            print(page_path)
        _write_index(args.out, pages, answers, "pairs" if args.pair else "records")
    return 0


@contextmanager
def _answers(out: Path, pages: list[Path]):
    """The files where each page's notebook writes its design answer, in a temporary folder, for the index of the
    folder ``out`` of ``pages``; None for each when ``out`` is the one page (no index)."""
    if pages == [out]:
        yield [None]
        return
    with tempfile.TemporaryDirectory(prefix="stickslip-answers-") as folder:
        yield [str(Path(folder) / f"{number}.json") for number in range(len(pages))]


def _write_index(out: Path, pages: list[Path], answers: list, what: str) -> None:
    """For pages in the folder ``out`` (of ``what``: records or pairs): its index page, each page named by its file
    (:mod:`stickslip.reports.pages_index`), its path on stdout."""
    from stickslip.reports.pages_index import IndexedPage, write_index

    if pages != [out]:
        print(write_index([IndexedPage(page, page.stem, Path(answer)) for page, answer in zip(pages, answers)],
                          out, f"stickslip report: {len(pages)} {what}"))


def _check_out(out: Path, count: int, what: str) -> None:
    """``--out`` checked as the page of one, or the folder of ``count`` pages (of ``what``: records or pairs)."""
    if count == 1:
        check_output_path(out, "the HTML report")
    else:
        _check_pages_folder(out, count, what)


def _pair_files(pair) -> tuple[Path, Path]:
    """The files of a pair's two components, resolved."""
    return Path(record_name(pair.first)).resolve(), Path(record_name(pair.second)).resolve()


def _pair_page_name(files: tuple[Path, Path]) -> str:
    """A pair's page in a folder of pages: ``{first stem}_{second stem}.html``."""
    return f"{files[0].stem}_{files[1].stem}.html"


def _pair_label(files: tuple[Path, Path]) -> str:
    """How the progress line names a pair: its two file names."""
    return f"{files[0].name} + {files[1].name}"


def _page_paths(out: Path, names: list[str], given: int | None = None) -> list[Path]:
    """Where each page goes: ``out`` for one page, else ``out/<name>`` for each of ``names`` (beside the folder's
    index, :data:`~stickslip.reports.pages_index.INDEX_NAME`, which no page may take); ``given`` records (default
    as many as ``names``; more where ``--keep-going`` left some out) make ``out`` a folder."""
    from stickslip.reports.pages_index import INDEX_NAME

    if (given or len(names)) == 1:
        return [out]
    if INDEX_NAME in names:
        raise StickslipError(f"--out {out}: a page would be named {INDEX_NAME}, the name of the folder's index of "
                             "pages: rename that record's file")
    return [out / name for name in names]


def _check_pages_folder(out: Path, count: int, what: str) -> None:
    """``--out`` as the folder of ``count`` pages (of ``what``: records or pairs); a page's name is one line."""
    if (out.exists() and not out.is_dir()) or (not out.exists() and out.suffix.lower() in (".html", ".htm")):
        folder = out.with_suffix("") if out.suffix else out.parent / "pages"
        raise StickslipError(f"--out {out}: {count} {what} give one page each: give a folder for them, such as "
                             f"--out {folder}/")
    check_output_dir(out, "the HTML reports")


def _rendering(number: int, count: int, name: str) -> None:
    """The one line on stderr that says which page is being rendered (a page takes some seconds)."""
    print(f"stickslip: rendering page {number} of {count} ({name})", file=sys.stderr, flush=True)


def run_pairs(args, start: float, stop: float, step: float, mass: float, g: float, reference: float,
              range_points: int) -> int:
    """``report --pair``: one page per pair of components (the block in the plane beside each component alone), its
    design answer defined by ``--q``, the ``reference`` μ and ``range_points`` as a record's."""
    from stickslip.reports.pair_report import render_pair_report

    pairs = pairs_from_args(args)  # a bad file, a mismatched pair or an option stops here, before any notebook starts
    given = len(record_files(args.paths)) // 2
    _check_out(args.out, given, "pairs")
    sources = [_pair_files(pair) for pair in pairs]
    pages = _page_paths(args.out, [_pair_page_name(files) for files in sources], given)
    with _answers(args.out, pages) as answers:
        for number, ((first, second), page_path, answer) in enumerate(zip(sources, pages, answers), start=1):
            _rendering(number, len(pages), _pair_label((first, second)))
            page = render_pair_report({
                "first": str(first),
                "second": str(second),
                "pad": args.pad, "any_pair": args.any_pair, "format": args.format, "dt": args.dt,
                "units": args.units, "mu_start": start, "mu_stop": stop, "mu_step": step,
                "near_optimal_fraction": args.q, "reference_mu": reference, "range_points": range_points,
                "mu_case": args.mu_case, "mass": mass, "g": g, "answer_path": answer,
            })
            write_text_atomic(page_path, page)
            print(page_path)
        _write_index(args.out, pages, answers, "pairs")
    return 0
