"""The flexible sliding mass: a soil layer over the sliding surface, decoupled or coupled (SLAMMER's flexible analyses).

Two entries, ``decoupled`` (the layer's average acceleration drives a rigid
block; sliding does not feed back, Makdisi & Seed 1978) and ``coupled`` (the
layer and the block interact, Rathje & Bray 2000): one component, a yield
coefficient k_y (constant, or a :class:`~stickslip.models.yield_table.YieldTable`
for the ``slammer`` scheme), the layer's height H [m], V_s and V_s,base
[m/s], damping and soil model.  The physics is in
:mod:`~stickslip.models.layer.layer`; the schemes are ``exact``
(:mod:`~stickslip.models.layer.exact`, closed forms per step, events
located, an energy ledger) and ``slammer``
(:mod:`~stickslip.models.layer.slammer`, SLAMMER 1.1's stepping).  The result
is a :class:`~stickslip.models.layer.result.FlexibleResult`.
"""

from __future__ import annotations

import functools
import importlib
from dataclasses import dataclass

from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.models.entry import Model, Parameter, Scheme
from stickslip.models.layer.layer import DEFAULT_REFERENCE_STRAIN, Layer
from stickslip.models.parameters import GRAVITY, INVERSE, KY, flag, positive
from stickslip.models.registry import register

HEIGHT = Parameter("height", "m", "layer height H [m] above the sliding surface", check=positive("layer height H [m]"),
                   swept=True, plural="layer heights H [m]", example="10:100:10",
                   usual=(0.5, 500.0, "soil layers above a sliding surface"))
VS = Parameter("vs", "m s-1", "shear-wave velocity V_s of the layer [m/s]",
               check=positive("shear-wave velocity V_s [m/s]"), usual=(50.0, 2500.0, "the shear-wave velocity of soil"))
VS_BASE = Parameter("vs_base", "m s-1", "shear-wave velocity V_s,base below it [m/s]",
                    check=positive("base shear-wave velocity V_s,base [m/s]"),
                    usual=(50.0, 5000.0, "the shear-wave velocity of soil and rock"))
DAMPING = Parameter("damping", "1", "material damping ratio [-] (default 0.05); the foundation damping "
                    "min(0.55 (V_s,base/V_s)^-0.99, 0.20) is added to it", default=0.05, check=float)
EQUIVALENT_LINEAR = Parameter("equivalent_linear", "1", "equivalent-linear soil: V_s and damping from the strain "
                              "(default: linear elastic)", default=False, check=flag, kind="flag")
REFERENCE_STRAIN = Parameter("reference_strain", "percent", "reference shear strain of the equivalent-linear soil, "
                             f"in percent with its unit (0.05%; default {DEFAULT_REFERENCE_STRAIN:g}%; pySLAMMER's "
                             "decimal strain 0.0005 is 0.05%)",
                             check=positive("reference strain [%]"), kind="strain", requires=("equivalent_linear", True))
LEDGER = Parameter("ledger", "1", "keep the energy ledger where the scheme keeps one (exact); it about doubles the "
                   "exact scheme's time per sample", default=True, check=flag, kind="flag", command_line=False)


@dataclass(frozen=True)
class LayerScheme(Scheme):
    """A scheme of the flexible models.

    Attributes
    ----------
    name, summary:
        The name users give and what it is.
    steps:
        ``"module:function"``: ``flexible_steps(coupled, a, dt, yield_thresholds, layer, ...)``.
    takes_yield_table:
        Whether it solves a k_y that varies with displacement.
    keeps_ledger:
        Whether it keeps the energy ledger (:mod:`stickslip.models.layer.energy`).
    min_steps_per_period:
        Record samples per period of the layer it needs to be accurate (0: none).
    """

    name: str
    summary: str
    steps: str
    takes_yield_table: bool = False
    keeps_ledger: bool = False
    min_steps_per_period: int = 0

    @functools.cached_property
    def flexible_steps(self):
        """The function :attr:`steps` names, imported when first asked for."""
        module, function = self.steps.split(":")
        return getattr(importlib.import_module(module), function)

    def solve(self, record, case, **options):
        """The :class:`~stickslip.models.layer.result.FlexibleResult` of ``case`` on ``record`` [m/s²]."""
        from stickslip.models.layer.result import solve_case

        return solve_case(self, record, case)


#: The schemes of the flexible models, the default first.
SCHEMES = (
    LayerScheme("exact", "closed forms per sample step, the block's starts and stops located; an energy ledger",
                "stickslip.models.layer.exact:flexible_steps", keeps_ledger=True),
    LayerScheme("slammer", "SLAMMER 1.1's stepping (Newmark's average acceleration)",
                "stickslip.models.layer.slammer:flexible_steps", takes_yield_table=True, min_steps_per_period=10),
)


