"""The exact event-driven solver: hand-derived cases, energy balance, resampling invariance, batched kernel."""

from __future__ import annotations

import math
import signal
import subprocess
import sys
import time

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from stickslip.errors import StickslipError
from stickslip.records.process import integrate_linear_acceleration, resample
from stickslip.models.rigid import events
from stickslip.models.rigid import exact
from stickslip.models.rigid.exact import (
    SCALAR_NAMES,
    record_scalars,
    sweep_scalars,
    sweep_scalars_reference,
)
from stickslip.models.rigid.exact_scheme import solve_history
from stickslip.solvers import events as solver_events
from stickslip.solvers.compilation import engine_pieces

G = 9.81
first_stop_time = engine_pieces()["first_stop_time"]


def history_scalars(history, duration: float, g: float, mu: float) -> dict[str, float]:
    """The SCALAR_NAMES values of one solve_history result, per unit mass."""
    velocity_end = history.ground_velocity[-1] + history.relative_velocity[-1]
    return {
        "energy_dissipated": history.energy_dissipated[-1],
        "energy_input": history.energy_input[-1],
        "kinetic_energy_final": 0.5 * velocity_end**2,
        "residual_displacement": history.relative_displacement[-1],
        "peak_relative_displacement": history.peak_relative_displacement,
        "sliding_path": history.sliding_path,
        "slip_fraction": history.slip_time / duration,
        "n_slip_episodes": history.n_slip_episodes,
    }


# --- hand-derived cases ------------------------------------------------------------------


def test_ramp_breakaway_matches_hand_solution():
    """ü_g = k·t on [0, 1 s]: breakaway at t_b = μg/k, then ẋ = −k(t−t_b)²/2, x = −k(t−t_b)³/6."""
    slope, mu, dt = 3.0, 0.1, 1.0
    history = solve_history(np.array([0.0, slope * dt]), dt, mu, G)
    t_slide = dt - mu * G / slope
    assert history.relative_velocity[-1] == pytest.approx(-slope * t_slide**2 / 2, rel=1e-13)
    assert history.relative_displacement[-1] == pytest.approx(-slope * t_slide**3 / 6, rel=1e-13)
    assert history.sliding_path == pytest.approx(slope * t_slide**3 / 6, rel=1e-13)
    assert history.energy_dissipated[-1] == pytest.approx(mu * G * slope * t_slide**3 / 6, rel=1e-13)
    assert history.slip_time == pytest.approx(t_slide, rel=1e-13)
    assert history.n_slip_episodes == 1
    assert list(history.phase) == [0, -1]
    # E_I: stick part ∫k t · k t²/2 dt = k² t_b⁴/8, slip part ∫ μg · k t²/2 dt from t_b to 1.
    t_b = dt - t_slide
    expected_input = slope**2 * t_b**4 / 8 + mu * G * slope * (dt**3 - t_b**3) / 6
    assert history.energy_input[-1] == pytest.approx(expected_input, rel=1e-13)


def test_constant_pulse_stops_where_relative_velocity_vanishes():
    """A rectangular pulse A for 0.5 s (1 ms ramps) then rest: the stop is at t = A·t_p/(μg) after onset.

    During the pulse the block lags with ẍ = −(A − μg); after it ẍ = +μg until ẋ = 0.
    """
    mu, amplitude, dt = 0.2, 4.0, 0.001
    n_pulse = 500
    acceleration = np.zeros(3000)
    acceleration[1 : 1 + n_pulse] = amplitude
    history = solve_history(acceleration, dt, mu, G)
    # Pulse plateau from t = 1 ms to 500 ms, linear ramps of 1 ms on each side: solve the
    # impulse balance exactly: ∫(a − μg)⁺ before the stop equals μg·(time after the pulse).
    friction = mu * G
    t_break = dt * friction / amplitude  # on the rising ramp
    excess_impulse = 0.5 * (dt - t_break) * (amplitude - friction) + (n_pulse - 1) * dt * (amplitude - friction)
    # On the falling ramp (from t_pulse_end = 500 ms) a drops from A to 0 over dt.
    drop_impulse = dt * (amplitude / 2 - friction)  # ∫(a − μg) over the falling ramp
    stop_time = n_pulse * dt + dt + (excess_impulse + drop_impulse) / friction
    stopped = np.flatnonzero(history.phase[1:] == 0)[0] + 1
    assert history.time[stopped - 1] < stop_time <= history.time[stopped]
    assert history.n_slip_episodes == 1
    assert history.slip_time == pytest.approx(stop_time - t_break, rel=1e-12)
    balance = 0.5 * (history.ground_velocity + history.relative_velocity) ** 2 + history.energy_dissipated
    np.testing.assert_allclose(balance, history.energy_input, rtol=0, atol=1e-12 * history.energy_input[-1])


