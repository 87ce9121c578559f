"""The friction pendulum in the plane as a model: a pair of components (and its vertical) through the one route.

Oracles at the model's level (1e-9): a very large radius is the flat planar
block; turning both components turns the response and keeps its scalars; a
pair whose second component is zero is the one-direction pendulum (with and
without the vertical, Coulomb and the velocity law, its closed forms where it
has them); a constant vertical acceleration c·g is gravity g·(1 + c), the base
shear coefficient scaled by 1 + c.  Then the command line: ``solve``,
``sweep`` and ``optimum`` with ``--pair --radius`` (and ``--vertical``), and
its mistakes in one line.  The motions are pyslammer's sample records, so a
stranger without the shared records runs every test.
"""

from __future__ import annotations

import json
import math
from importlib.resources import files as package_files

import numpy as np
import pytest
from conftest import assert_one_error_line

import stickslip
from stickslip.errors import StickslipError
from stickslip.models.pendulum.case import PendulumCase
from stickslip.solvers.friction_law import FrictionLaw
from stickslip.models.pendulum.pair import sweep_pair_motions
from stickslip.records.pair import RecordPair
from stickslip.records.readers import read_record
from stickslip.records.record import Record, RecordMeta
from stickslip.records.vertical import WithVertical
from stickslip.sweeps import read_cube

G = 9.81
SAMPLES = package_files("pyslammer") / "sample_ground_motions"
#: The end results compared between two solves that must agree.
COMPARED = ("energy_dissipated", "energy_input", "kinetic_energy_final", "potential_energy_final",
            "residual_displacement", "peak_relative_displacement", "sliding_path", "slip_fraction", "peak_base_shear",
            "liftoff_time")


def component(values, dt: float, name: str) -> Record:
    return Record(np.ascontiguousarray(values, dtype=float), dt, RecordMeta(record_id=name, component=name[-3:],
                                                                           source=f"{name}.txt"))


@pytest.fixture(scope="module")
def motion() -> dict:
    """Northridge VSP-360 and Loma Prieta HSP-000 (0.005 s) as two horizontal axes of one station, and Coalinga
    PVB-045 times −3 (1.1 g at most downwards: the slider lifts off) as its vertical, positive up; cut to 40 s."""
    first = read_record(SAMPLES / "Northridge_1994_VSP-360.csv")
    second = read_record(SAMPLES / "Loma_Prieta_1989_HSP-000.csv")
    third = read_record(SAMPLES / "Coalinga_1983_PVB-045.csv")
    length = min(first.npts, second.npts, third.npts, 8001)
    dt = first.dt
    return {"first": component(first.acceleration[:length], dt, "STA-000"),
            "second": component(second.acceleration[:length], dt, "STA-090"),
            "vertical": component(-3.0 * third.acceleration[:length], dt, "STA-UP"), "dt": dt}


def pair_of(motion, first=None, second=None) -> RecordPair:
    return RecordPair(first or motion["first"], second or motion["second"])


def relative(value: float, reference: float) -> float:
    return abs(value - reference) / max(abs(reference), 1e-300)


def test_a_pair_chooses_the_pendulum_with_a_radius_or_a_vertical_and_the_planar_block_without(motion):
    pair = pair_of(motion)
    assert stickslip.solve(pair, mu=0.08).model == "planar"
    solved = stickslip.solve(pair, mu=0.08, radius=2.0)
    assert solved.model == "pendulum" and solved.case()["motion"] == "pair"
    assert stickslip.solve(WithVertical.of(pair, motion["vertical"]), mu=0.08).model == "pendulum"
    scalars = solved.scalars()
    assert scalars["sliding_path"] > 0.1 and scalars["potential_energy_final"] > 0.0
    assert scalars["energy_input_vertical"] == 0.0
    assert scalars["balance_residual"] < 1e-9 * scalars["energy_input"]
    assert set(solved.scalar_units()) == set(scalars) and solved.scalar_units()["peak_base_shear"] == "1"


