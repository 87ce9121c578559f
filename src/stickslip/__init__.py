"""stickslip: sliding blocks (rigid, a flexible soil layer, in the plane) with friction under seismic base motion.

The public names are imported lazily so that ``stickslip --help`` starts fast
and does not compile numba kernels.
"""

from __future__ import annotations

import importlib

__version__ = "0.1.0"

_PUBLIC = {
    "Record": "stickslip.records.record",
    "RecordMeta": "stickslip.records.record",
    "RecordPair": "stickslip.records.pair",
    "WithVertical": "stickslip.records.vertical",
    "read_record": "stickslip.records.readers",
    "intensity_measures": "stickslip.measures",
    "MODELS": "stickslip.models",
    "solve": "stickslip.models",
    "sweep": "stickslip.models",
    "Result": "stickslip.models.result",
    "Response": "stickslip.models.rigid.response",
    "Resistance": "stickslip.models.rigid.resistance",
    "YieldTable": "stickslip.models.yield_table",
    "Layer": "stickslip.models.layer.layer",
    "FlexibleResult": "stickslip.models.layer.result",
    "solve_flexible": "stickslip.models.layer",
    "flexible_sweep": "stickslip.models.layer",
    "PlanarResponse": "stickslip.models.planar.response",
    "solve_planar": "stickslip.models.planar",
    "planar_sweep": "stickslip.models.planar",
    "with_optimum": "stickslip.models",
    "Spectra": "stickslip.spectra",
    "motion_spectra": "stickslip.spectra",
    "StickslipError": "stickslip.errors",
}

__all__ = sorted(_PUBLIC) + ["__version__"]


def __getattr__(name: str):
    if name in _PUBLIC:
        return getattr(importlib.import_module(_PUBLIC[name]), name)
    raise AttributeError(f"module 'stickslip' has no attribute {name!r}")


def __dir__() -> list[str]:
    """The public names (``dir(stickslip)``, tab completion), though they are imported only when first used."""
    return __all__
