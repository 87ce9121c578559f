"""Sliding in the plane on a spherical dish, with the vertical ground motion and velocity-dependent friction.

The planar kernel's oracles for what it adds to the flat block: a very large
radius is the flat surface; a constant vertical acceleration c·g is gravity
g·(1 + c); free vibration after a pulse, along a line at any azimuth, is the
closed-form friction pendulum (4μR of amplitude lost per cycle, period
2π√(R/g), at rest once |u| ≤ μR); a circular harmonic base acceleration has
a closed-form steady orbit; turning both components turns the path; the
ledger E_k + E_r + E_df = E_I closes; velocity-dependent friction slides at
its closed-form steady speed and breaks away at μ(0); the block flies where
g + a_v ≤ 0.  The pair is two of pyslammer's sample motions taken as the two
axes of one motion (and, where a vertical motion is needed, a third one as
the vertical): a stranger without the shared records runs every test.
"""

from __future__ import annotations

import math
from importlib.resources import files

import numpy as np
import pytest

from stickslip.errors import StickslipError
from stickslip.records.readers import read_record
from stickslip.models.pendulum.normal_force import liftoff_intervals
from stickslip.solvers import plane
from stickslip.solvers.plane import interval, manifold, resistance, stepping
from stickslip.solvers.plane.state import N_STATE, SLIDING, SLOW, TAU, V1, V2

G = 9.81
SAMPLES = files("pyslammer") / "sample_ground_motions"
SCALARS = plane.SURFACE_SCALAR_NAMES


@pytest.fixture(scope="module")
def motion() -> dict:
    """Northridge VSP-360 and Loma Prieta HSP-000 (0.005 s) as the two horizontal axes, and Coalinga PVB-045 (0.38 g
    at most) as a vertical acceleration (positive up), cut to the shortest."""
    first = read_record(SAMPLES / "Northridge_1994_VSP-360.csv")
    second = read_record(SAMPLES / "Loma_Prieta_1989_HSP-000.csv")
    third = read_record(SAMPLES / "Coalinga_1983_PVB-045.csv")
    assert first.dt == second.dt == third.dt
    length = min(first.npts, second.npts, third.npts)
    return {"first": np.ascontiguousarray(first.acceleration[:length]),
            "second": np.ascontiguousarray(second.acceleration[:length]),
            "vertical": np.ascontiguousarray(third.acceleration[:length]), "dt": first.dt}


def surface(first, second, dt, mu_slow, mu_fast=None, rate=0.0, radius=math.inf, vertical=None, gravity=G,
            history=False):
    """The kernel's end scalars by name, and its history when asked (rows of :data:`HISTORY_NAMES`)."""
    out = np.zeros(len(SCALARS))
    rows = np.zeros((first.size if history else 0, len(plane.HISTORY_NAMES)))
    plane.solve_pair_on_surface(np.ascontiguousarray(first), np.ascontiguousarray(second),
                                np.zeros(0) if vertical is None else np.ascontiguousarray(vertical), dt,
                                gravity, mu_slow, mu_slow if mu_fast is None else mu_fast, rate,
                                0.0 if math.isinf(radius) else 1.0 / radius, plane.RTOL,
                                plane.LOCK_RATIO, rows, out)
    scalars = dict(zip(SCALARS, out))
    return (scalars, rows) if history else scalars


def relative(value: float, reference: float) -> float:
    return abs(value - reference) / abs(reference)


def ground_velocity(first, second, dt) -> np.ndarray:
    """u̇_g [m/s] at the samples, shape (n, 2): trapezoid sums, exact for a linear between samples."""
    steps = 0.5 * dt * np.column_stack([first[1:] + first[:-1], second[1:] + second[:-1]])
    return np.vstack([np.zeros(2), np.cumsum(steps, axis=0)])


def test_a_very_large_radius_is_the_flat_surface(motion):
    flat = surface(motion["first"], motion["second"], motion["dt"], 0.08)
    assert flat["sliding_path"] > 0.05
    gaps = []
    for radius in (1e6, 1e9, 1e12):
        curved = surface(motion["first"], motion["second"], motion["dt"], 0.08, radius=radius)
        gaps.append(max(relative(curved[name], flat[name]) for name in
                        ("energy_dissipated", "energy_input", "peak_displacement", "sliding_path")))
    assert gaps[2] < 1e-9
    assert gaps[0] > 100 * gaps[1] > 1e4 * gaps[2]  # the restoring force's effect falls as 1/R


