"""The rigid block sliding in the plane on a flat surface, under both horizontal components at once.

One friction force of magnitude μ·m·g opposes the sliding velocity (the
friction circle): a pair of components (a :class:`~stickslip.records.pair.RecordPair`),
a friction ratio μ, the block's mass and gravity; one scheme, ``exact``
(tolerance-controlled integration with the events located,
:mod:`stickslip.solvers.plane`, :mod:`~stickslip.models.planar.solver`).  Its result is a
:class:`~stickslip.models.planar.response.PlanarResponse`; its sweep
(:mod:`~stickslip.models.planar.sweep`) sets the plane beside each component
alone and, with ``angles``, the 1-D block on turned axes.
"""

from __future__ import annotations

from dataclasses import dataclass

from stickslip.constants import DEFAULT_BLOCK_MASS, STANDARD_GRAVITY
from stickslip.models.entry import Model, Scheme
from stickslip.models.parameters import GRAVITY, MASS, MU
from stickslip.models.registry import public_names, register


@dataclass(frozen=True)
class PlanarScheme(Scheme):
    """The planar block's scheme: DOP853 with error control on the velocity, events located (option ``rtol`` [1])."""

    name: str = "exact"
    summary: str = "tolerance-controlled integration (relative tolerance 1e-10) with stops and starts located"
    batched: bool = True

    @property
    def options(self) -> dict:
        return {"rtol": None}

    def solve(self, pair, case, **options):
        """The :class:`~stickslip.models.planar.response.PlanarResponse` of ``case`` (μ, mass, g) on ``pair``."""
        from stickslip.models.planar.response import solve_case

        return solve_case(pair, case["mu"], case["mass"], case["g"], **options)

    def sweep(self, pairs, case, coefficient: str, values, rtol=None):
        """The planar kernel's end results, shape (pairs, values, 9), per unit mass, at the friction ratios ``values``."""
        from stickslip.models.planar.sweep import plane_scalars

        return plane_scalars(pairs, values, case["g"], rtol)


class PlanarModel(Model):
    """The planar block's entry: a pair of components, a friction ratio, one scheme."""

    name = "planar"
    summary = ("a rigid block sliding in the plane on a flat surface under both horizontal components, one friction "
               "force opposing the sliding velocity")
    motions = ("pair",)
    pair_report = True
    parameters = (MU, MASS, GRAVITY)
    schemes = (PlanarScheme(),)
    examples = ({"mu": 0.1},)

    @property
    def result(self) -> type:
        from stickslip.models.planar.response import PlanarResponse

        return PlanarResponse

    def case(self, parameters) -> dict:
        """μ [1], the mass [kg] and g [m/s²]; μ is needed."""
        from stickslip.errors import StickslipError

        if parameters["mu"] is None:
            raise StickslipError("give a friction ratio mu for sliding in the plane")
        return parameters

    def sweep(self, pairs, method=None, *, mu=None, angles=None, progress: bool = False, options=None, config=None,
              **parameters):
        """Every pair at every friction ratio ``mu`` [1]: in the plane, each component alone and, with ``angles``
        [degrees], on turned axes (:func:`stickslip.models.planar.sweep.planar_cube`); ``config`` is recorded in
        the cube's ``config`` attribute (JSON)."""
        import json

        from stickslip.models.planar.sweep import planar_cube

        case = self.case(self.checked({**parameters, "mu": 1.0}))
        scheme = self.scheme(method)
        cube = planar_cube(pairs, mu, case["mass"], case["g"], angles, progress=progress,
                           **scheme.checked_options(options))
        if config is not None:
            cube.attrs["config"] = json.dumps(dict(config), sort_keys=True, default=str)
        return cube


    #: The per-direction design answer a pair's table shows (:meth:`answers`): name -> (heading, units).
    answer_columns = {"mu_max": ("mu_max grid", "1"), "mu_max_continuous": ("mu_max continuous", "1"),
                      "energy_dissipated_max": ("E_df,max grid", "J"),
                      "energy_dissipated_max_continuous": ("E_df,max continuous", "J"), "mu_low": ("mu_low", "1"),
                      "mu_high": ("mu_high", "1"), "grid_values_in_range": ("values in range", "1"),
                      "peak_relative_displacement_at_mu_max": ("stroke at mu_max", "m"),
                      "residual_displacement_at_mu_max": ("end at mu_max", "m"),
                      "largest_stroke": ("largest stroke", "m")}

    def answers(self, cube, pairs, q: float, reference: float, min_points: int, options=None) -> list[dict]:
        """Per pair of a :meth:`sweep` cube: the design answer in the plane and for each component alone, refined as
        a record's, how the plane's μ_max relates to theirs and the worst turned axis where the cube has azimuths
        (:func:`stickslip.models.planar.design.labelled_answers`)."""
        from stickslip.models.planar.design import labelled_answers

        return labelled_answers(cube, pairs, q, reference, min_points, (options or {}).get("rtol"))


#: The planar block's entry.
PLANAR = register(PlanarModel())

#: The planar block's public names beside its entry (:func:`~stickslip.models.registry.public_names`).
PUBLIC = {"azimuths": "sweep", "labelled_answers": "design", "SCALAR_ATTRS": "response"}
__getattr__ = public_names(__name__, PUBLIC)


def solve_planar(pair, mu: float, mass: float = DEFAULT_BLOCK_MASS, g: float = STANDARD_GRAVITY, rtol=None):
    """:func:`stickslip.solve` of the planar model: ``pair`` at the friction ratio ``mu`` [1], ``rtol`` the tolerance."""
    return PLANAR.solve(pair, mu=mu, mass=mass, g=g, rtol=rtol)


def planar_sweep(pairs, mu, mass: float = DEFAULT_BLOCK_MASS, g: float = STANDARD_GRAVITY, angles=None, rtol=None,
                 progress: bool = True):
    """:func:`stickslip.sweep` of the planar model: ``pairs`` × friction ratios ``mu`` [1] (× turned axes, ``angles``)."""
    return PLANAR.sweep(pairs, mu=mu, mass=mass, g=g, angles=angles, progress=progress, options={"rtol": rtol})
