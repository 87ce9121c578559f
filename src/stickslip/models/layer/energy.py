"""The energy ledger of the flexible sliding block, per unit mass of the sliding mass [J/kg].

Energies are absolute, as the rigid block's (the ground's velocity
v_g(t) = ∫₀ᵗ a dt' [m/s] from rest), and per unit mass of the layer
M_tot (ρH per unit area of the base, which cancels).  With the mode shape
φ(z) = sin(πz/2H), r = L/M_tot = 2/π and M/M_tot = 1/2
(:mod:`stickslip.models.layer.layer`), a layer whose base moves at v_b and
whose modal coordinate is u has

    E_k = ½ v_b² + r v_b u̇ + ¼ u̇²          (½∫ρ(v_b + φu̇)² dz / M_tot),
    E_s = ¼ ω² u²,                          E_d = ½ · 2ξω ∫u̇² dt,

the kinetic, strain and viscously damped energies (ω and ξ the final
response's, foundation damping included).  The block slides one way, so its
friction dissipates E_df = k_y g D.

**Coupled** (one system: the layer on its sliding base, v_b = v_g − w, w the
downslope sliding velocity).  The ground acts on the sliding mass with the
force per unit mass F = a + r ü while the block sticks and k_y g while it
slides, and puts in E_I = ∫F v_g dt, so that

    E_k − E_k(0) + E_s + E_d + E_df = E_I.

**Decoupled** (two systems, each closing alone).  The layer on a base that
moves with the ground (v_b = v_g, F = a + r ü throughout):
E_k − E_k(0) + E_s + E_d = E_I.  The block on the layer's average motion,
velocity v_b = v_g + r u̇ (whose rate is k(t)·g), with F_b = k·g while it
sticks and k_y g while it slides: E_I,block = ∫F_b v_b dt,
E_k,block = ½(v_b − w)² and E_k,block − E_k,block(0) + E_df = E_I,block.
The block's input is not the layer's: sliding takes energy from a layer that
never loses it, the decoupled analysis' known inconsistency, which the two
ledgers show side by side.

The integrals E_I, ∫u̇² dt and E_I,block are closed forms per phase of the
exact scheme (:func:`stickslip.models.layer.exact._ledger_step`), so the
ledger closes to round-off.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from stickslip.models.layer.layer import PARTICIPATION_OVER_MASS, PARTICIPATION_OVER_MODAL_MASS

#: M/M_tot: the modal mass over the layer's mass [1].
MODAL_MASS_FRACTION = PARTICIPATION_OVER_MASS / PARTICIPATION_OVER_MODAL_MASS

#: The ledger's histories: name, and what each is (every one in J/kg).
HISTORIES = {
    "energy_input": "work of the ground on the sliding mass (coupled) or on the layer (decoupled), E_I",
    "kinetic_energy": "absolute kinetic energy of the layer, E_k",
    "strain_energy": "strain energy of the layer's mode, E_s",
    "energy_damped": "energy dissipated by the layer's viscous (material and foundation) damping, E_d",
    "energy_dissipated": "energy dissipated by friction on the sliding surface, E_df = k_y g D",
    "block_energy_input": "work of the layer's average motion on the decoupled block, E_I,block",
    "block_kinetic_energy": "absolute kinetic energy of the decoupled block, E_k,block",
}


@dataclass(frozen=True)
class FlexibleLedger:
    """The energy ledger of one flexible analysis at the samples, per unit mass of the sliding mass [J/kg].

    Attributes
    ----------
    coupled:
        Whether the block and the layer are coupled (one system) or decoupled (two).
    energy_input, kinetic_energy, strain_energy, energy_damped, energy_dissipated:
        E_I, E_k, E_s, E_d and E_df (:data:`HISTORIES`).
    block_energy_input, block_kinetic_energy:
        The decoupled block's own ledger, E_I,block and E_k,block; ``None`` for the coupled model.
    """

    coupled: bool
    energy_input: np.ndarray = field(repr=False)
    kinetic_energy: np.ndarray = field(repr=False)
    strain_energy: np.ndarray = field(repr=False)
    energy_damped: np.ndarray = field(repr=False)
    energy_dissipated: np.ndarray = field(repr=False)
    block_energy_input: np.ndarray | None = field(default=None, repr=False)
    block_kinetic_energy: np.ndarray | None = field(default=None, repr=False)

    def residuals(self) -> dict[str, np.ndarray]:
        """Each system's E_k − E_k(0) + (stored and dissipated) − E_I [J/kg]: the whole ``system`` (coupled),
        or the ``layer`` and the ``block`` (decoupled)."""
        layer = self.kinetic_energy - self.kinetic_energy[0] + self.strain_energy + self.energy_damped
        if self.block_energy_input is None:
            return {"system": layer + self.energy_dissipated - self.energy_input}
        block = self.block_kinetic_energy - self.block_kinetic_energy[0] + self.energy_dissipated
        return {"layer": layer - self.energy_input, "block": block - self.block_energy_input}

    @property
    def balance_residual(self) -> float:
        """The largest |residual| over the record and the systems [J/kg] (round-off for the exact scheme)."""
        return float(max(np.max(np.abs(residual)) for residual in self.residuals().values()))

    def histories(self) -> dict[str, np.ndarray]:
        """The model's histories by name (:data:`HISTORIES`) [J/kg]."""
        return {name: getattr(self, name) for name in HISTORIES if getattr(self, name) is not None}


def flexible_ledger(coupled: bool, integrals: np.ndarray, u: np.ndarray, sliding_velocity: np.ndarray,
                    displacement: np.ndarray, threshold: float, omega: float, damping: float) -> FlexibleLedger:
    """The ledger from the exact scheme's integrals at the samples and its response.

    ``integrals`` are the rows v_g [m/s], u̇ [m/s], E_I [J/kg], ∫u̇² dt [m²/s]
    and E_I,block [J/kg] (:func:`stickslip.models.layer.exact.flexible_exact`);
    ``u`` [m] the modal coordinate, ``sliding_velocity`` w [m/s] and
    ``displacement`` D [m] the block's downslope ones, ``threshold`` k_y g [m/s²],
    ``omega`` [rad/s] and ``damping`` [1] the layer's final ω and ξ; ``coupled``
    whether the block and layer are coupled.
    """
    ground_velocity, modal_velocity, energy_input, velocity_square, block_input = integrals
    base_velocity = ground_velocity - sliding_velocity if coupled else ground_velocity
    ratio, fraction = PARTICIPATION_OVER_MASS, MODAL_MASS_FRACTION
    energies = {
        "energy_input": energy_input,
        "kinetic_energy": (0.5 * base_velocity**2 + ratio * base_velocity * modal_velocity
                           + 0.5 * fraction * modal_velocity**2),
        "strain_energy": 0.5 * fraction * omega**2 * u**2,
        "energy_damped": fraction * 2.0 * damping * omega * velocity_square,
        "energy_dissipated": threshold * displacement,
    }
    if not coupled:
        block_velocity = ground_velocity + ratio * modal_velocity
        energies.update(block_energy_input=block_input,
                        block_kinetic_energy=0.5 * (block_velocity - sliding_velocity) ** 2)
    return FlexibleLedger(coupled, **energies)
