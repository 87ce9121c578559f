"""The design answer of a pair (``optimum --pair``, the pair report): each direction refined as a record's answer,
and a sentence on how the plane's μ_max relates to each component's (``stickslip.models.planar.design``)."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from test_optimum import pulse, write_at2

import stickslip
from stickslip.grids import Grid, range_values
from stickslip.models.planar.design import component_records, pair_answers, relation
from stickslip.models.rigid import RIGID
from stickslip.optimum import grid_for_ranges, optimum, solve_curves
from stickslip.records.record import Record, RecordMeta

G = 9.81
MU = range_values(0.01, 0.2, 0.01)


def component(name: str, amplitude: float, seed: int) -> Record:
    """A noisy pulse [m/s²] named as one component of station S of Test 2024."""
    record = pulse(name, amplitude, seed)
    return Record(record.acceleration, record.dt, RecordMeta(record_id=f"S-{name}", event="Test 2024", station="S",
                                                             component=name))


@pytest.fixture(scope="module")
def weak_pair():
    """A pair of PGA about 0.07 g and 0.05 g: its ranges hold a few values of MU."""
    return stickslip.RecordPair(component("000", 0.6, 4), component("090", 0.45, 6))


def test_each_component_gets_the_answer_optimum_gives_it_alone(weak_pair):
    cube = stickslip.planar_sweep([weak_pair], MU, mass=5.1, progress=False)
    (answer,) = pair_answers(cube, [weak_pair], 0.95, 0.1, 10)
    for direction, record in zip(("first", "second"), component_records(weak_pair)):
        design = RIGID.design(Grid("mu", MU), mass=5.1, g=G)
        curves, _, refinements = grid_for_ranges([record], solve_curves([record], design), design)
        alone, _ = optimum([record], curves, design.with_values(curves.grid.values))
        found = answer.directions[direction]
        for name in ("mu_max_continuous", "mu_low", "mu_high", "largest_stroke", "energy_dissipated_max_continuous"):
            assert found.results[name] == pytest.approx(float(alone[name][0]), rel=1e-12), (direction, name)
        assert len(found.refinements) == len(refinements) == 1  # a weak record: its range refined
    plane = answer.directions["plane"]
    assert plane.refinements and plane.results["grid_values_in_range"] >= 10  # two or three values on MU before
    assert plane.refinements[0].before <= 3
    grid_best = float(cube.isel(pair=0)["energy_dissipated_max"].sel(direction="plane"))
    assert plane.results["energy_dissipated_max_continuous"] >= grid_best
    assert plane.results["mu_low"] <= plane.results["mu_max_continuous"] <= plane.results["mu_high"]
    mu = [answer.directions[direction].results["mu_max_continuous"] for direction in ("plane", "first", "second")]
    assert answer.relation.startswith(f"the plane's μ_max {mu[0]:.4g} lies ")
    assert f"000's {mu[1]:.4g} and 090's {mu[2]:.4g}" in answer.relation


@pytest.mark.parametrize(("mu", "words"), [
    ((0.12, 0.09, 0.15), "the plane's μ_max 0.12 lies between the components' (000's 0.09 and 090's 0.15)"),
    ((0.0585, 0.0419, 0.041), "the plane's μ_max 0.0585 lies above both components' (000's 0.0419 and 090's 0.041): "
                              "the block in the plane slides wherever the magnitude of the ground acceleration"),
    ((0.03, 0.0419, 0.041), "the plane's μ_max 0.03 lies below both components' (000's 0.0419 and 090's 0.041), "
                            "although the magnitude of the ground acceleration in the plane (peak 0.418 g)"),
    ((0.05, math.nan, 0.04), "the plane's μ_max is 0.05, beside 090's 0.04 alone; under 000 alone the block never "
                             "slides on the grid"),
    ((math.nan, math.nan, math.nan), "the block in the plane never slides on the grid, so it has no μ_max"),
])
def test_the_sentence_says_how_the_plane_s_mu_max_relates_to_the_components(mu, words):
    assert relation(*mu, ("000", "090"), (0.324, 0.409, 0.418)).startswith(words)


def test_optimum_pair_prints_each_direction_s_refined_answer_and_the_relation(run_cli, weak_pair, tmp_path):
    paths = []
    for record in (weak_pair.first, weak_pair.second):
        paths.append(tmp_path / f"S-{record.meta.component}.AT2")
        write_at2(paths[-1], record)
        paths[-1].write_text(paths[-1].read_text().replace("Station Z, 090", f"Station Z, {record.meta.component}"))
    code, out, err = run_cli("optimum", *paths, "--pair", "--mu", "0.01:0.2:0.01", "--json")
    assert code == 0, err
    (pair,) = json.loads(out)["pairs"]
    plane = pair["results"]["in the plane"]
    assert plane["grid_refinements"] and plane["grid_values_in_range"] >= 10 and plane["bounds"] == {}
    assert pair["relation"].startswith("the plane's μ_max ")
    code, out, err = run_cli("optimum", *paths, "--pair", "--mu", "0.01:0.2:0.01")
    assert code == 0, err
    lines = out.splitlines()
    assert any(line.startswith("  in the plane: grid of ") and "its near-optimal range holds" in line
               for line in lines)
    row = next(line for line in lines if line.startswith("in the plane "))
    assert f"{plane['mu_max_continuous']:.5g}" in row.split()
    assert pair["relation"][0].upper() + pair["relation"][1:] + "." in lines
    np.testing.assert_array_less(0.0, [plane["mu_low"], plane["mu_high"]])
