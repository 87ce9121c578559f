"""``stickslip isolation design``: the equivalent-lateral-force design of a friction pendulum by three codes.

ASCE 7-22 Chapter 17, AASHTO's Guide Specifications for Seismic Isolation
Design and EN 1998-2, side by side, each at nominal, upper- and lower-bound
friction (:mod:`stickslip.codes.friction_pendulum`).  A flat slider with a
linear re-centring device of stiffness k_r (``--recentring-period``) has the
pendulum's force W D/R + μW with R = W/k_r, and is designed as that pendulum.  The spectrum is given
by ASCE's MCE_R parameters (``--sms``, ``--sm1``, ``--tl``, or a multi-period
table ``--asce-table``); AASHTO's (``--as``, ``--sds``, ``--sd1``) and EN's
(``--ag``, ``--ground``, ``--spectrum-type``) are their own options, and
where they are not given they are derived from ASCE's so that the three
codes work on one spectrum: A_s = 0.4 S_MS, S_DS = S_MS, S_D1 = S_M1; EN's
a_g S = S_MS/2.5 (S = 1), T_C = S_M1/S_MS, T_B = T_C/5, T_D = T_L
(docs/isolation_design.md).  A text table by default, or ``--json``.
"""

from __future__ import annotations

import json
import math
from dataclasses import asdict, replace
from pathlib import Path

from stickslip.cli.quantities import of_unit, quantity_type, read_gravity
from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import StickslipError

#: The codes, in output order.
CODES = ("asce7_22", "aashto", "en1998_2")

#: The isolator's radius R [m] (``2``, ``200cm``): a bare number outside the range of friction pendulums' surfaces
#: gets a warning naming its other readings, as ``solve --radius`` does.
RADIUS = of_unit("m", (0.2, 20.0, "the surfaces of friction pendulums (T = 0.9 to 9 s)"))
#: The nominal friction coefficient mu [1] (``0.06``, ``6%``); a bare number above 0.5 is likely a percentage.
FRICTION = of_unit("1", (0.005, 0.5, "the sliding surfaces of isolators"))
#: A length [m] (``12``, ``1200cm``), a period [s] (``8``, ``8000ms``), a ratio [1] (``1.8``, ``180%``).
LENGTH, PERIOD, RATIO = of_unit("m"), of_unit("s"), of_unit("1")
#: The options of a spectral or ground acceleration, in units of g; read after parsing, with ``--g``
#: (:func:`read_spectral_accelerations`): the attribute -> the option.
ACCELERATION_OPTIONS = {"sms": "--sms", "sm1": "--sm1", "a_s": "--as", "sds": "--sds", "sd1": "--sd1", "ag": "--ag"}


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "isolation", help="design of sliding isolators by the codes (ASCE 7-22, AASHTO, EN 1998-2)",
        description="Seismic isolation by friction pendulums: the codes' procedures. Definitions and clauses: "
                    "docs/isolation_design.md.")
    actions = parser.add_subparsers(dest="isolation_command", required=True, metavar="ACTION")
    design = actions.add_parser(
        "design", help="equivalent-lateral-force design of a friction pendulum by ASCE 7-22, AASHTO and EN 1998-2",
        description="The fixed point in D of each code's equivalent lateral force procedure for a friction pendulum "
                    "of radius R and friction mu, at nominal, upper-bound (lambda_max mu) and lower-bound "
                    "(lambda_min mu) friction: D, T_eff, beta_eff, the damping factor, the base shear coefficient, "
                    "ASCE's superstructure shear, the total displacement with torsion and the restoring-force checks.")
    add_isolator_options(design)
    add_spectrum_options(design)
    structure = design.add_argument_group("the structure (ASCE's superstructure shear, torsion)")
    structure.add_argument("--weight-ratio", type=float, default=1.0,
                           help="W_s/W, the seismic weight above the base level over the whole (default 1)")
    structure.add_argument("--ri", type=float, default=1.0,
                           help="R_I, ASCE's response modification of the superstructure, 1 <= R_I <= 2 (default 1)")
    structure.add_argument("--plan", type=quantity_type(LENGTH, "--plan"), nargs=2, default=None, metavar=("B", "D"),
                           help="plan dimensions b and d [m]: gives the total displacement with torsion")
    structure.add_argument("--offset", type=quantity_type(LENGTH, "--offset"), default=None,
                           help="with --plan: distance y [m] of the bearing from the centre of rigidity, perpendicular "
                                "to the direction considered (default: the plan's corner, half the longer dimension)")
    structure.add_argument("--eccentricity", type=quantity_type(LENGTH, "--eccentricity"), default=0.0,
                           help="with --plan: actual eccentricity e [m] (5 %% of the longer dimension is added)")
    structure.add_argument("--period-ratio", type=float, default=1.0,
                           help="with --plan: ASCE's P_T, translational over torsional period (default 1)")
    design.add_argument("--g", type=read_gravity, default=STANDARD_GRAVITY,
                        help=f"gravity [m/s2] (9.81, 9.81m/s2 or 981cm/s2; default {STANDARD_GRAVITY})")
    design.add_argument("--json", action="store_true",
                        help="print one JSON object: the inputs, then per code (asce7_22, aashto, en1998_2) its "
                             "spectrum and its nominal, upper_bound and lower_bound designs, and the 'units'")
    design.set_defaults(func=run_design)
    from stickslip.cli.isolation_suite import register_suite

    register_suite(actions)


