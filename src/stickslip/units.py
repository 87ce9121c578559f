"""The units of every quantity stickslip writes, in UDUNITS spelling, and their equivalent spellings.

One table, :data:`UNITS`, names the units of each column of the workflow's
tables (``results/tables/*.csv``, listed in ``results/tables/units.csv``),
of each NetCDF variable (records, cubes, histories) and of each intensity
measure (``measures --json``, ``results/measures/*.json``).  The spelling is
UDUNITS-2's, as the CF Conventions ask: ``m s-2``, ``m s-1``, ``m``, ``s``,
``J``, ``J kg-1``, ``kg``, ``N``, ``Hz`` and ``1`` for a dimensionless number or a
count.  Every NetCDF file declares :data:`CF_CONVENTIONS`.

Readers accept the spellings people write for the same units (``m/s²``,
``m/s2``, ``m/s^2`` …): :func:`normalise_units` maps them to the UDUNITS one.
A small map rather than a units library: the few units stickslip reads need no
C library (UDUNITS-2) at run time; the tests check the map against UDUNITS-2
itself (``cfunits``).
"""

from __future__ import annotations

#: The CF Conventions version of every NetCDF file stickslip writes: the newest
#: version the CF checker (``cfchecker``, run by the tests) validates.
CF_CONVENTIONS = "CF-1.8"

