"""The result of a flexible analysis: the permanent displacement, the layer's peak and properties, the histories.

:func:`solve_case` is what both flexible schemes' ``solve`` does
(:class:`~stickslip.models.layer.LayerScheme`): it runs the scheme's
``flexible_steps`` on one record for one yield coefficient k_y and one
:class:`~stickslip.models.layer.layer.Layer`, decoupled or coupled, and
returns a :class:`FlexibleResult`.  An equivalent-linear layer whose V_s
ends below :data:`SOFTENED_VS_FRACTION` of its start gets a warning
(:func:`warn_if_softened`): a reference strain in the wrong unit does that.
"""

from __future__ import annotations

import functools
import warnings
from dataclasses import dataclass, field

import numpy as np

from stickslip.checks import checked_positive
from stickslip.errors import StickslipError, StickslipWarning
from stickslip.records.process import record_name
from stickslip.records.record import Record
from stickslip.models.layer.layer import Layer
from stickslip.models.layer.energy import HISTORIES, FlexibleLedger
from stickslip.models.yield_table import YieldTable, table_integral
from stickslip.models.result import Result
from stickslip.units import UNITS


#: What the two k_max of :class:`FlexibleResult` are (the long names of their NetCDF variables).
KMAX_NAMES = {
    "kmax": "largest |k| of the layer's average acceleration k(t) g, in g, as the scheme resolves it (exact: "
            "between the samples as at them; slammer: at the samples)",
    "kmax_samples": "largest |k| of the layer's average acceleration k(t) g at the record's samples, in g "
                    "(SLAMMER's Kmax)",
}

#: The end results of :meth:`FlexibleResult.scalars`: units (UDUNITS, from the one units table) and long names;
#: the ledger's (:data:`LEDGER_ENDS`, ``balance_residual_per_mass``) where the exact scheme kept one.
SCALARS = {name: (UNITS[name], long_name) for name, long_name in (
    ("displacement", "permanent downslope displacement of the block"),
    *KMAX_NAMES.items(),
    ("vs_final", "shear-wave velocity of the layer's final response"),
    ("damping_final", "total damping ratio of the layer's final response"),
    ("iterations", "equivalent-linear iterations run"),
    ("energy_dissipated_per_mass", "energy dissipated by friction per unit mass of the sliding mass, E_df = k_y g D"),
    ("energy_input_per_mass", "work of the ground per unit mass of the sliding mass (on the layer, decoupled), E_I"),
    ("energy_damped_per_mass", "energy dissipated by the layer's damping per unit mass of the sliding mass, E_d"),
    ("block_energy_input_per_mass", "work of the layer's average motion on the decoupled block per unit mass of the "
                                    "sliding mass, E_I,block"),
    ("balance_residual_per_mass", "largest |residual| of the energy ledger over the record and the systems, per "
                                  "unit mass of the sliding mass"),
)}

#: The end results of :data:`SCALARS` that are a ledger's histories at the end of the record, where it has them.
LEDGER_ENDS = ("energy_input_per_mass", "energy_damped_per_mass", "block_energy_input_per_mass")

#: Units of :meth:`FlexibleResult.scalars` (:data:`SCALARS`).
SCALAR_UNITS = {name: unit for name, (unit, _) in SCALARS.items()}

#: The histories of :meth:`FlexibleResult.to_xarray`: units and long names; the ledger's ``{name}_per_mass``
#: (:data:`~stickslip.models.layer.energy.HISTORIES`) where the exact scheme kept one.
HISTORY_ATTRS = {
    "average_acceleration": ("m s-2", "average acceleration of the layer k(t) g"),
    "modal_displacement": ("m", "modal displacement u of the layer's first mode"),
    "block_displacement": ("m", "downslope displacement of the block"),
    "block_velocity": ("m s-1", "downslope velocity of the block"),
    **{f"{name}_per_mass": ("J kg-1", f"{long_name} per unit mass") for name, long_name in HISTORIES.items()},
}

#: What the printed table's two k_max are (a line of :meth:`FlexibleResult.notes`).
KMAX_NOTE = ("kmax_samples is k_max at the record's samples, as SLAMMER prints it; kmax the peak as the method "
             "resolves it (exact: between the samples too, where the block starts to slide)")

