"""The rigid block over a grid of its friction ratio μ or yield coefficient k_y, into one cube.

:func:`rigid_sweep` is the rigid model's ``sweep``
(:meth:`stickslip.models.rigid.RigidModel.sweep`): every record (and scaled
version) at every value of the grid, solved by the scheme's batched kernel
(``exact``) or one solve per case (``newmark``, ``slammer``), into the cube
of :mod:`stickslip.sweeps`.  Its variables are the response scalars of
:class:`~stickslip.models.rigid.response.Response` (energies in J for the
given block mass, lengths in m); a block on a slope (a yield coefficient)
adds the permanent ``downslope_displacement`` and the body-force work.  Its
attributes record the model, solver and its options, mass, gravity, how the
block slides and the polarity; :func:`cube_parameters` reads them back.
"""

from __future__ import annotations

import json

import numpy as np

from stickslip.grids import COEFFICIENTS, Grid
from stickslip.models.rigid.history import SCALAR_NAMES
from stickslip.models.rigid.response import SCALAR_ATTRS, SLOPE_SCALAR_ATTRS
from stickslip.plumbing.files import provenance
from stickslip.sweeps import CubeLayout, fill_cube, missing_cube
from stickslip.units import CF_CONVENTIONS, UNITS

#: The end results of a flat block's cube, in the kernel's column order: name -> CF attributes.
VARIABLES: dict[str, dict[str, str]] = {name: {"units": SCALAR_ATTRS[name][0], "long_name": SCALAR_ATTRS[name][1]}
                                        for name in SCALAR_NAMES}

#: What a block on a slope adds after :data:`VARIABLES`: name -> CF attributes.
SLOPE_VARIABLES: dict[str, dict[str, str]] = {name: {"units": units, "long_name": long_name}
                                              for name, (units, long_name) in SLOPE_SCALAR_ATTRS.items()}

#: The kernel's energies, per unit mass [J/kg] (times the mass in the cube, J).
ENERGIES = ("energy_dissipated", "energy_input", "kinetic_energy_final")

#: The cube's ``polarity`` attribute: whether the records were solved with their sign flipped.
POLARITY = {False: "normal (record as given)", True: "inverse (record sign flipped)"}


def sweep_setup(model, method=None, options=None, **parameters):
    """The grid, the block at the grid's first value, the scheme and its options of a sweep's ``parameters``.

    ``parameters`` are the rigid model's, the swept coefficient (``mu`` or
    ``ky``) given as a list of values [1]; each is checked as a solve checks it.
    """
    given = {name: parameters.pop(name, None) for name in COEFFICIENTS}
    named = [name for name, values in given.items() if values is not None]
    if len(named) != 1:  # the model's own check says what is wrong with the combination
        model.case(model.checked({**parameters, **{name: 1.0 for name in named}}))
    grid = Grid(named[0], given[named[0]])
    case = model.case(model.checked({**parameters, grid.name: float(grid.values[0])}))
    scheme = model.scheme(method)
    scheme.check_resistance(case.resistance)
    return grid, case, scheme, scheme.run_options(options, case.inverse)


def layout(grid: Grid, case, scheme, run_options: dict, scale=None, target_pga=None, config=None) -> CubeLayout:
    """The cube's layout for the block ``case`` over ``grid``, solved by ``scheme`` with ``run_options``."""
    variables = {**VARIABLES, **(SLOPE_VARIABLES if case.resistance.on_slope else {})}
    solver = {}
    for name, value in run_options.items():
        solver[f"solver_{name}"] = int(value) if isinstance(value, bool) else value  # NetCDF has no booleans
        if name in UNITS:
            solver[f"solver_{name}_units"] = UNITS[name]
    attrs = {
        "title": grid.coefficient.title,
        "Conventions": CF_CONVENTIONS,
        **provenance(),
        "model": "rigid",
        "solver": scheme.name,
        **solver,
        "block_mass": case.mass,
        "block_mass_units": UNITS["block_mass"],
        "gravity": case.g,
        "gravity_units": UNITS["gravity"],
        **sliding_attrs(case),
        "polarity": POLARITY[case.inverse],
        "scaling": "factor" if scale is not None else "target_pga" if target_pga is not None else "none",
        "config": json.dumps(dict(config or {}), sort_keys=True, default=str),
    }
    coords = {}
    if case.resistance.on_slope:
        coords["yield_acceleration"] = (grid.values * case.g, {"units": UNITS["yield_acceleration"],
                                                               "long_name": "yield acceleration k_y g"})
    return CubeLayout(grid, variables, attrs, case.g, scale, target_pga, coords, counts=("n_slip_episodes",))


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


def end_results(records, case, scheme, grid: Grid, options: dict) -> np.ndarray:
    """The end results (records, grid values, variables) of the block ``case`` at every grid value, in the cube's units.

    A batched scheme solves all at once; another solves case by case, with the scheme's ``options`` as given.
    """
    if scheme.batched:
        values = np.array(scheme.sweep(records, case, grid.name, grid.values), dtype=float)
        for name in ENERGIES:
            values[..., SCALAR_NAMES.index(name)] *= case.mass
        if case.resistance.on_slope:
            displacement = values[..., SCALAR_NAMES.index("residual_displacement")]
            body = np.array([case.at(grid.name, value).resistance.body for value in grid.values])
            body_work = np.where(body == 0.0, 0.0, case.mass * body * displacement)  # as Response.body_force_work
            values = np.concatenate([values, -displacement[..., None], body_work[..., None]], axis=-1)
        return values
    names = list(VARIABLES) + (list(SLOPE_VARIABLES) if case.resistance.on_slope else [])
    values = np.empty((len(records), grid.values.size, len(names)))
    for i, record in enumerate(records):
        for j, value in enumerate(grid.values):
            scalars = scheme.solve(record, case.at(grid.name, value), **options).scalars()
            values[i, j] = [scalars[name] for name in names]
    return values


def rigid_sweep(model, records, method=None, *, scale=None, target_pga=None, progress: bool = False, config=None,
                measures=None, options=None, **parameters):
    """Every record (scaled by ``scale`` [1] or to ``target_pga`` [m/s²]) over a grid of ``mu`` or ``ky``; one cube.

    ``parameters`` are the rigid model's (``mu`` or ``ky`` a list of values
    [1], ``mass`` [kg], ``g`` [m/s²], ``direction``, ``thrust_angle``
    [degrees], ``inverse``); ``options`` the scheme's (``{"time_step":
    0.001}`` [s] for ``newmark``; the cube records every option the solver
    ran with); ``config`` settings recorded in the cube's ``config``
    attribute (JSON); ``measures`` the records' intensity measures when known
    (:func:`stickslip.sweeps.fill_cube`).  Returns the cube, dimensions
    ``(record, [scale or target_pga,] mu or ky)``.
    """
    grid, case, scheme, run_options = sweep_setup(model, method, options, **parameters)
    given = {name: value for name, value in (options or {}).items() if value is not None}
    cube_layout = layout(grid, case, scheme, run_options, scale, target_pga, config)
    return fill_cube(records, cube_layout, lambda versions: end_results(versions, case, scheme, grid, given),
                     batched=scheme.batched, measures=measures, progress=progress)


def rigid_missing_cube(model, record_id: str, status: str, *, scale=None, target_pga=None, config=None,
                       method=None, options=None, **parameters):
    """The cube of a record that could not be swept, as :func:`rigid_sweep` would lay it out (NaN, with ``status``)."""
    grid, case, scheme, run_options = sweep_setup(model, method, options, **parameters)
    return missing_cube(record_id, status, layout(grid, case, scheme, run_options, scale, target_pga, config))