#: Units of each quantity (table column, NetCDF variable, intensity measure), UDUNITS spelling.
UNITS: dict[str, str] = {
    # ground motion and intensity measures
    "acceleration": "m s-2",
    "pga": "m s-2",
    "paper_pga": "m s-2",
    "target_pga": "m s-2",
    "rms_acceleration": "m s-2",
    "paper_rms_acceleration": "m s-2",
    "gravity": "m s-2",
    "pgv": "m s-1",
    "pgd": "m",
    "arias_intensity": "m s-1",
    "paper_arias_intensity": "m s-1",
    "t5": "s",
    "t95": "s",
    "significant_duration": "s",
    "paper_significant_duration": "s",
    "significant_duration_samples": "s",
    "paper_significant_duration_samples": "s",
    "mean_period": "s",
    "duration": "s",
    "paper_duration": "s",
    "dt": "s",
    "paper_dt": "s",
    "time": "s",
    "time_step": "s",
    "npts": "1",
    "scale_factor": "1",
    # harmonic base motion
    "frequency": "Hz",
    "displacement_amplitude": "m",
    "ramp_cycles": "1",
    # block and friction
    "block_mass": "kg",
    "masses": "kg",
    "mu": "1",
    "mu_max": "1",
    "mu_max_fine": "1",
    "mu_max_continuous": "1",
    "mu_max_per_mass": "1",
    "mu_low": "1",
    "mu_high": "1",
    "mu_low_fine": "1",
    "mu_high_fine": "1",
    "paper_mu_low": "1",
    "paper_mu_high": "1",
    "q": "1",
    "q_above": "1",
    "q_at_most": "1",
    "ky": "1",
    "ky_displacement": "m",
    "ky_max": "1",
    "ky_max_continuous": "1",
    "ky_max_at_grid_edge": "1",
    "ky_low": "1",
    "ky_high": "1",
    "ky_low_at_grid_edge": "1",
    "ky_high_at_grid_edge": "1",
    "reference_ky": "1",
    "yield_acceleration": "m s-2",
    "thrust_angle": "degree",
    # response
    "energy_dissipated": "J",
    "paper_energy_dissipated": "J",
    "energy_dissipated_max": "J",
    "energy_dissipated_max_fine": "J",
    "energy_dissipated_max_continuous": "J",
    "energy_dissipated_per_mass": "J kg-1",
    # the flexible block's ledger per unit mass of the sliding mass (stickslip.models.layer.energy)
    **{f"{name}_per_mass": "J kg-1" for name in ("energy_input", "energy_damped", "kinetic_energy", "strain_energy",
                                                  "block_energy_input", "block_kinetic_energy", "balance_residual")},
    "energy_input": "J",
    "kinetic_energy_final": "J",
    "balance_residual": "J",
    "residual_displacement": "m",
    "downslope_displacement": "m",
    "body_force_work": "J",
    "peak_relative_displacement": "m",
    "sliding_path": "m",
    "slip_fraction": "1",
    "n_slip_episodes": "1",
    "phase_changes": "1",
    "max_abs_acceleration_stick": "m s-2",
    "stick_stutter_rms": "m s-2",
    "block_acceleration": "m s-2",
    "phase": "1",
    # time histories
    "ground_acceleration": "m s-2",
    "ground_velocity": "m s-1",
    "ground_displacement": "m",
    "relative_acceleration": "m s-2",
    "relative_velocity": "m s-1",
    "relative_displacement": "m",
    "absolute_acceleration": "m s-2",
    "absolute_velocity": "m s-1",
    "absolute_displacement": "m",
    "friction_force": "N",
    "kinetic_energy": "J",
    # record descriptions
    "mw": "1",
    "year": "1",
    # record collections (docs/collections.md): metadata, SLAMMER's published measures (PGA in units of
    # standard gravity, g = 9.80665 m s-2), ours in SLAMMER's definitions
    "bytes": "byte",
    "epicentral_distance": "km",
    "hypocentral_distance": "km",
    "rupture_distance": "km",
    "vs30": "m s-1",
    "latitude": "degree_north",
    "longitude": "degree_east",
    "listed_pga": "standard_free_fall",
    "slammer_pga": "standard_free_fall",
    "slammer_pgv": "cm s-1",
    "slammer_arias_intensity": "m s-1",
    "slammer_dobry_duration": "s",
    "slammer_mean_period": "s",
    "slammer_convention_pga": "standard_free_fall",
    "slammer_convention_arias_intensity": "m s-1",
    "slammer_convention_dobry_duration": "s",
    "slammer_convention_mean_period": "s",
    # the collection study
    "mu_max_at_grid_edge": "1",
    "mu_low_at_grid_edge": "1",
    "mu_high_at_grid_edge": "1",
    "contiguous": "1",
    "energy_dissipated_reference": "J",
    "efficiency": "1",
    "mu_max_g_over_pga": "1",
    # the per-record results of every sweep (stickslip.optimum)
    "near_optimal_fraction": "1",
    **{f"{name}_at_{at}": "m" for name in ("peak_relative_displacement", "residual_displacement")
       for at in ("mu_max", "mu_low", "mu_high", "ky_max", "ky_low", "ky_high")},
    **{f"downslope_displacement_at_{at}": "m" for at in ("ky_max", "ky_low", "ky_high")},
    "largest_stroke": "m",
    "largest_residual_displacement": "m",
    "largest_downslope_displacement": "m",
    **{f"{c}_at_largest_{name}": "1" for c in ("mu", "ky") for name in ("stroke", "residual_displacement")},
    "pgv_over_pga": "s",
    "reference_mu": "1",
    "share_reference_in_range": "1",
    "median_efficiency_reference": "1",
    "best_single_mu": "1",
    "share_best_single_mu": "1",
    "design_mu": "1",
    "share_design_mu": "1",
    "design_mu_low": "1",
    "design_mu_high": "1",
    "pearson_r": "1",
    "spearman_rho": "1",
    "loeo_skill": "1",
    "factor": "1",
    "mu_max_scaled": "1",
    "mu_max_ratio": "1",
    "max_relative_energy_difference": "1",
    # single solved cases (model_responses.csv)
    "normalized_friction": "1",
    "scale": "1",
    # the flexible block's end results (stickslip.models.layer.result.FlexibleResult); the layer's peak average
    # acceleration k_max in g, as the scheme resolves it and at the samples
    "displacement": "m",
    "kmax": "1",
    "kmax_samples": "1",
    "vs_final": "m s-1",
    "damping_final": "1",
    "iterations": "1",
    # the friction pendulum and the vertical motion (stickslip.models.pendulum)
    "radius": "m",
    "mu_slow": "1",
    "mu_fast": "1",
    "mu_slow_ratio": "1",
    "rate": "s m-1",
    "energy_input_vertical": "J",
    "potential_energy": "J",
    "potential_energy_final": "J",
    "restoring_work": "J",  # the spring's stored energy (stickslip.models.spring)
    "peak_base_shear": "1",
    "liftoff_time": "s",
    "vertical_acceleration": "m s-2",
    "period": "s",
    "initial_velocity": "m s-1",
    # the vertical-motion study's tables (stickslip.studies.vertical.effect): each case at mu_max and at the
    # reference mu, the vertical's peaks in g, and the changes the vertical makes (ratios, differences)
    **{f"peak_base_shear_at_{at}": "1" for at in ("mu_max", "mu_low", "mu_high")},
    "peak_relative_displacement_at_reference": "m",
    "residual_displacement_at_reference": "m",
    "peak_base_shear_at_reference": "1",
    "vertical_down_peak": "1",
    "vertical_pga": "1",
    "energy_ratio": "1",
    "mu_max_change": "1",
    "peak_displacement_ratio": "1",
    "residual_displacement_change": "m",
    "base_shear_ratio": "1",
    "energy_ratio_at_reference": "1",
    "peak_displacement_ratio_at_reference": "1",
    "residual_displacement_change_at_reference": "m",
    "base_shear_ratio_at_reference": "1",
    # the planar block's end results (stickslip.models.planar.response.PlanarResponse)
    "peak_displacement": "m",
    # the verification against SLAMMER 1.1's own results (results/verification/): SLAMMER's units, cm and
    # standard gravity
    "slammer_target_pga": "standard_free_fall",
    "reference_displacement": "cm",
    "computed_displacement": "cm",
    "displacement_difference": "cm",
    "displacement_tolerance": "cm",
    "normalized_difference": "1",
    "refinement": "1",
    "exact_displacement": "cm",
    "scheme_displacement": "cm",
    "difference_from_exact": "cm",
    # ... and its flexible analyses (flexible_analyses.csv): the layer, SLAMMER's other outputs, pySLAMMER's value
    "height": "m",
    "vs": "m s-1",
    "vs_base": "m s-1",
    "damping": "1",
    "reference_strain": "percent",
    "pyslammer_displacement": "cm",
    **{f"{which}_{name}": unit for which in ("reference", "computed")
       for name, unit in (("kmax", "1"), ("vs_final", "m s-1"), ("damping_final", "1"))},
    # Jibson (2007), recomputed (results/collections/<study>/jibson2007_displacements.csv): Jibson's unit, cm;
    # ky is a_c in units of g
    "critical_acceleration_ratio": "1",
    "newmark_displacement": "cm",
    # stickslip displacements (stickslip.slope_displacements): D_n per polarity and Jibson's (2007) estimates, in cm
    **{f"newmark_displacement_{polarity}": "cm" for polarity in ("normal", "inverse", "mean")},
    "jibson2007_ratio": "cm",
    "jibson2007_arias": "cm",
    "records": "1",
    # comparisons
    "relative_difference": "1",
    **{f"rel_diff_{name}": "1" for name in (
        "duration", "significant_duration", "significant_duration_samples", "dt", "arias_intensity", "pga")},
    "reading_rms_relative_difference": "1",
    "max_relative_spread": "1",
    "tolerance": "1",
}

