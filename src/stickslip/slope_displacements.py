"""Newmark's permanent displacements for slope engineers: D_n per record and k_y, both polarities, with statistics.

What SLAMMER's table of rigid-block results gives, for any records: the
permanent downslope displacement D_n [cm] of a rigid block sliding one way
(downslope only, past the yield acceleration k_y·g) for each record and each
yield coefficient k_y [1], in SLAMMER's two polarities (``normal``: the
record as given; ``inverse``: its sign flipped) and their mean; over the
records, for each k_y, the mean, median and sample standard deviation of
each (over the horizontal components: a vertical one is solved and listed
but left out of them, :mod:`stickslip.records.verticals_apart`); and, beside
each computed D_n, the empirical estimate of Jibson (2007)
from the record's PGA (and Arias intensity), with his printed coefficients
(``stickslip/reference/jibson2007.yaml``).

D_n is in cm, SLAMMER's and Jibson's unit.  The solver is the exact one
(:mod:`stickslip.models.rigid.exact`, one batched sweep per polarity) or SLAMMER's
own stepping (``method="slammer"``).  A k_y with k_y·g at least the record's
PGA gives D_n = 0 (the block never slides) and no Jibson estimate (his
equations hold for a_c/a_max below 1).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from stickslip.constants import STANDARD_GRAVITY
from stickslip.estimates.jibson import jibson_reference, predict
from stickslip.grids import positive_increasing
from stickslip.measures import intensity_measures
from stickslip.models.parameters import POLARITIES
from stickslip.records.components import vertical_component
from stickslip.records.record import Record


#: Centimetres per metre: D_n is in cm, the solver's lengths in m.
CM_PER_M = 100.0

#: Jibson's (2007) two forms, by the name of ``stickslip/reference/jibson2007.yaml``, and how a column names each.
JIBSON_FORMS = {"critical_acceleration_ratio": "jibson2007_ratio", "arias_intensity_and_ratio": "jibson2007_arias"}

#: The statistics over the records, in order.
STATISTICS = ("mean", "median", "std")


@dataclass(frozen=True)
class SlopeDisplacements:
    """D_n of n records at m yield coefficients, both polarities, with Jibson's (2007) estimates.

    Attributes
    ----------
    records, sources:
        The records' ids and files, length n.
    ky:
        Yield coefficients k_y [1], increasing, length m.
    pga, arias_intensity:
        Each record's PGA [m s-2] and Arias intensity [m s-1], length n.
    normal, inverse:
        D_n [cm] in each polarity, shape (n, m).
    jibson:
        Form name (:data:`JIBSON_FORMS`) -> Jibson's median estimate of D_n [cm], shape (n, m), NaN where
        a_c/a_max ≥ 1.
    jibson_sigma:
        Form name -> the standard deviation of his log10 D_n [log10 cm], as printed.
    g, method:
        Gravity [m s-2] and the solver.
    verticals:
        Why each record is a vertical component (:func:`~stickslip.records.components.vertical_component`), or
        None for a horizontal one, length n: the statistics leave the vertical ones out.
    """

    records: list[str]
    sources: list[str]
    ky: np.ndarray
    pga: np.ndarray
    arias_intensity: np.ndarray
    normal: np.ndarray
    inverse: np.ndarray
    jibson: dict[str, np.ndarray]
    jibson_sigma: dict[str, float]
    g: float
    method: str
    verticals: list[str | None]

    @property
    def apart(self) -> tuple[np.ndarray, list[dict]]:
        """Which records enter the statistics (a boolean each) and the vertical components left out of them
        (``record``, ``source``, ``reason``: :func:`~stickslip.records.verticals_apart.verticals_apart`)."""
        from stickslip.records.verticals_apart import verticals_apart

        return verticals_apart(list(zip(self.records, self.sources, self.verticals)))

    @property
    def mean(self) -> np.ndarray:
        """The mean of both polarities [cm], shape (n, m): SLAMMER's summary of one record."""
        return (self.normal + self.inverse) / 2.0

    @property
    def critical_acceleration_ratio(self) -> np.ndarray:
        """a_c/a_max = k_y·g/PGA [1], shape (n, m)."""
        return self.ky[None, :] * self.g / self.pga[:, None]

    def statistics(self) -> dict[str, dict[str, np.ndarray]]:
        """Over the horizontal records, per k_y: statistic (:data:`STATISTICS`) -> column -> values [cm], length m.

        Columns ``normal``, ``inverse`` and ``mean``; the standard deviation is
        the sample one (n − 1 in the denominator), NaN for one record; every
        statistic NaN where no record is horizontal.
        """
        included, _ = self.apart
        columns = {"normal": self.normal[included], "inverse": self.inverse[included], "mean": self.mean[included]}
        n = int(included.sum())
        if n == 0:
            return {statistic: {name: np.full(self.ky.size, np.nan) for name in columns} for statistic in STATISTICS}
        return {
            "mean": {name: values.mean(axis=0) for name, values in columns.items()},
            "median": {name: np.median(values, axis=0) for name, values in columns.items()},
            "std": {name: (values.std(axis=0, ddof=1) if n > 1 else np.full(self.ky.size, np.nan))
                    for name, values in columns.items()},
        }

    def rows(self) -> list[dict]:
        """One row per record and k_y (record-major): the table of :data:`ROW_COLUMNS`."""
        ratio = self.critical_acceleration_ratio
        rows = []
        for i, record in enumerate(self.records):
            for j, ky in enumerate(self.ky):
                rows.append({
                    "record": record, "source": self.sources[i], "ky": float(ky),
                    "yield_acceleration": float(ky * self.g), "pga": float(self.pga[i]),
                    "arias_intensity": float(self.arias_intensity[i]),
                    "critical_acceleration_ratio": float(ratio[i, j]),
                    "newmark_displacement_normal": float(self.normal[i, j]),
                    "newmark_displacement_inverse": float(self.inverse[i, j]),
                    "newmark_displacement_mean": float(self.mean[i, j]),
                    **{f"{column}": float(self.jibson[form][i, j]) for form, column in JIBSON_FORMS.items()},
                })
        return rows

    def statistic_rows(self) -> list[dict]:
        """One row per statistic and k_y: the table of :data:`STATISTIC_COLUMNS`."""
        found = self.statistics()
        records = int(self.apart[0].sum())
        return [{"statistic": statistic, "records": records, "ky": float(ky),
                 **{f"newmark_displacement_{name}": float(found[statistic][name][j])
                    for name in ("normal", "inverse", "mean")}}
                for statistic in STATISTICS for j, ky in enumerate(self.ky)]