@pytest.mark.parametrize(("mu_slow", "mu_fast", "rate", "radius"),
                         [(0.08, 0.08, 0.0, math.inf), (0.05, 0.05, 0.0, 2.0), (0.04, 0.09, 30.0, 1.5)])
@pytest.mark.parametrize("level", [0.3, -0.4])
def test_a_constant_vertical_acceleration_is_gravity_scaled(motion, mu_slow, mu_fast, rate, radius, level):
    """n = g + c·g: the block sees gravity g·(1 + c), in its friction limit and its restoring force alike; the
    vertical motion's work is W_v = −c·g·|u|²/(2R) (none under the scaled gravity alone)."""
    vertical = np.full(motion["first"].size, level * G)
    moving = surface(motion["first"], motion["second"], motion["dt"], mu_slow, mu_fast, rate, radius, vertical)
    scaled = surface(motion["first"], motion["second"], motion["dt"], mu_slow, mu_fast, rate, radius,
                     gravity=G * (1 + level))
    assert scaled["sliding_path"] > 0.0
    for name in SCALARS:
        if name in ("residual_displacement_1", "residual_displacement_2"):
            assert abs(moving[name] - scaled[name]) < 1e-9 * scaled["peak_displacement"], name
        elif name == "energy_input_vertical":
            assert scaled[name] == 0.0
            lifted = 0.0 if math.isinf(radius) else -0.5 * level * G / radius * (
                moving["residual_displacement_1"] ** 2 + moving["residual_displacement_2"] ** 2)
            assert moving[name] == pytest.approx(lifted, rel=1e-9, abs=1e-15 * scaled["energy_input"])
        elif name == "flight_time":
            assert moving[name] == scaled[name] == 0.0
        else:
            assert relative(moving[name], scaled[name]) < 1e-9, name


def free_vibration(start: float, velocity: float, begin: float, times: np.ndarray, mu: float, radius: float):
    """The friction pendulum on a line after a pulse, in closed form: positions [m] at ``times`` [s] and the turning
    points (time [s], position [m]) from position ``start`` [m] and velocity ``velocity`` [m/s] at ``begin`` [s].

    Between stops ü = −(g/R)·(u − c) with c = −μR·sign(u̇): half a cycle of a harmonic oscillator about c; it stays
    at a stop once |u| ≤ μR.
    """
    omega = math.sqrt(G / radius)
    position = np.empty_like(times)
    turns = []
    u, v, t, k = start, velocity, begin, 0
    while True:
        centre = -mu * radius * (math.copysign(1.0, v) if v != 0.0 else -math.copysign(1.0, u))
        amplitude = math.hypot(u - centre, v / omega)
        phase = math.atan2(v / omega, u - centre)  # u − c = amplitude·cos(ω(t' − t) − phase)
        stop = t + (math.pi * math.ceil(-phase / math.pi + 1e-15) + phase) / omega
        if stop <= t:
            stop += math.pi / omega
        while k < times.size and times[k] <= stop:
            position[k] = centre + amplitude * math.cos(omega * (times[k] - t) - phase)
            k += 1
        u, v, t = centre + amplitude * math.cos(omega * (stop - t) - phase), 0.0, stop
        turns.append((t, u))
        if abs(u) <= mu * radius:
            position[k:] = u
            return position, turns