#: Spellings readers accept, lower case and without spaces around, -> the UDUNITS spelling.
EQUIVALENT_SPELLINGS: dict[str, str] = {
    **{spelling: "m s-2" for spelling in (
        "m s-2", "m/s2", "m/s^2", "m/s**2", "m/s²", "m s^-2", "m.s-2", "m s**-2", "m/s/s", "m·s-2", "m s⁻²", "m·s⁻²")},
    **{spelling: "m s-1" for spelling in ("m s-1", "m/s", "m s^-1", "m.s-1", "m s**-1", "m·s-1", "m s⁻¹", "m·s⁻¹")},
    **{spelling: "cm s-1" for spelling in ("cm s-1", "cm/s", "cm s^-1", "cm.s-1", "cm s**-1", "cm·s-1", "cm s⁻¹",
                                           "cm·s⁻¹")},
    **{spelling: "J kg-1" for spelling in ("j kg-1", "j/kg", "j kg^-1", "j.kg-1", "j·kg-1", "j kg⁻¹")},
    **{spelling: "1" for spelling in ("1", "-", "")},
}


#: How a table for people writes units (UDUNITS spelling -> shown): dimensionless as ``-``.
READABLE_UNITS = {"1": "-", "m s-2": "m/s2", "m s-1": "m/s", "J kg-1": "J/kg"}


