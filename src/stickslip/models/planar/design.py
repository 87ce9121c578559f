"""The design answer of a pair of components: the block in the plane beside each component alone, over μ.

For each :class:`~stickslip.records.pair.RecordPair`, :func:`pair_answers`
gives what ``stickslip optimum`` gives one record (:mod:`stickslip.optimum`):
μ_max on the grid and continuous, E_df,max at the continuous μ_max, the
near-optimal range, the stroke and the displacement at the end at μ_max, at the
range's ends and the largest over the range, on a grid extended and refined
for each range (:func:`stickslip.optimum.grid_for_ranges`), for the block in
the plane (:class:`PlaneDesign`) and for the 1-D block under each component
alone (the rigid model's design on that axis); and a sentence that says how the
plane's μ_max relates to the components' (:func:`relation`).

In the plane the stroke is the block's largest distance from its start and the
displacement at the end its distance from its start [m]; alone, the stroke is
the largest |x| and the displacement at the end x itself (signed) [m].
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace

import numpy as np

from stickslip.grids import Grid
from stickslip.objectives import ENERGY
from stickslip.optimum import (
    STATUS,
    Curves,
    GridExtension,
    RangeRefinement,
    grid_for_ranges,
    optimum,
    range_bounds,
    range_sizes,
    solve_curves,
)
from stickslip.records.pair import RecordPair
from stickslip.records.record import Record

#: The directions of a pair's design answer, as a planar cube's ``direction`` names them.
DIRECTIONS = ("plane", "first", "second")


@dataclass(frozen=True)
class PlaneDesign:
    """The block sliding in the plane over a grid of μ, as :mod:`stickslip.optimum` reads a design.

    Attributes
    ----------
    grid:
        The friction ratios μ [1].
    mass, g:
        Block mass [kg] and gravity [m/s²].
    rtol:
        The planar integration's relative tolerance (None: the kernel's, 1e-10).
    """

    grid: Grid
    mass: float
    g: float
    rtol: float | None = None
    demands: Mapping = field(default_factory=dict)
    #: What is optimal in the plane: the most energy dissipated (:data:`~stickslip.objectives.ENERGY`).
    objective = ENERGY
    #: No further end results beside the curves (:attr:`stickslip.optimum.Design.extra`).
    extra = ()

    def with_values(self, values) -> PlaneDesign:
        """The same block over other friction ratios ``values`` [1]."""
        return replace(self, grid=self.grid.with_values(values))

    def curves(self, pairs: Sequence[RecordPair]) -> dict[str, np.ndarray]:
        """E_df [J], the largest distance from the start [m] and the distance at the end [m] of each pair over the
        grid, (pairs, values) each."""
        from stickslip.models.planar.sweep import plane_scalars

        scalars = plane_scalars(list(pairs), self.grid.values, self.g, self.rtol)
        return {"energy_dissipated": scalars[..., 0] * self.mass,
                "peak_relative_displacement": np.abs(scalars[..., 5]),
                "residual_displacement": np.hypot(scalars[..., 3], scalars[..., 4])}

    def energy(self, pair: RecordPair, values) -> np.ndarray:
        """E_df [J] of ``pair`` at each of the friction ratios ``values`` [1]."""
        return self.with_values(np.atleast_1d(np.asarray(values, dtype=float))).curves([pair])["energy_dissipated"][0]

    def merit(self, pair: RecordPair, values) -> np.ndarray:
        """The merit of the :attr:`objective`: E_df [J] of ``pair`` at each of the friction ratios ``values`` [1]."""
        return self.energy(pair, values)

    def still_reason(self, pair: RecordPair, index: int = 0) -> str:
        """Why the block does not slide on ``pair`` at ``grid.values[index]``: the acceleration stays in the friction
        circle."""
        value = float(self.grid.values[index])
        peak = float(np.max(np.hypot(*pair.horizontal())))
        return (f"the ground acceleration's largest magnitude in the plane, {peak:.4g} m/s2, stays within the friction circle mu*g = {value * self.g:.4g} m/s2 at mu = {value:g}")


@dataclass(frozen=True)
class DirectionAnswer:
    """The design answer of one pair in one direction (the plane, or one component alone).

    Attributes
    ----------
    results:
        The per-record results of :func:`stickslip.optimum.results_of` ``("mu")`` by name, with
        ``optimum_status`` and ``grid_values_in_range`` (how many grid values the near-optimal range holds).
    grid_size:
        How many values of μ the grid solved holds (after extension and refinement).
    extensions, refinements:
        How the grid was extended beyond its edges and refined around the range, for this pair.
    """

    results: dict
    grid_size: int
    extensions: list[GridExtension]
    refinements: list[RangeRefinement]

    def bounds(self) -> dict[str, str]:
        """The results that are bounds, and which way (:func:`stickslip.optimum.range_bounds`)."""
        return range_bounds(self.results, "mu")


@dataclass(frozen=True)
class PairAnswer:
    """The design answer of one pair: each direction's (:data:`DIRECTIONS`) and how the plane's μ_max relates."""

    directions: dict[str, DirectionAnswer]
    relation: str


def component_records(pair: RecordPair) -> tuple[Record, Record]:
    """The pair's ground acceleration on its two orthogonal axes [m/s²] as records (the second resolved when the
    components are not a right angle apart), each with its component's metadata."""
    first, second = pair.horizontal()
    return Record(first, pair.dt, pair.first.meta), Record(second, pair.dt, pair.second.meta)


