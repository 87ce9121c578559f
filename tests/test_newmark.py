"""The paper's Algorithm 1 (``newmark``): its two readings against the ``exact`` solver."""

from __future__ import annotations

import numpy as np
import pytest

from stickslip.errors import StickslipError
from stickslip.models.rigid import exact_scheme
from stickslip.models.rigid import newmark

G = 9.81


# --- the converging (default) reading -----------------------------------------------


@pytest.mark.parametrize("mu", [0.05, 0.1, 0.2])
def test_converging_reading_matches_exact_at_paper_time_step(paper_records, distinct_paper_file, mu):
    record = paper_records[distinct_paper_file]
    reference = exact_scheme.solve_history(record.acceleration, record.dt, mu, G)
    history = newmark.solve_history(record.acceleration, record.dt, mu, G, time_step=0.001)
    # Measured: at most 1.2e-5 relative on these records (G06-320, mu = 0.05).
    assert history.energy_dissipated[-1] == pytest.approx(reference.energy_dissipated[-1], rel=1e-3)
    assert history.relative_displacement[-1] == pytest.approx(reference.relative_displacement[-1], abs=1e-4)
    assert history.n_slip_episodes == reference.n_slip_episodes


@pytest.mark.parametrize("mu", [0.05, 0.1])
def test_converging_reading_is_second_order(paper_records, mu):
    """Sliding path error vs exact at Δt = 4, 2, 1 ms (all divide Kobe's 0.02 s): ratio ≈ 4 per halving."""
    record = paper_records["SLAMMER_Kobe_1995_KJM-090.txt"]
    reference = exact_scheme.solve_history(record.acceleration, record.dt, mu, G).sliding_path
    errors = [
        abs(newmark.solve_history(record.acceleration, record.dt, mu, G, time_step=step).sliding_path - reference)
        for step in (0.004, 0.002, 0.001)
    ]
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    # Measured: orders 2.05, 2.05 (mu = 0.05) and 2.06, 1.93 (mu = 0.1).
    assert np.all((orders > 1.7) & (orders < 2.4)), orders