def add_isolator_options(parser) -> None:
    """Add the isolator's options: ``--radius`` or ``--recentring-period``, ``--mu``, ``--lambda-max``, ``--lambda-min``."""
    isolator = parser.add_argument_group("the isolator: a friction pendulum (--radius) or a flat slider with a "
                                         "re-centring device (--recentring-period)")
    shape = isolator.add_mutually_exclusive_group(required=True)
    shape.add_argument("--radius", type=quantity_type(RADIUS, "--radius"),
                       help="radius of curvature R [m] of the friction pendulum (2, or 200cm)")
    shape.add_argument("--recentring-period", type=quantity_type(PERIOD, "--recentring-period"), metavar="T_R",
                       help="a flat slider with a linear re-centring device instead: the period [s] of the device's "
                            "stiffness k_r alone, T_R = 2 pi sqrt(W/(k_r g)); it acts as a pendulum of radius "
                            "R = g T_R^2/(4 pi^2)")
    isolator.add_argument("--mu", type=quantity_type(FRICTION, "--mu"), required=True,
                          help="nominal friction coefficient mu [1] (0.06, or 6%%)")
    isolator.add_argument("--lambda-max", type=quantity_type(RATIO, "--lambda-max"), default=None,
                          help="property modification factor of the upper bound, mu_upper = lambda_max mu (default 1.8)")
    isolator.add_argument("--lambda-min", type=quantity_type(RATIO, "--lambda-min"), default=None,
                          help="property modification factor of the lower bound, mu_lower = lambda_min mu (default 0.6)")