def _answers(versions: Sequence, curves: Curves, design, q: float, reference: float,
             min_points: int) -> list[DirectionAnswer]:
    """Each version's :class:`DirectionAnswer` from its ``curves`` on the grid as given, solved by ``design``."""
    curves, extensions, refinements = grid_for_ranges(versions, curves, design, q, min_points)
    results, statuses = optimum(versions, curves, design.with_values(curves.grid.values), q, reference)
    sizes = range_sizes(curves, q)
    return [DirectionAnswer({**{name: float(values[index]) for name, values in results.items()},
                             STATUS: statuses[index], "grid_values_in_range": int(sizes[index])},
                            int(curves.grid.values.size),
                            [extension for extension in extensions if extension.case == index],
                            [refinement for refinement in refinements if refinement.case == index])
            for index in range(len(versions))]


def pair_answers(cube, pairs: Sequence[RecordPair], q: float, reference: float, min_points: int,
                 rtol: float | None = None) -> list[PairAnswer]:
    """The :class:`PairAnswer` of each pair of a planar sweep's ``cube`` (its ``mu`` the grid as given, its mass and
    g the block's), in the plane and for each component alone.

    The plane's curves on the grid as given are the cube's; the values that
    extension and refinement add are solved by the planar kernel (relative
    tolerance ``rtol``), each component alone by the rigid model's exact solver.
    ``q`` is the near-optimal fraction, ``reference`` the μ whose E_df and
    efficiency are given [1], ``min_points`` the fewest grid values of a range.
    """
    from stickslip.models.rigid import RIGID

    grid = Grid("mu", cube["mu"].values)
    mass, g = float(cube.attrs["mass"]), float(cube.attrs["g"])
    plane = cube.sel(direction="plane")
    curves = Curves(grid, plane["energy_dissipated"].values, plane["peak_displacement"].values,
                    plane["residual_displacement"].values)
    found = {"plane": _answers(pairs, curves, PlaneDesign(grid, mass, g, rtol), q, reference, min_points)}
    line = RIGID.design(grid, mass=mass, g=g)
    components = [component_records(pair) for pair in pairs]
    for column, direction in enumerate(DIRECTIONS[1:]):
        versions = [records[column] for records in components]
        found[direction] = _answers(versions, solve_curves(versions, line), line, q, reference, min_points)
    answers = []
    for index, pair in enumerate(pairs):
        directions = {direction: found[direction][index] for direction in DIRECTIONS}
        names = tuple(record.meta.component or record.meta.record_id for record in (pair.first, pair.second))
        answers.append(PairAnswer(directions, relation(
            *(directions[direction].results["mu_max_continuous"] for direction in DIRECTIONS), names,
            (*(float(np.max(np.abs(axis))) / g for axis in pair.horizontal()),
             float(np.max(np.hypot(*pair.horizontal()))) / g))))
    return answers