#: Fraction of its initial V_s below which an equivalent-linear layer's final V_s gets a warning.
SOFTENED_VS_FRACTION = 0.2


@dataclass(frozen=True)
class FlexibleResult(Result):
    """One flexible analysis: the permanent displacement, the layer's peak and properties, the histories.

    Attributes
    ----------
    model, method, ky, g, polarity, layer:
        What was solved: the model and scheme, k_y [1] (a number or a
        :class:`~stickslip.models.yield_table.YieldTable`), g [m/s²], ``"normal"``
        or ``"inverse"`` (the record's sign flipped), the :class:`Layer`.
    displacement:
        D [m], the block's permanent downslope displacement.
    kmax:
        k_max [1]: the largest |k(t)| of the layer's average acceleration k(t)·g, in g, as the scheme
        resolves it: ``exact`` between the samples as at them (a block whose k_y is below it slides),
        ``slammer`` at the samples.
    kmax_samples:
        k_max [1] at the record's samples only, as SLAMMER reports it (its "Kmax"); for ``exact`` up
        to a few per cent below :attr:`kmax` when the layer's period is a few samples long.
    vs_final, damping_final:
        The layer's V_s [m/s] and total damping ratio [1] of the final response
        (the strain-compatible ones for the equivalent-linear model).
    iterations:
        Equivalent-linear iterations run (0 for a linear layer).
    dt:
        The record's sample interval [s] (:attr:`time`).
    average_acceleration:
        k(t)·g [m/s²] at the samples.
    modal_displacement:
        The layer's modal coordinate u [m] at the samples.
    block_displacement, block_velocity:
        The block's downslope displacement [m] and velocity [m/s] relative to the layer's base.
    ledger:
        The energy ledger per unit mass [J/kg] (:class:`~stickslip.models.layer.energy.FlexibleLedger`),
        kept by the ``exact`` scheme; ``None`` for ``slammer`` or when not asked for.
    caveats:
        What limits the result's accuracy (a record time step coarse for the layer's period under a stepping scheme).
    """

    history_table = HISTORY_ATTRS
    counts = ("iterations",)

    model: str
    method: str
    ky: float | YieldTable
    g: float
    polarity: str
    layer: Layer
    displacement: float
    kmax: float
    kmax_samples: float
    vs_final: float
    damping_final: float
    iterations: int
    dt: float
    average_acceleration: np.ndarray = field(repr=False)
    modal_displacement: np.ndarray = field(repr=False)
    block_displacement: np.ndarray = field(repr=False)
    block_velocity: np.ndarray = field(repr=False)
    ledger: FlexibleLedger | None = field(default=None, repr=False)
    caveats: tuple[str, ...] = ()

    @functools.cached_property
    def time(self) -> np.ndarray:
        """Sample times [s], starting at 0 (made when first asked for: most callers read the end results only)."""
        return np.arange(self.block_displacement.size) * self.dt

    @property
    def scalar_table(self) -> dict[str, tuple[str, str]]:
        """The end results' units and long names (:data:`SCALARS`): those of the ledger where there is one."""
        names = [name for name in SCALARS if name not in (*LEDGER_ENDS, "balance_residual_per_mass")]
        if self.ledger is not None:
            kept = self.ledger.histories()
            names += [name for name in LEDGER_ENDS if name.removesuffix("_per_mass") in kept]
            names.append("balance_residual_per_mass")
        return {name: SCALARS[name] for name in names}

    @property
    def ledger_terms(self) -> tuple[str, ...]:
        """The ledger's histories per unit mass of the sliding mass, ``{name}_per_mass`` [J kg-1]; none without one
        (``slammer``; not asked for)."""
        return () if self.ledger is None else tuple(f"{name}_per_mass" for name in self.ledger.histories())

    def end_values(self) -> dict[str, float]:
        """D [m], k_max and k_max at the samples [1] (:data:`KMAX_NAMES`), V_s [m/s], damping [1], iterations,
        the energy dissipated by friction per unit mass E_df = ∫ k_y(D) g dD over the one-way slide [J/kg] (any
        scheme) and, with a ledger, its other energies at the end of the record and its largest residual [J/kg]."""
        table = self.ky if isinstance(self.ky, YieldTable) else YieldTable((0.0,), (self.ky,))
        values = {"displacement": self.displacement, "kmax": self.kmax, "kmax_samples": self.kmax_samples,
                  "vs_final": self.vs_final, "damping_final": self.damping_final, "iterations": self.iterations,
                  "energy_dissipated_per_mass": self.g * table_integral(self.displacement, table.displacement,
                                                                        table.ky)}
        if self.ledger is not None:
            ends = {f"{name}_per_mass": history[-1] for name, history in self.ledger.histories().items()}
            values = {**ends, **values, "balance_residual_per_mass": self.ledger.balance_residual}
        return values

    def histories(self) -> dict[str, np.ndarray]:
        """The layer's average acceleration k(t) g [m/s²] and modal displacement u [m], the block's downslope
        displacement [m] and velocity [m/s], and the ledger's histories [J/kg] where there is one."""
        ledger = {} if self.ledger is None else self.ledger.histories()
        return {"average_acceleration": self.average_acceleration, "modal_displacement": self.modal_displacement,
                "block_displacement": self.block_displacement, "block_velocity": self.block_velocity,
                **{f"{name}_per_mass": values for name, values in ledger.items()}}

    def describe(self) -> str:
        """The layer, its soil, k_y, the polarity, g [m/s²] and the scheme, in one line."""
        layer = self.layer
        polarity = ", inverse polarity" if self.polarity == "inverse" else ""
        soil = (f"equivalent-linear, reference strain {layer.reference_strain:g} %"
                if layer.soil_model == "equivalent-linear" else "linear")
        return (f"{self.model} layer H = {layer.height:g} m, V_s = {layer.vs:g} m/s over {layer.vs_base:g} m/s, "
                f"damping {layer.damping:g} ({soil}); {self.describe_yield()}{polarity}, g = {self.g:g} m/s2, "
                f"method = {self.method}")

    def case(self) -> dict:
        """The model, the scheme, k_y, g, the polarity and the layer (H [m], V_s, V_s,base [m/s], damping, soil)."""
        layer = self.layer
        return {"model": self.model, "method": self.method, **self.yield_parameters(), "g": self.g,
                "polarity": self.polarity, "height": layer.height, "vs": layer.vs, "vs_base": layer.vs_base,
                "damping": layer.damping, "soil_model": layer.soil_model, "reference_strain": layer.reference_strain}

    def case_units(self) -> dict[str, str]:
        """The units of :meth:`case`'s numbers."""
        return {**{name: UNITS[name] for name in self.yield_parameters()}, "g": UNITS["gravity"],
                **{name: UNITS[name] for name in ("height", "vs", "vs_base", "damping", "reference_strain")}}

    def notices(self) -> list[str]:
        """That the block never slid, and a time step coarse for the layer's period under a stepping scheme."""
        return super().notices() + list(self.caveats)

    @property
    def never_slides(self) -> str | None:
        """Why the block did not slide: its driving acceleration's peak k_max stayed within k_y; None when it slid."""
        if self.displacement > 0.0:
            return None
        first = self.ky.ky[0] if isinstance(self.ky, YieldTable) else self.ky
        return f"k_max = {self.kmax:.4g} does not exceed k_y = {first:g}"

    def notes(self) -> list[str]:
        """What the two k_max are (:data:`KMAX_NOTE`), and what the energies are, or why there are none."""
        if self.ledger is None:
            return [KMAX_NOTE, f"no energy ledger: method {self.method} keeps none (method exact does); "
                               "energy_dissipated_per_mass is the friction's work, k_y g over the slide"]
        if not self.ledger.coupled:
            return [KMAX_NOTE, "energies per kg of the sliding mass: energy_input is the ground's work on the layer, "
                               "block_energy_input the layer's on the block; each ledger closes alone"]
        return [KMAX_NOTE, "energies per kg of the sliding mass: the ground's work on the layer and block, one closed "
                           "ledger"]

    def yield_parameters(self) -> dict:
        """``{"ky": k_y}``, or a table's ``{"ky": [k_y,i], "ky_displacement": [D_i]}`` (k_y [1], D [m])."""
        return self.ky.parameters() if isinstance(self.ky, YieldTable) else {"ky": self.ky}

    def describe_yield(self) -> str:
        """``k_y = 0.1``, or the table's line (:meth:`YieldTable.describe`)."""
        return self.ky.describe() if isinstance(self.ky, YieldTable) else f"k_y = {self.ky:g}"

    def case_attrs(self) -> dict:
        """:meth:`case`, its reference strain named with its unit (``reference_strain_percent``)."""
        attrs = super().case_attrs()
        attrs["reference_strain_percent"] = attrs.pop("reference_strain")
        return attrs


