"""Sliding in the plane: the planar solver against its oracles, and the record pair's checks.

Oracles: one component zero is the 1-D exact solver; turning both components
turns the path and leaves the energies alone; a circular harmonic base
acceleration has a closed-form steady state; the energy ledger closes; the
answer does not move with the integration's tolerances.  The pairs are the
shared Coyote Lake G06 pair (230/320) and, for a stranger without the shared
records, two of pyslammer's sample motions taken as the two axes of one motion.
"""

from __future__ import annotations

import math
from importlib.resources import files

import numpy as np
import pytest

import stickslip
from stickslip.errors import StickslipError
from conftest import shared_dir

from stickslip.records.components import component_azimuth, same_event
from stickslip.records.pair import RecordPair
from stickslip.records.readers import read_record
from stickslip.records.record import Record, RecordMeta
from stickslip.models.planar.solver import solve_pair
from stickslip.solvers import plane
from stickslip.models.rigid.exact import record_scalars
from stickslip.models.rigid.history import SCALAR_NAMES

G = 9.81
SAMPLES = files("pyslammer") / "sample_ground_motions"


def sample_axes(first: str, second: str) -> RecordPair:
    """Two pyslammer sample motions as the two axes of one motion (cut to the shorter; no station names)."""
    one, other = read_record(SAMPLES / first), read_record(SAMPLES / second)
    assert one.dt == other.dt
    length = min(one.npts, other.npts)
    return RecordPair(Record(one.acceleration[:length], one.dt), Record(other.acceleration[:length], other.dt))


@pytest.fixture(scope="module")
def stranger_pair() -> RecordPair:
    """pyslammer's Northridge VSP-360 and Loma Prieta HSP-000 (both 0.005 s) on two axes: no shared data needed."""
    return sample_axes("Northridge_1994_VSP-360.csv", "Loma_Prieta_1989_HSP-000.csv")


@pytest.fixture(scope="module")
def coyote_lake_pair(paper_records_dir) -> RecordPair:
    """The shared Coyote Lake 1979 G06 pair, components 230 and 320 (orthogonal)."""
    return RecordPair.padded(read_record(paper_records_dir / "SLAMMER_Coyote_Lake_1979_G06-230.txt"),
                             read_record(paper_records_dir / "SLAMMER_Coyote_Lake_1979_G06-320.txt"))


def planar_scalars(first: np.ndarray, second: np.ndarray, dt: float, mu: float, rtol: float = plane.RTOL,
                   lock_ratio: float = plane.LOCK_RATIO) -> dict:
    """The kernel's end scalars of one pair of axes, by name."""
    out = np.zeros(len(plane.PLANAR_SCALAR_NAMES))
    solve_pair(np.ascontiguousarray(first), np.ascontiguousarray(second), dt, mu * G, rtol, lock_ratio,
               np.zeros((0, 8)), out)
    return dict(zip(plane.PLANAR_SCALAR_NAMES, out))


def relative(value: float, reference: float) -> float:
    return abs(value - reference) / abs(reference)


@pytest.mark.parametrize("mu", [0.02, 0.05, 0.1, 0.2, 0.3])
def test_one_component_zero_is_the_one_dimensional_exact_solver(stranger_pair, mu):
    acceleration = stranger_pair.first.acceleration
    one_d = dict(zip(SCALAR_NAMES, record_scalars(acceleration, stranger_pair.dt, mu, G)))
    plane = planar_scalars(acceleration, np.zeros_like(acceleration), stranger_pair.dt, mu)
    assert one_d["sliding_path"] > 0.0
    assert relative(plane["energy_dissipated"], one_d["energy_dissipated"]) < 1e-9
    assert relative(plane["energy_input"], one_d["energy_input"]) < 1e-9
    assert relative(plane["peak_displacement"], one_d["peak_relative_displacement"]) < 1e-9
    assert abs(plane["residual_displacement_1"] - one_d["residual_displacement"]) < 1e-9 * one_d["peak_relative_displacement"]
    assert plane["residual_displacement_2"] == 0.0
    assert relative(plane["slip_fraction"], one_d["slip_fraction"]) < 1e-9
    assert plane["n_slip_episodes"] == one_d["n_slip_episodes"]
    balance = one_d["kinetic_energy_final"] + one_d["energy_dissipated"] - one_d["energy_input"]
    assert abs(plane["kinetic_energy_final"] + plane["energy_dissipated"] - plane["energy_input"] - balance) \
        < 1e-9 * one_d["energy_input"]