#: The per-record table's columns, in order (units in :data:`stickslip.units.UNITS`).
ROW_COLUMNS = ("record", "source", "ky", "yield_acceleration", "pga", "arias_intensity", "critical_acceleration_ratio",
               "newmark_displacement_normal", "newmark_displacement_inverse", "newmark_displacement_mean",
               *JIBSON_FORMS.values())

#: The statistics table's columns, in order.
STATISTIC_COLUMNS = ("statistic", "records", "ky", "newmark_displacement_normal", "newmark_displacement_inverse",
                     "newmark_displacement_mean")


def jibson_estimates(ratio: np.ndarray, arias_intensity: np.ndarray) -> tuple[dict[str, np.ndarray], dict[str, float]]:
    """Jibson's (2007) median D_n [cm] of each form at a_c/a_max ``ratio`` [1] and Arias intensity [m s-1], and his σ.

    NaN where ``ratio`` is not in (0, 1): his equations do not hold there.
    """
    reference = jibson_reference()["forms"]
    valid = (ratio > 0.0) & (ratio < 1.0)
    inside = np.where(valid, ratio, 0.5)
    arias = np.broadcast_to(arias_intensity, ratio.shape)
    estimates = {form: np.where(valid, 10.0 ** predict(form, reference[form]["coefficients"], inside.ravel(),
                                                        arias.ravel()).reshape(ratio.shape), np.nan)
                 for form in JIBSON_FORMS}
    return estimates, {form: float(reference[form]["sigma"]) for form in JIBSON_FORMS}


def slope_displacements(records: Sequence[Record], ky, g: float = STANDARD_GRAVITY,
                        method: str = "exact") -> SlopeDisplacements:
    """D_n [cm] of ``records`` (acceleration in m s-2) at the yield coefficients ``ky`` [1], both polarities.

    ``g`` [m s-2] makes a_c = k_y·g (SLAMMER's is 9.80665); ``method`` is
    ``"exact"`` or ``"slammer"``.  See the module's docstring.
    """
    from stickslip.models import sweep

    records = list(records)
    kys = positive_increasing(ky, "yield coefficients ky")
    measured = [intensity_measures(record, g) for record in records]
    pga = np.array([measures.pga for measures in measured])
    arias = np.array([measures.arias_intensity for measures in measured])
    # + 0.0: a block that never slides has D_n = 0, not the solver's -0.0 (printed "-0")
    displaced = {polarity: CM_PER_M * sweep(records, ky=kys, g=g, method=method,
                                            inverse=polarity == "inverse").downslope_displacement.values + 0.0
                 for polarity in POLARITIES}
    ratio = kys[None, :] * g / pga[:, None]
    estimates, sigma = jibson_estimates(ratio, arias[:, None])
    return SlopeDisplacements(
        records=[str(record.meta.record_id) for record in records], sources=[str(record.meta.source) for record in records],
        ky=kys, pga=pga, arias_intensity=arias, normal=displaced["normal"], inverse=displaced["inverse"],
        jibson=estimates, jibson_sigma=sigma, g=float(g), method=method,
        verticals=[vertical_component(record.meta) for record in records])