def test_a_slider_that_never_slides_says_why_from_the_pair_s_largest_acceleration(motion):
    pair = pair_of(motion)
    peak = float(np.max(np.hypot(*pair.horizontal())))
    mu = 1.01 * peak / G
    still = stickslip.solve(pair, mu=mu, radius=2.0)
    assert still.scalars()["energy_dissipated"] == 0.0 and still.scalars()["n_slip_episodes"] == 0
    assert still.never_slides == (f"its largest |a| on the pair's axes {peak:.4g} m/s2 ({peak / G:.4g} g) is at most "
                                  f"mu*g = {mu * G:.4g} m/s2 at mu = {mu:g}")
    assert stickslip.solve(pair, mu=0.99 * peak / G, radius=2.0).never_slides is None


def test_a_very_large_radius_is_the_flat_block_in_the_plane(motion):
    pair = pair_of(motion)
    flat = stickslip.solve(pair, mu=0.08, mass=3.0).scalars()
    for radius in (math.inf, 1e12):
        curved = stickslip.solve(pair, model="pendulum", mu=0.08, radius=radius, mass=3.0).scalars()
        assert curved["potential_energy_final"] == pytest.approx(0.0, abs=1e-9 * flat["energy_input"])
        assert curved["energy_input_vertical"] == 0.0
        assert curved["peak_relative_displacement"] == pytest.approx(flat["peak_displacement"], rel=1e-9)
        for name in ("energy_dissipated", "energy_input", "kinetic_energy_final", "residual_displacement",
                     "sliding_path", "slip_fraction"):
            assert relative(curved[name], flat[name]) < 1e-9, (radius, name)
        assert curved["n_slip_episodes"] == flat["n_slip_episodes"]
        assert curved["peak_base_shear"] == pytest.approx(0.08, rel=1e-9)  # flat: |u''| = mu*g while it slides


@pytest.mark.parametrize("angle", [30.0, 123.0])
def test_turning_both_components_turns_the_pendulum_and_keeps_its_results(motion, angle):
    turn = math.radians(angle)
    first, second = motion["first"].acceleration, motion["second"].acceleration
    turned = pair_of(motion, component(first * math.cos(turn) + second * math.sin(turn), motion["dt"], "STA-030"),
                     component(-first * math.sin(turn) + second * math.cos(turn), motion["dt"], "STA-120"))
    case = {"mu_slow": 0.04, "mu_fast": 0.09, "rate": 30.0, "radius": 1.5}
    reference = stickslip.solve(WithVertical.of(pair_of(motion), motion["vertical"]), **case)
    rotated = stickslip.solve(WithVertical.of(turned, motion["vertical"]), **case)
    assert reference.scalars()["liftoff_time"] > 0.0
    for name in COMPARED:
        assert relative(rotated.scalars()[name], reference.scalars()[name]) < 1e-9, name
    residual = reference.relative_displacement[-1]
    expected = (residual[0] * math.cos(turn) + residual[1] * math.sin(turn),
                -residual[0] * math.sin(turn) + residual[1] * math.cos(turn))
    scale = reference.scalars()["peak_relative_displacement"]
    np.testing.assert_allclose(rotated.relative_displacement[-1], expected, rtol=0, atol=1e-9 * scale)


@pytest.mark.parametrize("vertical", [False, True])
@pytest.mark.parametrize("case", [{"mu": 0.05, "radius": 2.0}, {"mu": 0.07, "radius": math.inf},
                                  {"mu_slow": 0.04, "mu_fast": 0.09, "rate": 30.0, "radius": 1.5}],
                         ids=["coulomb", "flat", "velocity-law"])
