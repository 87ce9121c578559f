"""What "optimal" may mean: each objective's merit, and the refusal of one a model does not offer."""

import numpy as np
import pytest

from stickslip.errors import StickslipError
from stickslip.objectives import OBJECTIVES, objective_named


@pytest.mark.parametrize("name, curve", [("drift", "peak_drift"), ("floor-acceleration", "peak_floor_acceleration"),
                                         ("base-shear", "base_shear_coefficient"),
                                         ("displacement", "peak_relative_displacement")])
def test_the_structure_objectives_prefer_the_smallest_value(name, curve):
    objective = OBJECTIVES[name]
    assert objective.curve == curve
    merit = objective.merit([0.5, 0.25, 0.0])
    assert merit.tolist() == [2.0, 4.0, np.inf]
    assert "{c}_max" in objective.long_names and objective.note.startswith("objective: the smallest")


def test_energy_prefers_the_largest_dissipation():
    assert OBJECTIVES["energy"].merit([1.0, 3.0]).tolist() == [1.0, 3.0]


def test_a_model_refuses_an_objective_it_does_not_offer():
    with pytest.raises(StickslipError, match="objective drift: the rigid model's optimum is energy or displacement "
                                             r"\(.*\), not the smallest peak story drift"):
        objective_named("drift", ("energy", "displacement"), "rigid")
    with pytest.raises(StickslipError, match="objective 'comfort': expected one of energy, displacement, drift, "
                                             "floor-acceleration, base-shear"):
        objective_named("comfort", ("energy",), "rigid")
