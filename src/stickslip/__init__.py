"""stickslip: sliding blocks (rigid, or a flexible soil layer) with Coulomb friction under seismic base motion.

The public names are imported lazily so that ``stickslip --help`` starts fast
and does not compile numba kernels.
"""

from __future__ import annotations

import importlib

__version__ = "0.1.0"

_PUBLIC = {
    "Record": "stickslip.records.record",
    "RecordMeta": "stickslip.records.record",
    "read_record": "stickslip.records.readers",
    "intensity_measures": "stickslip.measures",
    "solve": "stickslip.solution",
    "Response": "stickslip.response",
    "Resistance": "stickslip.solvers.resistance",
    "sweep": "stickslip.sweeps",
    "YieldTable": "stickslip.solvers.yield_table",
    "Layer": "stickslip.solvers.layer",
    "solve_flexible": "stickslip.solvers.flexible",
    "flexible_sweep": "stickslip.flexible_sweeps",
    "with_optimum": "stickslip.optimum",
    "RecordPair": "stickslip.records.pair",
    "solve_planar": "stickslip.solvers.planar",
    "PlanarResponse": "stickslip.solvers.planar",
    "planar_sweep": "stickslip.planar_sweeps",
    "StickslipError": "stickslip.errors",
}

__all__ = sorted(_PUBLIC) + ["__version__"]


def __getattr__(name: str):
    if name in _PUBLIC:
        return getattr(importlib.import_module(_PUBLIC[name]), name)
    raise AttributeError(f"module 'stickslip' has no attribute {name!r}")
