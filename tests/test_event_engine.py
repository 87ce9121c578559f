"""The event engine of stickslip.solvers: each model's own compiled loops, and the pieces of the loop in an interval."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from stickslip.models.pendulum import vertical_exact
from stickslip.models.rigid import events as rigid_events
from stickslip.models.rigid import exact as rigid_exact
from stickslip.solvers import events, restoring


@pytest.mark.parametrize("module, loops", [
    (rigid_exact, ("_record_state", "_sweep_pairs")),
    (restoring, ("_record_state", "_sweep_pairs", "advance_interval")),
    (vertical_exact, ("_sweep_pairs",)),
])
def test_each_model_compiles_the_engine_s_loops_as_its_own(module, loops):
    """The loops are the engine's code compiled on the model's phase functions, cached beside the model: two
    models with one cache file for the same loop would load each other's machine code."""
    for name in loops:
        function = getattr(module, name).py_func
        assert function.__code__.co_code == getattr(events, function.__code__.co_name).__code__.co_code
        assert Path(function.__code__.co_filename) == Path(module.__file__)
        assert function.__module__ == module.__name__


@pytest.mark.parametrize("module", [rigid_exact, restoring])
def test_the_record_loop_counts_no_references(module):
    """The inlined phase functions take the record's arrays from its tuple at every interval: with numba's
    reference counting, two atomic operations per array and interval (the rigid μ sweep 30 % slower)."""
    assert module._record_state.targetoptions["_nrt"] is False
    assert "_nrt" not in module._record_scalars.targetoptions  # the caller holds the record's arrays


def test_the_rigid_block_runs_the_engine_s_interval_loop_as_plain_python():
    """Short records are solved without numba: the engine's loop bound to the block's plain phase functions."""
    loop = rigid_events.advance_interval
    assert loop.__code__.co_code == events.interval_state.__code__.co_code
    assert loop.__globals__["band"] is rigid_events.band
    assert loop.__globals__["slid"] is rigid_events.slid
    # a block at rest under a ground acceleration rising from 0 to 2 m/s² over 0.1 s breaks away at μ·g = 1 m/s²
    x, v, s, phase_after_start, _, path, slip_time, episodes, _, _ = loop((-1.0, 1.0), 0.0, 2.0, 20.0, 0.1, 0.0,
                                                                          0.0, 0.0, 0)
    assert (s, phase_after_start, episodes) == (-1, 0, 1)
    assert slip_time == pytest.approx(0.05, rel=1e-15)
    # ẍ = −(a − 1) = −20·τ over the 0.05 s of the slide: v = −10·τ², x = −10·τ³/3
    assert v == pytest.approx(-0.025, rel=1e-14)
    assert x == pytest.approx(-10.0 * 0.05**3 / 3.0, rel=1e-14)
    assert path == pytest.approx(-x, rel=1e-15)


@pytest.mark.parametrize("a, a_end, slope, expected", [
    (1.5, 2.0, 5.0, (0.0, -1)),            # above the band already: slides towards −x at once
    (-1.5, -2.0, -5.0, (0.0, 1)),          # below it: towards +x
    (0.0, 2.0, 20.0, (0.05, -1)),          # crosses the upper edge 1 m/s² after 0.05 s
    (0.0, -2.0, -20.0, (0.05, 1)),         # the lower edge
    (0.0, 1.0, 10.0, (math.inf, 0)),       # ends exactly at the edge: no slide of zero length
    (0.5, 0.7, 2.0, (math.inf, 0)),        # stays inside
])
def test_breakaway_is_decided_by_the_interval_s_end_sample(a, a_end, slope, expected):
    """The band [−1, 1] m/s²: where and which way a held state breaks away inside an interval."""
    tau, direction = events.breakaway(a, a_end, slope, -1.0, 1.0)
    assert direction == expected[1]
    assert tau == pytest.approx(expected[0], rel=1e-15)


def test_the_ground_at_an_event_stays_between_the_interval_s_end_values():
    """Round-off past an end sample would put a stop beyond an edge that the sample sits on."""
    a, vg = events.ground_at(0.1 + 1e-17, 0.0, 1.0, 10.0, 0.5)
    assert a == 1.0
    assert vg == pytest.approx(0.5 + 0.1 * 0.5, rel=1e-15)
    assert events.ground_at(0.04, 0.0, 1.0, 10.0, 0.0) == pytest.approx((0.4, 0.008), rel=1e-15)