def add_spectrum_options(parser) -> None:
    """Add the codes' spectra: ASCE's (``--sms``, ``--sm1``, ``--tl`` or ``--asce-table``), AASHTO's (``--as``,
    ``--sds``, ``--sd1``) and EN's (``--ag``, ``--ground``, ``--spectrum-type``, ``--soil-factor``, ``--tb``, ``--tc``,
    ``--td``); :func:`procedures_from_args` reads them (:func:`procedure_from_args` one code's)."""
    asce = parser.add_argument_group("ASCE 7-22 MCE_R spectrum (5 %)")
    asce.add_argument("--sms", default=None, help="S_MS [g], the short-period MCE_R spectral acceleration (1.5, 1.5g "
                      "or 14.7m/s2)")
    asce.add_argument("--sm1", default=None, help="S_M1 [g], the MCE_R spectral acceleration at 1 s")
    asce.add_argument("--tl", type=quantity_type(PERIOD, "--tl"), default=None,
                      help="T_L [s], the long-period transition period")
    asce.add_argument("--asce-table", type=Path, default=None, metavar="CSV",
                      help="a multi-period MCE_R spectrum instead: a CSV file of period [s] and S_a [g] per line "
                           "(ASCE 7-22 §11.4.5.1); --sms and --sm1 still derive the other codes' spectra where those "
                           "are not given")
    aashto = parser.add_argument_group("AASHTO spectrum (5 %; default: derived from ASCE's)")
    aashto.add_argument("--as", dest="a_s", default=None, help="A_s [g], the peak ground acceleration "
                        "coefficient times its site factor")
    aashto.add_argument("--sds", default=None, help="S_DS [g], the short-period spectral acceleration")
    aashto.add_argument("--sd1", default=None, help="S_D1 [g], the spectral acceleration at 1 s")
    euro = parser.add_argument_group("EN 1998-1 spectrum (default: derived from ASCE's)")
    euro.add_argument("--ag", default=None, help="a_g [g], the design ground acceleration on ground type A")
    euro.add_argument("--ground", default=None, help="ground type A, B, C, D or E (with --ag; default A)")
    euro.add_argument("--spectrum-type", type=int, default=1, choices=(1, 2), help="EN spectrum type (default 1)")
    for option, what, quantity in (("--soil-factor", "the soil factor S [1]", RATIO),
                                   ("--tb", "the corner period T_B [s]", PERIOD),
                                   ("--tc", "the corner period T_C [s]", PERIOD),
                                   ("--td", "the corner period T_D [s]", PERIOD)):
        euro.add_argument(option, type=quantity_type(quantity, option), default=None,
                          help=f"with --ag: {what} instead of the ground type's (EN 1998-1 Tables 3.2, 3.3; ground "
                               "types S1, S2 and national annexes)")


def read_spectral_accelerations(args) -> None:
    """Turn the spectra's accelerations (:data:`ACCELERATION_OPTIONS`) into numbers in units of g, in place: a bare
    number is in g (``1.5``), as is ``1.5g``; ``14.7m/s2`` or ``1471cm/s2`` is divided by ``args.g`` [m/s²].  A bare
    number above 4 g gets a warning naming its readings in the record units; one error line for anything else."""
    from stickslip.cli.accelerations import in_units_of_g

    for name, option in ACCELERATION_OPTIONS.items():
        text = getattr(args, name)
        if isinstance(text, str):
            setattr(args, name, in_units_of_g(text, args.g, option, "1.5", largest=4.0))


def _positive(value: float | None, option: str) -> float | None:
    if value is not None and not (math.isfinite(value) and value > 0.0):
        raise StickslipError(f"{option} {value:g}: expected a positive number")
    return value


def procedures_from_args(args) -> tuple[list, dict]:
    """The three codes' procedures on their spectra, and how each spectrum was obtained (given or derived)."""
    found = [procedure_from_args(args, code) for code in CODES]
    return [procedure for procedure, _ in found], {procedure.key: source for procedure, source in found}


def procedure_from_args(args, code: str) -> tuple:
    """The procedure of ``code`` (one of :data:`CODES`) on its spectrum, and how that spectrum was obtained."""
    return {"asce7_22": _asce_procedure, "aashto": _aashto_procedure, "en1998_2": _eurocode_procedure}[code](args)


def _asce_values(args) -> tuple:
    """S_MS, S_M1 [g] and T_L [s] of ``--sms``, ``--sm1``, ``--tl`` (None where not given), each checked."""
    return _positive(args.sms, "--sms"), _positive(args.sm1, "--sm1"), _positive(args.tl, "--tl")


