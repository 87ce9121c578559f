"""``--model`` and the soil layer's options of ``stickslip solve``: the flexible sliding block.

``--model rigid`` (the default) is the rigid block; ``decoupled`` and
``coupled`` make the sliding mass a soil layer
(:class:`stickslip.solvers.layer.Layer`): ``--height`` H [m], ``--vs`` V_s
and ``--vs-base`` V_s,base [m/s], ``--damping`` ξ [1], ``--equivalent-linear``
with ``--reference-strain`` γ_r, written with its unit (``0.05%``: a bare
number is refused, since pySLAMMER's decimal strain ``0.0005`` is our
``0.05%``).  Layer options without a flexible model, and a flexible model
without them, are one-line errors.  An equivalent-linear layer whose V_s ends
below :data:`SOFTENED_VS_FRACTION` of its start gets a warning
(:func:`warn_softened_layer`).
"""

from __future__ import annotations

import argparse
import math
import sys
import warnings

from stickslip.errors import StickslipError, StickslipWarning
from stickslip.records.process import record_name
from stickslip.solvers.flexible import MODELS, layer_scheme
from stickslip.solvers.layer import DEFAULT_REFERENCE_STRAIN, Layer

#: The layer's options, as the command line spells them, and their attribute names.
LAYER_OPTIONS = {"--height": "height", "--vs": "vs", "--vs-base": "vs_base", "--damping": "damping",
                 "--equivalent-linear": "equivalent_linear", "--reference-strain": "reference_strain"}

#: Fraction of its initial V_s below which an equivalent-linear layer's final V_s gets a warning.
SOFTENED_VS_FRACTION = 0.2

def add_layer_options(parser: argparse.ArgumentParser, several_heights: bool = False) -> None:
    """``--model`` and the layer's options; ``several_heights``: ``--height`` takes a list or range (``sweep``)."""
    parser.add_argument("--model", choices=tuple(MODELS), default="rigid",
                        help="sliding-block model: rigid (default), decoupled or coupled (a soil layer over the "
                             "sliding surface, SLAMMER's flexible analyses; needs --ky or --ky-table and the layer "
                             "options), or planar (the rigid block sliding in the plane under two components: --pair)")
    layer = parser.add_argument_group("soil layer (--model decoupled or coupled)")
    if several_heights:
        layer.add_argument("--height", metavar="H", help="layer heights H [m] above the sliding surface: "
                                                          "START:STOP:STEP or a comma list (10,50,100)")
    else:
        layer.add_argument("--height", type=float, metavar="H", help="layer height H [m] above the sliding surface")
    layer.add_argument("--vs", type=float, metavar="VS", help="shear-wave velocity V_s of the layer [m/s]")
    layer.add_argument("--vs-base", type=float, metavar="VS", help="shear-wave velocity V_s,base below it [m/s]")
    layer.add_argument("--damping", type=float, metavar="XI",
                       help="material damping ratio [-] (default 0.05); the foundation damping "
                            "min(0.55 (V_s,base/V_s)^-0.99, 0.20) is added to it")
    layer.add_argument("--equivalent-linear", action="store_true",
                       help="equivalent-linear soil: V_s and damping from the strain (default: linear elastic)")
    layer.add_argument("--reference-strain", metavar="STRAIN%",
                       help=f"reference shear strain of the equivalent-linear soil, in percent with its unit "
                            f"(0.05%%; default {DEFAULT_REFERENCE_STRAIN:g}%%; pySLAMMER's decimal strain 0.0005 is "
                            "0.05%%)")


def layer_settings_from_args(args: argparse.Namespace) -> dict | None:
    """The layer's settings but its height (``vs``, ``vs_base``, ``damping``, ``soil_model``, ``reference_strain``)
    for a flexible ``--model``, or None for the rigid block; one-line errors.  The height is the command's."""
    given = [option for option, name in LAYER_OPTIONS.items() if getattr(args, name) not in (None, False)]
    if not MODELS[args.model].layer:
        if given:
            raise StickslipError(f"{given[0]} applies to --model decoupled or coupled (the rigid block has no layer)")
        return None
    missing = [option for option in ("--height", "--vs", "--vs-base") if getattr(args, LAYER_OPTIONS[option]) is None]
    if missing:
        raise StickslipError(f"--model {args.model} needs the layer's {', '.join(missing)} (H [m], V_s and V_s,base [m/s])")
    if args.reference_strain is not None and not args.equivalent_linear:
        raise StickslipError("--reference-strain applies to --equivalent-linear only (a linear layer has no strain rule)")
    for option, unit in (("--vs", "m/s"), ("--vs-base", "m/s")):
        value = getattr(args, LAYER_OPTIONS[option])
        if not (math.isfinite(value) and value > 0.0):
            raise StickslipError(f"{option} {value:g}: expected a positive number [{unit}]")
    return {"vs": args.vs, "vs_base": args.vs_base, "damping": 0.05 if args.damping is None else args.damping,
            "soil_model": "equivalent-linear" if args.equivalent_linear else "linear",
            "reference_strain": DEFAULT_REFERENCE_STRAIN if args.reference_strain is None
            else _percent(args.reference_strain)}