@pytest.mark.parametrize("angle", [0.0, 17.0, 90.0, 133.0, 251.5])
def test_turning_both_components_turns_the_path_and_keeps_the_energies(stranger_pair, angle):
    first, second = stranger_pair.horizontal()
    mu = 0.08
    reference = planar_scalars(first, second, stranger_pair.dt, mu)
    turned_1, turned_2 = stranger_pair.rotated(angle)
    turned = planar_scalars(turned_1, turned_2, stranger_pair.dt, mu)
    for name in ("energy_dissipated", "energy_input", "kinetic_energy_final", "sliding_path", "peak_displacement",
                 "slip_fraction"):
        assert relative(turned[name], reference[name]) < 1e-9, name
    assert turned["n_slip_episodes"] == reference["n_slip_episodes"]
    turn = math.radians(angle)
    expected_1 = reference["residual_displacement_1"] * math.cos(turn) + reference["residual_displacement_2"] * math.sin(turn)
    expected_2 = -reference["residual_displacement_1"] * math.sin(turn) + reference["residual_displacement_2"] * math.cos(turn)
    assert abs(turned["residual_displacement_1"] - expected_1) < 1e-9 * reference["peak_displacement"]
    assert abs(turned["residual_displacement_2"] - expected_2) < 1e-9 * reference["peak_displacement"]


def circular_cycle_energy(amplitude: float, omega: float, mu: float, dt: float, cycles: int = 30):
    """E_df/m of the last cycle [J/kg] and the last cycle's change from the one before, sampled every dt."""
    period = 2 * math.pi / omega
    steps = round(period / dt)
    time = np.arange(cycles * steps + 1) * (period / steps)
    history = np.zeros((time.size, 8))
    solve_pair(amplitude * np.cos(omega * time), amplitude * np.sin(omega * time), period / steps, mu * G, plane.RTOL,
               plane.LOCK_RATIO, history, np.zeros(9))
    last = history[-1, 5] - history[-1 - steps, 5]
    before = history[-1 - steps, 5] - history[-1 - 2 * steps, 5]
    speed = math.hypot(history[-1, 2], history[-1, 3])
    return last, (last - before) / last, speed


@pytest.mark.parametrize("mu", [0.1, 3.0 / (math.sqrt(2) * G), 0.28])
def test_circular_harmonic_base_acceleration_reaches_the_closed_form_steady_state(mu):
    amplitude, omega = 3.0, 2 * math.pi
    steady_speed = math.sqrt(amplitude**2 - (mu * G) ** 2) / omega
    per_cycle = 2 * math.pi * mu * G * steady_speed / omega
    energies = {}
    for steps in (250, 500, 1000):  # the record is linear between samples: a polygon, off the circle by O(dt²)
        energy, change, speed = circular_cycle_energy(amplitude, omega, mu, 1.0 / steps)
        assert abs(change) < 1e-12  # steady
        assert abs(energy / per_cycle - 1) < (omega / steps) ** 2
        assert abs(speed / steady_speed - 1) < (omega / steps) ** 2
        energies[steps] = energy
    first = (4 * energies[500] - energies[250]) / 3  # Richardson: the polygon's error is a series in dt²
    second = (4 * energies[1000] - energies[500]) / 3
    assert abs((16 * second - first) / 15 / per_cycle - 1) < 1e-8


def test_the_circular_optimum_is_at_mu_star_where_it_dissipates_pi_a_squared_over_omega_squared():
    amplitude, omega = 3.0, 2 * math.pi
    mu_star = amplitude / (math.sqrt(2) * G)
    at_star = circular_cycle_energy(amplitude, omega, mu_star, 1e-3)[0]
    assert abs(at_star / (math.pi * amplitude**2 / omega**2) - 1) < 1e-5
    for mu in (0.97 * mu_star, 1.03 * mu_star):
        assert circular_cycle_energy(amplitude, omega, mu, 1e-3)[0] < at_star