def _asce_procedure(args) -> tuple:
    from stickslip.codes.friction_pendulum import asce7_22
    from stickslip.codes.target_spectra import AsceTwoPeriod, MultiPeriodTable

    sms, sm1, tl = _asce_values(args)
    if args.asce_table is not None:
        return asce7_22(MultiPeriodTable.from_csv(args.asce_table)), "given"
    if None in (sms, sm1, tl):
        raise StickslipError("the ASCE 7-22 spectrum needs --sms, --sm1 and --tl (or a multi-period table, --asce-table)")
    return asce7_22(AsceTwoPeriod(sms, sm1, tl)), "given"


def _aashto_procedure(args) -> tuple:
    from stickslip.codes.friction_pendulum import aashto
    from stickslip.codes.target_spectra import AashtoThreePoint

    given = [value is not None for value in (args.a_s, args.sds, args.sd1)]
    if any(given) and not all(given):
        raise StickslipError("AASHTO's spectrum needs all three of --as, --sds and --sd1 (or none: derived from ASCE's)")
    if all(given):
        return aashto(AashtoThreePoint(_positive(args.a_s, "--as"), _positive(args.sds, "--sds"),
                                       _positive(args.sd1, "--sd1"))), "given"
    sms, sm1, _ = _asce_values(args)
    _need_asce_values(sms, sm1, "AASHTO's spectrum (--as, --sds, --sd1)")
    return aashto(AashtoThreePoint(0.4 * sms, sms, sm1)), "derived from ASCE's S_MS and S_M1"


def _eurocode_procedure(args) -> tuple:
    from stickslip.codes.friction_pendulum import en1998_2
    from stickslip.codes.target_spectra import Eurocode8

    own = {"soil_factor": args.soil_factor, "tb": args.tb, "tc": args.tc, "td": args.td}
    if args.ag is not None:
        spectrum = Eurocode8.of_ground(_positive(args.ag, "--ag"), args.ground or "A", args.spectrum_type)
        given = {name: _positive(value, f"--{name.replace('_', '-')}") for name, value in own.items() if value is not None}
        if given:
            spectrum = replace(spectrum, **given, label=f"{spectrum.label}, with the user's "
                               + ", ".join(f"{name} {value:g}" for name, value in given.items()))
        return en1998_2(spectrum), "given"
    for option, value in (("--ground", args.ground), *((f"--{name.replace('_', '-')}", value)
                                                       for name, value in own.items())):
        if value is not None:
            raise StickslipError(f"{option} applies with --ag (EN's design ground acceleration)")
    sms, sm1, tl = _asce_values(args)
    _need_asce_values(sms, sm1, "EN's spectrum (--ag)")
    if tl is None:
        raise StickslipError("EN's spectrum derived from ASCE's needs --tl (T_D = T_L), or give --ag")
    corner = sm1 / sms
    if tl <= corner:
        raise StickslipError(f"--tl {tl:g}: EN's T_D = T_L must exceed T_C = S_M1/S_MS = {corner:.3g} s; give --ag")
    spectrum = Eurocode8(sms / 2.5, 1.0, corner / 5.0, corner, tl,
                         label="a_g S = S_MS/2.5, T_C = S_M1/S_MS, T_B = T_C/5, T_D = T_L")
    return en1998_2(spectrum), "derived from ASCE's S_MS, S_M1 and T_L"


def _need_asce_values(sms, sm1, what: str) -> None:
    if sms is None or sm1 is None:
        raise StickslipError(f"{what}: give it, or --sms and --sm1 to derive it from ASCE's")


def plan_from_args(args):
    """The :class:`~stickslip.codes.friction_pendulum.Plan` of ``--plan`` (None without it); ``--offset``,
    ``--eccentricity`` and ``--period-ratio`` apply with it only."""
    from stickslip.codes.friction_pendulum import Plan

    if args.plan is None:
        for option, value, default in (("--offset", args.offset, None), ("--eccentricity", args.eccentricity, 0.0),
                                       ("--period-ratio", args.period_ratio, 1.0)):
            if value != default:
                raise StickslipError(f"{option} applies with --plan B D (the plan dimensions)")
        return None
    width, depth = args.plan
    offset = 0.5 * max(width, depth) if args.offset is None else args.offset
    return Plan(width, depth, offset, args.eccentricity, args.period_ratio)


