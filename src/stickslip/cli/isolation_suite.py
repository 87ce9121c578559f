"""``stickslip isolation suite X1 Y1 X2 Y2 ... --pair``: a suite of station pairs scaled to a code's target, run exactly.

The target is the spectrum ``stickslip isolation design`` takes (the same
options: :func:`~stickslip.cli.isolation.add_spectrum_options`) of the code
``--code`` (ASCE 7-22 unless given), and the isolator its friction pendulum
(``--radius`` or ``--recentring-period``, ``--mu``, ``--lambda-max``,
``--lambda-min``).  The command

1. designs the pendulum by the code's ELF procedure at the three bounds
   (:func:`stickslip.codes.friction_pendulum.design`), which gives T_M at
   the upper and lower bounds and so the period range
   (:func:`stickslip.codes.suite_scaling.period_range`);
2. computes each pair's RotD100 (:mod:`stickslip.spectra`), scales the suite
   (``--scaling``, :func:`stickslip.codes.suite_scaling.scale_suite`) and
   checks its average against the target over the range;
3. solves every scaled pair (with its vertical, ``--vertical V1 V2 ...``, scaled
   by the same factor) in the plane at λ_max μ and λ_min μ
   (:mod:`stickslip.codes.response_history`);
4. prints the suite's statistic of the peak displacement and V_b/W beside the
   ELF values and the code's limits on their ratio: a text table, or one
   ``--json`` object; ``--page DIR`` writes ``DIR/index.html`` with the
   figure (``DIR/suite_spectra.png``) and ``DIR/suite.json``; ``--plot PNG``
   the figure alone.

Definitions and clauses: docs/isolation_design.md, "Suites".
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from stickslip.cli.isolation import (
    CODES,
    SPECTRUM_UNITS,
    add_isolator_options,
    add_spectrum_options,
    check_isolator_args,
    isolator_name,
    lambdas_from_args,
    procedure_from_args,
    radius_from_args,
    read_spectral_accelerations,
    spectra_inputs,
)
from stickslip.cli.pair_options import (
    add_pair_options,
    add_vertical_options,
    motion_config,
    motion_kind_from_args,
    pairs_from_args,
)
from stickslip.cli.quantities import read_gravity
from stickslip.cli.record_options import add_record_options
from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.plumbing.files import check_output_dir, check_output_path

#: The damping ratio of the target spectra and of the pairs' RotD100 [1].
TARGET_DAMPING = 0.05

#: The files ``--page DIR`` writes.
PAGE_FILES = {"page": "index.html", "figure": "suite_spectra.png", "document": "suite.json"}


def register_suite(actions) -> None:
    """Add ``isolation suite`` to the ``isolation`` command's ``actions``."""
    from stickslip.codes.suite_scaling import MINIMUM_PAIRS_FOR_MEAN, SCALINGS

    suite = actions.add_parser(
        "suite", help="a suite of station pairs scaled to a code's target spectrum and run exactly in the plane, "
                      "beside the ELF design",
        description="Scale a suite of station pairs (two horizontal components each, --pair, and their verticals) so "
                    "that the average of their RotD100 spectra is not below the code's target over 0.75 T_M (upper "
                    "bound) to 1.25 T_M (lower bound), solve each scaled pair exactly on the friction pendulum in the "
                    "plane at the upper- and lower-bound friction, and set the suite's statistic (the mean over "
                    f"{MINIMUM_PAIRS_FOR_MEAN} pairs or more, else the maximum) of the peak displacement and V_b/W "
                    "beside the ELF values. Definitions and clauses: docs/isolation_design.md, \"Suites\".")
    suite.add_argument("paths", type=Path, nargs="+", metavar="RECORD",
                       help="the pairs' record files, two by two (X1 Y1 X2 Y2 ...), with --pair")
    add_record_options(suite)
    add_pair_options(suite, "(required: a suite is of pairs)")
    add_vertical_options(suite, several=True)
    add_isolator_options(suite)
    add_spectrum_options(suite)
    rule = suite.add_argument_group("the suite")
    rule.add_argument("--code", choices=CODES, default=CODES[0],
                      help="whose target spectrum and ELF design the suite is set against (default asce7_22); the "
                           "scaling rule, period range and limits are ASCE 7-22's for every code")
    rule.add_argument("--scaling", choices=SCALINGS, default=SCALINGS[0],
                      help="pairs: each pair fitted to the target's shape over the range, then one suite factor so "
                           "that the average touches the target (default); common: one factor for all, the smallest "
                           "that keeps the average at or above the target; period: each pair to the target at T_M "
                           "(nominal friction), the average then checked")
    suite.add_argument("--g", type=read_gravity, default=STANDARD_GRAVITY,
                       help=f"gravity [m/s2] of the design and the runs, and that converts records in g (default "
                            f"{STANDARD_GRAVITY}; or with its unit, 981cm/s2)")
    suite.add_argument("--json", action="store_true",
                       help="print one JSON object: the inputs, the target and period range, each pair's "
                            "scale_factor and responses, the spectrum check, per bound the statistic beside the ELF "
                            "values, the spectra, and the 'units'")
    suite.add_argument("--page", type=Path, default=None, metavar="DIR",
                       help=f"write DIR/{PAGE_FILES['page']} (the table and the figure), DIR/{PAGE_FILES['figure']} "
                            f"and DIR/{PAGE_FILES['document']} (the --json object)")
    suite.add_argument("--plot", type=Path, default=None, metavar="PNG",
                       help="draw each pair's scaled RotD100, their average and the target, the range shaded, to PNG")
    suite.set_defaults(func=run_suite)