@pytest.mark.parametrize("azimuth", [0.0, 33.0])
def test_free_vibration_after_a_pulse_is_the_closed_form_friction_pendulum(azimuth):
    """A half-sine pulse along one azimuth, then rest: the block swings on that line, loses 4μR of amplitude per
    cycle at the period 2π√(R/g), and stops once |u| ≤ μR, as the closed form (1-D for azimuth 0: the second
    component is zero)."""
    radius, mu, dt = 2.0, 0.01, 0.005
    time = np.arange(int(30.0 / dt) + 1) * dt
    pulse = np.where(time < 0.5, 4.0 * np.sin(math.pi * time / 0.5), 0.0)
    turn = math.radians(azimuth)
    scalars, rows = surface(pulse * math.cos(turn), pulse * math.sin(turn), dt, mu, radius=radius, history=True)
    along = rows[:, 0] * math.cos(turn) + rows[:, 1] * math.sin(turn)
    across = -rows[:, 0] * math.sin(turn) + rows[:, 1] * math.cos(turn)
    velocity = rows[:, 2] * math.cos(turn) + rows[:, 3] * math.sin(turn)
    assert np.max(np.abs(across)) < 1e-12 * np.max(np.abs(along))
    end = int(round(0.5 / dt))
    closed, turns = free_vibration(along[end], velocity[end], time[end], time[end:], mu, radius)
    assert np.max(np.abs(along[end:] - closed)) < 1e-9 * np.max(np.abs(closed))
    period = 2 * math.pi * math.sqrt(radius / G)
    swings = [abs(position) for _, position in turns]
    assert len(turns) >= 6
    for (t0, u0), (t2, u2) in zip(turns[:-2], turns[2:]):
        if abs(u2) > mu * radius:  # a whole cycle: the same side, 4μR nearer the centre, one period later
            assert abs((abs(u0) - abs(u2)) - 4 * mu * radius) < 1e-9 * abs(u0)
            assert abs((t2 - t0) - period) < 1e-9 * period
    assert swings[-1] <= mu * radius < swings[-2]
    assert abs(scalars["residual_displacement_1"] * math.cos(turn) + scalars["residual_displacement_2"]
               * math.sin(turn) - turns[-1][1]) < 1e-9 * swings[0]
    assert relative(scalars["peak_displacement"], max(swings[0], np.max(np.abs(along[:end + 1])))) < 1e-9


def circular_orbit(amplitude: float, omega: float, mu: float, radius: float, steps: int, cycles: int = 80):
    """E_df/m over the last cycle [J/kg] and the last cycle's change from the one before, and the final distance from
    the centre [m], under a = A·(cos ωt, sin ωt) sampled ``steps`` times per cycle."""
    period = 2 * math.pi / omega
    time = np.arange(cycles * steps + 1) * (period / steps)
    _, rows = surface(amplitude * np.cos(omega * time), amplitude * np.sin(omega * time), period / steps, mu,
                      radius=radius, history=True)
    last = rows[-1, 5] - rows[-1 - steps, 5]
    before = rows[-1 - steps, 5] - rows[-1 - 2 * steps, 5]
    return last, (last - before) / last, math.hypot(rows[-1, 0], rows[-1, 1])


def test_a_circular_harmonic_base_acceleration_drives_the_closed_form_orbit():
    """Steady state: u on a circle of radius ρ turning with the ground at ω, the friction μ·g along the path and the
    restoring force (g/R)·ρ inwards: A·sin δ = μ·g and A·cos δ = (ω² − g/R)·ρ, so ρ = √(A² − μ²g²)/(ω² − g/R) and the
    friction dissipates 2π·μ·g·ρ per cycle.  The record is a polygon, off the circle by O(dt²): Richardson's
    extrapolation in dt² meets the closed form."""
    amplitude, omega, mu, radius = 3.0, 2 * math.pi, 0.1, 2.0
    orbit = math.sqrt(amplitude**2 - (mu * G) ** 2) / (omega**2 - G / radius)
    per_cycle = 2 * math.pi * mu * G * orbit
    energies = {}
    for steps in (250, 500, 1000):
        energy, change, distance = circular_orbit(amplitude, omega, mu, radius, steps)
        assert abs(change) < 1e-12  # steady (the free swing at √(g/R) has died out)
        assert abs(energy / per_cycle - 1) < 3 * (omega / steps) ** 2
        assert abs(distance / orbit - 1) < 3 * (omega / steps) ** 2
        energies[steps] = energy
    first = (4 * energies[500] - energies[250]) / 3
    second = (4 * energies[1000] - energies[500]) / 3
    assert abs((16 * second - first) / 15 / per_cycle - 1) < 1e-8


