"""``stickslip estimate [RECORD...] --ky K[,K...]``: every simplified Newmark estimate that applies, beside the rigorous answer.

From each record the command measures PGA, PGV, Arias intensity, the mean
period T_m and, with ``--ts``, the 5 %-damped Sa(1.5 T_s)
(:func:`stickslip.estimates.measures.estimate_inputs`), then prints every
method of :data:`stickslip.estimates.registry.METHODS` whose inputs are
there, side by side with the rigorous rigid-block D_n of both polarities
(:func:`stickslip.solve`, exact) and, with a soil layer, the coupled D
(:func:`stickslip.solve` of the coupled model).  Without a record it takes the measures
given (``--pga 0.3g --pgv 40cm/s --arias 1.2 --tm 0.4 --sa 0.5g``), each
with its unit or, where the option allows, a bare number in the papers' unit;
a bare number outside its usual range gets a warning naming its likely units
(:mod:`stickslip.cli.quantities`).  ``--ky`` takes a list (one table per
k_y), or ``--fs`` and ``--slope-angle`` give the infinite slope's
(:mod:`stickslip.cli.slope_options`).  The table shows displacements in cm;
``--json`` gives them in m, one row per record and k_y, per method
``median_displacement`` [m], ``sigma``, ``log_base`` and ``p_zero``.  One g
per call: ``--g`` converts records stored in g as well as k_y·g and the
measures in g, and both outputs state it.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

from stickslip.cli.accelerations import in_units_of_g
from stickslip.cli.quantities import DAMPING_RATIO, Quantity, read_gravity, read_quantity
from stickslip.cli.record_options import add_record_options, read_records_from_args, read_settings
from stickslip.cli.slope_options import INFINITE_SLOPE, add_slope_options, yield_coefficients
from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.records.plausibility import PLAUSIBLE_PGA, PLAUSIBLE_PGA_UNSTATED
from stickslip.records.readers import POSSIBLE_PGA

#: The options that give a measure instead of a record, and the input each sets.
MEASURE_OPTIONS = {"--pga": "pga", "--pgv": "pgv", "--arias": "arias_intensity", "--tm": "mean_period",
                   "--sa": "spectral_acceleration", "--sa13": "spectral_acceleration_13"}

#: Each input as the command line spells it (the missing inputs of a method are named so).
INPUT_OPTIONS = {"ky": "--ky", "magnitude": "--mw", "site_period": "--ts", **{name: option for option, name in
                                                                              MEASURE_OPTIONS.items()}}

#: The layer's options (a coupled analysis), and the attribute each sets.
LAYER_OPTIONS = {"--height": "height", "--vs": "vs", "--vs-base": "vs_base", "--damping": "damping"}

#: Centimetres per metre: the table shows cm.
CM_PER_M = 100.0

#: How each option that is not an acceleration reads its number (:mod:`stickslip.cli.quantities`).  A bare PGV is
#: refused: 40 (cm/s) and 0.4 (m/s) are both usual.  The Arias intensities of the SLAMMER library's 2,133 records
#: reach 22.8 m/s: a bare one above 30 m/s is likely in cm/s (a small one is a weak motion, not a doubt).
QUANTITIES = {
    "--pgv": Quantity("cm/s", {"cm/s": 1.0, "m/s": CM_PER_M}, "40cm/s or 0.4m/s"),
    "--arias": Quantity("m/s", {None: 1.0, "m/s": 1.0, "cm/s": 1.0 / CM_PER_M}, "1.2 or 1.2m/s",
                        usual=(0.0, 30.0)),
    "--tm": Quantity("s", {None: 1.0, "s": 1.0}, "0.4 or 0.4s"),
    "--ts": Quantity("s", {None: 1.0, "s": 1.0}, "0.3 or 0.3s"),
    "--height": Quantity("m", {None: 1.0, "m": 1.0}, "20 or 20m"),
    "--vs": Quantity("m/s", {None: 1.0, "m/s": 1.0}, "300 or 300m/s"),
    "--vs-base": Quantity("m/s", {None: 1.0, "m/s": 1.0}, "760 or 760m/s"),
    "--damping": DAMPING_RATIO,
    "--exceed": Quantity("m", {None: 1.0 / CM_PER_M, "cm": 1.0 / CM_PER_M, "m": 1.0}, "5cm or 0.05m"),
}

#: A bare PGA is in g; above 2 g (nearly no recorded motion, and 0.2 to 0.4 g written in m/s2) it gets a warning;
#: a bare Sa above 4 g does.
LARGEST_BARE = {"--pga": PLAUSIBLE_PGA_UNSTATED[1], "--sa": PLAUSIBLE_PGA[1], "--sa13": PLAUSIBLE_PGA[1]}


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "estimate",
        help="the simplified (empirical) Newmark estimates beside the rigorous rigid and coupled displacements",
        description=(
            "Print every simplified estimate of the permanent displacement that SLAMMER 1.1 offers and that the "
            "inputs allow (Jibson 1993, 2000, 2007; Ambraseys & Menu 1988; Saygili & Rathje 2008; Rathje & Saygili "
            "2009; Bray & Travasarou 2007; Rathje & Antonakos 2011), and those of current practice (Bray & Macedo "
            "2019 for shallow crustal earthquakes, Bray, Macedo & Travasarou 2018 for subduction-zone earthquakes): "
            "median, sigma with its log base, P(D = 0) where the method has one, at each k_y (or, with --fs and "
            f"--slope-angle, at {INFINITE_SLOPE}). From record files it measures PGA, PGV, Arias intensity, T_m, "
            "Sa(1.5 T_s) and Sa(1.3 T_s), and solves the rigid block exactly in both polarities (and, with a layer, the coupled analysis); without a "
            "record it takes the measures given. Differences from SLAMMER: docs/estimates.md."
        ),
    )
    parser.add_argument("paths", type=Path, nargs="*", metavar="path", help="record files (formats may mix)")
    add_slope_options(parser, "yield coefficients k_y [-]: one, a comma list (0.05,0.1,0.15: one table each) or "
                              "START:STOP:STEP, each a number in g (0.1), a percentage of g (10%%) or a yield "
                              "acceleration with its unit (0.98m/s2)")
    parser.add_argument("--mw", type=float, default=None, metavar="M", help="moment magnitude of the earthquake")
    parser.add_argument("--ts", default=None, metavar="T",
                        help="fundamental period T_s of the sliding mass [s] (0 for a rigid one): 0.3 or 0.3s; Bray & "
                             "Travasarou, Bray & Macedo, Bray et al., Rathje & Antonakos; with --vs and --vs-base, the "
                             "layer of height V_s*T_s/4")
    given = parser.add_argument_group("measures instead of a record (with their unit, or a bare number in the unit "
                                      "shown; a bare number outside the usual gets a warning)")
    given.add_argument("--pga", metavar="A", help="peak ground acceleration: 0.3 or 0.3g, or 2.94m/s2")
    given.add_argument("--pgv", metavar="V", help="peak ground velocity with its unit: 40cm/s or 0.4m/s")
    given.add_argument("--arias", metavar="IA", help="Arias intensity [m/s]: 1.2 or 1.2m/s, or 120cm/s")
    given.add_argument("--tm", metavar="T", help="mean period T_m [s] (Rathje et al. 1998): 0.4 or 0.4s")
    given.add_argument("--sa", metavar="SA", help="5%%-damped spectral acceleration Sa(1.5 T_s): 0.5 or 0.5g")
    given.add_argument("--sa13", metavar="SA",
                       help="5%%-damped spectral acceleration Sa(1.3 T_s) (Bray & Macedo 2019): 0.5 or 0.5g")
    layer = parser.add_argument_group("soil layer over the sliding surface (the coupled analysis of each record)")
    layer.add_argument("--height", metavar="H", help="layer height H [m]: 20 or 20m (else V_s*T_s/4 from --ts)")
    layer.add_argument("--vs", metavar="VS", help="shear-wave velocity V_s of the layer [m/s]: 300 or 300m/s")
    layer.add_argument("--vs-base", metavar="VS", help="shear-wave velocity V_s,base below it [m/s]: 760 or 760m/s")
    layer.add_argument("--damping", metavar="XI", help="material damping ratio [-]: 0.05 or 5%% (default 0.05)")
    parser.add_argument("--exceed", metavar="D",
                        help="also print P(D > d) of each method at this displacement d: 5cm, 0.05m (a bare number "
                             "is in cm)")
    parser.add_argument("--g", default=STANDARD_GRAVITY,
                        help=f"gravity [m/s2] of k_y*g and of the measures in g, which also converts records stored "
                             f"in g: 9.81 or 9.81m/s2 (default {STANDARD_GRAVITY}; SLAMMER's is 9.80665)")
    add_record_options(parser)
    parser.add_argument("--json", action="store_true",
                        help="print one JSON object: settings, units, and per record and k_y its measures, each method's "
                             "median_displacement [m], sigma, log_base and p_zero, and the rigorous displacements [m]")
    parser.set_defaults(func=run)


def _positive(value: float | None, option: str, unit: str) -> float | None:
    if value is not None and not (math.isfinite(value) and value > 0.0):
        raise StickslipError(f"{option} {value:g}: expected a positive number [{unit}]")
    return value


def _quantity(text: str | None, option: str) -> float | None:
    """The value of ``option``'s ``text`` in its unit (:data:`QUANTITIES`), or None when not given."""
    return None if text is None else read_quantity(text, option, QUANTITIES[option])