def relation(plane: float, first: float, second: float, names: tuple[str, str],
             peaks: tuple[float, float, float], tolerance: float = 1e-6) -> str:
    """How the plane's μ_max [1] relates to each component's alone (``first``, ``second``, named ``names``), as a
    sentence: between them, or above or below both and why.

    ``peaks`` are the peak ground accelerations [g] along each axis and of
    the acceleration's magnitude in the plane; μ_max values within
    ``tolerance`` [1] (the continuous search's) count as equal; NaN is a
    direction in which the block never slides on the grid.
    """
    def text(value: float) -> str:
        return f"{value:.4g}"

    alone = f"{names[0]}'s {text(first)} and {names[1]}'s {text(second)}"
    if math.isnan(plane):
        return "the block in the plane never slides on the grid, so it has no μ_max"
    if math.isnan(first) or math.isnan(second):
        still, other, value = (names[0], names[1], second) if math.isnan(first) else (names[1], names[0], first)
        beside = "" if math.isnan(value) else f", beside {other}'s {text(value)} alone"
        return (f"the plane's μ_max is {text(plane)}{beside}; under {still} alone the block never slides on the "
                "grid")
    low, high = min(first, second), max(first, second)
    if low - tolerance <= plane <= high + tolerance:
        return f"the plane's μ_max {text(plane)} lies between the components' ({alone})"
    if plane > high:
        return (f"the plane's μ_max {text(plane)} lies above both components' ({alone}): the block in the plane "
                f"slides wherever the magnitude of the ground acceleration, both components at once, exceeds μ·g, and "
                f"that magnitude exceeds either component alone (peak {peaks[2]:.3g} g against {peaks[0]:.3g} and "
                f"{peaks[1]:.3g} g), so the block keeps sliding, and dissipating, up to a larger μ")
    return (f"the plane's μ_max {text(plane)} lies below both components' ({alone}), although the magnitude of the "
            f"ground acceleration in the plane (peak {peaks[2]:.3g} g) exceeds either component's ({peaks[0]:.3g} and "
            f"{peaks[1]:.3g} g): the one friction force in the plane opposes the sliding velocity, so the two axes do "
            "not slide independently, and here E_df(μ) in the plane peaks at a smaller μ than on either axis alone")


def labelled_answers(cube, pairs: Sequence[RecordPair], q: float, reference: float, min_points: int,
                     rtol: float | None = None) -> list[dict]:
    """Per pair of a planar sweep's ``cube``: ``directions``, label -> :class:`DirectionAnswer` ("in the plane",
    "<first component> alone", "<second> alone"), ``relation`` (:func:`relation`) and, where the cube has azimuths,
    ``worst``: the worst turned axis's label, its μ_max [1] and E_df,max [J] on the grid as given."""
    entries = []
    for index, answer in enumerate(pair_answers(cube, pairs, q, reference, min_points, rtol)):
        at = cube.isel(pair=index)
        labels = {"plane": "in the plane", "first": f"{at['first_component'].item()} alone",
                  "second": f"{at['second_component'].item()} alone"}
        entry = {"directions": {labels[direction]: found for direction, found in answer.directions.items()},
                 "relation": answer.relation, "worst": None}
        if "angle" in at.dims:
            worst = int(np.argmax(at["energy_dissipated_max_azimuth"].values))
            entry["worst"] = (f"worst azimuth ({float(at['angle'].values[worst]):g} deg)",
                              {"mu_max": float(at["mu_max_azimuth"].values[worst]),
                               "energy_dissipated_max": float(at["energy_dissipated_max_azimuth"].values[worst])})
        entries.append(entry)
    return entries