@pytest.mark.parametrize("mu", [0.01, 0.05, 0.15, 0.4])
def test_the_energy_ledger_closes_on_a_pair(stranger_pair, mu):
    response = stickslip.solve(stranger_pair, mu=mu)
    scalars = response.scalars()
    assert scalars["sliding_path"] > 0.0
    assert scalars["balance_residual"] < 1e-9 * scalars["energy_input"]
    assert np.all(np.diff(response.sliding_path) >= 0.0)  # a slip never runs backwards through a stop


@pytest.mark.parametrize("mu", [0.03, 0.12])
def test_the_answer_does_not_move_with_the_tolerances(stranger_pair, mu):
    first, second = stranger_pair.horizontal()
    reference = planar_scalars(first, second, stranger_pair.dt, mu, rtol=1e-13, lock_ratio=1e-9)
    for rtol, lock_ratio, limit in ((plane.RTOL, plane.LOCK_RATIO, 1e-10), (1e-10, 1e-4, 1e-8)):
        other = planar_scalars(first, second, stranger_pair.dt, mu, rtol=rtol, lock_ratio=lock_ratio)
        for name in ("energy_dissipated", "sliding_path", "peak_displacement"):
            assert relative(other[name], reference[name]) < limit, (name, rtol, lock_ratio)


def test_the_shared_coyote_lake_pair_slides_in_the_plane_with_a_closed_ledger(coyote_lake_pair):
    assert coyote_lake_pair.azimuths == (230.0, 320.0) and coyote_lake_pair.orthogonal
    for mu in (0.02, 0.1, 0.3):
        scalars = stickslip.solve(coyote_lake_pair, mu=mu).scalars()
        assert scalars["balance_residual"] < 1e-9 * scalars["energy_input"]
        one_d = [dict(zip(SCALAR_NAMES, record_scalars(component.acceleration, coyote_lake_pair.dt, mu, G)))
                 for component in (coyote_lake_pair.first, coyote_lake_pair.second)]
        # the friction circle resists both components with one force: the plane's path is at least either's
        assert scalars["sliding_path"] >= max(case["sliding_path"] for case in one_d) * (1 - 1e-9)


def test_the_response_has_a_component_dimension_with_units(stranger_pair):
    dataset = stickslip.solve(stranger_pair, mu=0.1).to_xarray()
    assert dataset["relative_displacement"].dims == ("time", "component")
    assert dataset["relative_displacement"].attrs["units"] == "m"
    assert dataset["energy_dissipated"].attrs["units"] == "J"
    assert dataset.attrs["model"] == "planar" and dataset.attrs["mu"] == 0.1
    scalars = stickslip.solve(stranger_pair, mu=0.1).scalars()
    for history in ("energy_dissipated", "energy_input", "sliding_path"):  # histories, not overwritten by end values
        assert dataset[history].dims == ("time",)
        assert float(dataset[history][-1]) == pytest.approx(scalars[history], rel=1e-12, abs=1e-15)
    assert float(dataset["peak_displacement"]) >= float(np.max(np.hypot(*dataset["relative_displacement"].values.T)))


def named(acceleration: np.ndarray, dt: float, component: str, event: str = "Landers 1992") -> Record:
    return Record(acceleration, dt, RecordMeta(record_id=component.lower(), event=event, component=component))


def test_the_azimuth_comes_from_the_component_name():
    assert [component_azimuth(name) for name in ("TAK-000", "TAK-090", "LCN-345", "ARL-360", "CHY080-N",
                                                  "CHY080-E", "PAR-L", "UP")] == [0.0, 90.0, 345.0, 0.0, 0.0, 90.0,
                                                                                  None, None]


def test_components_that_are_not_orthogonal_are_resolved_onto_orthogonal_axes():
    rng = np.random.default_rng(3)
    north, east = rng.normal(size=(2, 400))
    azimuths = (260.0, 345.0)  # the SLAMMER library's Landers LCN pair, 85 degrees apart
    along = [north * math.cos(math.radians(a)) + east * math.sin(math.radians(a)) for a in azimuths]
    pair = RecordPair(named(along[0], 0.01, "LCN-260"), named(along[1], 0.01, "LCN-345"))
    assert pair.azimuths == azimuths and not pair.orthogonal and pair.separation == 85.0
    first, second = pair.horizontal()
    normal = 260.0 + 90.0  # the second axis, a quarter turn from the first towards the second component
    expected = north * math.cos(math.radians(normal)) + east * math.sin(math.radians(normal))
    np.testing.assert_allclose(first, along[0])
    np.testing.assert_allclose(second, expected, atol=1e-12)


