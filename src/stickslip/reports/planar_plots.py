"""Figures of a block sliding in the plane: E_df(μ) and the stroke beside each component alone, the path, the ledger.

Each function takes what :func:`stickslip.planar_sweep` and
:func:`stickslip.solve` return for a :class:`~stickslip.records.pair.RecordPair`
and draws one matplotlib figure; SI units throughout.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from stickslip.records.components import component_label
from stickslip.reports.plots import LEGEND_OUTSIDE, axis_names, draw_path, new_figure
from stickslip.units import energy_units, readable_units

#: Colours of the directions of a planar cube: both components at once, and each alone.
DIRECTION_STYLE = {"plane": {"color": "k", "lw": 1.6}, "first": {"color": "tab:blue", "lw": 1.0, "ls": "--"},
                   "second": {"color": "tab:orange", "lw": 1.0, "ls": "--"}}


def _labels(cube) -> dict[str, str]:
    """The legend label of each direction of a one-pair cube."""
    return {"plane": "in the plane (both components)",
            "first": f"{component_label(str(cube['first_component'].item()))} alone (1-D)",
            "second": f"{component_label(str(cube['second_component'].item()))} alone (1-D)"}


def plot_planar_curves(cube, quantity: str, ylabel: str, title: str) -> Figure:
    """``quantity`` of a one-pair cube (pair dimension selected) against μ, in the plane and each component alone.

    The μ of largest E_df of each direction is marked when ``quantity`` is the dissipated energy;
    with an azimuth sweep, the largest and median 1-D value over the turned axes are shaded.
    """
    figure, ax = new_figure(figsize=(9.0, 4.5))
    mu = cube["mu"].values
    labels = _labels(cube)
    rotd = f"{quantity}_rotd100"
    if rotd in cube:
        ax.fill_between(mu, cube[f"{quantity}_rotd50"].values, cube[rotd].values, color="0.85",
                        label="1-D on the turned axes: median to largest over the azimuths")
    for direction, style in DIRECTION_STYLE.items():
        ax.plot(mu, cube[quantity].sel(direction=direction).values, label=labels[direction], **style)
        if quantity == "energy_dissipated" and np.isfinite(cube["mu_max"].sel(direction=direction).item()):
            ax.plot(cube["mu_max"].sel(direction=direction).item(),
                    cube["energy_dissipated_max"].sel(direction=direction).item(), "o", color=style["color"],
                    mfc="none" if direction != "plane" else style["color"])
    sliding = cube["energy_dissipated"].max("direction").values > 0
    right = mu[min(np.flatnonzero(sliding)[-1] + 2, mu.size - 1)] if sliding.any() else mu[-1]
    ax.set(xlabel="friction ratio μ [-]", ylabel=ylabel, xlim=(0, right), ylim=(0, None), title=title)
    ax.grid(True, lw=0.3)
    ax.legend(fontsize="small", **LEGEND_OUTSIDE)
    return figure


def plot_path(response, title: str) -> Figure:
    """The block's path relative to the base in the plane [m], its start, end and farthest point."""
    figure, ax = new_figure(figsize=(6.5, 6.0))
    draw_path(ax, response, title)
    return figure


def plot_acceleration_orbit(response, title: str) -> Figure:
    """The ground acceleration's orbit [m/s²] and the friction circle of radius μ·g: outside it, the block slides."""
    figure, ax = new_figure(figsize=(6.5, 6.0))
    acceleration = response.ground_acceleration
    ax.plot(acceleration[:, 0], acceleration[:, 1], color="0.45", lw=0.5)
    sliding = response.sliding
    ax.plot(acceleration[sliding, 0], acceleration[sliding, 1], ".", color="tab:red", ms=1.5,
            label="samples where the block slides")
    angle = np.linspace(0.0, 2.0 * np.pi, 361)
    radius = response.mu * response.g
    ax.plot(radius * np.cos(angle), radius * np.sin(angle), color="tab:blue", lw=1.4,
            label=f"friction circle μ·g = {radius:.3g} m/s²")
    reach = float(np.max(np.abs(acceleration))) * 1.1
    first, second = axis_names(response.pair)
    ax.set(xlim=(-reach, reach), ylim=(-reach, reach), aspect="equal", title=title,
           xlabel=f"ground acceleration along {first} [m/s²]", ylabel=f"ground acceleration along {second} [m/s²]")
    ax.grid(True, lw=0.3)
    ax.legend(fontsize="small", loc="upper left")
    return figure


def plot_ledger(response, title: str) -> Figure:
    """E_I, E_df and E_k [J; J/kg for the default 1 kg block] against time, and below them, on its own axis and scale, the balance residual
    E_k − E_k(0) + E_df − E_I [J] (round-off, some 1e-13 J: on the energies' axis it would be a flat line)."""
    figure, (energies, residual) = new_figure(2, 1, figsize=(9.0, 5.5), sharex=True, height_ratios=[3, 1])
    time, units = response.time, readable_units(energy_units(response.mass))
    energies.plot(time, response.energy_input, color="k", lw=1.2, label="input E_I")
    energies.plot(time, response.energy_dissipated, color="tab:red", lw=1.2, label="dissipated by friction E_df")
    energies.plot(time, response.kinetic_energy, color="tab:blue", lw=0.8, label="kinetic E_k")
    energies.set(ylabel=f"energy [{units}]", title=title)
    residual.plot(time, response.balance_residual, color="0.45", lw=0.6,
                  label="balance residual E_k − E_k(0) + E_df − E_I")
    residual.set(xlabel="time [s]", ylabel=f"residual [{units}]")
    for ax in (energies, residual):
        ax.grid(True, lw=0.3)
        ax.legend(fontsize="small", **LEGEND_OUTSIDE)
    return figure