def test_first_stop_time_is_accurate_without_cancellation():
    """A root of size 1e-12 next to one of size 1e6: the naive formula loses it, this one does not."""
    c0, c1, c2 = 1e-12, -1.0, 1e-6
    root = first_stop_time(c0, c1, c2)
    assert root == pytest.approx(1e-12, rel=1e-12)
    assert c0 + c1 * root + c2 * root**2 == pytest.approx(0.0, abs=1e-24)


@pytest.mark.parametrize(
    ("coefficients", "expected"),
    [
        ((1.0, 0.0, -1.0), 1.0),  # c2 < 0: one positive root
        ((1.0, -2.0, 0.0), 0.5),  # linear
        ((1.0, 1.0, 0.0), math.inf),  # speed growing linearly: no stop
        ((1.0, 0.0, 1.0), math.inf),  # no real root
        ((0.0, 2.0, -1.0), 2.0),  # slip from rest: the root at 0 does not count
        ((0.0, 0.0, 1.0), math.inf),  # breakaway at the threshold: speed grows as τ²
        ((2.0, -3.0, 1.0), 1.0),  # two positive roots: the first
    ],
)
def test_first_stop_time_cases(coefficients, expected):
    assert first_stop_time(*coefficients) == pytest.approx(expected, rel=1e-15)


def test_block_never_slips_below_the_friction_limit():
    acceleration = 0.99 * 0.3 * G * np.sin(np.linspace(0.0, 20.0, 2001))
    history = solve_history(acceleration, 0.01, 0.3, G)
    assert history.n_slip_episodes == 0
    assert not np.any(history.relative_displacement)
    assert history.energy_dissipated[-1] == 0.0
    # Sticking: E_I = ½ u̇_g² exactly (to round-off accumulated over the record).
    kinetic = 0.5 * history.ground_velocity**2
    np.testing.assert_allclose(history.energy_input, kinetic, rtol=0, atol=1e-12 * kinetic.max())


# --- the shared records ------------------------------------------------------------------


@pytest.mark.parametrize("mu", [0.05, 0.1, 0.2])
def test_energy_balance_closes_to_round_off_on_paper_records(paper_records, distinct_paper_file, mu):
    record = paper_records[distinct_paper_file]
    history = solve_history(record.acceleration, record.dt, mu, G)
    kinetic = 0.5 * (history.ground_velocity + history.relative_velocity) ** 2
    residual = kinetic - kinetic[0] + history.energy_dissipated - history.energy_input
    assert history.energy_dissipated[-1] > 0.0
    assert np.max(np.abs(residual)) / history.energy_input[-1] < 1e-9


@pytest.mark.parametrize("name", ["SLAMMER_Cape_Mendocino_1992_PET-090.txt", "SLAMMER_Coyote_Lake_1979_G06-230.txt"])
def test_resampling_to_a_twentieth_of_dt_changes_nothing(paper_records, name):
    record = paper_records[name]
    fine = resample(record, record.dt / 20)
    assert fine.npts == 20 * (record.npts - 1) + 1
    mu = 0.1
    coarse_scalars = sweep_scalars([record.acceleration], record.dt, np.array([mu]), G)[0, 0]
    fine_scalars = sweep_scalars([fine.acceleration], fine.dt, np.array([mu]), G)[0, 0]
    scale = dict(zip(SCALAR_NAMES, coarse_scalars))
    for k, name_k in enumerate(SCALAR_NAMES):
        reference = max(abs(coarse_scalars[k]), 1e-9 * abs(scale["peak_relative_displacement"]))
        if name_k == "kinetic_energy_final":
            reference = scale["energy_input"]
        assert abs(fine_scalars[k] - coarse_scalars[k]) <= 1e-9 * reference, name_k
    # The histories agree at the coarse samples too.
    coarse = solve_history(record.acceleration, record.dt, mu, G)
    fine_history = solve_history(fine.acceleration, fine.dt, mu, G)
    np.testing.assert_allclose(
        fine_history.relative_displacement[::20], coarse.relative_displacement, rtol=0, atol=1e-12
    )


