"""The isolated building and the friction tuned mass damper in the plane, with the vertical and μ(v), through the models.

On the first 5 s of a three-component station (Tabas 1978, station Tabas: two horizontal components of 0.85 g and a
vertical of 0.64 g, every 0.02 s):

* ``solve --pair``, ``--vertical`` and both give every answer, finite, exit code 0; a bad combination is one line;
* a pair whose second component is zero is the exact one-direction answer (at the samples, where the plane's peaks
  are taken);
* a pair turned by 30° gives the same magnitudes;
* a constant vertical acceleration c is the building under gravity g + c (the normal force N₀·(1 + c/g)), with the
  vertical's work W_v the potential energy the heavier normal force stores beyond the static one;
* the ledger closes, with the vertical and μ(v), and μ(v) with μ_slow = μ_fast is Coulomb friction;
* a sweep of pairs over μ is the solves', every variable of its cube (with W_v, and with the vertical the lift-off
  time) and its units and long name, and ``stickslip sweep --out`` writes both.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

import stickslip
from stickslip.records.pair import RecordPair
from stickslip.records.readers import read_record
from stickslip.records.record import Record, RecordMeta
from stickslip.records.vertical import WithVertical

G = 9.81
#: The first 5 s of the station, every 0.02 s.
SAMPLES = 251
STATION = ("Tabas_Tabas", "RSN143_TABAS_TAB-L1.AT2", "RSN143_TABAS_TAB-T1.AT2", "RSN143_TABAS_TAB-V1.AT2")
MODELS = {
    "isolated": {"model": "isolated", "superstructure_period": 0.5, "stories": 2, "radius": 2.0, "mu": 0.06},
    "friction-tmd": {"model": "friction-tmd", "structure_period": 1.0, "stories": 2, "mass_ratio": 0.05,
                     "radius": 2.0, "mu": 0.1},
}
#: The answers compared, per model: the stroke, the largest drift, the floor acceleration and E_df.
ANSWERS = {"isolated": ("peak_isolator_displacement", "peak_drift", "peak_floor_acceleration",
                        "base_shear_coefficient", "energy_dissipated"),
           "friction-tmd": ("peak_damper_stroke", "peak_drift", "peak_floor_acceleration", "base_shear_coefficient",
                            "energy_dissipated")}


@pytest.fixture(scope="module")
def station(shared_records):
    """(first, second, vertical) records of the station's first 5 s, in m/s²."""
    folder = shared_records / "three_component" / STATION[0]
    records = []
    for name, component in zip(STATION[1:], ("L1", "T1", "V1")):
        record = read_record(folder / name)
        assert record.dt == 0.02
        records.append(Record(record.acceleration[:SAMPLES].copy(), record.dt,
                              RecordMeta(record_id=f"TAB-{component}", station="Tabas", component=component)))
    return tuple(records)


@pytest.fixture(scope="module")
def station_files(station, tmp_path_factory):
    """The station's three components as two-column text files [s, m/s²]."""
    folder = tmp_path_factory.mktemp("station")
    paths = []
    for record in station:
        path = folder / f"{record.meta.record_id}.txt"
        time = np.arange(record.acceleration.size) * record.dt
        path.write_text("\n".join(f"{t:.2f} {a:.15e}" for t, a in zip(time, record.acceleration)) + "\n")
        paths.append(path)
    return paths


def _options(parameters: dict) -> list[str]:
    return [part for name, value in parameters.items() for part in (f"--{name.replace('_', '-')}", str(value))]


@pytest.mark.parametrize("name", MODELS)
@pytest.mark.parametrize("motion", ["pair", "vertical", "pair-vertical"])
def test_solve_takes_the_pair_and_the_vertical(run_cli, station_files, name, motion):
    first, second, vertical = station_files
    files = [first, second, "--pair"] if motion.startswith("pair") else [first]
    extra = ["--vertical", vertical, "--vertical-positive", "up"] if motion.endswith("vertical") else []
    code, out, err = run_cli("solve", *files, *extra, "--units", "m/s2", *_options(MODELS[name]), "--json")
    assert code == 0, err
    document = json.loads(out)
    expected = {"peak_drift", "peak_floor_acceleration", "base_shear_coefficient", "energy_dissipated",
                "energy_input", "energy_input_vertical", "balance_residual", "liftoff_time", "peak_story_drifts"}
    expected |= ({"peak_isolator_displacement", "residual_isolator_displacement", "superstructure_shear_coefficient"}
                 if name == "isolated" else
                 {"peak_structure_displacement", "peak_damper_stroke", "peak_drift_reduction", "bare_structure"})
    assert expected <= set(document)
    assert all(math.isfinite(document[key]) for key in expected if isinstance(document[key], float))
    assert document["motion"] == ("pair" if motion.startswith("pair") else "component") + (
        " with its vertical" if extra else "")
    assert document["energy_dissipated"] > 0.0
    assert (document["energy_input_vertical"] != 0.0) == bool(extra)