def _in_g(text: str | None, option: str, g: float) -> float | None:
    """An acceleration option [g] (``--pga``, ``--sa``, ``--sa13``), positive, or None when not given."""
    if text is None:
        return None
    return _positive(in_units_of_g(text, g, option, "0.3", largest=LARGEST_BARE[option], impossible=POSSIBLE_PGA[1]),
                     option, "g")


def given_measures(args) -> dict[str, float | None]:
    """The measures given as options, in the estimates' units (g, cm/s, m/s, s, g, g)."""
    return {
        "pga": _in_g(args.pga, "--pga", args.g),
        "pgv": _positive(_quantity(args.pgv, "--pgv"), "--pgv", "cm/s"),
        "arias_intensity": _positive(_quantity(args.arias, "--arias"), "--arias", "m/s"),
        "mean_period": _positive(_quantity(args.tm, "--tm"), "--tm", "s"),
        "spectral_acceleration": _in_g(args.sa, "--sa", args.g),
        "spectral_acceleration_13": _in_g(args.sa13, "--sa13", args.g),
    }


def layer_from_args(args):
    """The soil layer of the coupled analysis, or None; its period sets T_s (or --ts sets its height)."""
    from stickslip.models.layer import Layer

    for option, name in LAYER_OPTIONS.items():
        setattr(args, name, _quantity(getattr(args, name), option))
    given = [option for option, name in LAYER_OPTIONS.items() if getattr(args, name) is not None]
    if not given:
        return None
    missing = [option for option in ("--vs", "--vs-base") if getattr(args, LAYER_OPTIONS[option]) is None]
    if missing:
        raise StickslipError(f"{given[0]}: the layer needs {' and '.join(missing)} (V_s and V_s,base [m/s])")
    _positive(args.vs, "--vs", "m/s")
    _positive(args.vs_base, "--vs-base", "m/s")
    if args.height is None and args.ts is None:
        raise StickslipError("the layer needs its height --height [m] or its period --ts [s] (H = V_s*T_s/4)")
    if args.height is not None and args.ts is not None:
        raise StickslipError("--height and --ts both set the layer's period T_s = 4H/V_s: give one of them")
    height = _positive(args.height, "--height", "m") if args.height is not None else args.vs * args.ts / 4.0
    if not height > 0.0:
        raise StickslipError(f"--ts {args.ts:g}: a layer needs a period > 0 s")
    try:
        return Layer(height, args.vs, args.vs_base, 0.05 if args.damping is None else args.damping)
    except StickslipError as error:
        raise StickslipError(f"--damping: {error}") from None