def test_reference_sweep_scalars_equal_solve_history_scalars(paper_records):
    names = ["SLAMMER_Kobe_1995_KJM-090.txt", "SLAMMER_Northridge_1994_NWH-090.txt", "SLAMMER_Coyote_Lake_1979_G06-320.txt"]
    records = [paper_records[name] for name in names]
    mu = np.array([0.03, 0.1, 0.25, 0.6])
    cube = sweep_scalars_reference([r.acceleration for r in records], [r.dt for r in records], mu, G)
    assert cube.shape == (3, 4, len(SCALAR_NAMES))
    for i, record in enumerate(records):
        for j, friction_ratio in enumerate(mu):
            history = solve_history(record.acceleration, record.dt, friction_ratio, G)
            expected = history_scalars(history, record.duration, G, friction_ratio)
            assert list(cube[i, j]) == [expected[name] for name in SCALAR_NAMES]


def test_sweep_scalars_accepts_a_2d_array_and_one_dt():
    rng = np.random.default_rng(7)
    accelerations = rng.normal(0.0, 3.0, (2, 300))
    from_array = sweep_scalars(accelerations, 0.01, np.array([0.1, 0.2]), G)
    from_list = sweep_scalars(list(accelerations), [0.01, 0.01], [0.1, 0.2], G)
    np.testing.assert_array_equal(from_array, from_list)
    assert np.all(from_array[:, :, SCALAR_NAMES.index("n_slip_episodes")] >= 1)


@pytest.mark.parametrize(
    ("arguments", "message"),
    [
        (([np.zeros(10)], 0.01, [0.1, -0.1], G), "friction ratio mu must be a positive"),
        (([np.zeros(10)], 0.0, [0.1], G), "time step of record 0"),
        (([np.zeros(1)], 0.01, [0.1], G), "record 0: expected a 1-D acceleration history with at least 2 samples"),
        (([np.array([0.0, np.nan, 1.0])], 0.01, [0.1], G), "record 0: acceleration contains NaN"),
        (([], 0.01, [0.1], G), "no records given"),
    ],
)
def test_sweep_scalars_rejects_bad_input(arguments, message):
    with pytest.raises(StickslipError, match=message):
        sweep_scalars(*arguments)


def test_solve_history_rejects_bad_mu():
    with pytest.raises(StickslipError, match="friction ratio mu must be a positive finite number"):
        solve_history(np.zeros(5), 0.01, float("nan"), G)


# --- the sweep kernel against its oracle --------------------------------------------------


def assert_equal_to_reference(accelerations, dts, mu):
    """sweep_scalars equals sweep_scalars_reference: E_I to 1e-12 of its scale, everything else exactly."""
    new = sweep_scalars(accelerations, dts, mu, G)
    old = sweep_scalars_reference(accelerations, dts, mu, G)
    column = SCALAR_NAMES.index("energy_input")
    others = [k for k in range(len(SCALAR_NAMES)) if k != column]
    np.testing.assert_array_equal(new[..., others], old[..., others])
    scale = np.maximum(np.abs(old[..., column]), np.max(np.abs(old[..., column]), axis=-1, keepdims=True) * 1e-3)
    assert np.all(np.abs(new[..., column] - old[..., column]) <= 1e-12 * scale + 1e-300)
    return new


def test_sweep_scalars_equal_the_reference_kernel_on_every_shared_record(paper_records):
    records = list(paper_records.values())
    mu = np.linspace(0.01, 0.4, 200)
    assert_equal_to_reference([r.acceleration for r in records], [r.dt for r in records], mu)