def readable_units(units: str) -> str:
    """``units`` (UDUNITS spelling) as a table for people shows them: ``m s-2`` -> ``m/s2``, ``1`` -> ``-``."""
    return READABLE_UNITS.get(units, units)


def energy_units(mass: float) -> str:
    """How text and pages label an energy [J] of a block of ``mass`` [kg]: ``J kg-1`` for the default mass, 1 kg
    (:data:`~stickslip.constants.DEFAULT_BLOCK_MASS`: its energies are those per kg of any block, since they scale
    with the mass), else ``J``.  JSON, CSV and NetCDF keep ``J`` with the mass beside it."""
    from stickslip.constants import DEFAULT_BLOCK_MASS

    return "J kg-1" if mass == DEFAULT_BLOCK_MASS else "J"


def per_unit_mass(text: str, mass: float) -> str:
    """``text`` with each energy's ``[J]`` written ``[J/kg]`` for the default mass (:func:`energy_units`)."""
    return text.replace("[J]", f"[{readable_units(energy_units(mass))}]")


def normalise_units(spelling: str) -> str | None:
    """The UDUNITS spelling of the units ``spelling`` (``"m/s²"`` -> ``"m s-2"``), or None if unknown.

    A spelling that is already one of :data:`UNITS`' values is returned as it is.
    """
    text = " ".join(str(spelling).split())
    if text in UNITS.values():
        return text
    return EQUIVALENT_SPELLINGS.get(text.lower())


#: The units a quantity may be written in (a command-line option's value, ``--radius 200cm``), for each unit stickslip
#: takes it in (UDUNITS spelling): the spelling, lower case, -> how many of that unit one of it is.  The first of
#: each is the unit itself; ``""`` is a bare number.  Any spelling of the same units is taken
#: (:func:`normalise_units`, and a record's units, ``gal``), read by :mod:`stickslip.cli.quantities`.
QUANTITY_UNITS: dict[str, dict[str, float]] = {
    "1": {"": 1.0, "%": 0.01},
    "m": {"m": 1.0, "cm": 0.01, "mm": 0.001, "km": 1000.0},
    "km": {"km": 1.0, "m": 0.001},
    "kg": {"kg": 1.0, "g": 0.001, "t": 1000.0},
    "s": {"s": 1.0, "ms": 0.001, "min": 60.0},
    "m s-1": {"m/s": 1.0, "cm/s": 0.01, "mm/s": 0.001, "km/h": 1.0 / 3.6},
    "s m-1": {"s/m": 1.0, "s/cm": 100.0},
    "degree": {"deg": 1.0, "degree": 1.0, "degrees": 1.0, "°": 1.0},
    "m s-2": {"m/s2": 1.0, "cm/s2": 0.01, "gal": 0.01},
}

