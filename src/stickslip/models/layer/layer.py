"""The flexible sliding mass: a soil layer over a sliding surface, as SLAMMER 1.1 models it (Rathje & Bray 2000).

The mass above the sliding surface is a uniform shear beam of height H [m],
shear-wave velocity V_s [m/s] and unit weight γ, fixed at its base (the
sliding surface), driven by the base acceleration a(t) [m/s²].  SLAMMER keeps
its first mode only, with the mode shape φ(z) = sin(π z / 2H) (z up from the
base), so that the layer's state is one modal coordinate u(t) [m]:

    ü + 2 ξ ω u̇ + ω² u = −(L/M) a(t),        ω = π V_s / (2H),

with, per unit area of the base (ρ = γ/g the mass density),

    M_tot = ρ H          the layer's mass,
    L     = 2 ρ H / π    its participation, ∫ρ φ dz,
    M     = ρ H / 2      its modal mass, ∫ρ φ² dz,

(SLAMMER's ``DeCoupledCommon``, ``Decoupled`` and ``Coupled``: ``Mtot``,
``L = −2ρH/π·cos π`` and ``M``).  ρ cancels from every quantity used here
(L/M = 4/π, L/M_tot = 2/π, L²/(M M_tot) = 8/π²), so the unit weight, which
SLAMMER fixes at 20 kN/m³ or 120 pcf, does not matter.  The average
acceleration of the layer, the seismic coefficient that drives a block on
the sliding surface in the decoupled analysis, is

    k(t)·g = a(t) + (L/M_tot) ü(t).

**Damping.** The modal damping ratio is the material damping plus a
foundation damping that stands for the energy radiated into the base
(``Decoupled``, ``Coupled``: ``dampf``)::

    ξ_f = min(0.55016 (V_s,base / V_s)^−0.9904, 0.20),

so ξ = ξ_material + ξ_f.  A linear-elastic analysis keeps V_s and ξ.

**Equivalent-linear soil** (``DeCoupledCommon.eq`` and ``eq_property``):
after a linear response with the current V_s and ξ, the effective shear
strain is γ_eff = 0.65 · 1.57 · max|u| / H (1.57 ≈ π/2, the mode's largest
strain per unit u times H; 0.65 the usual ratio of effective to peak strain),
in percent γ% = 100 γ_eff; with the reference strain γ_r [%], the
hyperbolic modulus reduction and Masing damping with Darendeli's reduction
factor 0.62·(G/G_max)^0.1 give

    V_s = V_s,0 / √(1 + γ%/γ_r),
    ξ_material [%] = 0.62 (1/(1 + γ%/γ_r))^0.1 · (100/π) · (4 (γ% − γ_r ln((γ_r + γ%)/γ_r)) / (γ%²/(γ% + γ_r)) − 2) + 1,
    ξ = (ξ_f [%] at the new V_s + ξ_material [%]) / 100,

the material damping given by the user taking no part after the first
response.  The iteration repeats until both the shear modulus (∝ V_s²) and the
material damping change by at most 5 % from one iteration to the next
(:data:`CONVERGENCE_PERCENT`); the first iteration always continues
(SLAMMER compares with a material damping of zero before any).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from stickslip.checks import checked_positive
from stickslip.errors import StickslipError

#: The default reference strain γ_r of the equivalent-linear soil [%] (SLAMMER's and pySLAMMER's 0.05 %).
DEFAULT_REFERENCE_STRAIN = 0.05

#: L/M: the participation over the modal mass of the first mode [1].
PARTICIPATION_OVER_MODAL_MASS = 4.0 / math.pi

#: L/M_tot: the participation over the layer's mass [1]; k·g = a + (L/M_tot)·ü.
PARTICIPATION_OVER_MASS = 2.0 / math.pi

#: L²/(M·M_tot) [1]: the share of the modal mass that moves with the block while it slides (coupled analysis).
COUPLING = 8.0 / math.pi**2

#: SLAMMER's ratio of effective to peak shear strain times the mode's strain factor: γ_eff = 0.65·1.57·max|u|/H.
EFFECTIVE_STRAIN_FACTOR = 0.65 * 1.57

#: The largest foundation damping ratio [1] (SLAMMER's cap of 20 %).
MAX_FOUNDATION_DAMPING = 0.20

#: The equivalent-linear iteration stops when shear modulus and damping each change by at most this [%].
CONVERGENCE_PERCENT = 5.0

#: The soil models of the layer: linear elastic, or equivalent linear (strain-compatible V_s and damping).
SOIL_MODELS = ("linear", "equivalent-linear")


def foundation_damping(vs: float, vs_base: float) -> float:
    """The foundation damping ratio ξ_f [1] of a layer of V_s over a base of V_s,base [m/s] (capped at 0.20)."""
    return min(0.55016 * (vs_base / vs) ** -0.9904, MAX_FOUNDATION_DAMPING)


def circular_frequency(vs: float, height: float) -> float:
    """ω = π V_s / (2H) [rad/s] of the layer's first mode (V_s [m/s], H [m])."""
    return math.pi * vs / (2.0 * height)


