"""The flexible sliding block: a soil layer on a sliding surface, decoupled or coupled (SLAMMER's flexible analyses).

:func:`solve_flexible` solves one record for one yield coefficient k_y and
one :class:`~stickslip.solvers.layer.Layer`, with the model ``decoupled``
(the layer's average acceleration k(t)·g drives a rigid block; sliding does
not feed back) or ``coupled`` (the layer and the block interact).  The
physics is in :mod:`stickslip.solvers.layer`; the scheme ``slammer`` steps
as SLAMMER 1.1 does (:mod:`stickslip.solvers.layer_slammer`).

:data:`MODELS` is the one table of the sliding-block models: the rigid block
(:func:`stickslip.solve` and its schemes, :mod:`stickslip.solvers.registry`)
and the two flexible ones.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from stickslip.checks import checked_positive
from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.records.record import Record
from stickslip.solvers.layer import Layer
from stickslip.solvers.layer_energy import HISTORIES, FlexibleLedger
from stickslip.solvers.yield_table import YieldTable, table_integral
from stickslip.units import UNITS


@dataclass(frozen=True)
class Model:
    """One sliding-block model: its name, what it is, and the schemes that solve it.

    Attributes
    ----------
    name:
        The name users give (``model="coupled"``).
    summary:
        What it is, in one line.
    schemes:
        The schemes that solve it (``method=...``), the default first.
    layer:
        Whether it takes a :class:`~stickslip.solvers.layer.Layer` (the flexible models).
    """

    name: str
    summary: str
    schemes: tuple[str, ...]
    layer: bool = False


#: The sliding-block models, by name: the rigid block, SLAMMER's two flexible analyses, and sliding in the
#: plane (:func:`stickslip.solvers.planar.solve_planar`).
MODELS = {
    "rigid": Model("rigid", "a rigid block on the moving base (Newmark)", ("exact", "newmark", "slammer")),
    "decoupled": Model("decoupled", "a soil layer whose average acceleration drives a rigid block; sliding does "
                       "not feed back (Makdisi & Seed 1978)", ("exact", "slammer"), layer=True),
    "coupled": Model("coupled", "a soil layer and the block sliding at its base, each acting on the other "
                     "(Rathje & Bray 2000)", ("exact", "slammer"), layer=True),
    "planar": Model("planar", "a rigid block sliding in the plane on a flat surface under both horizontal "
                    "components, one friction force opposing the sliding velocity", ("exact",)),
}


#: The flexible models' schemes, by name: the module that defines each one's ``flexible_steps``,
#: ``MIN_STEPS_PER_PERIOD`` (the record samples per period of the layer it needs to be accurate; 0: none),
#: ``TAKES_YIELD_TABLE`` (whether it solves a k_y that varies with displacement) and ``KEEPS_LEDGER`` (whether
#: it keeps the energy ledger of :mod:`stickslip.solvers.layer_energy`).
LAYER_SCHEMES = {"exact": "stickslip.solvers.layer_exact", "slammer": "stickslip.solvers.layer_slammer"}


def layer_scheme(method: str):
    """The module of the flexible models' scheme ``method`` (:data:`LAYER_SCHEMES`)."""
    import importlib

    return importlib.import_module(LAYER_SCHEMES[method])


def model(name: str) -> Model:
    """The entry of the model ``name``; an unknown name raises :class:`StickslipError` naming the known ones."""
    if name not in MODELS:
        raise StickslipError(f"unknown sliding-block model {name!r}; known: {', '.join(MODELS)}")
    return MODELS[name]


#: Units of :meth:`FlexibleResult.scalars`, UDUNITS spelling.
SCALAR_UNITS = {"displacement": "m", "vs_final": "m s-1", "damping_final": "1", "iterations": "1",
                **{name: UNITS[name] for name in ("kmax", "kmax_samples", "energy_dissipated_per_mass",
                                                  "energy_input_per_mass", "energy_damped_per_mass",
                                                  "block_energy_input_per_mass", "balance_residual_per_mass")}}

#: What the two k_max of :class:`FlexibleResult` are (the long names of their NetCDF variables).
KMAX_NAMES = {
    "kmax": "largest |k| of the layer's average acceleration k(t) g, in g, as the scheme resolves it (exact: "
            "between the samples as at them; slammer: at the samples)",
    "kmax_samples": "largest |k| of the layer's average acceleration k(t) g at the record's samples, in g "
                    "(SLAMMER's Kmax)",
}