def suite_motions(args) -> list:
    """The pairs of ``args.paths`` (``--pair``), each with its vertical of ``--vertical`` where given; one-line errors.

    A vertical whose component label says which way its positive axis points (UP, DWN) is read so;
    ``--vertical-positive`` gives the sense of the others (a suite mixes files labelled UP, DWN and V).
    """
    from stickslip.cli.record_options import read_record_from_args
    from stickslip.records.vertical import WithVertical, vertical_sense

    if not args.pair:
        raise StickslipError("isolation suite takes station pairs: give the files two by two with --pair")
    motion_kind_from_args(args)
    pairs = pairs_from_args(args)
    if args.vertical is None:
        return pairs
    if len(args.vertical) != len(pairs):
        raise StickslipError(f"--vertical: {len(args.vertical)} file(s) for {len(pairs)} pair(s): give one vertical per "
                             "pair, in the pairs' order")
    motions = []
    for pair, path in zip(pairs, args.vertical):
        vertical = read_record_from_args(path, args)
        positive = args.vertical_positive if vertical_sense(vertical) is None else None
        motions.append(WithVertical.of(pair, vertical, positive, pad=args.pad, any_vertical=args.any_vertical))
    return motions


def target_periods(spectrum, periods: np.ndarray) -> np.ndarray:
    """``periods`` [s] where ``spectrum`` is defined (a multi-period table's range; every period for the others)."""
    table = getattr(spectrum, "periods", None)
    if table is None:
        return periods
    return periods[(periods >= table[0]) & (periods <= table[-1])]


def pair_label(pair) -> str:
    """How the tables name a pair: ``Dayhook (L + T)``, its station (where the files name it) and components."""
    station = pair.first.meta.station
    return f"{station} ({pair.name})" if station else pair.name