@dataclass(frozen=True)
class Layer:
    """The sliding mass as a soil layer: what SLAMMER's decoupled and coupled analyses take.

    Attributes
    ----------
    height:
        H [m], the layer's thickness above the sliding surface.
    vs:
        V_s [m/s], its shear-wave velocity (the small-strain one for the equivalent-linear model).
    vs_base:
        V_s,base [m/s], the shear-wave velocity below the sliding surface (foundation damping).
    damping:
        ξ_material [1], the layer's material damping ratio; the foundation damping
        is added to it (:func:`foundation_damping`).  May be negative if the
        total stays in [0, 1): SLAMMER's verification cases use −0.05 with a
        foundation damping of 0.20, a total of 0.15.
    soil_model:
        ``"linear"`` or ``"equivalent-linear"`` (:data:`SOIL_MODELS`).
    reference_strain:
        γ_r [%] of the equivalent-linear model (0.05 means 0.05 %).
    """

    height: float
    vs: float
    vs_base: float
    damping: float = 0.05
    soil_model: str = "linear"
    reference_strain: float = DEFAULT_REFERENCE_STRAIN

    def __post_init__(self):
        checked_positive(self.height, "layer height H [m]")
        checked_positive(self.vs, "shear-wave velocity V_s [m/s]")
        checked_positive(self.vs_base, "base shear-wave velocity V_s,base [m/s]")
        if not math.isfinite(self.damping):
            raise StickslipError(f"damping ratio {self.damping!r}: expected a number")
        total = self.total_damping
        if not 0.0 <= total < 1.0:
            raise StickslipError(
                f"damping ratio {self.damping:g}: with the foundation damping {self.foundation_damping:.4g} "
                f"(V_s {self.vs:g} m/s over V_s,base {self.vs_base:g} m/s) the total is {total:.4g}; "
                "it must lie in [0, 1)")
        if self.soil_model not in SOIL_MODELS:
            raise StickslipError(f"soil model {self.soil_model!r}: expected one of {', '.join(SOIL_MODELS)}")
        checked_positive(self.reference_strain, "reference strain [%]")

    def parameters(self) -> dict:
        """The layer as the flexible models' parameters (:func:`stickslip.solve` with ``model="coupled"``)."""
        equivalent_linear = self.soil_model == "equivalent-linear"
        return {"height": self.height, "vs": self.vs, "vs_base": self.vs_base, "damping": self.damping,
                "equivalent_linear": equivalent_linear,
                **({"reference_strain": self.reference_strain} if equivalent_linear else {})}

    @property
    def foundation_damping(self) -> float:
        """ξ_f [1] at the small-strain V_s."""
        return foundation_damping(self.vs, self.vs_base)

    @property
    def total_damping(self) -> float:
        """ξ = ξ_material + ξ_f [1], the modal damping of a linear-elastic analysis."""
        return self.damping + self.foundation_damping

    @property
    def period(self) -> float:
        """T = 4H / V_s [s], the first mode's period at the small-strain V_s."""
        return 4.0 * self.height / self.vs


def equivalent_linear_properties(peak_modal_displacement: float, height: float, vs_initial: float, vs_base: float,
                                 reference_strain: float) -> tuple[float, float, float]:
    """The strain-compatible V_s [m/s], total damping ξ [1] and material damping [%] of one iteration.

    ``peak_modal_displacement`` max|u| [m] of the last response, ``height`` H
    [m], ``vs_initial`` the small-strain V_s,0 and ``vs_base`` [m/s],
    ``reference_strain`` γ_r [%]; the rules of the module docstring.
    """
    strain = 100.0 * EFFECTIVE_STRAIN_FACTOR * peak_modal_displacement / height  # [%]
    ratio = strain / reference_strain
    vs = vs_initial / math.sqrt(1.0 + ratio)
    if strain > 0.0:  # SLAMMER's arithmetic, log((γ_r + γ)/γ_r) included
        masing = 100.0 / math.pi * (4.0 * (strain - reference_strain * math.log((reference_strain + strain)
                                                                                / reference_strain))
                                    / (strain * strain / (strain + reference_strain)) - 2.0)
    else:  # its limit at zero strain
        masing = 0.0
    material = 0.62 * (1.0 / (1.0 + ratio)) ** 0.1 * masing + 1.0  # [%]
    return vs, (100.0 * foundation_damping(vs, vs_base) + material) / 100.0, material


def settled_properties(layer: Layer, peak_modal_displacement) -> tuple[float, float, int]:
    """The layer's V_s [m/s] and total damping ξ [1] for its final response, and the iterations run (SLAMMER's ``eq``).

    ``peak_modal_displacement(vs, damping)`` is max|u| [m] of the layer's
    response with those properties (the scheme's).  A linear layer keeps its V_s
    and ξ_material + ξ_f; an equivalent-linear one iterates
    :func:`equivalent_linear_properties` until the modulus and the material
    damping each change by at most :data:`CONVERGENCE_PERCENT` (the first
    iteration always continues: SLAMMER compares with a damping of zero).
    """
    vs, damping = layer.vs, layer.total_damping
    if layer.soil_model == "linear":
        return vs, damping, 0
    modulus_change = damping_change = 100.0
    material_before, iterations = 0.0, 0
    while modulus_change > CONVERGENCE_PERCENT or damping_change > CONVERGENCE_PERCENT:
        new_vs, damping, material = equivalent_linear_properties(peak_modal_displacement(vs, damping), layer.height,
                                                                 layer.vs, layer.vs_base, layer.reference_strain)
        modulus_change = abs(vs * vs - new_vs * new_vs) / (vs * vs) * 100.0
        damping_change = (abs((material_before - material) / material_before) * 100.0 if material_before != 0.0
                          else math.inf)
        vs, material_before, iterations = new_vs, material, iterations + 1
    return vs, damping, iterations