@pytest.mark.parametrize("angle", [17.0, 133.0, 251.5])
def test_turning_both_components_turns_the_pendulum_and_keeps_its_energies(motion, angle):
    turn = math.radians(angle)
    first, second = motion["first"], motion["second"]
    turned_1 = first * math.cos(turn) + second * math.sin(turn)
    turned_2 = -first * math.sin(turn) + second * math.cos(turn)
    case = {"mu_slow": 0.04, "mu_fast": 0.09, "rate": 30.0, "radius": 1.5, "vertical": motion["vertical"]}
    reference = surface(first, second, motion["dt"], **case)
    rotated = surface(turned_1, turned_2, motion["dt"], **case)
    assert reference["sliding_path"] > 0.05 and reference["energy_input_vertical"] != 0.0
    for name in ("energy_dissipated", "energy_input", "kinetic_energy_final", "sliding_path", "peak_displacement",
                 "slip_fraction", "energy_input_vertical"):
        assert relative(rotated[name], reference[name]) < 1e-9, name
    assert rotated["n_slip_episodes"] == reference["n_slip_episodes"]
    expected = (reference["residual_displacement_1"] * math.cos(turn) + reference["residual_displacement_2"]
                * math.sin(turn), -reference["residual_displacement_1"] * math.sin(turn)
                + reference["residual_displacement_2"] * math.cos(turn))
    assert abs(rotated["residual_displacement_1"] - expected[0]) < 1e-9 * reference["peak_displacement"]
    assert abs(rotated["residual_displacement_2"] - expected[1]) < 1e-9 * reference["peak_displacement"]


@pytest.mark.parametrize(("mu_slow", "mu_fast", "rate", "radius", "vertical"),
                         [(0.05, 0.05, 0.0, 2.0, False), (0.03, 0.08, 25.0, math.inf, True),
                          (0.04, 0.09, 30.0, 1.5, True), (0.06, 0.06, 0.0, 3.0, True)])
def test_the_ledger_closes_with_a_restoring_force_a_vertical_motion_and_velocity_dependent_friction(
        motion, mu_slow, mu_fast, rate, radius, vertical):
    """E_k − E_k(0) + E_p + E_df − E_I − W_v at every sample, against the largest E_I, with the potential energy
    E_p = g·|u|²/(2R) and the vertical motion's work W_v (zero without a vertical); the path never runs back."""
    first, second, dt = motion["first"], motion["second"], motion["dt"]
    scalars, rows = surface(first, second, dt, mu_slow, mu_fast, rate, radius,
                            motion["vertical"] if vertical else None, history=True)
    absolute = ground_velocity(first, second, dt) + rows[:, 2:4]
    potential = 0.0 if math.isinf(radius) else 0.5 * G / radius * np.einsum("ij,ij->i", rows[:, 0:2], rows[:, 0:2])
    balance = 0.5 * np.einsum("ij,ij->i", absolute, absolute) + potential + rows[:, 5] - rows[:, 6] - rows[:, 8]
    assert scalars["sliding_path"] > 0.05
    assert np.max(np.abs(balance)) < 1e-9 * np.max(np.abs(rows[:, 6]))
    assert np.all(np.diff(rows[:, 7]) >= 0.0)
    if vertical and not math.isinf(radius):  # the vertical ground motion works through the normal force
        assert abs(scalars["energy_input_vertical"]) > 1e-6 * np.max(potential)
    else:
        assert np.all(rows[:, 8] == 0.0) and scalars["energy_input_vertical"] == 0.0


def test_velocity_dependent_friction_slides_at_its_steady_speed_and_breaks_away_at_mu_slow():
    """A ground acceleration ramping up along one axis to A, μ_slow·g < A < μ_fast·g: the block breaks away when the
    ramp passes μ_slow·g (not μ_fast·g), then slides towards the speed where μ(v)·g = A,
    v* = −ln((μ_fast − A/g)/(μ_fast − μ_slow))/rate."""
    mu_slow, mu_fast, rate, dt = 0.05, 0.12, 20.0, 0.005
    level = 0.09 * G
    time = np.arange(int(20.0 / dt) + 1) * dt
    ramp = np.minimum(time / 1.0, 1.0) * level
    scalars, rows = surface(ramp, np.zeros_like(ramp), dt, mu_slow, mu_fast, rate, history=True)
    steady = -math.log((mu_fast - level / G) / (mu_fast - mu_slow)) / rate
    assert abs(rows[-1, 2] + steady) < 1e-9 * steady  # the block lags the ground: v < 0
    breakaway = mu_slow * G / level * 1.0
    assert abs(scalars["slip_fraction"] * time[-1] - (time[-1] - breakaway)) < 1e-9 * time[-1]
    assert scalars["n_slip_episodes"] == 1


