"""The in-memory ground-motion record shared by every part of stickslip."""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np


@dataclass(frozen=True)
class RecordMeta:
    """Where a record came from and what has been done to it.

    Attributes
    ----------
    record_id:
        Short identifier (manifest id, or the file stem for a user's file).
    event, station, component:
        Descriptive metadata; empty strings where the source has none.
    source:
        The file the samples were read from (a path or a package resource).
    sha256:
        SHA-256 of the source file's bytes, hex.
    units:
        Units of the values in the source file: ``"g"``, ``"m/s2"`` or ``"cm/s2"``.
    format:
        The source format (``peer_at2``, ``slammer_1col``, ``time_acc_csv``, ``two_column``).
    processing:
        Processing steps applied after reading, in order (e.g. ``"scale 1.5"``).
    dt_source:
        Where the time step came from: ``"the file"``, the manifest that knows
        the file, or ``"given"`` (the ``dt`` argument); empty for a record not read from a file.
    gravity:
        The g [m/s²] that converted values in g (``units`` ``"g"``) into m/s²;
        None when no value was in g.
    stored_in:
        The stored record (a NetCDF file that ``stickslip records fetch`` or the
        workflow wrote) the samples were read from, when they were not read from
        ``source`` itself; empty otherwise.
    """

    record_id: str = ""
    event: str = ""
    station: str = ""
    component: str = ""
    source: str = ""
    sha256: str = ""
    units: str = "m/s2"
    format: str = ""
    processing: tuple[str, ...] = ()
    dt_source: str = ""
    gravity: float | None = None
    stored_in: str = ""


@dataclass(frozen=True)
class Record:
    """A uniformly sampled ground acceleration history.

    The ground acceleration is taken as linear between samples everywhere in
    stickslip (solvers, measures and resampling agree on this).

    Attributes
    ----------
    acceleration:
        Ground acceleration [m/s²], float64, one value per sample.
    dt:
        Time step [s], positive.
    meta:
        Provenance and description, see :class:`RecordMeta`.
    """

    acceleration: np.ndarray
    dt: float
    meta: RecordMeta = field(default_factory=RecordMeta)

    def __post_init__(self) -> None:
        acceleration = np.ascontiguousarray(self.acceleration, dtype=np.float64)
        acceleration.setflags(write=False)
        object.__setattr__(self, "acceleration", acceleration)
        object.__setattr__(self, "dt", float(self.dt))

    @property
    def npts(self) -> int:
        """Number of samples."""
        return self.acceleration.size

    @property
    def time(self) -> np.ndarray:
        """Sample times [s], starting at 0."""
        return np.arange(self.npts) * self.dt

    @property
    def duration(self) -> float:
        """Total duration t0 = (npts − 1)·dt [s]."""
        return (self.npts - 1) * self.dt

    def derive(self, acceleration: np.ndarray, dt: float | None = None, step: str = "") -> "Record":
        """A new record with other samples, the same provenance and ``step`` appended.

        Parameters
        ----------
        acceleration:
            The new ground acceleration [m/s²].
        dt:
            The new time step [s]; unchanged when ``None``.
        step:
            A short description of the processing step, recorded in ``meta.processing``.
        """
        processing = self.meta.processing + ((step,) if step else ())
        return Record(
            acceleration=acceleration,
            dt=self.dt if dt is None else dt,
            meta=replace(self.meta, processing=processing),
        )
