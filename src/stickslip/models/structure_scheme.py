"""The schemes of the friction-linked structures (the isolated building, the friction tuned mass damper).

Both models have the pendulum's two schemes: ``exact`` solves one component
with Coulomb friction and no vertical in closed form per sample step, the
events located to round-off
(:mod:`stickslip.solvers.structure.friction_linked`), and integrates every
other motion or law, as ``integrated`` always does: a pair of components,
the vertical (the normal force N = N₀·(1 + a_v/g), lift-off where it
vanishes) or μ(v), integrated in the plane to a relative tolerance
(:mod:`stickslip.solvers.structure.integrated`; one component is the plane's
first axis, the second at rest).  A model's scheme subclasses
:class:`StructureScheme` with its ``solve`` and ``sweep``.
"""

from __future__ import annotations

from dataclasses import dataclass

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


def structure_schemes(scheme_type: type) -> tuple[StructureScheme, StructureScheme]:
    """(``exact``, ``integrated``) of the model's :class:`StructureScheme` subclass ``scheme_type``."""
    return scheme_type("exact"), scheme_type("integrated", integrates_always=True)