@settings(max_examples=100, deadline=None)
@given(
    arrays(np.float64, st.integers(min_value=2, max_value=300),
           elements=st.floats(min_value=-10.0, max_value=10.0, allow_nan=False, allow_subnormal=False)),
    st.floats(min_value=1e-3, max_value=0.05),
    st.lists(st.floats(min_value=0.01, max_value=1.0), min_size=1, max_size=5),
)
def test_sweep_scalars_equal_the_reference_kernel_on_random_records(acceleration, dt, mu):
    assert_equal_to_reference([acceleration], dt, np.array(mu))


def snapped(acceleration: np.ndarray, mu_g: float, tolerance: float) -> np.ndarray:
    """``acceleration`` with every sample within ``tolerance``·μg of ±μg set to ±μg exactly."""
    result = acceleration.copy()
    near = np.abs(np.abs(result) - mu_g) <= tolerance * mu_g
    result[near] = np.sign(result[near]) * mu_g
    return result


@pytest.mark.parametrize("tolerance", [0.01, 0.02, 0.05, 0.1])
def test_samples_exactly_at_the_friction_limit_start_no_spurious_episode(paper_records, tolerance):
    """Kobe snapped to ±μg at μ = 0.05: both kernels count the episodes of the record resampled to dt/20."""
    record = paper_records["SLAMMER_Kobe_1995_KJM-090.txt"]
    mu = 0.05
    coarse = record.derive(snapped(record.acceleration, mu * G, tolerance), dt=record.dt, step="snap to mu g")
    fine = resample(coarse, coarse.dt / 20)
    episodes = SCALAR_NAMES.index("n_slip_episodes")
    expected = sweep_scalars_reference([fine.acceleration], fine.dt, [mu], G)[0, 0, episodes]
    for kernel in (sweep_scalars, sweep_scalars_reference):
        assert kernel([coarse.acceleration], coarse.dt, [mu], G)[0, 0, episodes] == expected
    assert_equal_to_reference([coarse.acceleration], coarse.dt, np.array([mu]))


#: Sample levels [μg] of the threshold property: 0 and ±1 (at the friction limit) exactly, the others
#: off the half-integers.  Levels of ±0.5 and ±1.5 μg can stop the block exactly where |ü_g| reaches μg
#: (or bring its velocity to zero tangentially there): whether that is one episode or two is then
#: decided by round-off, in the record and in its resampled copy alike.
THRESHOLD_LEVELS = (-1.0, -0.53, 0.0, 0.47, 1.0, 1.51, -1.49)


@settings(max_examples=100, deadline=None)
@given(
    st.lists(st.sampled_from(THRESHOLD_LEVELS), min_size=2, max_size=40),
    st.floats(min_value=0.02, max_value=0.5),
)
def test_exact_threshold_samples_count_episodes_as_the_fine_record(levels, mu):
    """Records whose samples sit at 0, ±μg and off it: episodes as on the record resampled to dt/20."""
    dt = 0.01
    acceleration = np.array(levels) * mu * G
    fine_dt = dt / 20
    fine = np.interp(np.arange(20 * (acceleration.size - 1) + 1) / 20, np.arange(acceleration.size), acceleration)
    episodes = SCALAR_NAMES.index("n_slip_episodes")
    expected = sweep_scalars_reference([fine], fine_dt, [mu], G)[0, 0, episodes]
    for kernel in (sweep_scalars, sweep_scalars_reference):
        assert kernel([acceleration], dt, [mu], G)[0, 0, episodes] == expected
    assert_equal_to_reference([acceleration], dt, np.array([mu]))


# --- the history as plain Python against the compiled kernel ------------------------------


def assert_python_history_equals_compiled(acceleration: np.ndarray, dt: float, mu: float) -> None:
    ground_velocity, _ = integrate_linear_acceleration(acceleration, dt)
    python = events.history_kernel(acceleration.tolist(), ground_velocity.tolist(), dt, mu * G)
    compiled = exact.history_kernel(acceleration, ground_velocity, dt, mu * G)
    for as_python, as_compiled in zip(python, compiled, strict=True):
        np.testing.assert_array_equal(as_python, as_compiled)


