"""The friction pendulum's ledger with a vertical ground motion: E_k + E_p + E_df = E_I,h + E_I,v.

E_p = m·g·|u|²/(2R) is the potential energy (a state, never negative) and
E_I,v = W_v = −∫(N − m·g)·u·du/R the work of the vertical motion through the
normal force on the curved surface, zero without a vertical; in one direction
and in the plane, on a three-component station and on synthetic motions.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
import xarray as xr

import stickslip
from stickslip.records.pair import RecordPair
from stickslip.records.record import Record, RecordMeta
from stickslip.records.vertical import WithVertical

G = 9.81
RADIUS = 2.0
MASS = 3.0
LEDGER = ("energy_input", "energy_input_vertical", "energy_dissipated", "kinetic_energy", "potential_energy",
          "balance_residual")


def component(acceleration: np.ndarray, dt: float, name: str) -> Record:
    return Record(np.asarray(acceleration, dtype=float), dt, RecordMeta(record_id=name, component=name.split("-")[-1]))


@pytest.fixture(scope="module")
def synthetic() -> dict:
    """20 s at 0.01 s: two horizontal components (0.5 g and 0.35 g) and a vertical of 0.6 g at 7 Hz, positive up."""
    dt = 0.01
    time = np.arange(0.0, 20.0, dt)
    envelope = time * np.exp(-0.35 * time)
    envelope /= envelope.max()
    first = 0.5 * G * envelope * np.sin(2 * np.pi * 0.8 * time)
    second = 0.35 * G * envelope * np.cos(2 * np.pi * 1.3 * time + 0.4)
    vertical = 0.6 * G * envelope * np.sin(2 * np.pi * 7.0 * time + 1.0)
    return {"first": component(first, dt, "SYN-000"), "second": component(second, dt, "SYN-090"),
            "vertical": component(vertical, dt, "SYN-UP")}


def assert_ledger_closes(result, tolerance: float) -> dict:
    """The ledger's histories [J] close, E_p is m·g·|u|²/(2R) at every sample and never negative; returns them."""
    ledger = result.energy_ledger()
    assert tuple(ledger) == LEDGER
    balance = (ledger["kinetic_energy"] - ledger["kinetic_energy"][0] + ledger["potential_energy"]
               - ledger["potential_energy"][0] + ledger["energy_dissipated"] - ledger["energy_input"]
               - ledger["energy_input_vertical"])
    largest = np.max(np.abs(ledger["energy_input"]))
    np.testing.assert_allclose(ledger["balance_residual"], balance, rtol=0, atol=1e-14 * largest)
    assert np.max(np.abs(balance)) <= tolerance * largest
    displacement = np.asarray(result.to_xarray()["relative_displacement"].values).reshape(balance.size, -1)
    squared = np.sum(displacement * displacement, axis=1)
    assert np.all(ledger["potential_energy"] >= 0.0)
    np.testing.assert_allclose(ledger["potential_energy"], MASS * G * squared / (2 * RADIUS), rtol=1e-14, atol=0)
    scalars = result.scalars()
    assert scalars["potential_energy_final"] == pytest.approx(MASS * G * squared[-1] / (2 * RADIUS), rel=1e-14)
    assert scalars["energy_input_vertical"] == ledger["energy_input_vertical"][-1]
    return ledger


@pytest.mark.parametrize("law", [{"mu": 0.06}, {"mu_slow": 0.04, "mu_fast": 0.09, "rate": 25.0}])
def test_the_split_ledger_closes_on_synthetic_motions_in_one_direction_and_in_the_plane(synthetic, law):
    case = {**law, "radius": RADIUS, "mass": MASS}
    pair = RecordPair(synthetic["first"], synthetic["second"])
    for horizontal in (synthetic["first"], pair):
        alone = stickslip.solve(horizontal, model="pendulum", **case)
        ledger = assert_ledger_closes(alone, 1e-9)
        assert np.all(ledger["energy_input_vertical"] == 0.0)  # no vertical: N = m·g
        moved = stickslip.solve(WithVertical.of(horizontal, synthetic["vertical"], "up"), **case)
        ledger = assert_ledger_closes(moved, 1e-9)
        vertical_work = ledger["energy_input_vertical"]
        assert np.max(np.abs(vertical_work)) > 1e-3 * np.max(ledger["potential_energy"])
        # the restoring force's work ∫(N/R)·u du is E_p − E_p(0) − W_v: positive N, so it grows with |u| on the way out
        assert moved.scalars()["liftoff_time"] == 0.0


