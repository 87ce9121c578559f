"""Two horizontal components of one station's record, for sliding in the plane.

A :class:`RecordPair` holds two :class:`~stickslip.records.record.Record` of
the same station and event, sampled alike (the same dt and the same number of
samples), and the azimuth of each component's positive direction where the
record's name tells it (``TAK-000``, ``TAK-090``, ``LCN-260``, ``CHY080-N``).
:meth:`RecordPair.horizontal` gives the ground acceleration on two orthogonal
axes: axis 1 along the first component, axis 2 a quarter turn from it towards
the second.  Components that are not orthogonal (the SLAMMER library's Landers
LCN 260/345, 85° apart) are resolved onto those axes: each instrument records
the projection of the horizontal acceleration on its own direction, so with
the second component at Δ from the first, a₂ = a·cos Δ + b·sin Δ and the
second axis carries b = (a₂ − a₁·cos Δ)/sin Δ.  Without azimuths the two
components are taken as orthogonal, as record files almost always are.

A pair whose names say that its records are not one station's two
horizontal components (a vertical component, two events or two stations:
:func:`pair_doubt`, from :mod:`stickslip.records.components`) is refused,
unless it is made with ``any_pair=True`` (``--any-pair``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from stickslip.errors import StickslipError
from stickslip.records.components import component_azimuth, recording_mismatch, vertical_component
from stickslip.records.process import record_name, scale
from stickslip.records.record import Record

#: Relative difference of two time steps that still counts as the same dt.
DT_TOLERANCE = 1e-9
#: How far from a right angle [degrees] two azimuths may be and still be taken as orthogonal.
ORTHOGONAL_TOLERANCE = 1e-6
#: Smallest angle [degrees] between two components that can be resolved onto orthogonal axes.
MIN_SEPARATION = 30.0


def _component_name(record: Record) -> str:
    """The name the component goes by: its ``component`` (``TAK-090``), else its record id."""
    return record.meta.component or record.meta.record_id


def pair_doubt(first: Record, second: Record) -> str | None:
    """What says that two records are not one station's two horizontal components, or None.

    A vertical component (:func:`~stickslip.records.components.vertical_component`:
    ``the second is a vertical component (its component is UP)``), then two
    events, stations or PEER records (:func:`~stickslip.records.components.recording_mismatch`).
    """
    for which, record in (("first", first), ("second", second)):
        vertical = vertical_component(record.meta)
        if vertical is not None:
            return f"the {which} is a vertical component ({vertical})"
    mismatch = recording_mismatch(first.meta, second.meta)
    return f"the components come from {mismatch}" if mismatch is not None else None


@dataclass(frozen=True)
class RecordPair:
    """Two horizontal components of one record, sampled alike.

    Attributes
    ----------
    first, second:
        The components; ground acceleration [m/s²].  One may be zero
        throughout (a uniaxial test: the block then slides as under the other
        alone).
    azimuths:
        Azimuth of each component's positive direction [degrees clockwise from
        north], or None when unknown (the components are then taken as
        orthogonal, the second a quarter turn clockwise from the first).
    any_pair:
        Pair the two records although their names say they are not one
        station's two horizontal components (:func:`pair_doubt`: a vertical
        component, two events, two stations); ``--any-pair`` on the command
        line.  Without it, such a pair is refused.
    """

    first: Record
    second: Record
    azimuths: tuple[float, float] | None = None
    any_pair: bool = False

    def __post_init__(self) -> None:
        first, second = self.first, self.second
        names = f"{record_name(first)} and {record_name(second)}"
        if not self.any_pair:
            doubt = pair_doubt(first, second)
            if doubt is not None:
                raise StickslipError(f"{names}: not one station's two horizontal components: {doubt} "
                                     "(--any-pair, any_pair=True, pairs them all the same)")
        if abs(first.dt - second.dt) > DT_TOLERANCE * max(first.dt, second.dt):
            raise StickslipError(f"{names}: the two components have different time steps "
                                 f"({first.dt:g} s and {second.dt:g} s); resample one of them first")
        if first.npts != second.npts:
            raise StickslipError(f"{names}: the two components have different lengths "
                                 f"({first.npts:,} and {second.npts:,} samples); pad the shorter one with zeros "
                                 f"at its end (RecordPair.padded, --pad) if both start at the same time")
        if self.azimuths is None:
            one, other = component_azimuth(_component_name(first)), component_azimuth(_component_name(second))
            if one is not None and other is not None:
                object.__setattr__(self, "azimuths", (one, other))
        if self.azimuths is not None:
            separation = self.separation
            if not MIN_SEPARATION <= abs(separation) <= 180.0 - MIN_SEPARATION:
                raise StickslipError(f"{names}: the components point {abs(separation):g} degrees apart "
                                     f"(azimuths {self.azimuths[0]:g} and {self.azimuths[1]:g}); two horizontal "
                                     f"components at least {MIN_SEPARATION:g} degrees apart are needed")

    @classmethod
    def padded(cls, first: Record, second: Record, any_pair: bool = False) -> RecordPair:
        """The pair of two components that start together, the shorter one padded with zeros at its end.

        Library records such as SLAMMER's were trimmed component by component,
        so the two components of one station often differ in length by a few
        samples; the padding is the ground at rest after the shorter one ends.
        ``any_pair`` as for :class:`RecordPair`.
        """
        length = max(first.npts, second.npts)

        def padded_record(record: Record) -> Record:
            extra = length - record.npts
            if extra == 0:
                return record
            return record.derive(np.concatenate([record.acceleration, np.zeros(extra)]),
                                 step=f"padded with {extra} zeros at the end")

        return cls(padded_record(first), padded_record(second), any_pair=any_pair)

    @property
    def doubt(self) -> str | None:
        """What says that the two are not one station's two horizontal components (:func:`pair_doubt`), or None."""
        return pair_doubt(self.first, self.second)

    @property
    def dt(self) -> float:
        """The time step [s]."""
        return self.first.dt

    @property
    def npts(self) -> int:
        """The number of samples."""
        return self.first.npts

    @property
    def name(self) -> str:
        """``TAK-000 + TAK-090``: how results and messages name the pair."""
        return f"{_component_name(self.first) or record_name(self.first)} + " \
               f"{_component_name(self.second) or record_name(self.second)}"

    @property
    def meta(self):
        """The pair's description where one record is named (a sweep's ``record``): the first component's, with the
        record id of both (``RSN126_GAZLI_GAZ000+RSN126_GAZLI_GAZ090``; one id when both have it) and both components
        (``0 + 90``)."""
        first, second = self.first.meta, self.second.meta
        ids = [first.record_id, second.record_id]
        record_id = ids[0] if ids[0] == ids[1] or not ids[1] else "+".join(filter(None, ids))
        components = " + ".join(filter(None, (first.component, second.component)))
        return replace(first, record_id=record_id, component=components)

    def peak_acceleration(self) -> float:
        """The peak of |a| [m/s²] on the pair's orthogonal axes (exact for components linear between samples)."""
        first, second = self.horizontal()
        return float(np.max(np.hypot(first, second))) if self.npts else 0.0

    @property
    def separation(self) -> float:
        """The angle from the first component to the second [degrees, in (−180, 180]]; 90 when unknown."""
        if self.azimuths is None:
            return 90.0
        angle = (self.azimuths[1] - self.azimuths[0]) % 360.0
        return angle - 360.0 if angle > 180.0 else angle

    @property
    def orthogonal(self) -> bool:
        """Whether the components are a right angle apart (or their azimuths are unknown)."""
        return abs(abs(self.separation) - 90.0) <= ORTHOGONAL_TOLERANCE

    def horizontal(self) -> tuple[np.ndarray, np.ndarray]:
        """The ground acceleration [m/s²] on two orthogonal axes: along the first component, and a right angle from it.

        The second axis is turned towards the second component.  For components
        Δ apart (:attr:`separation`), the second axis carries
        (a₂ − a₁·cos Δ)/sin Δ, which is a₂ when Δ = ±90°.
        """
        first, second = self.first.acceleration, self.second.acceleration
        if self.orthogonal:
            return first, second
        angle = math.radians(abs(self.separation))
        return first, (second - first * math.cos(angle)) / math.sin(angle)

    def rotated(self, angle: float) -> tuple[np.ndarray, np.ndarray]:
        """The acceleration [m/s²] along the axes of :meth:`horizontal` turned by ``angle`` [degrees] towards axis 2."""
        return turned_axes(*self.horizontal(), angle)

    def scaled(self, factor: float) -> RecordPair:
        """Both components multiplied by ``factor`` [1] (:func:`stickslip.records.process.scale`)."""
        return RecordPair(scale(self.first, factor), scale(self.second, factor), self.azimuths, self.any_pair)


def turned_axes(first: np.ndarray, second: np.ndarray, angle: float) -> tuple[np.ndarray, np.ndarray]:
    """Accelerations [m/s²] on two orthogonal axes, expressed on the axes turned by ``angle`` [degrees] from 1 to 2."""
    turn = math.radians(angle)
    return first * math.cos(turn) + second * math.sin(turn), -first * math.sin(turn) + second * math.cos(turn)