def test_constant_ground_acceleration_above_threshold_slides_with_closed_form():
    """ü_g = a > μg from t = 0: ẍ = −(a − μg), x = −(a − μg)·t²/2; Newmark is exact for constant ẍ."""
    a, mu, dt = 2.0, 0.1, 0.01
    history = newmark.solve_history(np.full(101, a), dt, mu, G, time_step=dt)
    t = history.time
    np.testing.assert_allclose(history.relative_displacement, -0.5 * (a - mu * G) * t**2, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(history.relative_velocity, -(a - mu * G) * t, rtol=1e-12, atol=1e-15)
    assert history.sliding_path == pytest.approx(0.5 * (a - mu * G) * t[-1] ** 2, rel=1e-12)
    assert history.slip_time == pytest.approx(t[-1], rel=1e-12)
    assert history.n_slip_episodes == 1
    assert set(history.phase[1:]) == {-1}


def test_converging_reading_holds_the_block_while_stuck():
    """Below the threshold the block moves with the base: x = ẋ = ẍ = 0, nothing dissipated."""
    time = np.arange(0, 2.0, 0.01)
    acceleration = 0.5 * np.sin(2 * np.pi * 3 * time)  # peak 0.5 < μg = 0.981 m/s²
    history = newmark.solve_history(acceleration, 0.01, 0.1, G, time_step=0.002)
    assert not np.any(history.relative_displacement)
    assert not np.any(history.relative_velocity)
    assert not np.any(history.phase)
    assert history.energy_dissipated[-1] == 0.0
    assert history.n_slip_episodes == 0


def test_discrete_energy_balance_is_first_order_not_round_off(paper_records):
    """Eqs. 17-21 are right-end rectangle rules: E_k + E_df − E_I is small, not zero.

    Measured on Kobe KJM-090, mu = 0.1: |E_k + E_df − E_I| / max E_I = 6.4e-4, 9.9e-5, 3.2e-4 at
    Δt = 4, 2, 1 ms (up to 7.3e-3 on PET-090 with mu = 0.2).
    """
    record = paper_records["SLAMMER_Kobe_1995_KJM-090.txt"]
    history = newmark.solve_history(record.acceleration, record.dt, 0.1, G, time_step=0.001)
    kinetic = 0.5 * (history.ground_velocity + history.relative_velocity) ** 2
    residual = kinetic + history.energy_dissipated - history.energy_input
    scale = np.max(np.abs(history.energy_input))
    assert np.max(np.abs(residual)) / scale < 1e-2
    assert np.max(np.abs(residual)) / scale > 1e-8  # not round-off: the rectangle rule shows
    # Eq. 18 integrates μ·g·|ẋ| by the rectangle rule; the path is integrated exactly per step.
    assert history.energy_dissipated[-1] == pytest.approx(0.1 * G * history.sliding_path, rel=1e-4)


# --- the literal reading -----------------------------------------------------------


def test_literal_reading_first_steps_follow_the_printed_equations():
    """Constant ü_g = a below μg: Eq. 12 with sgn(0) = 0 and ẍ = 0 in stick lets the block drift."""
    a, mu, h = 0.3, 0.1, 0.01
    history = newmark.solve_history(np.full(4, a), h, mu, G, time_step=h, reading="literal")
    # Initialisation: ẍ_0 = −ü_g,0. Step 1: x_1 = h²/4·(ẍ_0 − a), ẋ_1 = 2/h·x_1.
    x1 = 0.25 * h * h * (-a - a)
    assert history.relative_acceleration[0] == -a
    assert history.relative_displacement[1] == pytest.approx(x1, rel=1e-14)
    assert history.relative_velocity[1] == pytest.approx(2 / h * x1, rel=1e-14)
    # Step 2 uses sgn(ẋ_1) = −1 and ẍ_1 = 0 (stick): ẋ_2 = ẋ_1 − h/2·(a − μg).
    assert history.relative_velocity[2] == pytest.approx(2 / h * x1 - 0.5 * h * (a - mu * G), rel=1e-12)
    assert not np.any(history.phase)  # still "stuck", yet moving relative to the base


def test_literal_reading_chatters_and_does_not_converge(paper_records):
    """The documented failure, on Coyote Lake G06-230 with mu = 0.05.

    After a breakaway ẋ is only the stick drift; the velocity test |ẋ_i| > v_t
    then sticks the block again after one step, so a slide becomes a train of
    one-step slips whose number doubles when Δt halves, and E_df tends to a
    limit about 5.5 % below the exact value (measured: 302 / 604 episodes at
    Δt = 1 / 0.5 ms against 12 for exact; E_df/exact = 0.953 at 1 ms, 0.945 at 0.1 ms).
    """
    record = paper_records["SLAMMER_Coyote_Lake_1979_G06-230.txt"]
    reference = exact_scheme.solve_history(record.acceleration, record.dt, 0.05, G)
    coarse, fine = (
        newmark.solve_history(record.acceleration, record.dt, 0.05, G, time_step=step, reading="literal")
        for step in (0.001, 0.0005)
    )
    assert coarse.n_slip_episodes > 10 * reference.n_slip_episodes
    assert fine.n_slip_episodes / coarse.n_slip_episodes == pytest.approx(2.0, rel=0.1)
    for history in (coarse, fine):
        assert history.energy_dissipated[-1] / reference.energy_dissipated[-1] < 0.96
    # Drift in "stick": the block moves relative to the base while U = 0.
    stuck = coarse.phase == 0
    velocity_tolerance = 1e-2 * np.max(np.abs(coarse.ground_velocity))
    assert np.max(np.abs(coarse.relative_velocity[stuck])) > 0.5 * velocity_tolerance


# --- input checks ------------------------------------------------------------------


def test_unknown_reading_is_an_error():
    with pytest.raises(StickslipError, match="unknown reading 'paper'"):
        newmark.solve_history(np.zeros(10), 0.01, 0.1, G, reading="paper")


@pytest.mark.parametrize(
    ("options", "message"),
    [
        ({"time_step": 0.0}, "time_step"),
        ({"acceleration_tolerance": -1.0}, "acceleration_tolerance"),
        ({"velocity_tolerance": float("nan")}, "velocity_tolerance"),
    ],
)
def test_bad_options_are_errors(options, message):
    with pytest.raises(StickslipError, match=message):
        newmark.solve_history(np.ones(10), 0.01, 0.1, G, **options)


def test_bad_friction_ratio_is_an_error():
    with pytest.raises(StickslipError, match="friction ratio mu"):
        newmark.solve_history(np.ones(10), 0.01, -0.1, G)


def test_time_step_larger_than_the_record_step_is_refused():
    acceleration = np.sin(np.linspace(0.0, 6.0, 301))
    with pytest.raises(StickslipError, match=r"time_step \[s\].*time_step = 0.05 s, record dt = 0.02 s"):
        newmark.solve_history(acceleration, 0.02, 0.1, G, time_step=0.05)
    same = newmark.solve_history(acceleration, 0.02, 0.1, G, time_step=0.02)  # equal is fine
    assert same.time.size == 301


def test_cli_newmark_time_step_larger_than_dt_exits_2(run_cli, paper_records_dir):
    code, out, err = run_cli("solve", paper_records_dir / "CHY080-N.AT2", "--mu", "0.1", "--method", "newmark",
                             "--time-step", "1")
    assert code == 2 and out == "" and "Traceback" not in err
    assert err.splitlines() == [
        "stickslip: error: newmark time_step [s] must not exceed the record's time step: "
        "time_step = 1 s, record dt = 0.005 s (a larger step would skip samples)"
    ]
