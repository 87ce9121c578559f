"""Figures of the single solved cases (the paper's Figs. 2, 3, 11-12 and 16, and a flexible mass), from stored responses.

Each function takes the NetCDF datasets that
:func:`stickslip.studies.model_response.cases.write_model_responses` wrote (every
history of :class:`stickslip.models.rigid.response.Response`, SI units), or for
:func:`plot_flexible_ledger` those of
:func:`stickslip.studies.model_response.flexible_ledger.write_flexible_ledgers`, and returns a
:class:`matplotlib.figure.Figure`.  Nothing is computed here beyond unit
changes for display (m to mm).  Legends sit below the axes, clear of the data.
"""

from __future__ import annotations

import textwrap

import xarray as xr
from matplotlib.figure import Figure

from stickslip.reports.plots import new_figure

BASE = {"color": "0.55", "linewidth": 0.9}
BLOCK = {"color": "C3", "linewidth": 1.0}


def _legend_below(figure: Figure, ax, ncol: int = 4) -> None:
    """One legend for the figure, under the axes (so that it covers no data)."""
    handles, labels = ax.get_legend_handles_labels()
    figure.legend(handles, labels, loc="outside lower center", ncol=ncol, fontsize="small", frameon=False)


def _case_title(dataset: xr.Dataset) -> str:
    return f"{dataset.attrs['record_id']}, μ = {float(dataset.attrs['mu']):.3g}, {dataset.attrs['method']} solver"


def plot_harmonic_regimes(stick_slip: xr.Dataset, permanent: xr.Dataset, threshold: float) -> Figure:
    """The paper's Fig. 2: absolute velocity [m/s] and acceleration [m/s²] of block and base, two regimes.

    ``stick_slip`` and ``permanent`` are the two harmonic cases (with their
    attributes ``normalized_friction`` and ``closed_form_regime``); ``threshold`` is f_f of Eq. 4 [-].  The closed
    forms are marked: the slip limit ±μ·g and, in each title, f_f (Eq. 3) and
    the regime Eq. 4 predicts.
    """
    figure, axes = new_figure(2, 2, figsize=(10.0, 6.5), sharex=True)
    for column, dataset in enumerate((stick_slip, permanent)):
        time = dataset.time.values
        limit = float(dataset.attrs["mu"]) * float(dataset.attrs["g"])
        velocity, acceleration = axes[0, column], axes[1, column]
        velocity.plot(time, dataset.ground_velocity, label="base", **BASE)
        velocity.plot(time, dataset.absolute_velocity, label="block", **BLOCK)
        acceleration.plot(time, dataset.ground_acceleration, **BASE)
        acceleration.plot(time, dataset.absolute_acceleration, **BLOCK)
        for sign in (1, -1):
            acceleration.axhline(sign * limit, color="k", linestyle="--", linewidth=0.8,
                                 label="±μg, the slip limit (closed form)" if sign == 1 else None)
        f_f = float(dataset.attrs["normalized_friction"])
        relation = "<" if f_f < threshold else "≥"
        velocity.set_title(f"({'ab'[column]}) f_f = {f_f:.2f} {relation} {threshold:.4f} (Eq. 4): "
                           f"{dataset.attrs['closed_form_regime'].replace('_', ' ')}\nμ = "
                           f"{float(dataset.attrs['mu']):.3f}", fontsize="medium")
        velocity.set_ylabel("absolute velocity [m/s]")
        acceleration.set_ylabel("absolute acceleration [m/s²]")
        acceleration.set_xlabel("time [s]")
        for ax in (velocity, acceleration):
            ax.grid(True, linewidth=0.3)
    handles, labels = axes[0, 0].get_legend_handles_labels()
    more, more_labels = axes[1, 0].get_legend_handles_labels()
    figure.legend(handles + more, labels + more_labels, loc="outside lower center", ncol=3, fontsize="small",
                  frameon=False)
    figure.suptitle("Harmonic base motion, exact solver, "
                    f"u_g0 = {float(stick_slip.attrs['displacement_amplitude']) * 1e3:g} mm, "
                    f"f0 = {float(stick_slip.attrs['frequency']):g} Hz")
    return figure


def plot_algorithm1(algorithm1: xr.Dataset, exact: xr.Dataset, reason: str) -> Figure:
    """The paper's Fig. 3: absolute displacement [m], velocity [m/s] and acceleration [m/s²], Algorithm 1 and exact."""
    panels = (("displacement", "m"), ("velocity", "m/s"), ("acceleration", "m/s²"))
    figure, axes = new_figure(3, 1, figsize=(9.0, 8.5), sharex=True)
    step = float(algorithm1.attrs["solver_time_step"])
    for ax, (name, units) in zip(axes, panels):
        ax.plot(exact.time, exact[f"ground_{name}"], label="base", **BASE)
        ax.plot(algorithm1.time, algorithm1[f"absolute_{name}"], label=f"block, Algorithm 1 (Δt = {step:g} s)",
                **BLOCK)
        ax.plot(exact.time, exact[f"absolute_{name}"], color="C0", linestyle="--", linewidth=0.8,
                label="block, exact solver")
        ax.set_ylabel(f"absolute {name} [{units}]")
        ax.grid(True, linewidth=0.3)
    axes[-1].set_xlabel("time [s]")
    _legend_below(figure, axes[0], ncol=3)
    figure.suptitle(f"Absolute response, {_case_title(algorithm1).replace(', newmark solver', '')}, "
                    f"Δt = {step:g} s\n" + "\n".join(textwrap.wrap(f"Substitute for Mendoza 1985: {reason}", 110)),
                    fontsize="medium")
    return figure


