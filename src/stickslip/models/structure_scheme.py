"""The schemes and the cases' shared part of the friction-linked structures (the isolated building, the friction
tuned mass damper).

Both models have the pendulum's two schemes: ``exact`` solves one component
with Coulomb friction and no vertical in closed form per sample step, the
events located to round-off
(:mod:`stickslip.solvers.structure.friction_linked`), and integrates every
other motion or law, as ``integrated`` always does: a pair of components,
the vertical (the normal force N = N₀·(1 + a_v/g), lift-off where it
vanishes) or μ(v), integrated in the plane to a relative tolerance
(:mod:`stickslip.solvers.structure.integrated`; one component is the plane's
first axis, the second at rest).  A model names the module of each: its
one-direction module gives ``solve_motion(motion, case, method)`` and
``sweep_motions(motions, case, values)``, its plane module
``solve_in_plane(motion, case, method, rtol)`` and
``sweep_in_plane(motions, case, values, rtol)``.  :class:`StructureCase` is
what both models' cases share: their friction law, a friction ratio moved
along a grid, and whether a motion moves their interface.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from importlib import import_module

from stickslip.models.entry import Scheme

#: The two schemes' one-line summaries, by name.
SUMMARIES = {
    "exact": "closed forms per sample step (each phase's matrix exponential), events located to round-off, on one "
             "component with Coulomb friction and no vertical; a pair, the vertical (N = N0 (1 + a_v/g), lift-off) "
             "or mu(v) integrated in the plane to 1e-10",
    "integrated": "embedded Runge-Kutta (DOP853) in the plane to a relative tolerance of 1e-10 (rtol), events "
                  "located, lift-off where the normal force vanishes",
}


@dataclass(frozen=True)
class StructureScheme(Scheme):
    """``exact`` (closed forms where they apply, else integrated) or ``integrated`` (always)."""

    name: str
    #: The model's module that solves one component in closed form, and its module that solves in the plane.
    one_direction: str
    plane: str
    integrates_always: bool = False
    batched: bool = True

    @property
    def summary(self) -> str:
        return SUMMARIES[self.name]

    @property
    def options(self) -> dict:
        """``rtol``, the integration's relative tolerance per step (default 1e-10)."""
        return {"rtol": None}

    def in_one_direction(self, motions, case) -> bool:
        """Whether the closed forms solve ``case`` on every one of ``motions``: this scheme takes them, the friction
        is Coulomb's, and each motion is one component without its vertical."""
        from stickslip.records.record import Record

        return (not self.integrates_always and case.friction.is_coulomb
                and all(isinstance(motion, Record) for motion in motions))


    def solve(self, motion, case, rtol=None):
        """One solved case: in closed form where :meth:`in_one_direction`, else integrated in the plane."""
        if self.in_one_direction([motion], case):
            return import_module(self.one_direction).solve_motion(motion, case, self.name)
        return import_module(self.plane).solve_in_plane(motion, case, self.name, rtol)

    def sweep(self, motions, case, coefficient: str, values, rtol=None) -> dict:
        """End results of every motion at every friction ratio of ``values`` [1], by name, energies in J."""
        if self.in_one_direction(motions, case):
            return import_module(self.one_direction).sweep_motions(motions, case, values)
        return import_module(self.plane).sweep_in_plane(motions, case, values, rtol)


def plane_variables(variables: dict, plane_table: dict, motions) -> dict[str, dict[str, str]]:
    """The cube's end results of a structure on ``motions``: its one direction's ``variables`` (name -> CF
    attributes) on records of one component; on pairs or motions with their vertical, those of its result in the
    plane (``plane_table``, name -> (unit, long name): the answers as vector magnitudes) with the vertical's work W_v
    ``energy_input_vertical`` [J] (0 without a vertical) and, where a motion has its vertical, the time lifted off
    ``liftoff_time`` [s] (absent from a cube without one)."""
    from stickslip.records.record import Record
    from stickslip.records.vertical import WithVertical

    motions = list(motions)
    if all(isinstance(motion, Record) for motion in motions):
        return variables
    added = {"energy_input_vertical", *(("liftoff_time",) if any(isinstance(motion, WithVertical)
                                                                 for motion in motions) else ())}
    return {name: {"units": units, "long_name": long_name} for name, (units, long_name) in plane_table.items()
            if name in variables or name in added}


def structure_schemes(one_direction: str, plane: str) -> tuple[StructureScheme, StructureScheme]:
    """(``exact``, ``integrated``) of a model whose modules ``one_direction`` and ``plane`` solve it."""
    return (StructureScheme("exact", one_direction, plane),
            StructureScheme("integrated", one_direction, plane, integrates_always=True))


class StructureCase:
    """The part of a friction-linked structure's case (a frozen dataclass with the fields ``mu``, ``mu_slow`` and
    ``rate``, and a ``holding_ratio(motion)``) that the isolated building and the damper share."""

    #: The records are solved as given (no inverse polarity).
    inverse = False

    @property
    def friction(self):
        """μ(v), a :class:`~stickslip.solvers.friction_law.FrictionLaw` (Coulomb's where ``mu_slow`` is None)."""
        from stickslip.solvers.friction_law import FrictionLaw

        return FrictionLaw(self.mu if self.mu_slow is None else self.mu_slow, self.mu, self.rate)

    def at(self, coefficient: str, value: float):
        """The same structure with the interface's friction ratio μ at ``value`` [1] (the velocity law's μ_fast, its
        μ_slow/μ_fast and rate held)."""
        law = self.friction.at_mu_fast(float(value))
        return replace(self, mu=law.mu_fast, mu_slow=None if self.mu_slow is None else law.mu_slow)

    def solved(self, acceleration):
        """The ground acceleration [m/s²] as the scheme takes it (as given)."""
        return acceleration

    def slides(self, motion) -> bool:
        """Whether the interface leaves rest on ``motion``: holding it needs more than μ(0)·N."""
        return self.holding_ratio(motion) > self.friction.mu_slow