@pytest.mark.parametrize("mu", [0.01, 0.05, 0.13, 0.4])
def test_history_as_python_equals_the_compiled_kernel_on_every_shared_record(paper_records, mu):
    for record in paper_records.values():
        assert_python_history_equals_compiled(record.acceleration, record.dt, mu)


@settings(max_examples=100, deadline=None)
@given(
    st.lists(st.sampled_from([-1.0, -0.5, 0.0, 0.5, 1.0, 1.5, -1.5, 3.0]), min_size=2, max_size=40),
    st.floats(min_value=0.02, max_value=0.5),
)
def test_history_as_python_equals_the_compiled_kernel_at_exact_thresholds(levels, mu):
    assert_python_history_equals_compiled(np.array(levels) * mu * G, 0.01, mu)


def test_solve_history_of_a_long_record_runs_compiled(paper_records, monkeypatch):
    record = paper_records["SLAMMER_Kobe_1995_KJM-090.txt"]
    as_python = solve_history(record.acceleration, record.dt, 0.07, G)
    calls = []
    monkeypatch.setattr(events, "PYTHON_SAMPLES", record.npts - 1)
    monkeypatch.setattr(exact, "history_kernel", lambda *arguments: calls.append(1) or compiled(*arguments))
    compiled = exact._KERNELS["history_kernel"]
    as_compiled = solve_history(record.acceleration, record.dt, 0.07, G)
    assert calls == [1]
    for name in ("relative_displacement", "relative_velocity", "energy_dissipated", "energy_input", "phase"):
        np.testing.assert_array_equal(getattr(as_python, name), getattr(as_compiled, name))


def test_record_scalars_equal_one_case_of_the_sweep(paper_records):
    record = paper_records["SLAMMER_Northridge_1994_NWH-090.txt"]
    swept = sweep_scalars([record.acceleration], record.dt, [0.13], G)[0, 0]
    np.testing.assert_array_equal(record_scalars(record.acceleration, record.dt, 0.13, G), swept)


def test_sweep_is_split_into_short_interruptible_calls(monkeypatch):
    """Small groups and chunks (as a long sweep gets) give the same result as one call."""
    rng = np.random.default_rng(3)
    records = [rng.normal(0.0, 2.0, size) for size in (500, 1200, 80, 3000)]
    mu = np.linspace(0.02, 0.3, 17)
    whole = sweep_scalars(records, 0.01, mu, G)
    monkeypatch.setattr(exact, "GROUP_SAMPLES", 1000)
    monkeypatch.setattr(exact, "FIRST_CHUNK_WORK", 2000)
    monkeypatch.setattr(solver_events, "CALL_SECONDS", 1e-9)
    calls = []
    solver_events.run_in_calls(lambda first, last: calls.append((first, last)), np.repeat([500, 1200], 17), 2000)
    assert calls[:2] == [(0, 4), (4, 5)]  # 2,000 updates first, then a quarter of it: the calls were too fast
    np.testing.assert_array_equal(sweep_scalars(records, 0.01, mu, G), whole)


def test_ctrl_c_stops_a_long_sweep_within_two_seconds():
    """SIGINT during a sweep of several seconds raises KeyboardInterrupt between kernel calls, at once.

    The child prints time.monotonic() (one clock for all processes) when the
    interrupt reaches Python; the interpreter's own exit afterwards is not timed.
    """
    script = (
        "import numpy as np, time\n"
        "from stickslip.models.rigid.exact import sweep_scalars\n"
        "records = [np.random.default_rng(0).normal(0.0, 3.0, 20000)] * 100\n"
        "sweep_scalars(records[:1], 0.01, [0.1], 9.81)\n"
        "print('ready', flush=True)\n"
        "try:\n"
        "    sweep_scalars(records, 0.01, np.linspace(0.01, 0.4, 1000), 9.81)\n"
        "except KeyboardInterrupt:\n"
        "    print(time.monotonic(), flush=True)\n"
    )
    process = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
    assert process.stdout.readline().strip() == "ready"
    time.sleep(0.3)
    process.send_signal(signal.SIGINT)
    sent = time.monotonic()
    caught, _ = process.communicate(timeout=60)
    assert caught.strip(), "the sweep ended without KeyboardInterrupt"
    assert float(caught) - sent < 2.0