def run(args) -> int:
    from stickslip.estimates.measures import estimate_inputs

    args.g = read_gravity(args.g)
    kys, slope = yield_coefficients(args, args.g)
    if args.mw is not None and not math.isfinite(args.mw):
        raise StickslipError(f"--mw {args.mw}: expected a moment magnitude")
    args.ts = _quantity(args.ts, "--ts")
    if args.ts is not None and not (math.isfinite(args.ts) and args.ts >= 0.0):
        raise StickslipError(f"--ts {args.ts:g}: expected a period >= 0 s")
    exceed = _quantity(args.exceed, "--exceed")
    layer = layer_from_args(args)
    site_period = layer.period if layer is not None else args.ts
    measures = given_measures(args)
    given = [option for option, name in MEASURE_OPTIONS.items() if measures[name] is not None]
    if args.paths and given:
        raise StickslipError(f"{given[0]} is for estimates without a record: a record's measures are its own")
    if not args.paths and not given:
        raise StickslipError("give record files, or the measures to estimate from (--pga, --pgv, --arias, --tm, --sa, "
                             "--sa13)")
    if not args.paths and layer is not None:
        raise StickslipError("the layer options solve the coupled analysis of a record: give record files")
    settings = {"ky": [float(ky) for ky in kys], "magnitude": args.mw, "site_period": site_period, "slope": slope}
    cases = []
    if args.paths:
        for record in read_records_from_args(args.paths, args):
            measured = estimate_inputs(record, g=args.g, site_period=site_period)
            cases += [_case(record, {"ky": float(ky), "magnitude": args.mw, "site_period": site_period, **measured},
                            float(ky), args.g, layer, exceed) for ky in kys]
    else:
        cases += [_case(None, {"ky": float(ky), "magnitude": args.mw, "site_period": site_period, **measures},
                        float(ky), args.g, None, exceed) for ky in kys]
    if args.json:
        print(json.dumps(json_document(cases, {**settings, "read": read_settings(args)}, layer, exceed, args.g),
                         allow_nan=False))
    else:
        print("\n\n".join(format_case(case, exceed, args.g, slope) for case in cases))
    return 0