def test_a_pair_with_a_zero_component_is_the_pendulum_in_one_direction(motion, case, vertical):
    """The planar kernel against the one-direction schemes: closed forms for Coulomb friction (with a constant
    normal force on a curved surface, and under the vertical on a flat one), integration otherwise."""
    line = motion["first"]
    zero = component(np.zeros(line.npts), motion["dt"], "STA-090")
    pair = RecordPair(line, zero)
    if vertical:
        line, pair = WithVertical.of(line, motion["vertical"]), WithVertical.of(pair, motion["vertical"])
    alone = stickslip.solve(line, model="pendulum", **case).scalars()
    plane = stickslip.solve(pair, model="pendulum", **case)
    assert alone["sliding_path"] > 0.05
    assert (alone["liftoff_time"] > 0.0) == vertical
    for name in COMPARED:
        expected = abs(alone[name]) if name == "residual_displacement" else alone[name]
        scale = alone["energy_input"] if name in ("kinetic_energy_final", "potential_energy_final") else abs(expected)
        assert abs(plane.scalars()[name] - expected) <= 1e-9 * scale, name
    assert plane.scalars()["n_slip_episodes"] == alone["n_slip_episodes"]
    assert np.max(np.abs(plane.relative_displacement[:, 1])) == 0.0


@pytest.mark.parametrize("level", [0.3, -0.4])
def test_a_constant_vertical_acceleration_is_gravity_scaled(motion, level):
    """n = g + c·g: the slider sees gravity g·(1 + c); its base shear over its weight m·g is (1 + c) times the
    one over m·g·(1 + c), its potential energy m·g·|u|²/(2R) 1/(1 + c) times the one under g·(1 + c), and the
    vertical motion's work W_v = −m·c·g·|u|²/(2R) is −c/(1 + c) times that (none under g·(1 + c) alone)."""
    pair = pair_of(motion)
    constant = component(np.full(pair.npts, level * G), motion["dt"], "STA-UP")
    case = {"mu_slow": 0.04, "mu_fast": 0.09, "rate": 30.0, "radius": 2.0}
    moved = stickslip.solve(WithVertical.of(pair, constant), **case).scalars()
    scaled = stickslip.solve(pair, model="pendulum", g=G * (1 + level), **case).scalars()
    assert scaled["sliding_path"] > 0.05
    factor = {"peak_base_shear": 1 + level, "potential_energy_final": 1 / (1 + level)}
    for name in COMPARED:
        expected = scaled[name] * factor.get(name, 1.0)
        assert relative(moved[name], expected) < 1e-9 or moved[name] == expected == 0.0, name
    assert scaled["energy_input_vertical"] == 0.0 and scaled["potential_energy_final"] > 0.0
    assert relative(moved["energy_input_vertical"], -level / (1 + level) * scaled["potential_energy_final"]) < 1e-9


def test_the_base_shear_is_the_largest_absolute_acceleration_at_the_samples_or_more(motion):
    """V/W = max |u''|/g, u'' = a while stuck, -(n/R)·u - mu(s)·n·v/|v| while sliding: no sample exceeds it, and
    the samples come within a small fraction of it (the peaks between samples are the stops')."""
    radius, mu = 2.0, 0.06
    solved = stickslip.solve(pair_of(motion), mu=mu, radius=radius)
    u, v, a = solved.relative_displacement, solved.relative_velocity, solved.ground_acceleration
    speed = np.hypot(v[:, 0], v[:, 1])
    sliding = speed > 0.0
    direction = np.divide(v, speed[:, None], out=np.zeros_like(v), where=sliding[:, None])
    absolute = np.where(sliding[:, None], -(G / radius) * u - mu * G * direction, a)
    samples = np.max(np.hypot(absolute[:, 0], absolute[:, 1])) / G
    shear = solved.scalars()["peak_base_shear"]
    assert samples <= shear * (1 + 1e-12)
    assert shear < 1.05 * samples


@pytest.fixture
def record_files(tmp_path, motion):
    paths = {}
    for key in ("first", "second", "vertical"):
        record = motion[key]
        path = tmp_path / f"{record.meta.record_id}.txt"
        time = np.arange(record.npts) * record.dt
        path.write_text("\n".join(f"{t:.3f} {value:.12e}" for t, value in zip(time, record.acceleration)) + "\n")
        paths[key] = path
    return paths


def read(path) -> Record:
    return stickslip.read_record(path, units="m/s2")


