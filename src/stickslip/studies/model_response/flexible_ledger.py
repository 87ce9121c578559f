"""Beyond the paper: the record of its energy figures (Figs. 11-12) under a flexible sliding mass.

:func:`write_flexible_ledgers` solves the configuration's ``model_response``
seismic case (Kobe KJMA 090 × 0.65) with a soil layer on the sliding surface,
decoupled and coupled, by the exact scheme, from the block
``model_response.flexible``: ``ky`` [1], ``height`` [m], ``vs`` and
``vs_base`` [m/s], ``damping`` [1] (material, the foundation damping added).
Each model is written as a NetCDF file: the histories and the energy ledger per
unit mass [J/kg] of :meth:`stickslip.models.layer.result.FlexibleResult.to_xarray`
with ``status = "ok"``, or, when the record is missing, only
``status = "missing: …"``.
"""

from __future__ import annotations

from pathlib import Path

import xarray as xr

from stickslip.errors import RecordNotFoundError
from stickslip.plumbing.files import provenance
from stickslip.records.netcdf import read_record_netcdf
from stickslip.records.process import scale
from stickslip.models import solve
from stickslip.models.layer import Layer
from stickslip.sweeps import write_cube


def write_flexible_ledgers(seismic_record_path, decoupled_path, coupled_path, settings: dict,
                           g: float) -> list[Path]:
    """Solve both flexible models on the scaled seismic record; write one NetCDF file each.

    ``settings`` is the configuration's ``model_response`` block (``seismic.scale``
    and ``flexible``, see the module docstring); ``g`` gravity [m/s²].
    """
    flexible = settings["flexible"]
    layer = Layer(flexible["height"], flexible["vs"], flexible["vs_base"], flexible["damping"])
    paths = {"decoupled": Path(decoupled_path), "coupled": Path(coupled_path)}
    try:
        record = scale(read_record_netcdf(seismic_record_path), settings["seismic"]["scale"])
    except RecordNotFoundError as error:
        status = f"missing: {error}"
        return [write_cube(xr.Dataset(attrs={"title": f"stickslip flexible block, {model} (record missing)",
                                             "model": model, "status": status, **provenance()}), path)
                for model, path in paths.items()]
    written = []
    for model, path in paths.items():
        result = solve(record, model=model, ky=flexible["ky"], g=g, **layer.parameters())
        dataset = result.to_xarray()
        dataset.attrs.update(title=f"stickslip flexible block, {model}", status="ok",
                             record_id=record.meta.record_id, scale=settings["seismic"]["scale"], **provenance())
        written.append(write_cube(dataset, path))
    return written