@pytest.mark.parametrize("options, message", [
    (["--mu", "0.06", "--mu-fast", "0.1"], "are two friction laws"),
    (["--mu", "0.06", "--rate", "20"], "applies to the velocity law"),
])
def test_a_bad_combination_is_one_line(run_cli, station_files, options, message):
    first, second, _ = station_files
    building = ["--model", "isolated", "--superstructure-period", "0.5"]
    code, out, err = run_cli("solve", first, second, "--pair", "--units", "m/s2", *building, *options)
    assert (code, out) == (2, "")
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("stickslip: error: ") and message in lines[0], err


def _at_the_samples(name: str, result) -> dict:
    """The one-direction result's answers at the samples (where the plane's peaks are taken), from its histories."""
    histories = result.histories()
    if name == "isolated":
        drift = np.abs(histories["story_drift"]).max()
        stroke = np.abs(histories["isolator_displacement"]).max()
        acceleration = np.abs(histories["floor_acceleration"]).max()
        return {"peak_isolator_displacement": stroke, "peak_drift": drift, "peak_floor_acceleration": acceleration}
    floors = result.history["floor_displacement"]
    drift = np.abs(np.diff(floors, axis=1, prepend=0.0)).max()
    return {"peak_damper_stroke": np.abs(histories["relative_displacement"]).max(), "peak_drift": drift,
            "peak_floor_acceleration": np.abs(result.history["floor_acceleration"]).max()}


@pytest.mark.parametrize("name", MODELS)
def test_a_pair_with_a_zero_component_is_the_exact_one_direction_answer(station, name):
    first = station[0]
    quiet = Record(np.zeros_like(first.acceleration), first.dt, RecordMeta(record_id="TAB-0", component="0"))
    exact = stickslip.solve(first, **MODELS[name])
    plane = stickslip.solve(RecordPair(first, quiet), **MODELS[name])
    assert exact.method == plane.method == "exact" and type(exact) is not type(plane)
    solved = plane.scalars()
    assert solved["n_slip_episodes"] == exact.scalars()["n_slip_episodes"] >= 1
    for key, value in _at_the_samples(name, exact).items():
        assert solved[key] == pytest.approx(value, rel=1e-8), key
    assert solved["energy_dissipated"] == pytest.approx(exact.scalars()["energy_dissipated"], rel=1e-8)
    assert solved["energy_input_vertical"] == 0.0


@pytest.mark.parametrize("name", MODELS)
def test_a_turned_pair_gives_the_same_magnitudes(station, name):
    first, second, vertical = station
    angle = math.radians(30.0)
    turned = [Record(math.cos(angle) * first.acceleration - math.sin(angle) * second.acceleration, first.dt,
                     RecordMeta(record_id="TAB-a", component="a")),
              Record(math.sin(angle) * first.acceleration + math.cos(angle) * second.acceleration, first.dt,
                     RecordMeta(record_id="TAB-b", component="b"))]
    given = stickslip.solve(WithVertical(RecordPair(first, second), vertical, "positive up"), **MODELS[name])
    solved = stickslip.solve(WithVertical(RecordPair(*turned), vertical, "positive up"), **MODELS[name])
    assert given.scalars()["n_slip_episodes"] >= 1
    for key in (*ANSWERS[name], "energy_input", "energy_input_vertical", "sliding_path"):
        assert solved.scalars()[key] == pytest.approx(given.scalars()[key], rel=1e-8), key


def test_a_constant_vertical_is_the_building_under_a_heavier_gravity(station):
    first, second, _ = station
    lifted = 0.3 * G
    constant = Record(np.full(first.acceleration.size, lifted), first.dt, RecordMeta(record_id="up", component="UP"))
    pair = RecordPair(first, second)
    with_vertical = stickslip.solve(WithVertical(pair, constant, "positive up"), **MODELS["isolated"])
    heavier = stickslip.solve(pair, **{**MODELS["isolated"], "g": G + lifted})
    for key in ("peak_isolator_displacement", "peak_drift", "peak_floor_acceleration", "energy_dissipated"):
        assert with_vertical.scalars()[key] == pytest.approx(heavier.scalars()[key], rel=1e-9), key
    # W_v = −∫(ΔN/R)·s·ds: the potential energy the heavier N stores beyond the one the ledger keeps at the static N₀
    energies = with_vertical.scalars()
    assert energies["energy_input_vertical"] == pytest.approx(
        energies["potential_energy"] - heavier.scalars()["potential_energy"], rel=1e-8)
    assert energies["energy_input_vertical"] < 0.0


@pytest.mark.parametrize("name", MODELS)
@pytest.mark.parametrize("law", [{}, {"mu_slow_ratio": 0.5, "rate": 20.0}], ids=["coulomb", "velocity-law"])
def test_the_ledger_closes_with_the_vertical(station, name, law):
    first, second, vertical = station
    result = stickslip.solve(WithVertical(RecordPair(first, second), vertical, "positive up"), **MODELS[name], **law)
    scalars = result.scalars()
    assert scalars["n_slip_episodes"] >= 1
    assert scalars["balance_residual"] <= 1e-8 * scalars["energy_input"]
    ledger = result.energy_ledger()
    assert set(ledger) >= {"energy_input_vertical", "balance_residual"}
    assert (result.case()["friction_law"] == "velocity_dependent") == bool(law)