@pytest.mark.parametrize(("first", "second", "phrase"), [
    (named(np.zeros(10), 0.01, "TAK-000"), named(np.zeros(10), 0.02, "TAK-090"), "different time steps"),
    (named(np.zeros(10), 0.01, "TAK-000"), named(np.zeros(12), 0.01, "TAK-090"), "different lengths (10 and 12"),
    (named(np.zeros(10), 0.01, "TAK-000"), named(np.zeros(10), 0.01, "KJM-090"), "different stations (TAK and KJM)"),
    (named(np.zeros(10), 0.01, "TAK-000", "Kobe 1995"), named(np.zeros(10), 0.01, "TAK-090", "Landers 1992"),
     "different events"),
    (named(np.zeros(10), 0.01, "TAK-000"), named(np.zeros(10), 0.01, "TAK-010"), "10 degrees apart"),
])
def test_a_pair_that_is_not_one_refuses_with_a_message_naming_the_problem(first, second, phrase):
    with pytest.raises(StickslipError, match="the two components|the components") as caught:
        RecordPair(first, second)
    assert phrase in str(caught.value)


def test_padding_the_shorter_component_keeps_its_samples_and_says_so():
    pair = RecordPair.padded(named(np.ones(10), 0.01, "TAK-000"), named(np.ones(7), 0.01, "TAK-090"))
    assert pair.npts == 10
    np.testing.assert_array_equal(pair.second.acceleration, [1.0] * 7 + [0.0] * 3)
    assert pair.second.meta.processing == ("padded with 3 zeros at the end",)


def test_solve_refuses_what_the_plane_does_not_take(stranger_pair):
    with pytest.raises(StickslipError, match=r"the planar model \(a rigid block sliding in the plane on a flat surface.*\) "
                                             "does not take ky; it takes: g, mass, mu"):
        stickslip.solve(stranger_pair, model="planar", ky=0.1)
    with pytest.raises(StickslipError, match=r"no one model takes ky= on the two horizontal components of one station"):
        stickslip.solve(stranger_pair, ky=0.1)
    with pytest.raises(StickslipError, match="method exact, not 'newmark'"):
        stickslip.solve(stranger_pair, mu=0.1, method="newmark")


def test_components_whose_manifests_spell_the_event_and_station_differently_still_pair(paper_records_dir):
    """The paper records' manifest says 'Cape Mendocino' and component '090'; the SLAMMER library's, for the other
    component, 'Cape Mendocino 1992' and 'PET-000': one station and one event all the same."""
    library = shared_dir() / "records" / "slammer" / "records" / "Cape Mendocino 1992" / "PET-000"
    if not library.is_file():
        pytest.skip(f"the SLAMMER library's PET-000 is not at {library}")
    paper = read_record(paper_records_dir / "SLAMMER_Cape_Mendocino_1992_PET-090.txt")
    pair = RecordPair.padded(read_record(library), paper)
    assert pair.azimuths == (0.0, 90.0) and pair.orthogonal
    assert same_event("Chi-Chi, Taiwan 1999", "CHI-CHI") and not same_event("Kobe 1995", "Landers 1992")


def test_a_slow_slip_that_stops_and_starts_again_inside_one_step_is_not_carried_through_zero():
    """Cape Mendocino CPM 000/090 at μ = 0.2075: between two samples the block slows to a stop while |a| < μ·g and
    starts again when |a| rises past μ·g.  Integrating the settled speed through zero, as the kernel once did, ran
    the path backwards and left 5.7e-8 of E_I in the ledger."""
    folder = shared_dir() / "records" / "slammer" / "records" / "Cape Mendocino 1992"
    if not (folder / "CPM-000").is_file():
        pytest.skip(f"the SLAMMER library's CPM-000 is not in {folder}")
    pair = RecordPair.padded(read_record(folder / "CPM-000"), read_record(folder / "CPM-090"))
    response = stickslip.solve(pair, mu=0.2075)
    assert np.all(np.diff(response.sliding_path) >= 0.0)
    scalars = response.scalars()
    assert scalars["balance_residual"] < 1e-9 * scalars["energy_input"]
