"""Sweeps of the flexible sliding block: records × yield coefficients k_y × layer heights H, into one cube.

:func:`layer_sweep` (the flexible models' ``sweep``) solves every case with
the model's scheme and returns an
:class:`xarray.Dataset` with dimensions ``record``, ``ky`` and ``height``:
the permanent displacement D [m] and the energy dissipated by friction
E_df = k_y g D [J/kg] per case (and, from the ``exact`` scheme's ledger, the
ground's work E_I and the layer's damped energy E_d [J/kg]), and per record and
height the layer's k_max [1] (between the samples as at them for the ``exact``
scheme, and at the samples, SLAMMER's), final V_s [m/s] and damping [1] and the
equivalent-linear iterations (they do not depend on k_y).  A record under
which an equivalent-linear layer softens below a fifth of its V_s gets one
warning, at its softest height (:func:`~stickslip.models.layer.result.warn_if_softened`).
:func:`stickslip.sweeps.write_cube` writes it.
"""

from __future__ import annotations

import json
import sys
from collections.abc import Sequence

import numpy as np
import xarray as xr
from tqdm import tqdm

from stickslip.errors import StickslipError
from stickslip.grids import positive_increasing
from stickslip.models.layer.result import SCALAR_UNITS, SCALARS, warn_if_softened
from stickslip.plumbing.files import provenance
from stickslip.records.record import Record
from stickslip.units import CF_CONVENTIONS

#: The cube's variables: name -> (dimensions, long name); the long names are the result's (:data:`SCALARS`).
VARIABLES = {name: (dimensions, SCALARS[name][1]) for name, dimensions in (
    *((name, ("record", "ky", "height")) for name in ("displacement", "energy_dissipated_per_mass",
                                                      "energy_input_per_mass", "energy_damped_per_mass")),
    *((name, ("record", "height")) for name in ("kmax", "kmax_samples", "vs_final", "damping_final", "iterations")),
)}


def _swept(values, what: str) -> np.ndarray:
    """The values of a swept parameter (one number or several), checked; ``what`` names them in a message."""
    if values is None:
        raise StickslipError(f"a flexible sweep needs {what}")
    return positive_increasing(values, what)


def layer_sweep(model, records: Sequence[Record], method: str | None = None, *, progress: bool = False,
                config=None, **parameters) -> xr.Dataset:
    """Solve the flexible ``model`` on every record for every k_y [1] and layer height H [m]; one cube.

    ``parameters`` are the model's (:class:`~stickslip.models.layer.LayerModel`):
    ``ky`` and ``height`` lists of values (or one value each), the layer's
    ``vs``, ``vs_base`` [m/s], ``damping`` [1], ``equivalent_linear`` and
    ``reference_strain`` [%], ``g`` [m/s²] and ``inverse``; ``config``
    settings recorded in the cube's ``config`` attribute.  Records, k_y and H
    are checked before any case is solved.
    """
    records = list(records)
    kys = _swept(parameters.pop("ky", None), "yield coefficients ky")
    heights = _swept(parameters.pop("height", None), "layer heights H [m]")
    cases = [[model.case(model.checked({**parameters, "ky": float(ky), "height": float(height)})) for ky in kys]
             for height in heights]
    scheme = model.scheme(method)
    shape = (len(records), kys.size, heights.size)
    ledger = scheme.keeps_ledger and cases[0][0].ledger
    per_case = {name: np.zeros(shape) for name in ("displacement", "energy_dissipated_per_mass",
                                                    *(("energy_input_per_mass", "energy_damped_per_mass")
                                                      if ledger else ()))}
    per_layer = {name: np.zeros(shape[::2], dtype=int if name == "iterations" else float)
                 for name in ("kmax", "kmax_samples", "vs_final", "damping_final", "iterations")}
    show = progress and sys.stderr.isatty()
    with tqdm(total=len(records) * heights.size, desc="flexible sweep", unit="record x height", disable=not show,
              file=sys.stderr) as bar:
        for r, record in enumerate(records):
            for h, row in enumerate(cases):
                for k, case in enumerate(row):
                    result = scheme.solve(record, case)
                    scalars = result.scalars()
                    for name, values in per_case.items():
                        values[r, k, h] = scalars[name]
                for name in per_layer:
                    per_layer[name][r, h] = getattr(result, name)
                bar.update()
    first = cases[0][0]
    for record, vs_final in zip(records, per_layer["vs_final"]):
        softest = int(np.argmin(vs_final))
        warn_if_softened(record, cases[softest][0].layer, vs_final[softest])
    cube = xr.Dataset(
        {name: (VARIABLES[name][0], values, {"units": SCALAR_UNITS[name], "long_name": VARIABLES[name][1]})
         for name, values in {**per_case, **per_layer}.items()},
        coords={"record": ("record", [record.meta.record_id or f"record_{i}" for i, record in enumerate(records)]),
                "ky": ("ky", kys, {"units": "1", "long_name": "yield coefficient k_y (yield acceleration / g)"}),
                "height": ("height", heights, {"units": "m", "long_name": "layer height H"})},
    )
    cube.attrs.update(title="stickslip flexible-block sweep", Conventions=CF_CONVENTIONS, **provenance(),
                      model=model.name, solver=scheme.name, vs=first.layer.vs, vs_units="m s-1",
                      vs_base=first.layer.vs_base, damping=first.layer.damping, soil_model=first.layer.soil_model,
                      reference_strain=first.layer.reference_strain, reference_strain_units="percent",
                      gravity=first.g, gravity_units="m s-2", polarity="inverse" if first.inverse else "normal",
                      sources=json.dumps([record.meta.source for record in records]),
                      **({"config": json.dumps(dict(config), sort_keys=True, default=str)} if config else {}))
    return cube