@dataclass(frozen=True)
class LayerCase:
    """What the flexible models' schemes solve: a k_y [1] (or table), a :class:`~stickslip.models.layer.layer.Layer`,
    gravity g [m/s²], the polarity, whether to keep the ledger, and whether the block and layer are coupled."""

    ky: object
    layer: object
    g: float = STANDARD_GRAVITY
    inverse: bool = False
    ledger: bool = True
    model: str = "decoupled"
    coupled: bool = False


class LayerModel(Model):
    """A flexible model's entry: one component, a yield coefficient, the layer's parameters, two schemes."""

    motions = ("component",)
    parameters = (KY, HEIGHT, VS, VS_BASE, DAMPING, EQUIVALENT_LINEAR, REFERENCE_STRAIN, INVERSE, GRAVITY, LEDGER)
    schemes = SCHEMES
    #: An equivalent-linear layer (its iterations run the kernels of the layer on its base) with its ledger, in both
    #: polarities (in the inverse one the kernels get the record's negated copy, a writable array: another
    #: signature than the record's read-only samples).
    examples = tuple({"ky": 0.1, "height": 10.0, "vs": 300.0, "vs_base": 600.0, "equivalent_linear": True,
                      "inverse": inverse} for inverse in (False, True))

    def __init__(self, name: str, summary: str, coupled: bool):
        self.name, self.summary, self.coupled = name, summary, coupled

    @property
    def result(self) -> type:
        from stickslip.models.layer.result import FlexibleResult

        return FlexibleResult

    def case(self, parameters) -> LayerCase:
        """The :class:`LayerCase`: the layer of the parameters (H, V_s and V_s,base needed) at k_y."""
        missing = [name for name in ("ky", "height", "vs", "vs_base") if parameters[name] is None]
        if missing:
            raise StickslipError(f"model={self.name} needs {', '.join(name + '=' for name in missing)} (k_y [-], the "
                                 "layer's H [m], V_s and V_s,base [m/s])")
        strain = parameters["reference_strain"]
        if strain is not None and not parameters["equivalent_linear"]:
            raise StickslipError("reference_strain applies to the equivalent-linear soil only (a linear layer has no "
                                 "strain rule)")
        try:
            layer = Layer(parameters["height"], parameters["vs"], parameters["vs_base"], parameters["damping"],
                          "equivalent-linear" if parameters["equivalent_linear"] else "linear",
                          DEFAULT_REFERENCE_STRAIN if strain is None else strain)
        except StickslipError as error:
            raise StickslipError(f"damping={parameters['damping']:g}: {error}") from None
        return LayerCase(parameters["ky"], layer, parameters["g"], parameters["inverse"], parameters["ledger"],
                         self.name, self.coupled)

    def solve(self, motion, method: str | None = None, **keywords):
        """One case on the record ``motion`` (:meth:`Model.solve`), with a warning when an equivalent-linear layer
        softens below a fifth of its V_s (:func:`~stickslip.models.layer.result.warn_if_softened`)."""
        from stickslip.models.layer.result import warn_if_softened

        result = super().solve(motion, method, **keywords)
        warn_if_softened(motion, result.layer, result.vs_final)
        return result

    def sweep(self, motions, method=None, **keywords):
        """Every record over grids of ``ky`` and ``height`` into one cube (:mod:`stickslip.models.layer.sweep`)."""
        from stickslip.models.layer.sweep import layer_sweep

        return layer_sweep(self, motions, method, **keywords)


DECOUPLED = register(LayerModel("decoupled", "a soil layer whose average acceleration drives a rigid block; sliding "
                                "does not feed back (Makdisi & Seed 1978)", coupled=False))
COUPLED = register(LayerModel("coupled", "a soil layer and the block sliding at its base, each acting on the other "
                              "(Rathje & Bray 2000)", coupled=True))


def solve_flexible(record, ky, layer, model_name: str = "decoupled", method: str = "exact",
                   g: float = STANDARD_GRAVITY, inverse: bool = False, ledger: bool = True):
    """:func:`stickslip.solve` of the flexible model ``model_name`` with the :class:`~stickslip.models.layer.layer.Layer` ``layer``."""
    from stickslip.models import solve

    return solve(record, model=model_name, method=method, ky=ky, g=g, inverse=inverse, ledger=ledger,
                 **layer.parameters())


def flexible_sweep(records, ky, height, model_name: str = "decoupled", method: str = "exact", **keywords):
    """:func:`stickslip.sweep` of the flexible model ``model_name``: records × ``ky`` [1] × layer ``height`` [m]."""
    from stickslip.models import sweep

    return sweep(records, model=model_name, method=method, ky=ky, height=height, **keywords)