def suite_document(args) -> dict:
    """Everything the command reports, JSON-ready (module docstring; units in its ``units``)."""
    from dataclasses import asdict

    from stickslip.codes.friction_pendulum import UNITS as ELF_UNITS
    from stickslip.codes.friction_pendulum import design
    from stickslip.codes.response_history import RUN_BOUNDS, compared_with_elf, peak_responses
    from stickslip.codes.response_history import UNITS as RESPONSE_UNITS
    from stickslip.codes.suite_scaling import (
        MINIMUM_PAIRS_FOR_MEAN,
        RANGE_FACTORS,
        period_range,
        scale_suite,
        suite_periods,
        suite_statistic,
    )
    from stickslip.records.vertical import WithVertical
    from stickslip.spectra import DEFAULT_PERIODS, pair_spectra

    read_spectral_accelerations(args)
    check_isolator_args(args)
    procedure, source = procedure_from_args(args, args.code)
    radius = radius_from_args(args)
    designs = design(procedure, radius, args.mu, args.g, **lambdas_from_args(args))
    periods_m = {bound: designs[bound].effective_period for bound in designs}
    span = period_range(periods_m["upper_bound"], periods_m["lower_bound"])
    motions = suite_motions(args)
    periods = target_periods(procedure.spectrum, suite_periods(DEFAULT_PERIODS, span, periods_m["nominal"]))
    target = procedure.spectrum(periods, TARGET_DAMPING)
    pairs = [motion.horizontal if isinstance(motion, WithVertical) else motion for motion in motions]
    rotd100 = np.array([pair_spectra(*pair.horizontal(), pair.dt, periods, TARGET_DAMPING).pseudo_acceleration("rotd100")
                        for pair in pairs]) / args.g
    scaling = scale_suite(periods, rotd100, target, span, args.scaling, periods_m["nominal"])
    statistic = suite_statistic(len(motions))
    frictions = {bound: designs[bound].friction for bound in RUN_BOUNDS}
    peaks = peak_responses(motions, scaling.factors, radius, frictions, args.g, progress=True)
    comparisons = compared_with_elf(peaks, statistic, designs)
    scaled = scaling.factors[:, None] * rotd100
    return {
        "code": procedure.key, "code_title": procedure.title, "target": procedure.spectrum.name,
        "target_source": source, "isolator": isolator_name(args), "radius": radius,
        "recentring_period": args.recentring_period, "mu": args.mu, **lambdas_from_args(args), "g": args.g,
        "spectra_given": spectra_inputs(args), "read": motion_config(args),
        "friction": {bound: designs[bound].friction for bound in designs},
        "design_period": periods_m, "period_range": list(span), "range_factors": list(RANGE_FACTORS),
        "scaling": scaling.method,
        "suite_size": len(motions), "minimum_pairs_for_mean": MINIMUM_PAIRS_FOR_MEAN, "statistic": statistic,
        "spectrum_check": {"passed": scaling.passed, "smallest_ratio": scaling.smallest_ratio,
                           "at_period": scaling.at_period, "clause": "ASCE 7-22 §17.3.3 as coded",
                           "what": "average of the scaled pairs' RotD100 / target, over the period range, >= 1"},
        "pairs": [{"name": pair_label(pair), "event": pair.first.meta.event, "station": pair.first.meta.station,
                   "records": [pair.first.meta.record_id, pair.second.meta.record_id],
                   "vertical": motion.vertical.meta.record_id if isinstance(motion, WithVertical) else None,
                   "vertical_sense": motion.sense if isinstance(motion, WithVertical) else None,
                   "scale_factor": float(factor),
                   **{name: {bound: float(peaks[bound][name][index]) for bound in RUN_BOUNDS}
                      for name in RESPONSE_UNITS}}
                  for index, (motion, pair, factor) in enumerate(zip(motions, pairs, scaling.factors))],
        "response": {bound: {name: asdict(comparison) for name, comparison in comparisons[bound].items()}
                     for bound in RUN_BOUNDS},
        "elf": {bound: asdict(designs[bound]) for bound in designs},
        "spectra": {"periods": periods.tolist(), "target": target.tolist(), "average": scaled.mean(axis=0).tolist(),
                    "scaled_rotd100": scaled.tolist()},
        "units": {"radius": "m", "recentring_period": "s", "mu": "1", "lambda_max": "1", "lambda_min": "1",
                  "g": "m s-2", "spectra_given": SPECTRUM_UNITS, "friction": "1", "design_period": "s",
                  "period_range": "s",
                  "range_factors": "1", "scale_factor": "1", "spectrum_check": {"smallest_ratio": "1", "at_period": "s"},
                  **RESPONSE_UNITS, "response": {**RESPONSE_UNITS, "ratio": "1", "floor": "1"},
                  "elf": ELF_UNITS, "spectra": {"periods": "s", "target": "g", "average": "g", "scaled_rotd100": "g"}},
    }


def run_suite(args) -> int:
    from stickslip.reports.plots import save_figure
    from stickslip.reports.suite_page import plot_suite_spectra, suite_text, write_suite_page

    if args.page is not None:
        check_output_dir(args.page, "the suite's page")
    if args.plot is not None:
        check_output_path(args.plot, "the suite's figure")
    document = suite_document(args)
    if args.plot is not None:
        save_figure(plot_suite_spectra(document), args.plot)
    if args.page is not None:
        write_suite_page(document, args.page, PAGE_FILES)
    print(json.dumps(document, allow_nan=False) if args.json else suite_text(document))
    return 0