def radius_from_args(args) -> float:
    """R [m]: ``--radius``, or the radius of the pendulum whose period is ``--recentring-period``, g T_R²/(4π²)."""
    if args.recentring_period is None:
        return args.radius
    return args.g * args.recentring_period**2 / (4.0 * math.pi**2)


def isolator_name(args) -> str:
    """How the output names the isolator."""
    return "friction pendulum" if args.recentring_period is None else "flat slider with a re-centring device"


def designs_from_args(args) -> tuple[dict, dict, list]:
    """Each code's designs by bound, how each spectrum was obtained, and the procedures."""
    from stickslip.codes.friction_pendulum import design

    if not (math.isfinite(args.weight_ratio) and 0.0 < args.weight_ratio <= 1.0):
        raise StickslipError(f"--weight-ratio {args.weight_ratio:g}: expected W_s/W in (0, 1]")
    if not (math.isfinite(args.ri) and 1.0 <= args.ri <= 2.0):
        raise StickslipError(f"--ri {args.ri:g}: expected ASCE's R_I in [1, 2] (3/8 of R, at most 2)")
    _positive(args.g, "--g")
    procedures, sources = procedures_from_args(args)
    plan = plan_from_args(args)
    designs = {procedure.key: design(procedure, radius_from_args(args), args.mu, args.g, **lambdas_from_args(args),
                                     plan=plan, weight_ratio=args.weight_ratio, response_modification=args.ri)
               for procedure in procedures}
    return designs, sources, procedures


def json_document(args, designs: dict, sources: dict, procedures: list) -> dict:
    """The ``--json`` object: the inputs, and per code its spectrum, damping factor and designs by bound."""
    from stickslip.codes.friction_pendulum import UNITS

    document = {"isolator": isolator_name(args), "radius": radius_from_args(args),
                "recentring_period": args.recentring_period, "mu": args.mu, **lambdas_from_args(args), "g": args.g,
                "weight_ratio": args.weight_ratio, "ri": args.ri,
                "plan": None if args.plan is None else list(args.plan), **torsion_inputs(args),
                "spectra_given": spectra_inputs(args)}
    for procedure in procedures:
        document[procedure.key] = {"spectrum": procedure.spectrum.name, "spectrum_source": sources[procedure.key],
                                   "damping_factor_name": procedure.damping_factor_name,
                                   **{bound: asdict(answer) for bound, answer in designs[procedure.key].items()}}
    document["units"] = {"radius": "m", "recentring_period": "s", "mu": "1", "lambda_max": "1", "lambda_min": "1",
                         "g": "m s-2", "weight_ratio": "1", "ri": "1", "plan": "m", **TORSION_UNITS,
                         **SPECTRUM_UNITS, **UNITS}
    return document


#: The units of the spectra's inputs as the options give them (accelerations in g, periods in s).
SPECTRUM_UNITS = {"sms": "g", "sm1": "g", "tl": "s", "a_s": "g", "sds": "g", "sd1": "g", "ag": "g", "soil_factor": "1",
                  "tb": "s", "tc": "s", "td": "s"}
#: The units of the torsion's inputs.
TORSION_UNITS = {"offset": "m", "eccentricity": "m", "period_ratio": "1"}


def spectra_inputs(args) -> dict:
    """The spectra's options as given (null where not: derived, or the default), JSON-ready: S_MS, S_M1 [g], T_L
    [s], ASCE's table file, AASHTO's A_s, S_DS, S_D1 [g], EN's a_g [g], ground type, spectrum type, soil factor and
    corner periods [s]."""
    table = None if args.asce_table is None else str(args.asce_table)
    return {**{name: getattr(args, name) for name in SPECTRUM_UNITS}, "asce_table": table, "ground": args.ground,
            "spectrum_type": args.spectrum_type}