@dataclass(frozen=True)
class FlexibleResult:
    """One flexible analysis: the permanent displacement, the layer's peak and properties, the histories.

    Attributes
    ----------
    model, method, ky, g, polarity, layer:
        What was solved: the model and scheme, k_y [1] (a number or a
        :class:`~stickslip.solvers.yield_table.YieldTable`), g [m/s²], ``"normal"``
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
    time:
        Sample times [s].
    average_acceleration:
        k(t)·g [m/s²] at the samples.
    modal_displacement:
        The layer's modal coordinate u [m] at the samples.
    block_displacement, block_velocity:
        The block's downslope displacement [m] and velocity [m/s] relative to the layer's base.
    ledger:
        The energy ledger per unit mass [J/kg] (:class:`~stickslip.solvers.layer_energy.FlexibleLedger`),
        kept by the ``exact`` scheme; ``None`` for ``slammer`` or when not asked for.
    """

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
    time: np.ndarray = field(repr=False)
    average_acceleration: np.ndarray = field(repr=False)
    modal_displacement: np.ndarray = field(repr=False)
    block_displacement: np.ndarray = field(repr=False)
    block_velocity: np.ndarray = field(repr=False)
    ledger: FlexibleLedger | None = field(default=None, repr=False)

    def scalars(self) -> dict:
        """The end results: D [m], k_max and k_max at the samples [1] (:data:`KMAX_NAMES`), V_s [m/s], damping [1],
        iterations, the energy dissipated by friction
        per unit mass E_df = ∫ k_y(D) g dD over the one-way slide [J/kg] (any scheme) and, with a ledger, its other
        energies at the end of the record and its largest residual [J/kg] (units: :data:`SCALAR_UNITS`)."""
        table = self.ky if isinstance(self.ky, YieldTable) else YieldTable((0.0,), (self.ky,))
        scalars = {"displacement": self.displacement, "kmax": self.kmax, "kmax_samples": self.kmax_samples,
                   "vs_final": self.vs_final,
                   "damping_final": self.damping_final, "iterations": self.iterations,
                   "energy_dissipated_per_mass": self.g * float(table_integral(self.displacement, table.displacement,
                                                                               table.ky))}
        if self.ledger is not None:
            scalars.update({f"{name}_per_mass": float(values[-1]) for name, values in self.ledger.histories().items()
                            if f"{name}_per_mass" in SCALAR_UNITS and f"{name}_per_mass" not in scalars})
            scalars["balance_residual_per_mass"] = self.ledger.balance_residual
        return scalars

    def yield_parameters(self) -> dict:
        """``{"ky": k_y}``, or a table's ``{"ky": [k_y,i], "ky_displacement": [D_i]}`` (k_y [1], D [m])."""
        return self.ky.parameters() if isinstance(self.ky, YieldTable) else {"ky": self.ky}

    def describe_yield(self) -> str:
        """``k_y = 0.1``, or the table's line (:meth:`YieldTable.describe`)."""
        return self.ky.describe() if isinstance(self.ky, YieldTable) else f"k_y = {self.ky:g}"

    def to_xarray(self):
        """The histories and scalars as an :class:`xarray.Dataset` on ``time`` [s], with units and the case.

        The ledger's histories are ``{name}_per_mass`` [J/kg] (:data:`~stickslip.solvers.layer_energy.HISTORIES`);
        their values at the end of the record are the scalars of the same names.
        """
        import xarray as xr

        histories = {
            "average_acceleration": (self.average_acceleration, "m s-2", "average acceleration of the layer k(t) g"),
            "modal_displacement": (self.modal_displacement, "m", "modal displacement u of the layer's first mode"),
            "block_displacement": (self.block_displacement, "m", "downslope displacement of the block"),
            "block_velocity": (self.block_velocity, "m s-1", "downslope velocity of the block"),
        }
        dataset = xr.Dataset(
            {name: ("time", values, {"units": units, "long_name": long_name})
             for name, (values, units, long_name) in histories.items()},
            coords={"time": ("time", self.time, {"units": "s"})},
        )
        if self.ledger is not None:  # histories whose last value is the scalar of the same name
            for name, values in self.ledger.histories().items():
                dataset[f"{name}_per_mass"] = ("time", values, {"units": "J kg-1",
                                                                "long_name": HISTORIES[name] + " per unit mass"})
        for name, value in self.scalars().items():
            if name not in dataset:
                dataset[name] = ((), value, {"units": SCALAR_UNITS[name],
                                             **({"long_name": KMAX_NAMES[name]} if name in KMAX_NAMES else {})})
        dataset.attrs.update(model=self.model, method=self.method, **self.yield_parameters(), g=self.g,
                             polarity=self.polarity,
                             height=self.layer.height, vs=self.layer.vs, vs_base=self.layer.vs_base,
                             damping=self.layer.damping, soil_model=self.layer.soil_model,
                             reference_strain_percent=self.layer.reference_strain)
        return dataset


