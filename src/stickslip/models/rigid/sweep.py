"""The rigid block's cube over a grid of its friction ratio μ or yield coefficient k_y: what it holds and says.

The rigid model sweeps as every swept model does
(:class:`stickslip.models.swept.SweptModel`); this module says what is its
own.  The cube's variables (:func:`variables`) are the response scalars of
:class:`~stickslip.models.rigid.response.Response` (energies in J for the
given block mass, lengths in m); a block on a slope (a yield coefficient)
adds the permanent ``downslope_displacement`` and the body-force work, and
the grid's ``yield_acceleration`` (:func:`grid_coords`).  Its attributes
(:func:`cube_attrs`) record the solver's options, mass, gravity, how the
block slides and the polarity; :func:`cube_parameters` reads them back.
"""

from __future__ import annotations

from stickslip.grids import Grid
from stickslip.models.rigid.history import SCALAR_NAMES
from stickslip.models.rigid.response import SCALAR_ATTRS, SLOPE_SCALAR_ATTRS
from stickslip.units import UNITS

#: The end results of a flat block's cube, in the kernel's column order: name -> CF attributes.
VARIABLES: dict[str, dict[str, str]] = {name: {"units": SCALAR_ATTRS[name][0], "long_name": SCALAR_ATTRS[name][1]}
                                        for name in SCALAR_NAMES}

#: What a block on a slope adds after :data:`VARIABLES`: name -> CF attributes.
SLOPE_VARIABLES: dict[str, dict[str, str]] = {name: {"units": units, "long_name": long_name}
                                              for name, (units, long_name) in SLOPE_SCALAR_ATTRS.items()}

#: The cube's ``polarity`` attribute: whether the records were solved with their sign flipped.
POLARITY = {False: "normal (record as given)", True: "inverse (record sign flipped)"}


def variables(case) -> dict[str, dict[str, str]]:
    """The cube's end results for the block ``case``: :data:`VARIABLES`, and on a slope :data:`SLOPE_VARIABLES`."""
    return {**VARIABLES, **(SLOPE_VARIABLES if case.resistance.on_slope else {})}


def cube_attrs(case, run_options: dict) -> dict:
    """The solver's options (with units), mass, gravity, how the block slides and the polarity, as attributes."""
    solver = {}
    for name, value in run_options.items():
        solver[f"solver_{name}"] = int(value) if isinstance(value, bool) else value  # NetCDF has no booleans
        if name in UNITS:
            solver[f"solver_{name}_units"] = UNITS[name]
    return {**solver, "block_mass": case.mass, "block_mass_units": UNITS["block_mass"], "gravity": case.g,
            "gravity_units": UNITS["gravity"], **sliding_attrs(case), "polarity": POLARITY[case.inverse]}


def grid_coords(grid: Grid, case) -> dict:
    """On a slope, the grid's yield accelerations k_y·g [m s-2]; none on a flat surface."""
    if not case.resistance.on_slope:
        return {}
    return {"yield_acceleration": (grid.values * case.g, {"units": UNITS["yield_acceleration"],
                                                          "long_name": "yield acceleration k_y g"})}


def sliding_attrs(case) -> dict:
    """The cube attributes that say how the block slides (a slope's direction and thrust angle)."""
    parameters = case.resistance.parameters
    if not case.resistance.on_slope:
        return {"sliding": "flat surface, Coulomb friction"}
    if parameters["direction"] == "down":
        return {"sliding": "one-way (downslope only)", "direction": "down"}
    return {"sliding": "two-way (downslope and upslope)", "direction": "both",
            "thrust_angle": parameters["thrust_angle"], "thrust_angle_units": UNITS["thrust_angle"]}


def cube_parameters(cube) -> tuple[str, dict, dict]:
    """``(method, options, parameters)`` that a rigid cube was swept with, read from its attributes.

    ``parameters`` are the rigid model's but its swept coefficient: ``mass``
    [kg], ``g`` [m/s²], ``inverse`` and, on a slope, ``direction`` and
    ``thrust_angle`` [degrees]; ``options`` the scheme's as it ran.
    """
    attrs = cube.attrs
    parameters = {"mass": float(attrs["block_mass"]), "g": float(attrs["gravity"]),
                  "inverse": attrs.get("polarity", POLARITY[False]) == POLARITY[True],
                  **{key: attrs[key] for key in ("direction", "thrust_angle") if key in attrs}}
    options = {key.removeprefix("solver_"): value for key, value in attrs.items()
               if key.startswith("solver_") and not key.endswith("_units")}
    return attrs["solver"], options, parameters
