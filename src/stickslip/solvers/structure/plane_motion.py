"""A friction-linked structure in the plane on a record's motion: its axes, its vertical, and the peaks of its rows.

:func:`solve_on_motion` takes a motion as the command line and
:func:`stickslip.solve` give it (one component, a pair of components, either
with its vertical: a :class:`~stickslip.records.vertical.WithVertical`),
puts its horizontal ground acceleration on two orthogonal axes (a single
component on the first, the second zero) and solves the structure with
:func:`~stickslip.solvers.structure.integrated.solve_structure_in_plane`.
:func:`plane_peaks` takes the rows of a model's one-direction answers (the
``tracked`` rows on (x, ẋ, a_g, Q) of
:func:`~stickslip.solvers.structure.friction_linked.friction_linked_history`)
to the plane: each row applied on each axis, the peak of the vector's
magnitude over the samples.  :func:`integration_progress` is the bar the
models' sweeps in the plane show, one integration per motion and friction
ratio.
"""

from __future__ import annotations

import sys
from typing import NamedTuple

import numpy as np
from tqdm import tqdm

from stickslip.checks import checked_acceleration, checked_pair_axes
from stickslip.records.pair import RecordPair
from stickslip.records.vertical import WithVertical
from stickslip.solvers.structure.integrated import PlaneStructureHistory, solve_structure_in_plane


class PlaneMotion(NamedTuple):
    """A motion as the plane solver takes it."""

    ground_acceleration: np.ndarray
    """(samples, 2) [m/s²]: the horizontal ground acceleration on two orthogonal axes."""
    vertical: np.ndarray | None
    """a_v [m/s², positive up] at the samples, or None."""
    dt: float
    """The sample interval [s]."""
    axes: list[str]
    """The axes' names: the components' (the second resolved normal to the first where they are not orthogonal)."""
    pair: bool
    """Whether it is two horizontal components (else one, on the first axis)."""
    name: str
    """The horizontal motion's name (a pair's ``A-000 + A-090``), with ``with its vertical`` where it has one."""

    @property
    def kind(self) -> str:
        """``pair`` or ``component``, ``with its vertical`` where it has one."""
        return ("pair" if self.pair else "component") + ("" if self.vertical is None else " with its vertical")


def plane_motion(motion) -> PlaneMotion:
    """``motion`` (a component or a pair, either with its vertical) on two orthogonal axes; a value that is not
    finite is one line naming its component; a :class:`PlaneMotion` as it is."""
    if isinstance(motion, PlaneMotion):
        return motion
    horizontal, vertical = ((motion.horizontal, motion.vertical) if isinstance(motion, WithVertical)
                            else (motion, None))
    if isinstance(horizontal, RecordPair):
        first, second = checked_pair_axes(horizontal)
        names = [horizontal.first.meta.component or horizontal.first.meta.record_id or "1",
                 horizontal.second.meta.component or horizontal.second.meta.record_id or "2"]
        if not horizontal.orthogonal:
            names[1] = f"{names[1]} (resolved normal to {names[0]})"
        name = horizontal.name
    else:
        first = checked_acceleration(horizontal.acceleration, f"{horizontal.meta.record_id or 'the record'}")
        second = np.zeros_like(first)
        names = [horizontal.meta.component or horizontal.meta.record_id or "1", "normal to it (at rest)"]
        name = horizontal.meta.record_id or "the record"
    along = None
    if vertical is not None:
        along = checked_acceleration(vertical.acceleration, f"{vertical.meta.record_id or 'the vertical'}")
        name = f"{name} with its vertical"
    return PlaneMotion(np.column_stack([first, second]), along, float(horizontal.dt), names,
                       isinstance(horizontal, RecordPair), name)


def solve_on_motion(system, motion: PlaneMotion, friction, gravity: float, rtol: float) -> PlaneStructureHistory:
    """The structure ``system`` (a :class:`~stickslip.solvers.structure.friction_linked.FrictionLinkedSystem`, its
    normal force the static N₀ [N]) on ``motion`` with the friction law ``friction``
    (:class:`~stickslip.solvers.friction_law.FrictionLaw`), gravity [m/s²] and the relative tolerance ``rtol``."""
    mu_slow, mu_fast, rate = friction.parameters()
    return solve_structure_in_plane(system, motion.ground_acceleration[:, 0], motion.ground_acceleration[:, 1],
                                    motion.dt, vertical=motion.vertical, gravity=gravity, mu_slow=mu_slow,
                                    mu_fast=mu_fast, rate=rate, rtol=rtol)


def integration_progress(total: int) -> tqdm:
    """A progress bar on stderr, where that is a terminal, over ``total`` integrations in the plane (a tenth to half
    a second each for a pair of 2,000 to 30,000 samples: a sweep over a fine friction grid takes minutes)."""
    return tqdm(total=total, desc="integrating in the plane", unit="solve", leave=False, file=sys.stderr,
                disable=not sys.stderr.isatty())


def plane_peaks(rows: np.ndarray, history: PlaneStructureHistory, ground_acceleration: np.ndarray) -> np.ndarray:
    """The peak over the samples of the magnitude of each row of ``rows`` (k × (2n + 2), on (x, ẋ, a_g, Q) of one
    direction) applied on both axes: the plane's ``peaks`` of
    :func:`~stickslip.solvers.structure.friction_linked.friction_linked_history` (there also at its search points
    and events), shape (k,)."""
    state = np.concatenate([history.displacement, history.velocity, ground_acceleration[:, None, :],
                            history.interface_force[:, None, :]], axis=1)  # (samples, 2n + 2, 2)
    values = np.einsum("rj,kja->kra", rows, state)
    return np.max(np.hypot(values[..., 0], values[..., 1]), axis=0)