def plot_friction_response(dataset: xr.Dataset, title: str) -> Figure:
    """The paper's Fig. 16: relative displacement x [mm] and friction force F_f [N] against time, and F_f against x."""
    figure = Figure(figsize=(10.0, 7.0), layout="constrained")
    grid = figure.add_gridspec(2, 2)
    displacement_ax = figure.add_subplot(grid[0, 0])
    force_ax = figure.add_subplot(grid[1, 0], sharex=displacement_ax)
    loop_ax = figure.add_subplot(grid[:, 1])
    displacement = dataset.relative_displacement.values * 1e3
    force = dataset.friction_force.values
    displacement_ax.plot(dataset.time, displacement, **BLOCK)
    displacement_ax.set_ylabel("relative displacement x [mm]")
    displacement_ax.set_title("(a) relative displacement", fontsize="medium")
    force_ax.plot(dataset.time, force, **BLOCK)
    force_ax.set_ylabel("friction force F_f [N]")
    force_ax.set_xlabel("time [s]")
    force_ax.set_title("(b) friction force", fontsize="medium")
    loop_ax.plot(displacement, force, color="C0", linewidth=0.8)
    loop_ax.set_xlabel("relative displacement x [mm]")
    loop_ax.set_ylabel("friction force F_f [N]")
    loop_ax.set_title("(c) friction force against relative displacement", fontsize="medium")
    for ax in (displacement_ax, force_ax, loop_ax):
        ax.grid(True, linewidth=0.3)
    figure.suptitle(f"{title}: {_case_title(dataset)}, m = {float(dataset.attrs['mass']):g} kg")
    return figure


def plot_energy_histories(dataset: xr.Dataset, title: str) -> Figure:
    """Model energy histories E_k, E_df and E_I [J] against time [s] (the model side of the paper's Figs. 11-12)."""
    figure, ax = new_figure(figsize=(9.0, 5.0))
    ax.plot(dataset.time, dataset.energy_input, color="k", linewidth=1.0, label="E_I, absolute input energy")
    ax.plot(dataset.time, dataset.energy_dissipated, color="C3", linewidth=1.0, label="E_df, dissipated by friction")
    ax.plot(dataset.time, dataset.kinetic_energy, color="C0", linewidth=0.8, label="E_k = ½·m·u̇², kinetic")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("energy [J]")
    ax.grid(True, linewidth=0.3)
    _legend_below(figure, ax, ncol=3)
    ax.set_title(f"{title}: {_case_title(dataset)}, m = {float(dataset.attrs['mass']):g} kg\n"
                 f"E_df = {float(dataset.attrs['energy_dissipated']):.3f} J at the end; "
                 f"largest balance residual {float(dataset.attrs['balance_residual']):.1e} J", fontsize="medium")
    return figure


def plot_flexible_ledger(decoupled: xr.Dataset, coupled: xr.Dataset, title: str) -> Figure:
    """The flexible block's energy ledger per unit mass [J/kg] against time [s], decoupled beside coupled.

    Each dataset is :meth:`stickslip.models.layer.result.FlexibleResult.to_xarray`'s
    (exact scheme, with its ledger): E_I, E_df, E_d and the layer's stored
    E_k + E_s, and for the decoupled model the block's own input E_I,block.
    """
    figure = Figure(figsize=(11.0, 5.0), layout="constrained")
    axes = figure.subplots(1, 2, sharey=True)
    for ax, dataset, label in ((axes[0], decoupled, "(a) decoupled"), (axes[1], coupled, "(b) coupled")):
        ax.plot(dataset.time, dataset.energy_input_per_mass, color="k", linewidth=1.0,
                label="E_I, work of the ground (decoupled: on the layer)")
        if "block_energy_input_per_mass" in dataset:
            ax.plot(dataset.time, dataset.block_energy_input_per_mass, color="k", linewidth=1.0, linestyle="--",
                    label="E_I,block, work of the layer on the decoupled block")
        ax.plot(dataset.time, dataset.energy_dissipated_per_mass, color="C3", linewidth=1.0,
                label="E_df = k_y·g·D, dissipated by friction")
        ax.plot(dataset.time, dataset.energy_damped_per_mass, color="C0", linewidth=1.0,
                label="E_d, dissipated by the layer's damping")
        stored = dataset.kinetic_energy_per_mass + dataset.strain_energy_per_mass
        ax.plot(dataset.time, stored, color="C2", linewidth=0.7,
                label="E_k + E_s, kinetic and strain energy of the layer")
        ax.set_xlabel("time [s]")
        ax.grid(True, linewidth=0.3)
        ax.set_title(f"{label}: D = {100 * float(dataset.displacement):.1f} cm, "
                     f"E_df = {float(dataset.energy_dissipated_per_mass[-1]):.3f} J/kg\n"
                     f"largest ledger residual {float(dataset.balance_residual_per_mass):.1e} J/kg", fontsize="medium")
    axes[0].set_ylabel("energy per unit mass [J/kg]")
    handles = {text: handle for ax in axes for handle, text in zip(*ax.get_legend_handles_labels())}
    figure.legend(handles.values(), handles.keys(), loc="outside lower center", ncol=2, fontsize="small",
                  frameon=False)
    layer = decoupled.attrs
    figure.suptitle(f"{title}, exact scheme: a soil layer sliding at k_y = {float(layer['ky']):g}\n"
                    f"H = {float(layer['height']):g} m, V_s = {float(layer['vs']):g} m/s over "
                    f"{float(layer['vs_base']):g} m/s, damping {float(decoupled.damping_final):.2f} "
                    "(material and foundation)")
    return figure