def test_the_command_line_solves_sweeps_and_designs_the_pendulum_in_the_plane(run_cli, record_files, tmp_path):
    first, second, vertical = record_files["first"], record_files["second"], record_files["vertical"]
    common = ("--pair", "--radius", "2", "--units", "m/s2", "--vertical", vertical)
    code, out, err = run_cli("solve", first, second, *common, "--mu", "0.06", "--json")
    assert code == 0, err
    printed = json.loads(out)
    motion = WithVertical.of(RecordPair(read(first), read(second)), read(vertical))
    expected = stickslip.solve(motion, mu=0.06, radius=2.0)
    assert (printed["model"], printed["motion"], printed["radius"]) == ("pendulum", "pair", 2.0)
    assert printed["vertical_sense"] == "positive up (UP in its file name)"
    for name in COMPARED:
        assert printed[name] == pytest.approx(expected.scalars()[name], rel=1e-12, abs=1e-15), name
    assert printed["units"]["peak_base_shear"] == "1" and printed["units"]["liftoff_time"] == "s"
    np.testing.assert_allclose(printed["liftoff_intervals"], expected.liftoff, rtol=1e-12)
    assert len(printed["liftoff_intervals"]) > 0

    cube_path = tmp_path / "cube.nc"
    code, out, err = run_cli("sweep", first, second, *common, "--mu", "0.04:0.12:0.04", "--out", cube_path)
    assert code == 0, err
    cube = read_cube(cube_path)
    assert cube.attrs["model"] == "pendulum" and cube.sizes["mu"] == 3
    for index, mu in enumerate(cube["mu"].values):
        solved = stickslip.solve(motion, mu=float(mu), radius=2.0).scalars()
        for name in ("energy_dissipated", "peak_relative_displacement", "residual_displacement", "peak_base_shear",
                     "liftoff_time"):
            assert float(cube[name].values[0, index]) == pytest.approx(solved[name], rel=1e-12, abs=1e-15), name

    code, out, err = run_cli("optimum", first, second, *common, "--mu", "0.02:0.2:0.02", "--json")
    assert code == 0, err
    row = json.loads(out)["records"][0]
    at_best = stickslip.solve(motion, mu=row["mu_max"], radius=2.0).scalars()
    for name in ("peak_relative_displacement", "residual_displacement", "peak_base_shear"):
        assert row[f"{name}_at_mu_max"] == pytest.approx(at_best[name], rel=1e-9), name
    assert row["pga"] == pytest.approx(np.max(np.hypot(read(first).acceleration, read(second).acceleration)))


@pytest.mark.parametrize(("command", "arguments", "name", "phrase"), [
    ("sweep", ("--mu", "0.05:0.1:0.05", "--scale", "1", "2"), "scaling dimension", "pairs of components"),
    ("sweep", ("--mu", "0.05:0.1:0.05", "--angles", "30"), "angles", "the flat planar block's sweep"),
    ("solve", ("--mu", "0.05", "--radius", "0"), "--radius 0", "must be positive"),
    ("report", ("--mu", "0.02:0.2:0.02", "--mu-case", "0"), "--mu-case", "expected a positive number"),
])
def test_a_mistake_with_the_pendulum_in_the_plane_is_one_line(run_cli, record_files, tmp_path, command, arguments,
                                                              name, phrase):
    out = {"sweep": ("--out", tmp_path / "cube.nc"), "report": ("--out", tmp_path / "page.html")}.get(command, ())
    extra = () if "--radius" in arguments else ("--radius", "2")
    assert_one_error_line(*run_cli(command, record_files["first"], record_files["second"], "--pair", "--units",
                                   "m/s2", *extra, *arguments, *out), name, phrase)