@pytest.mark.parametrize("name", MODELS)
def test_the_velocity_law_with_equal_coefficients_is_coulomb_friction(station, name):
    first, second, vertical = station
    motion = WithVertical(RecordPair(first, second), vertical, "positive up")
    coulomb = {**MODELS[name]}
    mu = coulomb.pop("mu")
    law = stickslip.solve(motion, **coulomb, mu_slow=mu, mu_fast=mu, rate=20.0, method="integrated")
    plain = stickslip.solve(motion, **coulomb, mu=mu, method="integrated")
    for key in ANSWERS[name]:
        assert law.scalars()[key] == pytest.approx(plain.scalars()[key], rel=1e-12), key
    unequal = stickslip.solve(motion, **coulomb, mu_slow=0.5 * mu, mu_fast=mu, rate=20.0)
    assert unequal.scalars()["energy_dissipated"] != pytest.approx(plain.scalars()["energy_dissipated"], rel=1e-3)


@pytest.mark.parametrize("name", MODELS)
@pytest.mark.parametrize("vertical", [False, True], ids=["pair", "pair-vertical"])
def test_a_sweep_of_pairs_is_the_solves(station, name, vertical):
    first, second, up = station
    down = Record(up.acceleration * 1.2 * G / -up.acceleration.min(), up.dt, up.meta)  # down to -1.2 g: it lifts off
    motion = WithVertical(RecordPair(first, second), down, "positive up") if vertical else RecordPair(first, second)
    parameters = {key: value for key, value in MODELS[name].items() if key != "mu"}
    cube = stickslip.sweep([motion], mu=[0.04, 0.08], **parameters)
    assert ("liftoff_time" in cube) == vertical  # no vertical, no lift-off
    for index, mu in enumerate((0.04, 0.08)):
        solved = stickslip.solve(motion, mu=mu, **parameters)
        scalars, table = solved.scalars(), solved.scalar_table
        assert set(cube.data_vars) <= set(scalars)
        for key, variable in cube.data_vars.items():
            assert float(variable.values.reshape(-1)[index]) == pytest.approx(scalars[key], rel=1e-12, abs=0.0), key
            assert (variable.attrs["units"], variable.attrs["long_name"]) == table[key], key
        if vertical:
            assert scalars["energy_input_vertical"] != 0.0 and scalars["liftoff_time"] > 0.0
        else:
            assert float(cube.energy_input_vertical.values.reshape(-1)[index]) == 0.0


def test_the_sweep_command_s_cube_holds_the_vertical_s_work_and_the_lift_off_time(run_cli, station_files, tmp_path):
    import xarray as xr

    first, second, vertical = station_files
    out = tmp_path / "cube.nc"
    code, _, err = run_cli("sweep", first, second, "--pair", "--vertical", vertical, "--vertical-positive", "up",
                           "--units", "m/s2", *_options({**MODELS["isolated"], "mu": "0.04,0.08"}), "--out", out)
    assert code == 0, err
    with xr.open_dataset(out) as cube:
        for index, mu in enumerate((0.04, 0.08)):
            code, solved, err = run_cli("solve", first, second, "--pair", "--vertical", vertical,
                                        "--vertical-positive", "up", "--units", "m/s2",
                                        *_options({**MODELS["isolated"], "mu": mu}), "--json")
            document = json.loads(solved)
            for key, units in (("energy_input_vertical", "J"), ("liftoff_time", "s")):
                assert cube[key].attrs["units"] == units and cube[key].attrs["long_name"]
                assert float(cube[key].values.reshape(-1)[index]) == pytest.approx(document[key], rel=1e-12), key


def test_the_optimum_s_cube_holds_them_solved_once_with_its_curves(run_cli, station_files, tmp_path):
    import xarray as xr

    first, second, vertical = station_files
    out = tmp_path / "cube.nc"
    code, _, err = run_cli("optimum", first, second, "--pair", "--vertical", vertical, "--vertical-positive", "up",
                           "--units", "m/s2", *_options({**MODELS["friction-tmd"], "mu": "0.02:0.2:0.06"}),
                           "--range-points", "0", "--out", out)
    assert code == 0, err
    with xr.open_dataset(out) as cube:
        motion = WithVertical(RecordPair(*(read_record(path, units="m/s2") for path in (first, second))),
                              read_record(vertical, units="m/s2"), "positive up")
        for index, mu in enumerate(cube.mu.values):
            solved = stickslip.solve(motion, **{**MODELS["friction-tmd"], "mu": float(mu)}).scalars()
            for key in ("energy_input_vertical", "liftoff_time"):
                assert float(cube[key].values.reshape(-1)[index]) == pytest.approx(solved[key], rel=1e-12), key
