"""The rigid block: Coulomb friction on a flat surface, or Newmark's block on a slope (one way, or both ways).

A rigid block slides on the moving base when the ground acceleration leaves
the stick band of its :class:`~stickslip.models.rigid.resistance.Resistance`:
a friction ratio μ (the paper's Eq. 1, both ways past μ·g) or a yield
coefficient k_y (downslope past k_y·g; with ``direction="both"`` also
upslope, at a thrust angle), constant or varying with the downslope
displacement (a :class:`~stickslip.models.yield_table.YieldTable`).  Three
schemes solve it (:data:`SCHEMES`): ``exact`` (event-driven, with the batched
kernel that sweeps use), ``newmark`` (the paper's Algorithm 1) and
``slammer`` (SLAMMER 1.1's own stepping).  Its result is a
:class:`~stickslip.models.rigid.response.Response`.
"""

from __future__ import annotations

from stickslip.models.parameters import DIRECTION, GRAVITY, INVERSE, KY, MASS, MU, THRUST_ANGLE
from stickslip.models.registry import public_names, register
from stickslip.models.rigid.scheme import RigidScheme
from stickslip.models.swept import SweptModel

#: The schemes of the rigid block, the default first.
SCHEMES = (
    RigidScheme("exact", "event-driven, exact for a record linear between samples",
                "stickslip.models.rigid.exact_scheme:sliding_history", batched=True),
    RigidScheme("newmark", "the paper's Algorithm 1, explicit time stepping",
                "stickslip.models.rigid.newmark:sliding_history", flat_only=True,
                history_points_per_sample=None),  # resampled to time_step: it checks its memory on its own grid
    RigidScheme("slammer", "SLAMMER 1.1's rigid-block scheme", "stickslip.models.rigid.slammer:sliding_history",
                yield_table=True,
                inverse_options={"skip_zero_samples": False}),  # SLAMMER skips zero samples in normal polarity only
)


class RigidModel(SweptModel):
    """The rigid block's entry: one component, a friction ratio or a yield coefficient, three schemes."""

    name = "rigid"
    summary = "a rigid block on the moving base (Newmark): flat friction, or a slope one way or both ways"
    motions = ("component",)
    parameters = (MU, KY, DIRECTION, THRUST_ANGLE, INVERSE, MASS, GRAVITY)
    schemes = SCHEMES
    #: Flat friction, a slope (not newmark's) in both polarities (in the inverse one a kernel gets the record's
    #: negated copy, a writable array: another signature than the record's read-only samples), and the paper's
    #: Algorithm 1 read literally (newmark's option only).
    examples = ({"mu": 0.1}, {"ky": 0.1}, {"ky": 0.1, "inverse": True}, {"mu": 0.1, "reading": "literal"})

    @property
    def warm_up_samples(self) -> int:
        """One sample past the plain-Python limit: the exact scheme's compiled history kernels run only on longer
        records (:data:`~stickslip.models.rigid.events.PYTHON_SAMPLES`)."""
        from stickslip.models.rigid.events import PYTHON_SAMPLES

        return PYTHON_SAMPLES + 1

    @property
    def result(self) -> type:
        from stickslip.models.rigid.response import Response

        return Response

    def case(self, parameters):
        """The :class:`~stickslip.models.rigid.case.RigidCase`: exactly one of ``mu`` and ``ky``, and how it slides."""
        from stickslip.models.rigid.case import RigidCase

        return RigidCase.of(parameters["mass"], parameters["g"], parameters["inverse"], mu=parameters["mu"],
                            ky=parameters["ky"], direction=parameters["direction"],
                            thrust_angle=parameters["thrust_angle"])

    def variables(self, case):
        from stickslip.models.rigid.sweep import variables

        return variables(case)

    def cube_attrs(self, case, scheme, run_options):
        from stickslip.models.rigid.sweep import cube_attrs

        return cube_attrs(case, run_options)

    def grid_coords(self, grid, case):
        from stickslip.models.rigid.sweep import grid_coords

        return grid_coords(grid, case)

    def parameters_of(self, cube):
        from stickslip.models.rigid.sweep import cube_parameters

        return cube_parameters(cube)


#: The rigid block's entry.
RIGID = register(RigidModel())

#: The rigid block's public names beside its entry (:func:`~stickslip.models.registry.public_names`): name -> module.
PUBLIC = {"Response": "response", "SCALAR_ATTRS": "response", "SLOPE_SCALAR_ATTRS": "response",
          "PYTHON_SAMPLES": "events", "SLAMMER_GRAVITY": "slammer"}
__getattr__ = public_names(__name__, PUBLIC)