def test_el_centro_array_6_with_its_vertical_on_a_1_m_surface_at_mu_0_0005_is_solved(three_component_sets):
    """The first 4.5 s of El Centro Array #6 (Imperial Valley 1979; 1.9 g upwards at most: the slider lifts off),
    R = 1 m, μ = 0.0005: a slow slip entered at 4.47 s with a step grown at lower speeds overflowed, its error
    estimate NaN, and the solve never returned."""
    station = three_component_sets["ImperialValley06_ElCentroArray6"]
    cut = {name: record.derive(record.acceleration[:900], step="first 900 samples")
           for name, record in station.items()}
    motion = WithVertical.of(RecordPair(cut["H1"], cut["H2"], any_pair=True), cut["UP"], "up")
    result = stickslip.solve(motion, model="pendulum", mu=0.0005, radius=1.0)
    found = result.scalars()
    assert found["liftoff_time"] > 0.05 and found["slip_fraction"] > 0.9
    ledger = (found["kinetic_energy_final"] + found["potential_energy_final"] + found["energy_dissipated"]
              - found["energy_input"] - found["energy_input_vertical"])
    assert abs(ledger) < 1e-10 * found["energy_input"]
    tighter = stickslip.solve(motion, model="pendulum", mu=0.0005, radius=1.0, rtol=1e-12).scalars()
    nearby = stickslip.solve(motion, model="pendulum", mu=0.0005, radius=1.0000001).scalars()
    for name in COMPARED:
        assert relative(tighter[name], found[name]) < 1e-9, name
        assert relative(nearby[name], found[name]) < 1e-6, name


def test_a_solve_the_solver_gives_up_on_is_one_line_naming_the_case_and_the_time(motion):
    """A tolerance no step in double precision meets refuses every step, shorter and shorter: the solver gives up
    after :data:`~stickslip.solvers.plane.MAX_PASSES` passes in one sample interval, and says so."""
    from stickslip.solvers.plane import MAX_PASSES

    pair = pair_of(motion)
    with pytest.raises(stickslip.StickslipError) as caught:
        stickslip.solve(pair, model="pendulum", mu=0.05, radius=2.0, rtol=1e-40)
    message = str(caught.value)
    assert "\n" not in message
    assert message.startswith("000 + 090, friction pendulum R = 2 m (T = 2.84 s), mu = 0.05: the solver gave "
                              "up at t = ")
    assert message.endswith(f" s of the record, after {MAX_PASSES} passes of its event loop in one sample interval "
                            "without reaching the interval's end")
    case = PendulumCase(FrictionLaw.coulomb(0.1), 2.0, 1.0, G)
    with pytest.raises(stickslip.StickslipError, match=r"^000 \+ 090 with its vertical, friction pendulum "
                       r"R = 2 m \(T = 2.84 s\), mu = 0.05: the solver gave up at t = "):
        sweep_pair_motions([WithVertical.of(pair, motion["vertical"], "up")], case, [0.05, 0.1], rtol=1e-40)


def test_a_sweep_solves_with_the_scheme_options_it_records():
    """``options={"rtol": ...}`` reaches the batched kernel, as it reaches a solve, and the cube says so."""
    time = np.arange(1500) * 0.01
    first = stickslip.Record(3.0 * np.sin(2 * np.pi * 0.8 * time) * np.exp(-0.2 * time), 0.01,
                             stickslip.RecordMeta(record_id="s", station="S", component="N"))
    second = stickslip.Record(2.0 * np.cos(2 * np.pi * 0.5 * time) * np.exp(-0.1 * time), 0.01,
                              stickslip.RecordMeta(record_id="s", station="S", component="E"))
    pair, mu = stickslip.RecordPair(first, second), [0.05, 0.1]
    loose = stickslip.sweep([pair], model="pendulum", mu=mu, radius=2.0, options={"rtol": 1e-5})
    tight = stickslip.sweep([pair], model="pendulum", mu=mu, radius=2.0)
    solved = [stickslip.solve(pair, model="pendulum", mu=value, radius=2.0, rtol=1e-5).scalars()["energy_dissipated"]
              for value in mu]
    assert loose.attrs["solver_rtol"] == 1e-5
    np.testing.assert_allclose(loose.energy_dissipated.values.ravel(), solved, rtol=1e-12)
    assert not np.allclose(loose.energy_dissipated.values, tight.energy_dissipated.values, rtol=1e-10, atol=0.0)
    with pytest.raises(StickslipError, match=r"the pendulum model does not take rtol; .*go in options=\)$"):
        stickslip.sweep([pair], model="pendulum", mu=mu, radius=2.0, rtol=1e-5)
