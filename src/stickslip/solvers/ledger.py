"""The ledger of a slider in one direction: what the kernels on the event engine return, per unit mass.

The kernels of a slider with a restoring stiffness and a normal force
(:mod:`~stickslip.solvers.restoring`, :mod:`~stickslip.models.pendulum.vertical_exact`,
:mod:`~stickslip.models.pendulum.integrated`) fill a history array with the
columns :data:`HISTORY_COLUMNS` at the samples and a scalar array with the
columns :data:`SCALAR_NAMES`; :func:`history_dict` turns them into the plain
dict their wrappers return, with the energy ledger (docs/solvers.md, "The
friction pendulum and the vertical motion")

    E_k − E_k(0) + E_p − E_p(0) + E_df = E_I + W_v,

E_k = ½·(u̇_g + u̇)² the absolute kinetic energy, E_p = ½·ω²·u² the energy
stored by a restoring stiffness ω² (a state, ≥ 0: for the friction pendulum,
ω² = g/R, the potential energy of the slider's height u²/(2R) on its surface;
for a block on a spring, ω² = k/m), E_df = ∫μ(u̇)·(N/m)·|du| the friction's work, E_I = ∫ü·u̇_g dt the
absolute input energy of the horizontal motion and W_v = −∫(N/m − g)·(u/R) du
the work of the vertical motion through the normal force on the curved
surface (zero without a vertical, where N = m·g), all per unit mass [J/kg].
The restoring force's work ∫(N/mR)·u du is E_p − E_p(0) − W_v.
"""

from __future__ import annotations

import numba
import numpy as np

from stickslip.solvers.events import FLIGHT, STICK

#: Columns of a kernel's history (n samples × 7), per unit mass: the state just after each sample.
HISTORY_COLUMNS = (
    "relative_displacement",  # u [m], relative to the ground
    "relative_velocity",      # u̇ [m/s]
    "phase",                  # 0 stick, −1/+1 sliding with u̇ ≶ 0, 2 lifted off
    "energy_dissipated",      # E_df/m [J/kg], cumulative
    "energy_input",           # E_I/m [J/kg], cumulative
    "energy_input_vertical",  # W_v/m [J/kg], cumulative
    "sliding_path",           # ∫|du| while in contact [m], cumulative
)

#: End-of-record scalars of a kernel, per unit mass, in this order.
SCALAR_NAMES = (
    "energy_dissipated",           # E_df/m [J/kg]
    "energy_input",                # E_I/m [J/kg]
    "energy_input_vertical",       # W_v/m at the end [J/kg]
    "kinetic_energy_final",        # ½·(u̇_g + u̇)² at the end [J/kg]
    "potential_energy_final",      # E_p/m = ½·ω²·u² at the end [J/kg]
    "residual_displacement",       # u at the end [m]
    "peak_relative_displacement",  # max |u| over the whole motion [m]
    "sliding_path",                # ∫|du| while in contact [m]
    "slip_fraction",               # time sliding / record duration [-]
    "n_slip_episodes",             # stick-to-motion transitions [-]
    "peak_base_shear",             # max |ü|/g over the motion: V/W, W = m·g [-]
    "liftoff_time",                # time lifted off [s]
)

#: Units of :data:`SCALAR_NAMES` (UDUNITS), per unit mass for the energies.
SCALAR_UNITS = {
    "energy_dissipated": "J/kg", "energy_input": "J/kg", "energy_input_vertical": "J/kg",
    "kinetic_energy_final": "J/kg", "potential_energy_final": "J/kg",
    "residual_displacement": "m", "peak_relative_displacement": "m", "sliding_path": "m", "slip_fraction": "1",
    "n_slip_episodes": "1", "peak_base_shear": "1", "liftoff_time": "s",
}


@numba.njit(cache=True)
def potential_energy(distance, stiffness):
    """E_p/m = ½·ω²·|u|² [J/kg] of a slider at the distance |u| [m] (a number or an array) from its middle under the
    restoring ``stiffness`` ω² [1/s²] (0: none): on a spherical surface ω² = g/R, the height |u|²/(2R) in
    small-angle geometry times g."""
    return 0.5 * stiffness * distance * distance


def history_dict(history: np.ndarray, scalars: np.ndarray, ground_velocity: np.ndarray, dt: float,
                 stiffness: float) -> dict:
    """The plain dict of a kernel's ``history`` (n × 7) and ``scalars``, with the ledger's terms at the samples.

    Keys: ``time`` [s], ``ground_velocity`` u̇_g [m/s], the columns of
    :data:`HISTORY_COLUMNS` (``phase`` as int8), ``kinetic_energy`` E_k/m and
    ``potential_energy`` E_p/m (:func:`potential_energy`, ``stiffness`` ω²
    [1/s²]) [J/kg], ``balance_residual``
    E_k − E_k(0) + E_p − E_p(0) + E_df − E_I − W_v [J/kg], and ``scalars``, a
    dict of :data:`SCALAR_NAMES` (units in :data:`SCALAR_UNITS`).
    """
    result = {"time": np.arange(history.shape[0]) * dt, "ground_velocity": ground_velocity}
    for column, name in enumerate(HISTORY_COLUMNS):
        result[name] = history[:, column].astype(np.int8) if name == "phase" else history[:, column].copy()
    absolute = ground_velocity + result["relative_velocity"]
    result["kinetic_energy"] = 0.5 * absolute * absolute
    result["potential_energy"] = potential_energy(result["relative_displacement"], float(stiffness))
    result["balance_residual"] = (result["kinetic_energy"] - result["kinetic_energy"][0]
                                  + result["potential_energy"] - result["potential_energy"][0]
                                  + result["energy_dissipated"] - result["energy_input"]
                                  - result["energy_input_vertical"])
    result["scalars"] = {name: float(value) for name, value in zip(SCALAR_NAMES, scalars)}
    return result


@numba.njit(cache=True)
def store_scalars(out, energy_dissipated, energy_input, vertical_input, absolute_velocity, stiffness, displacement,
                  peak, path, slip_time, duration, episodes, peak_absolute_acceleration, g, liftoff_time):
    """Write the end-of-record scalars into ``out`` in the order of :data:`SCALAR_NAMES`.

    Energies per unit mass [J/kg] (``vertical_input`` W_v/m); ``absolute_velocity`` u̇_g + u̇ at the end
    [m/s]; ``stiffness`` ω² [1/s²] of the potential energy at the end; displacements and path [m]; times [s]; the
    largest |ü| [m/s²] over the motion, divided here by ``g`` [m/s²] into the base shear over the weight.
    """
    out[0] = energy_dissipated
    out[1] = energy_input
    out[2] = vertical_input
    out[3] = 0.5 * absolute_velocity * absolute_velocity
    out[4] = potential_energy(displacement, stiffness)
    out[5] = displacement
    out[6] = peak
    out[7] = path
    out[8] = slip_time / duration
    out[9] = episodes
    out[10] = peak_absolute_acceleration / g
    out[11] = liftoff_time
