"""The vertical component beside a horizontal motion: the normal force on a slider varies with it.

A :class:`WithVertical` is a horizontal motion (one component, a
:class:`~stickslip.records.record.Record`, or a
:class:`~stickslip.records.pair.RecordPair` of two) and the vertical
component of the same station, sampled alike, its acceleration a_v [m/s²]
**positive up**: a slider's normal force per unit mass is then g + a_v.

Which way a vertical file's positive axis points is read from its component
label (:func:`vertical_sense`), in the header or the file name, as PEER NGA
files write it: ``UP`` (positive up), ``DWN``, ``DN`` or ``DOWN`` (positive
down: the sign is flipped here).  A label that does not tell (``V``,
``VER``, ``Z``, as the Tabas files have it) is refused unless the sense is
given (``positive="up"`` or ``"down"``, the command line's
``--vertical-positive``); a sense given against the file's label is refused
unless ``any_vertical=True`` (``--any-vertical``).  PEER's documentation of its NGA-West2 records
names these labels but does not state a sign convention for them that could
be checked here; the labels' plain meaning is taken, and every output says
which sense was read and from what.

The vertical must be the same station's (:func:`vertical_doubt`): a file
whose component or name is a horizontal direction (``230``, ``T1``), a
horizontal record that is itself a vertical, or files whose headers, names
or manifests give different events or stations are refused in one line,
unless ``any_vertical=True`` (``--any-vertical``) takes them all the same.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from stickslip.errors import StickslipError
from stickslip.records.components import component_direction, file_stem, recording_mismatch, vertical_component
from stickslip.records.pair import RecordPair
from stickslip.records.process import record_name
from stickslip.records.record import Record

#: Where a vertical file's component label says its positive axis points, by label.
SENSES = {"UP": "up", "DWN": "down", "DN": "down", "DOWN": "down"}

#: Labels that name a vertical component without saying which way it is positive.
UNTOLD = ("V", "VER", "VRT", "Z", "HNZ")

_LABEL = re.compile(r"(?:^|[-_ .]|(?<=\d))(" + "|".join(sorted({*SENSES, *UNTOLD}, key=len, reverse=True))
                    + r")\d*$|(DWN|DOWN)$", re.IGNORECASE)


def vertical_sense(record: Record) -> tuple[str, str] | None:
    """``("up" or "down", how it was told)`` from the record's component label or file name; None if untold.

    ``UP`` is positive up; ``DWN``, ``DN`` and ``DOWN`` positive down
    (:data:`SENSES`); ``V``, ``VER``, ``Z`` … name a vertical without a sense.
    """
    for what, text in (("its component", record.meta.component), ("its file name", Path(record.meta.source).stem)):
        match = _LABEL.search(text.strip()) if text else None
        if match is not None:
            label = (match.group(1) or match.group(2)).upper()
            if label in SENSES:
                return SENSES[label], f"{label} in {what}"
            return None
    return None


def vertical_doubt(horizontal: Record | RecordPair, vertical: Record) -> str | None:
    """What says that ``vertical`` is not the vertical component of the station that recorded ``horizontal``, or None.

    In order: the vertical's component or file name names a horizontal
    direction (``its component 230 is a horizontal direction``); a horizontal
    record is itself a vertical component
    (:func:`~stickslip.records.components.vertical_component`); a horizontal
    component and the vertical come from different events, stations or PEER
    records (:func:`~stickslip.records.components.recording_mismatch`).
    Names that say nothing (``wave.csv``) raise no doubt.
    """
    meta = vertical.meta
    if vertical_component(meta) is None:
        for what, name in (("its component", meta.component.strip()), ("its file name", file_stem(meta))):
            if name and component_direction(name) is not None:
                return f"{what} {name} is a horizontal direction"
    components = (horizontal.first, horizontal.second) if isinstance(horizontal, RecordPair) else (horizontal,)
    for component in components:
        named = Path(component.meta.source).name if component.meta.source else record_name(component)
        told = vertical_component(component.meta)
        if told is not None:
            return f"the horizontal motion {named} is itself a vertical component ({told})"
        mismatch = recording_mismatch(component.meta, meta)
        if mismatch is not None:
            return f"it and {named} come from {mismatch}"
    return None


@dataclass(frozen=True)
class WithVertical:
    """A horizontal motion and the vertical component of the same station, sampled alike.

    Attributes
    ----------
    horizontal:
        One component (a :class:`Record`) or two (a :class:`RecordPair`), ground acceleration [m/s²].
    vertical:
        The vertical ground acceleration a_v [m/s²], positive up (its sign already turned if the file's was down).
    sense:
        How the vertical's sense was known, in words (``"positive up (UP in its component)"``).
    any_vertical:
        The vertical was taken although its names say it is not the same
        station's vertical (:func:`vertical_doubt`), or read in the sense given
        against its label; ``--any-vertical`` on the command line.
    positive:
        Which way the file's positive axis was taken to point: ``"up"`` or ``"down"``.
    sense_from:
        What said so: ``"label"`` (the file's component label or name, with or
        without ``positive=`` agreeing) or ``"option"`` (``positive=``, the
        command line's ``--vertical-positive``, where the label does not tell
        or, with ``any_vertical``, says otherwise).
    """

    horizontal: Record | RecordPair
    vertical: Record
    sense: str
    any_vertical: bool = False
    positive: str = "up"
    sense_from: str = "label"

    def __post_init__(self) -> None:
        other_step = abs(self.vertical.dt - self.horizontal.dt) > 1e-9 * self.dt
        if self.vertical.npts != self.horizontal.npts or other_step:
            remedy = ("resample one of them first" if other_step else
                      "pad the shorter with zeros at its end, --pad, if they start together")
            raise StickslipError(f"{record_name(self.vertical)}: the vertical component has {self.vertical.npts:,} "
                                 f"samples at dt = {self.vertical.dt:g} s, the horizontal motion "
                                 f"{self.horizontal.npts:,} at {self.horizontal.dt:g} s: they must be sampled alike "
                                 f"({remedy})")

    @classmethod
    def of(cls, horizontal: Record | RecordPair, vertical: Record, positive: str | None = None,
           pad: bool = False, any_vertical: bool = False) -> WithVertical:
        """The motion of ``horizontal`` with ``vertical`` read positive up.

        ``positive`` (``"up"`` or ``"down"``) says which way the vertical
        file's positive axis points; None reads it from the file
        (:func:`vertical_sense`), and a file that does not tell is refused.  A
        ``positive`` that contradicts the file's label is refused unless
        ``any_vertical``, which reads the file as ``positive`` says.
        ``pad`` pads the shorter of the two with zeros at its end.  A vertical
        whose names say it is not the same station's (:func:`vertical_doubt`)
        is refused unless ``any_vertical``.
        """
        if not any_vertical:
            doubt = vertical_doubt(horizontal, vertical)
            if doubt is not None:
                raise StickslipError(f"{record_name(vertical)}: not the same station's vertical component: {doubt} "
                                     "(--any-vertical, any_vertical=True, takes it all the same)")
        told = vertical_sense(vertical)
        if positive is not None:
            if positive not in ("up", "down"):
                raise StickslipError(f"vertical positive {positive!r}: expected up or down")
            sense, source = positive, "option"
            if told is None:
                how = "as given"
            elif told[0] == positive:
                how = f"{told[1]}, as given"
            elif any_vertical:
                how = f"as given, against {told[1]}"
            else:
                raise StickslipError(f"{record_name(vertical)}: --vertical-positive {positive} "
                                     f"contradicts its label: {told[1]} says positive {told[0]}; leave the option out, "
                                     f"or read it positive {positive} all the same with --any-vertical "
                                     "(any_vertical=True)")
        elif told is not None:
            (sense, how), source = told, "label"
        else:
            raise StickslipError(f"{record_name(vertical)}: its component ({vertical.meta.component or 'none'}) and "
                                 "name do not say which way its positive axis points (UP, DWN): say it, up or down "
                                 "(--vertical-positive)")
        if told is not None and told[0] == sense:
            source = "label"
        if sense == "down":
            vertical = vertical.derive(-vertical.acceleration, step="sign flipped: positive up")
        if pad:
            horizontal, vertical = _padded(horizontal, vertical)
        return cls(horizontal, vertical, f"positive {sense} ({how})" + (", turned positive up" if sense == "down"
                                                                         else ""), any_vertical, sense, source)

    @property
    def against_label(self) -> str | None:
        """The file's label that the sense was read against (``"DWN in its component"``, with ``any_vertical``), or
        None when the label agrees or does not tell."""
        told = vertical_sense(self.vertical)
        return told[1] if self.sense_from == "option" and told is not None and told[0] != self.positive else None

    @property
    def doubt(self) -> str | None:
        """What says that the vertical is not the same station's (:func:`vertical_doubt`), or None."""
        return vertical_doubt(self.horizontal, self.vertical)

    @property
    def dt(self) -> float:
        """The time step [s]."""
        return self.horizontal.dt

    @property
    def npts(self) -> int:
        """The number of samples."""
        return self.horizontal.npts

    @property
    def meta(self):
        """The horizontal motion's description (a pair's names both components: :attr:`RecordPair.meta`)."""
        return self.horizontal.meta

    def peak_acceleration(self) -> float:
        """The horizontal motion's PGA [m/s²] (of a pair, the peak of |a| on its orthogonal axes)."""
        if isinstance(self.horizontal, RecordPair):
            return self.horizontal.peak_acceleration()
        return float(np.max(np.abs(self.horizontal.acceleration))) if self.npts else 0.0

    @property
    def acceleration(self) -> np.ndarray:
        """The horizontal ground acceleration [m/s²] of one component (a pair has :meth:`RecordPair.horizontal`)."""
        if isinstance(self.horizontal, RecordPair):
            raise StickslipError("a pair's acceleration is two components: RecordPair.horizontal()")
        return self.horizontal.acceleration

    @property
    def name(self) -> str:
        """The horizontal motion's name with the vertical's: ``TAK-000 + TAK-090 + TAK-UP``."""
        first = self.horizontal.name if isinstance(self.horizontal, RecordPair) else record_name(self.horizontal)
        return f"{first} + {record_name(self.vertical)}"


def split_vertical(motion) -> tuple[Record | RecordPair, np.ndarray | None, WithVertical | None]:
    """(the horizontal motion, its vertical a_v [m/s², positive up] or None, the motion with its vertical or None) of
    ``motion``: a component or a pair, either with its vertical (a :class:`WithVertical`)."""
    if isinstance(motion, WithVertical):
        return motion.horizontal, motion.vertical.acceleration, motion
    return motion, None, None


def _padded(horizontal, vertical: Record):
    """The horizontal motion and the vertical padded with zeros at their ends to the longer length."""
    length = max(horizontal.npts, vertical.npts)

    def padded(record: Record) -> Record:
        extra = length - record.npts
        if extra == 0:
            return record
        return record.derive(np.concatenate([record.acceleration, np.zeros(extra)]),
                             step=f"padded with {extra} zeros at the end")

    if isinstance(horizontal, RecordPair):
        return (RecordPair(padded(horizontal.first), padded(horizontal.second), horizontal.azimuths,
                           horizontal.any_pair), padded(vertical))
    return padded(horizontal), padded(vertical)