def test_the_block_flies_where_the_normal_force_vanishes(motion):
    """Where g + a_v ≤ 0 no force acts on the block: its absolute velocity u̇_g + v is constant, E_I, E_df and the
    path stand still, and the vertical motion's work W_v takes the change of the potential energy g·|u|²/(2R) (the
    restoring force does no work); the flight time is the length of the lift-off intervals."""
    first, second, dt = motion["first"], motion["second"], motion["dt"]
    time = np.arange(first.size) * dt
    vertical = -1.6 * G * np.sin(2 * math.pi * 2.0 * time) * np.exp(-((time - 8.0) / 3.0) ** 2)
    intervals = liftoff_intervals(vertical, dt, G)
    assert len(intervals) >= 8
    scalars, rows = surface(first, second, dt, 0.1, radius=2.0, vertical=vertical, history=True)
    assert relative(scalars["flight_time"], float(np.sum(intervals[:, 1] - intervals[:, 0]))) < 1e-12
    absolute = ground_velocity(first, second, dt) + rows[:, 2:4]
    inside = np.zeros(first.size, dtype=bool)
    for start, end in intervals:
        inside |= (time > start) & (time < end)
    steps = np.flatnonzero(inside[1:] & inside[:-1])  # sample intervals wholly in flight
    assert steps.size > 50
    assert np.all(rows[steps + 1, 9] == 1.0) and np.all(rows[steps + 1, 4] == 1.0)
    assert np.max(np.abs(absolute[steps + 1] - absolute[steps])) < 1e-12 * np.max(np.abs(absolute))
    for column in (5, 6, 7):
        assert np.array_equal(rows[steps + 1, column], rows[steps, column])
    potential = 0.5 * G / 2.0 * np.einsum("ij,ij->i", rows[:, 0:2], rows[:, 0:2])
    restoring_work = potential - rows[:, 8]
    assert np.max(np.abs(restoring_work[steps + 1] - restoring_work[steps])) < 1e-14 * np.max(potential)


def test_the_sweep_is_the_single_solver_for_every_pair_and_case(motion):
    first, second, vertical, dt = motion["first"], motion["second"], motion["vertical"], motion["dt"]
    cut = first.size // 2
    pairs = [(first, second, vertical), (second[:cut], first[:cut], vertical[:cut])]
    cases = np.array([[0.05, 0.05, 0.0, 0.0], [0.04, 0.09, 30.0, 1 / 1.5], [0.1, 0.1, 0.0, 0.5]])
    offsets = np.array([0, first.size, first.size + cut], dtype=np.int64)
    out = np.zeros((2, len(cases), len(SCALARS)))
    plane.sweep_pairs_on_surface(np.concatenate([p[0] for p in pairs]), np.concatenate([p[1] for p in pairs]),
                                 np.concatenate([p[2] for p in pairs]), offsets, np.array([dt, dt]), G, cases,
                                 plane.RTOL, plane.LOCK_RATIO, out)
    for index, (one, other, up) in enumerate(pairs):
        for column, (mu_slow, mu_fast, rate, curvature) in enumerate(cases):
            single = surface(one, other, dt, mu_slow, mu_fast, rate, 1 / curvature if curvature else math.inf, up)
            np.testing.assert_array_equal(out[index, column], [single[name] for name in SCALARS])


#: One sample interval of El Centro Array #6 (Imperial Valley 1979: H1, H2 and the vertical, positive up) from
#: t = 4.470 s, as the kernel enters it on a surface of R = 1 m at μ = 0.0005 (exact binary values): the interval's
#: a, its slope, n and its slope, the ground velocity (:data:`~stickslip.solvers.plane.state.A1` ...); the slip's
#: state (v ≈ 0.56 mm/s, just above the slow regime's s_switch = 0.49 mm/s); s_switch, s_lock, rtol, the velocity
#: floor and the stop tolerance with dt; and each regime's step carried in from the intervals before.  The slow
#: regime's step, 24.6 in σ (dt = s·dσ), grew at far lower speeds: at this speed it spans 2 dt, where the
#: direction turns 27 radians (|b|·dσ), and its stages overflow.
EL_CENTRO_SEGMENT = ("0x1.40bd8af780afcp-1", "0x1.323f6f81981b1p+0", "-0x1.93fad97a852ccp+4", "0x1.a4929fc52cc59p+5",
                     "0x1.db9c91aef223fp+2", "-0x1.43e174596e313p+5", "0x1.144186d9f45f9p-4", "-0x1.e1da52e5c4d8fp-5",
                     (9.81).hex())