def _case(record, inputs: dict, ky: float, g: float, layer, exceed: float | None) -> dict:
    """One record's (or the given measures') estimates, rigorous displacements [m] and probabilities."""
    import stickslip
    from stickslip.estimates.jibson import failure_probability
    from stickslip.estimates.registry import estimates

    found, lacking = estimates(inputs)
    rigid = coupled = None
    if record is not None:
        rigid = {polarity: stickslip.solve(record, ky=ky, g=g, inverse=polarity == "inverse").downslope_displacement
                 for polarity in ("normal", "inverse")}
        if layer is not None:
            coupled = {polarity: stickslip.solve(record, model="coupled", ky=ky, g=g, inverse=polarity == "inverse",
                                                 ledger=False, **layer.parameters()).displacement
                       for polarity in ("normal", "inverse")}
    failure = {}
    if "jibson_2000" in found:
        failure["jibson_2000"] = failure_probability(found["jibson_2000"].median_displacement)
    for polarity, value in (rigid or {}).items():
        failure[f"rigid_{polarity}"] = failure_probability(max(value, 0.0))
    return {"record": record, "inputs": inputs, "estimates": found, "lacking": lacking, "rigid": rigid,
            "coupled": coupled, "failure": failure,
            "exceedance": None if exceed is None else {name: estimate.probability_of_exceeding(exceed)
                                                       for name, estimate in found.items()}}


def json_document(cases: list[dict], settings: dict, layer, exceed: float | None, g: float) -> dict:
    """The ``--json`` object (displacements in m): one row of ``records`` per record (or the given measures) and k_y."""
    from stickslip.estimates.registry import INPUTS

    layer_settings = None if layer is None else {"height": layer.height, "vs": layer.vs, "vs_base": layer.vs_base,
                                                 "damping": layer.damping, "period": layer.period}
    units = {"median_displacement": "m", "sigma": "1 (of log_base(D))", "p_zero": "1", "rigid_displacement": "m",
             "coupled_displacement": "m", "exceedance": "1", "failure_probability": "1",
             "exceed_displacement": "m", **{name: unit for name, (unit, _) in INPUTS.items()},
             "height": "m", "vs": "m s-1", "vs_base": "m s-1", "damping": "1", "period": "s",
             "factor_of_safety": "1", "slope_angle": "degree"}
    return {
        "settings": {**settings, "g": g, "layer": layer_settings, "exceed_displacement": exceed,
                     "rigid_solver": "exact, one-way (downslope)", "coupled_solver": "exact"},
        "units": units,
        "records": [{
            "record": None if case["record"] is None else case["record"].meta.record_id,
            "source": None if case["record"] is None else str(case["record"].meta.source),
            "ky": case["inputs"]["ky"],
            "measures": {name: case["inputs"].get(name) for name in INPUTS if name not in settings},
            "methods": {name: estimate.as_dict() for name, estimate in case["estimates"].items()},
            "no_sliding": {name: estimate.reason for name, estimate in case["estimates"].items() if estimate.reason},
            "not_applicable": {name: [INPUT_OPTIONS[input_name] for input_name in missing]
                               for name, missing in case["lacking"].items()},
            "rigid_displacement": case["rigid"],
            "coupled_displacement": case["coupled"],
            "failure_probability": case["failure"],
            "exceedance": case["exceedance"],
        } for case in cases],
    }


