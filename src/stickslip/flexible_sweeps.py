"""Sweeps of the flexible sliding block: records × yield coefficients k_y × layer heights H, into one cube.

:func:`flexible_sweep` solves every case with
:func:`stickslip.solvers.flexible.solve_flexible` and returns an
:class:`xarray.Dataset` with dimensions ``record``, ``ky`` and ``height``:
the permanent displacement D [m] and the energy dissipated by friction
E_df = k_y g D [J/kg] per case (and, from the ``exact`` scheme's ledger, the
ground's work E_I and the layer's damped energy E_d [J/kg]), and per record and
height the layer's k_max [1] (between the samples as at them for the ``exact``
scheme, and at the samples, SLAMMER's), final V_s [m/s] and damping [1] and the
equivalent-linear iterations (they do not depend on k_y).
:func:`stickslip.sweeps.write_cube` writes it.
"""

from __future__ import annotations

import json
import sys
from collections.abc import Sequence

import numpy as np
import xarray as xr
from tqdm import tqdm

from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import StickslipError
from stickslip.grids import positive_increasing
from stickslip.plumbing.files import provenance
from stickslip.records.record import Record
from stickslip.solvers.flexible import KMAX_NAMES, MODELS, SCALAR_UNITS, layer_scheme, model, solve_flexible
from stickslip.solvers.layer import DEFAULT_REFERENCE_STRAIN, Layer
from stickslip.units import CF_CONVENTIONS

#: The cube's variables: name -> (dimensions, long name).
VARIABLES = {
    "displacement": (("record", "ky", "height"), "permanent downslope displacement of the block"),
    "energy_dissipated_per_mass": (("record", "ky", "height"), "energy dissipated by friction per unit mass of the "
                                   "sliding mass, E_df = k_y g D"),
    "energy_input_per_mass": (("record", "ky", "height"), "work of the ground per unit mass of the sliding mass "
                              "(on the layer, decoupled), E_I"),
    "energy_damped_per_mass": (("record", "ky", "height"), "energy dissipated by the layer's damping per unit mass "
                               "of the sliding mass, E_d"),
    **{name: (("record", "height"), long_name) for name, long_name in KMAX_NAMES.items()},
    "vs_final": (("record", "height"), "shear-wave velocity of the layer's final response"),
    "damping_final": (("record", "height"), "total damping ratio of the layer's final response"),
    "iterations": (("record", "height"), "equivalent-linear iterations run"),
}


def flexible_sweep(records: Sequence[Record], ky, height, vs: float, vs_base: float, damping: float = 0.05,
                   soil_model: str = "linear", reference_strain: float = DEFAULT_REFERENCE_STRAIN,
                   model_name: str = "decoupled", method: str = "exact", g: float = STANDARD_GRAVITY,
                   inverse: bool = False, progress: bool = False) -> xr.Dataset:
    """Solve the flexible block on every record for every k_y [1] and layer height H [m]; one cube.

    ``vs``, ``vs_base`` [m/s], ``damping`` [1], ``soil_model`` and
    ``reference_strain`` [%] are the layer's (:class:`~stickslip.solvers.layer.Layer`),
    ``model_name`` and ``method`` as :func:`~stickslip.solvers.flexible.solve_flexible`
    takes them; ``inverse`` flips every record's sign.  Records, k_y and H are
    checked before any case is solved.
    """
    if not model(model_name).layer:
        flexible = ", ".join(name for name, entry in MODELS.items() if entry.layer)
        raise StickslipError(f"model {model_name!r} has no soil layer: flexible_sweep solves {flexible} "
                             "(stickslip.sweep solves the rigid block)")
    kys = positive_increasing(ky, "yield coefficients ky")
    heights = positive_increasing(height, "layer heights H [m]")
    layers = [Layer(float(h), vs, vs_base, damping, soil_model, reference_strain) for h in heights]
    shape = (len(records), kys.size, heights.size)
    ledger = layer_scheme(method).KEEPS_LEDGER
    per_case = {name: np.zeros(shape) for name in ("displacement", "energy_dissipated_per_mass",
                                                    *(("energy_input_per_mass", "energy_damped_per_mass")
                                                      if ledger else ()))}
    per_layer = {name: np.zeros(shape[::2], dtype=int if name == "iterations" else float)
                 for name in ("kmax", "kmax_samples", "vs_final", "damping_final", "iterations")}
    with tqdm(total=len(records) * heights.size, desc="flexible sweep", unit="record x height", disable=not progress,
              file=sys.stderr) as bar:
        for r, record in enumerate(records):
            for h, layer in enumerate(layers):
                for k, value in enumerate(kys):
                    result = solve_flexible(record, float(value), layer, model_name, method, g=g, inverse=inverse,
                                            ledger=ledger)
                    scalars = result.scalars()
                    for name, values in per_case.items():
                        values[r, k, h] = scalars[name]
                for name in per_layer:
                    per_layer[name][r, h] = getattr(result, name)
                bar.update()
    cube = xr.Dataset(
        {name: (VARIABLES[name][0], values, {"units": SCALAR_UNITS[name], "long_name": VARIABLES[name][1]})
         for name, values in {**per_case, **per_layer}.items()},
        coords={"record": ("record", [record.meta.record_id or f"record_{i}" for i, record in enumerate(records)]),
                "ky": ("ky", kys, {"units": "1", "long_name": "yield coefficient k_y (yield acceleration / g)"}),
                "height": ("height", heights, {"units": "m", "long_name": "layer height H"})},
    )
    cube.attrs.update(title="stickslip flexible-block sweep", Conventions=CF_CONVENTIONS, **provenance(),
                      model=model_name, solver=method, vs=vs, vs_units="m s-1", vs_base=vs_base,
                      damping=damping, soil_model=soil_model, reference_strain=reference_strain,
                      reference_strain_units="percent", gravity=g, gravity_units="m s-2",
                      polarity="inverse" if inverse else "normal",
                      sources=json.dumps([record.meta.source for record in records]))
    return cube