def torsion_inputs(args) -> dict:
    """The torsion's options with ``--plan`` (null without it): the bearing's offset y [m] (null: the plan's
    corner), the actual eccentricity e [m] and ASCE's period ratio P_T."""
    given = args.plan is not None
    return {name: getattr(args, name) if given else None for name in TORSION_UNITS}


#: The rows of the text table: label, field, format.
ROWS = (("mu", "friction", ".4g"), ("lambda", "property_factor", ".3g"), ("D [m]", "design_displacement", ".4f"),
        ("T_eff [s]", "effective_period", ".3f"), ("beta_eff", "effective_damping", ".4f"),
        ("damping factor", "damping_factor", ".3f"), ("V_b/W", "base_shear_coefficient", ".4f"),
        ("V_s/W", "superstructure_shear_coefficient", ".4f"), ("V_s exponent", "superstructure_shear_exponent", ".4f"),
        ("D_total [m]", "total_displacement", ".4f"), ("iterations", "iterations", "d"))


def format_code(procedure, designs: dict, source: str) -> str:
    """One code's block: its spectrum, then a row per quantity with a column per bound, then its checks."""
    bounds = list(designs)
    lines = [f"{procedure.title}: {procedure.spectrum.name} ({source}); damping factor {procedure.damping_factor_name}",
             f"{'':<22}" + "".join(f"{bound:>14}" for bound in bounds)]
    for label, name, form in ROWS:
        values = [getattr(designs[bound], name) for bound in bounds]
        if all(value is None for value in values):
            continue
        lines.append(f"{label:<22}" + "".join(f"{'-' if v is None else format(v, form):>14}" for v in values))
    for check, first in designs[bounds[0]].checks.items():
        marks = "".join(f"{'pass' if designs[b].checks[check]['passed'] else 'FAIL'} {designs[b].checks[check]['value']:.3g}"
                        .rjust(14) for b in bounds)
        lines.append(f"{check:<22}{marks}   {first['what']} ({first['clause']})")
    return "\n".join(lines)


def check_isolator_args(args) -> None:
    """Refuse, in one line, an isolator option of :func:`add_isolator_options` that is not a positive number."""
    for option, value in (("--radius", args.radius), ("--recentring-period", args.recentring_period),
                          ("--mu", args.mu), ("--lambda-max", args.lambda_max),
                          ("--lambda-min", args.lambda_min)):
        _positive(value, option)


def lambdas_from_args(args) -> dict[str, float]:
    """``lambda_max`` and ``lambda_min`` [1] of ``--lambda-max`` and ``--lambda-min``, or our defaults."""
    from stickslip.codes.friction_pendulum import DEFAULT_LAMBDA_MAX, DEFAULT_LAMBDA_MIN

    return {"lambda_max": DEFAULT_LAMBDA_MAX if args.lambda_max is None else args.lambda_max,
            "lambda_min": DEFAULT_LAMBDA_MIN if args.lambda_min is None else args.lambda_min}


def run_design(args) -> int:
    read_spectral_accelerations(args)
    check_isolator_args(args)
    designs, sources, procedures = designs_from_args(args)
    if args.json:
        print(json.dumps(json_document(args, designs, sources, procedures), allow_nan=False))
        return 0
    shape = (f"R = {args.radius:g} m" if args.recentring_period is None else
             f"T_R = {args.recentring_period:g} s, as a pendulum of R = {radius_from_args(args):.4g} m")
    print(f"{isolator_name(args)} {shape}, mu = {args.mu:g}, g = {args.g:g} m/s2")
    for procedure in procedures:
        print("\n" + format_code(procedure, designs[procedure.key], sources[procedure.key]))
    return 0