def solve_case(scheme, record: Record, case) -> FlexibleResult:
    """The flexible analysis of ``case`` (:class:`~stickslip.models.layer.LayerCase`) on ``record`` [m/s²] by ``scheme``.

    k_y [1] is a number or a :class:`~stickslip.models.yield_table.YieldTable`
    (a table of one pair is its constant k_y, which every scheme takes; a
    longer one needs a scheme that takes tables); the ledger is kept where the
    scheme keeps one and the case asks for it.
    """
    table = case.ky if isinstance(case.ky, YieldTable) else None
    ky = checked_positive(case.ky, "yield coefficient k_y [1]") if table is None else yield_of_table(scheme, table)
    g = checked_positive(case.g, "gravity g [m/s²]")
    thresholds = ((0.0,), (ky * g,)) if table is None else table.thresholds(g)  # a constant k_y: its one pair (0, k_y g)
    acceleration = -record.acceleration if case.inverse else record.acceleration
    options = {"ledger": True} if case.ledger and scheme.keeps_ledger else {}
    needed, period = scheme.min_steps_per_period, case.layer.period
    caveats = ((f"its time step {record.dt:g} s is coarse for the layer's period T = 4H/V_s = {period:.4g} s "
                f"(fewer than {needed} steps per period): the {scheme.name} scheme's layer response loses accuracy "
                "there",) if needed and record.dt * needed > period else ())
    steps = scheme.flexible_steps(case.coupled, acceleration, record.dt, thresholds, case.layer, **options)
    return FlexibleResult(
        model=case.model, method=scheme.name, ky=ky, g=g,
        polarity="inverse" if case.inverse else "normal", layer=case.layer,
        displacement=float(abs(steps["displacement"][-1])), kmax_samples=steps["sample_peak"] / g,
        kmax=float(steps.get("peak_average_acceleration", steps["sample_peak"])) / g,
        vs_final=float(steps["vs"]), damping_final=float(steps["damping"]), iterations=int(steps["iterations"]),
        dt=record.dt, average_acceleration=steps["average_acceleration"], modal_displacement=steps["u"],
        block_displacement=steps["displacement"], block_velocity=steps["velocity"], ledger=steps.get("ledger"),
        caveats=caveats,
    )