def checked_layer(height: float, settings: dict) -> Layer:
    """The :class:`Layer` of height ``height`` [m] and ``settings``; the total damping's error names ``--damping``."""
    try:
        return Layer(height, **settings)
    except StickslipError as error:
        raise StickslipError(f"--damping: {error}") from None


def layer_from_args(args: argparse.Namespace) -> Layer | None:
    """The :class:`Layer` of a flexible ``--model`` (one ``--height``), or None for the rigid block; one-line errors."""
    settings = layer_settings_from_args(args)
    if settings is None:
        return None
    if not (math.isfinite(args.height) and args.height > 0.0):
        raise StickslipError(f"--height {args.height:g}: expected a positive number [m]")
    return checked_layer(args.height, settings)


def check_flexible_args(args) -> None:
    """What a flexible ``--model`` does not take: ``--mu``, ``--direction``, ``--thrust-angle``, a rigid-only scheme."""
    if args.mu is not None:
        raise StickslipError(f"--model {args.model} takes a yield coefficient --ky or --ky-table, not a friction "
                             "ratio --mu")
    if args.direction is not None or args.thrust_angle is not None:
        raise StickslipError(f"--direction and --thrust-angle apply to the rigid block; --model {args.model} slides "
                             "downslope only, as SLAMMER's flexible analyses")
    if args.method not in MODELS[args.model].schemes:
        raise StickslipError(f"--method {args.method}: the {args.model} model is solved by "
                             f"{' or '.join(MODELS[args.model].schemes)}")


def _percent(text: str) -> float:
    """A strain [%] from ``"0.05%"``; a number without its unit is refused (pySLAMMER writes the same strain 0.0005)."""
    number = text.strip().removesuffix("%").strip()
    try:
        value = float(number)
    except ValueError:
        raise StickslipError(f"--reference-strain {text!r}: expected a strain in percent with its unit, such as "
                             "0.05%") from None
    if not text.strip().endswith("%"):
        raise StickslipError(f"--reference-strain {text!r}: give the strain with its unit, in percent: "
                             f"{value:g}% is a strain of {value / 100:g}; pySLAMMER's decimal strain {value:g} is "
                             f"{value * 100:g}% (pySLAMMER's 0.0005 is 0.05%)")
    if not value > 0.0:
        raise StickslipError(f"--reference-strain {text!r}: the reference strain must be positive")
    return value


def warn_softened_layer(record, layer: Layer, vs_final: float) -> None:
    """A warning when the equivalent-linear ``layer``'s final V_s ``vs_final`` [m/s] under ``record`` ends below
    :data:`SOFTENED_VS_FRACTION` of its initial V_s: the soil softened so far that its strain rule is far outside
    what it describes (a reference strain in the wrong unit does that: check ``--reference-strain``)."""
    final = float(vs_final)
    if layer.soil_model == "equivalent-linear" and final < SOFTENED_VS_FRACTION * layer.vs:
        warnings.warn(f"{record_name(record)}: the equivalent-linear layer's V_s ends at {final:.4g} m/s, below "
                      f"{SOFTENED_VS_FRACTION:.0%} of its initial {layer.vs:g} m/s (reference strain "
                      f"{layer.reference_strain:g} %): a soil this soft is far outside what the equivalent-linear "
                      "model describes well; check --reference-strain (pySLAMMER's 0.0005 is 0.05%)",
                      StickslipWarning, stacklevel=2)


def note_coarse_step(record, layer: Layer, method: str) -> None:
    """One note on stderr when the record's dt is coarse for the layer's period under the scheme ``method``.

    The scheme's ``MIN_STEPS_PER_PERIOD`` says how fine (:data:`stickslip.solvers.flexible.LAYER_SCHEMES`).
    """
    needed, period = layer_scheme(method).MIN_STEPS_PER_PERIOD, layer.period
    if needed and record.dt * needed > period:
        print(f"stickslip: note: {record.meta.source or record.meta.record_id}: its time step {record.dt:g} s is coarse "
              f"for the layer's period T = 4H/V_s = {period:.4g} s (fewer than {needed} steps per period): "
              f"the {method} scheme's layer response loses accuracy there", file=sys.stderr)