def test_a_constant_vertical_acceleration_works_minus_c_times_the_rise(synthetic):
    """a_v = c: the normal force is m·(g + c) throughout, the slider moves as under gravity g + c, and the vertical
    motion's work is W_v = −m·c·|u|²/(2R) at every sample (from the centre at rest), E_p = m·g·|u|²/(2R)."""
    for c in (0.3 * G, -0.25 * G):
        steady = component(np.full(synthetic["first"].npts, c), synthetic["first"].dt, "SYN-UP")
        for horizontal in (synthetic["first"], RecordPair(synthetic["first"], synthetic["second"])):
            moved = stickslip.solve(WithVertical.of(horizontal, steady, "up"), mu=0.05, radius=RADIUS, mass=MASS)
            ledger = assert_ledger_closes(moved, 1e-9)
            scale = np.max(ledger["potential_energy"])
            np.testing.assert_allclose(ledger["energy_input_vertical"], -c / G * ledger["potential_energy"],
                                       rtol=0, atol=1e-9 * scale)
            heavier = stickslip.solve(horizontal, model="pendulum", mu=0.05, radius=RADIUS, mass=MASS,
                                      g=G + c).scalars()
            assert moved.scalars()["peak_relative_displacement"] == pytest.approx(
                heavier["peak_relative_displacement"], rel=1e-8)


def test_on_a_flat_surface_both_terms_are_zero(synthetic):
    moved = stickslip.solve(WithVertical.of(synthetic["first"], synthetic["vertical"], "up"), mu=0.06, mass=MASS)
    assert moved.scalars()["potential_energy_final"] == 0.0 and moved.scalars()["energy_input_vertical"] == 0.0
    assert moved.scalars()["balance_residual"] <= 1e-12 * moved.scalars()["energy_input"]


def test_the_split_ledger_closes_on_a_three_component_station(three_component_sets):
    """Imperial Valley 1940, El Centro #9 (0.28 g horizontal, 0.18 g vertical), R = 2 m, μ = 0.06: measured 3.4e-15
    (one direction) and 1.1e-12 (the plane, integrated to 1e-10) of the largest E_I,h; on all fifteen stations at
    most 1.6e-14 and 2.2e-12."""
    station = three_component_sets["ImperialValley02_ElCentroArray9"]
    size = min(record.npts for record in station.values())
    cut = {name: record.derive(record.acceleration[:size], step=f"first {size} samples")
           for name, record in station.items()}
    for horizontal in (cut["H1"], RecordPair(cut["H1"], cut["H2"], any_pair=True)):
        moved = stickslip.solve(WithVertical.of(horizontal, cut["UP"], "up"), mu=0.06, radius=RADIUS, mass=MASS)
        ledger = assert_ledger_closes(moved, 1e-9)
        assert abs(ledger["energy_input_vertical"][-1]) > 0.0


def test_solve_names_both_terms_in_its_text_json_and_histories(run_cli, synthetic, tmp_path):
    horizontal, vertical = tmp_path / "SYN-000.txt", tmp_path / "SYN-UP.txt"
    for path, record in ((horizontal, synthetic["first"]), (vertical, synthetic["vertical"])):
        time = np.arange(record.npts) * record.dt
        path.write_text("\n".join(f"{t:.2f} {a:.12e}" for t, a in zip(time, record.acceleration)) + "\n")
    arguments = (horizontal, "--units", "m/s2", "--radius", RADIUS, "--mu", "0.06", "--mass", MASS, "--vertical",
                 vertical, "--vertical-positive", "up")
    code, out, err = run_cli("solve", *arguments, "--json")
    assert code == 0, err
    printed = json.loads(out)
    assert printed["units"]["potential_energy_final"] == printed["units"]["energy_input_vertical"] == "J"
    assert "restoring_work" not in printed
    ledger = (printed["kinetic_energy_final"] + printed["potential_energy_final"] + printed["energy_dissipated"]
              - printed["energy_input"] - printed["energy_input_vertical"])
    assert abs(ledger) <= 1e-9 * printed["energy_input"] and printed["energy_input_vertical"] != 0.0
    code, out, err = run_cli("solve", *arguments)
    assert code == 0, err
    assert "E_k - E_k(0) + E_p - E_p(0) + E_df = E_I,h + E_I,v" in out
    assert out.count("potential_energy_final") == 2 and out.count("energy_input_vertical") == 2
    history = tmp_path / "case.nc"
    code, out, err = run_cli("solve", *arguments, "--out", history)
    assert code == 0, err
    with xr.open_dataset(history) as dataset:
        for name in ("potential_energy", "energy_input_vertical", "energy_input"):
            assert dataset[name].dims == ("time",) and dataset[name].attrs["units"] == "J", name
        assert dataset["energy_input_vertical"].values[-1] == pytest.approx(printed["energy_input_vertical"],
                                                                            rel=1e-12)
        assert math.isclose(float(dataset["potential_energy_final"]), printed["potential_energy_final"],
                            rel_tol=1e-12)