def _cm(value: float) -> str:
    return f"{CM_PER_M * value:.3g}"


def format_case(case: dict, exceed: float | None, g: float, slope: dict | None = None) -> str:
    """The terminal output of one record (or of the given measures) at one k_y: measures, estimates, rigorous D,
    notes; ``g`` [m/s²] the gravity used, ``slope`` the factor of safety and angle [degrees] that gave k_y, if any."""
    from stickslip.estimates.registry import METHODS

    inputs, record = case["inputs"], case["record"]
    shown = [(f"PGA {inputs['pga']:.4g} g" if inputs.get("pga") else None),
             (f"PGV {inputs['pgv']:.4g} cm/s" if inputs.get("pgv") else None),
             (f"I_a {inputs['arias_intensity']:.4g} m/s" if inputs.get("arias_intensity") else None),
             (f"T_m {inputs['mean_period']:.3g} s" if inputs.get("mean_period") else None),
             (f"Sa(1.5 T_s) {inputs['spectral_acceleration']:.4g} g" if inputs.get("spectral_acceleration") else None),
             (f"Sa(1.3 T_s) {inputs['spectral_acceleration_13']:.4g} g" if inputs.get("spectral_acceleration_13")
              else None)]
    from_slope = (f" (F {slope['factor_of_safety']:g}, slope {slope['slope_angle']:g} degrees: (F - 1) sin(alpha), "
                  "Newmark 1965)") if slope else ""
    settings = [f"k_y {inputs['ky']:.4g}{from_slope}",
                f"M {inputs['magnitude']:g}" if inputs.get("magnitude") is not None else None,
                f"T_s {inputs['site_period']:.4g} s" if inputs.get("site_period") is not None else None,
                f"g = {g:g} m/s2"]
    title = "given measures" if record is None else f"{record.meta.record_id} ({record.meta.source})"
    lines = [f"{title}: {', '.join(item for item in shown if item)}; {', '.join(item for item in settings if item)}"]
    header = f"{'method':<38}  {'median D [cm]':>13}  {'sigma':>6}  {'log':>5}  {'P(D=0)':>7}"
    if exceed is not None:
        header += f"  {f'P(D>{_cm(exceed)} cm)':>14}"
    lines += ["", header]
    for name, estimate in case["estimates"].items():
        sigma = "-" if estimate.sigma is None else f"{estimate.sigma:.3g}"
        p_zero = "-" if estimate.p_zero is None else f"{estimate.p_zero:.3g}"
        row = (f"{METHODS[name].label:<38}  {_cm(estimate.median_displacement):>13}  {sigma:>6}  "
               f"{'log10' if estimate.log_base == '10' else 'ln':>5}  {p_zero:>7}")
        if exceed is not None:
            row += f"  {case['exceedance'][name]:>14.3g}"
        lines.append(row)
    if case["rigid"] is not None:
        lines += ["", f"rigorous rigid D_n [cm] (exact, one-way): normal {_cm(case['rigid']['normal'])}, "
                      f"inverse {_cm(case['rigid']['inverse'])}"]
    if case["coupled"] is not None:
        lines.append(f"coupled D [cm] (exact):                    normal {_cm(case['coupled']['normal'])}, "
                     f"inverse {_cm(case['coupled']['inverse'])}")
    if case["failure"]:
        lines.append("probability of failure, Jibson et al. (2000): " + ", ".join(
            f"{'from ' + METHODS[name].label if name in METHODS else name.replace('_', ' ') + ' D_n'} "
            f"{value:.3g}" for name, value in case["failure"].items()))
    reasons = {estimate.reason for estimate in case["estimates"].values() if estimate.reason}
    notes = [f"D = 0: {reason}" for reason in sorted(reasons)]
    if case["lacking"]:
        notes.append("not applicable (give " + "; ".join(
            f"{' '.join(INPUT_OPTIONS[name] for name in missing)} for {METHODS[method].label}"
            for method, missing in case["lacking"].items()) + ")")
    notes.append("medians of log-normal estimates (Bray & Travasarou, Bray & Macedo, Bray et al.: of the non-zero "
                 "part); sigma of log10 or ln D")
    return "\n".join(lines + [""] + notes)