def yield_of_table(scheme, table: YieldTable) -> float | YieldTable:
    """The yield coefficient of ``table`` as a result records it: its k_y [1] where it has one pair (every
    scheme takes a constant), else the table, which ``scheme`` must take (or one line naming the ones that do)."""
    from stickslip.models.layer import SCHEMES

    if len(table) == 1:
        return table.ky[0]
    if not scheme.takes_yield_table:
        takers = [other.name for other in SCHEMES if other.takes_yield_table]
        raise StickslipError(f"method {scheme.name} solves a constant yield coefficient, not {table.describe()}; "
                             f"use method {' or '.join(takers)}")
    return table


def warn_if_softened(record: Record, layer: Layer, vs_final: float) -> None:
    """A :class:`~stickslip.errors.StickslipWarning` when the equivalent-linear ``layer``'s final V_s ``vs_final``
    [m/s] under ``record`` ends below :data:`SOFTENED_VS_FRACTION` of its initial V_s [m/s]: the soil softened so
    far that its strain rule is far outside what it describes (a reference strain [%] given as pySLAMMER's decimal
    strain does that)."""
    final = float(vs_final)
    if layer.soil_model == "equivalent-linear" and final < SOFTENED_VS_FRACTION * layer.vs:
        warnings.warn(f"{record_name(record)}: the equivalent-linear layer's V_s ends at {final:.4g} m/s, below "
                      f"{SOFTENED_VS_FRACTION:.0%} of its initial {layer.vs:g} m/s (reference strain "
                      f"{layer.reference_strain:g} %): a soil this soft is far outside what the equivalent-linear "
                      "model describes well; check reference_strain= (pySLAMMER's 0.0005 is 0.05%)",
                      StickslipWarning, stacklevel=3)