def solve_flexible(record: Record, ky: float | YieldTable, layer: Layer, model_name: str = "decoupled",
                   method: str = "exact", g: float = STANDARD_GRAVITY, inverse: bool = False,
                   ledger: bool = True) -> FlexibleResult:
    """Solve the flexible sliding block on ``record`` (acceleration [m/s²]) at the yield coefficient ``ky`` [1].

    Parameters
    ----------
    record:
        The ground motion; a positive acceleration drives the block downslope.
    ky:
        Yield coefficient k_y [1]: the block slides when the layer's average
        acceleration (decoupled) or base shear (coupled) exceeds k_y·g.  A
        :class:`~stickslip.solvers.yield_table.YieldTable` makes k_y vary with
        the block's downslope displacement (``method="slammer"``; a table of
        one pair is its constant k_y, which every scheme takes).
    layer:
        The sliding mass (:class:`~stickslip.solvers.layer.Layer`).
    model_name:
        ``"decoupled"`` or ``"coupled"`` (:data:`MODELS`).
    method:
        The scheme: ``"exact"`` (:mod:`stickslip.solvers.layer_exact`, closed forms per step, located events)
        or ``"slammer"`` (:mod:`stickslip.solvers.layer_slammer`, SLAMMER 1.1's own stepping).
    g:
        Gravitational acceleration [m/s²] (SLAMMER's is 9.80665).
    inverse:
        Solve the record with its sign flipped (SLAMMER's inverse polarity).
    ledger:
        Keep the energy ledger (:mod:`stickslip.solvers.layer_energy`) where the scheme keeps one
        (``exact``; ``slammer`` keeps none).  It about doubles the exact scheme's time per
        sample (closed-form integrals in every step); sweeps and the verification leave it off.
    """
    entry = model(model_name)
    if not entry.layer:
        raise StickslipError(f"model {model_name!r} takes no soil layer: solve it with stickslip.solve")
    if method not in entry.schemes:
        raise StickslipError(f"the {model_name} model is solved by method {', '.join(entry.schemes)}, not {method!r}")
    table = ky if isinstance(ky, YieldTable) else YieldTable((0.0,), (checked_positive(ky, "yield coefficient k_y [1]"),))
    scheme = layer_scheme(method)
    if len(table) > 1 and not scheme.TAKES_YIELD_TABLE:
        takers = [name for name in entry.schemes if layer_scheme(name).TAKES_YIELD_TABLE]
        raise StickslipError(f"method {method} solves a constant yield coefficient, not {table.describe()}; "
                             f"use method {' or '.join(takers)}")
    g = checked_positive(g, "gravity g [m/s²]")
    acceleration = -record.acceleration if inverse else record.acceleration
    options = {"ledger": True} if ledger and scheme.KEEPS_LEDGER else {}
    steps = scheme.flexible_steps(model_name, acceleration, record.dt, table.thresholds(g), layer, **options)
    sample_peak = float(np.max(np.abs(steps["average_acceleration"])))
    return FlexibleResult(
        model=model_name, method=method, ky=table if len(table) > 1 else table.ky[0], g=g, polarity="inverse" if inverse else "normal", layer=layer,
        displacement=float(abs(steps["displacement"][-1])),
        kmax=float(steps.get("peak_average_acceleration", sample_peak)) / g, kmax_samples=sample_peak / g,
        vs_final=float(steps["vs"]), damping_final=float(steps["damping"]), iterations=int(steps["iterations"]),
        time=np.arange(record.npts) * record.dt, average_acceleration=steps["average_acceleration"],
        modal_displacement=steps["u"], block_displacement=steps["displacement"], block_velocity=steps["velocity"],
        ledger=steps.get("ledger"),
    )