EL_CENTRO_STATE = ("0x1.1f6a8ca1e75efp-11", "0x1.dcbb476e72635p-14", "0x1.47ae147ae147bp-8", "-0x1.a7baf9d2c3901p-14",
                   "-0x1.2a94326d48e18p-5", "0x1.ab9b65403a11fp-4", "0x1.6f84870cd8c3ap-7", "0x1.1aabe17fcfdc2p-11",
                   "0x1.b34757bb11ec8p-8")
EL_CENTRO_SCALES = ("0x1.47ae147ae147bp-8", "0x1.fe5874afa8239p-12", "0x1.054c0266396a4p-21", "0x1.b7cdfd9d7bdbbp-34",
                    "0x1.9846c3bfb9b60p-15", "0x1.1890bf870cf3fp-52")
EL_CENTRO_STEPS = ("0x1.ebda3531fef0cp-13", "0x1.89273d0cc8fe2p+4", "0x1.b6c761cf0bcd7p-9")


def el_centro_interval(slow_step: float | None = None) -> np.ndarray:
    """The state [v (m/s), τ (s), u (m), path (m), E_I, E_df, W_v (J/kg)] after the interval of
    :data:`EL_CENTRO_SEGMENT`, the slow regime's step carried in, or ``slow_step`` [s/(m/s)] instead."""
    law = np.zeros(resistance.LAW_SIZE)
    resistance.fill_law(0.0005, 0.0005, 0.0, 1.0, law)
    dt, s_switch, s_lock, rtol, floor, tolerance = map(float.fromhex, EL_CENTRO_SCALES)
    state = np.array([float.fromhex(value) for value in EL_CENTRO_STATE])
    steps = np.array([float.fromhex(value) for value in EL_CENTRO_STEPS])
    if slow_step is not None:
        steps[SLOW] = slow_step
    size = N_STATE
    motion = interval.advance_interval(
        np.array([float.fromhex(value) for value in EL_CENTRO_SEGMENT]), dt, law, s_switch, s_lock, rtol, floor,
        tolerance, state, np.zeros(size), SLIDING, steps, np.zeros((stepping.WORK_ROWS, size)),
        np.zeros(size), np.zeros(size), np.zeros(size), np.zeros(size), np.zeros(manifold.FLAT_ORDER + 1),
        np.zeros(5))
    assert motion == SLIDING
    return state


def test_a_slow_step_grown_at_lower_speeds_is_refused_where_it_overflows_not_taken():
    carried = el_centro_interval()
    assert np.all(np.isfinite(carried)) and carried[TAU] == float.fromhex(EL_CENTRO_SCALES[0])
    assert math.hypot(carried[V1], carried[V2]) < 0.01  # m/s: it was 1e180
    for slow_step in (1e-2, 1.0):  # the interval from a step of the speed's own scale: the same to the tolerance
        np.testing.assert_allclose(carried, el_centro_interval(slow_step), rtol=1e-10, atol=1e-15)


def test_the_sweep_says_where_the_solver_gave_up():
    dt = 0.01
    time = np.arange(400) * dt
    first, second = 3.0 * np.sin(2.0 * np.pi * time), 2.0 * np.cos(2.0 * np.pi * 1.3 * time)  # m/s²: it slides
    cases = np.array([[0.1, 0.1, 0.0, 1.0], [0.2, 0.2, 0.0, 1.0]])
    out = np.zeros((1, 2, len(SCALARS)))
    stalled_at = plane.sweep_pairs_on_surface(first, second, np.zeros(0), np.array([0, 400]), np.array([dt]),
                                              G, cases, 1e-40, plane.LOCK_RATIO, out)
    # a tolerance no step of double precision meets: each step is refused and shortened, without end
    assert stalled_at.shape == (1, 2) and np.all((stalled_at >= 0.0) & (stalled_at < 400 * dt))
    assert np.all(np.isnan(out))
    with pytest.raises(StickslipError) as caught:
        plane.check_progress(stalled_at, lambda index: f"pair {index[0]}, case {index[1]}")
    assert str(caught.value) == (
        f"pair 0, case 0: the solver gave up at t = {stalled_at[0, 0]:.6g} s of the record, after "
        f"{plane.MAX_PASSES} passes of its event loop in one sample interval without reaching the interval's "
        "end")
    plane.check_progress(np.full((1, 2), np.nan), lambda index: "never named")  # solved: nothing to say
