"""The resisting thresholds of a sliding block: flat friction, one-way and two-way yield coefficients."""

from __future__ import annotations

import math

import pytest

import stickslip
from stickslip.errors import StickslipError
from stickslip.models.rigid.resistance import Resistance

G = 9.81


def test_flat_friction_has_equal_thresholds_and_no_body_force():
    assert stickslip.Resistance is Resistance  # part of the public API
    flat = Resistance.friction(0.1, G)
    assert flat.thresholds() == (0.1 * G, 0.1 * G, 0.0)
    assert (flat.lower, flat.upper) == (-0.1 * G, 0.1 * G)
    assert flat.parameters == {"mu": 0.1}
    assert not flat.on_slope
    assert flat.describe() == "mu = 0.1"


def test_one_way_never_slides_upslope():
    one_way = Resistance.one_way(0.15, 9.80665)
    assert one_way.thresholds() == (math.inf, 0.15 * 9.80665, 0.0)
    assert one_way.lower == -math.inf and one_way.upper == 0.15 * 9.80665
    assert one_way.on_slope
    assert one_way.describe() == "ky = 0.15, one-way (downslope)"


def test_two_way_slides_upslope_past_ky_plus_twice_the_slope_component():
    """SLAMMER's thrust angle β: downslope past k_y·g, upslope past k_y·g + 2·g·sin β."""
    two_way = Resistance.two_way(0.1, G, 30.0)
    along = G * math.sin(math.radians(30.0))
    assert two_way.upper == pytest.approx(0.1 * G, rel=1e-15)
    assert two_way.lower == pytest.approx(-(0.1 * G + 2 * along), rel=1e-15)
    assert two_way.positive == two_way.negative == pytest.approx(0.1 * G + along, rel=1e-15)
    assert two_way.body == -along
    assert two_way.describe() == "ky = 0.1, two-way, thrust angle 30 deg"


def test_inclined_plane_with_friction_is_the_two_way_block():
    """A block with friction μ on a plane at β, shaken along it: k_y = μ·cos β − sin β, T = μ·g·cos β."""
    mu, beta = 0.6, 20.0
    ky = mu * math.cos(math.radians(beta)) - math.sin(math.radians(beta))
    inclined = Resistance.two_way(ky, G, beta)
    assert inclined.negative == pytest.approx(mu * G * math.cos(math.radians(beta)), rel=1e-14)


def test_two_way_at_zero_thrust_angle_is_flat_friction_bit_for_bit():
    two_way = Resistance.two_way(0.2, G, 0.0)
    flat = Resistance.friction(0.2, G)
    assert (two_way.lower, two_way.upper) == (flat.lower, flat.upper)
    assert two_way.positive == flat.positive and two_way.negative == flat.negative


@pytest.mark.parametrize(
    ("options", "message"),
    [
        ({"mu": 0.1, "ky": 0.1}, "not both"),
        ({}, "give a friction ratio mu or a yield coefficient ky"),
        ({"mu": 0.1, "direction": "down"}, "apply to a yield coefficient ky"),
        ({"ky": 0.1, "direction": "up"}, "direction must be one of down, both"),
        ({"ky": 0.1, "thrust_angle": 10.0}, "thrust_angle applies to two-way"),
        ({"ky": 0.1, "direction": "both", "thrust_angle": 91.0}, "between 0 and 90"),
        ({"ky": -0.1}, "yield coefficient ky must be a positive finite number"),
        ({"mu": math.nan}, "friction ratio mu must be a positive finite number"),
    ],
)
def test_from_options_refuses_what_means_nothing(options, message):
    with pytest.raises(StickslipError, match=message):
        Resistance.from_options(G, **options)


def test_from_options_builds_each_variant():
    assert Resistance.from_options(G, mu=0.1) == Resistance.friction(0.1, G)
    assert Resistance.from_options(G, ky=0.1) == Resistance.one_way(0.1, G)
    assert Resistance.from_options(G, ky=0.1, direction="down") == Resistance.one_way(0.1, G)
    assert Resistance.from_options(G, ky=0.1, direction="both") == Resistance.two_way(0.1, G, 0.0)
    assert Resistance.from_options(G, ky=0.1, direction="both", thrust_angle=5.0) == Resistance.two_way(0.1, G, 5.0)


@pytest.mark.parametrize(("positive", "negative", "body"), [(0.0, 1.0, 0.0), (1.0, math.inf, 0.0), (1.0, 1.0, math.nan)])
def test_thresholds_must_make_sense(positive, negative, body):
    with pytest.raises(StickslipError, match="expected thresholds"):
        Resistance(positive, negative, body)
