"""The friction pendulum in one direction against closed forms and against the flat block.

Oracles: R → ∞ is the flat block of the exact solver; free vibration loses
4μR of amplitude per cycle at the period 2π√(R/g) and stops once |u| ≤ μR;
Den Hartog's (1930) steady state of a spring with Coulomb friction under
harmonic forcing (the pendulum is that system with k/m = g/R); a flat block
pushed by a constant acceleration under the velocity-dependent friction law
has a closed-form speed; the tolerance-controlled kernel agrees with the
closed-form one where both apply; every ledger closes.
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
from scipy.integrate import quad

from stickslip.errors import StickslipError
from stickslip.models.rigid import exact_scheme
from stickslip.solvers.friction_law import FrictionLaw
from stickslip.models.pendulum.exact import pendulum_history, pendulum_sweep
from stickslip.solvers.restoring import phi_functions
from stickslip.models.pendulum.integrated import integrated_history, integrated_sweep
from stickslip.solvers.ledger import SCALAR_NAMES

G = 9.81
#: Scalars compared between kernels (the others are zero or counts).
COMPARED = ("energy_dissipated", "energy_input", "kinetic_energy_final", "potential_energy_final",
            "residual_displacement", "peak_relative_displacement", "sliding_path", "slip_fraction", "peak_base_shear")
ORACLE_FILES = ("SLAMMER_Cape_Mendocino_1992_PET-090.txt", "SLAMMER_Northridge_1994_NWH-090.txt",
                "SLAMMER_Kobe_1995_KJM-090.txt")


def largest_relative_difference(one: dict, other: dict, floor: float) -> float:
    """max over :data:`COMPARED` of |one − other| / max(|other|, floor)."""
    return max(abs(one[name] - other[name]) / max(abs(other[name]), floor) for name in COMPARED)


# --- R → ∞ is the flat block -----------------------------------------------------------------------------------------

@pytest.mark.parametrize("radius", [math.inf, 1e12])
def test_an_infinite_radius_is_the_flat_block_of_the_exact_solver(paper_records, radius):
    for name in ORACLE_FILES:
        record = paper_records[name]
        for mu in (0.03, 0.05, 0.1, 0.2):
            flat = exact_scheme.solve_history(record.acceleration, record.dt, mu, G)
            for result in (pendulum_history(record.acceleration, record.dt, mu, radius),
                           integrated_history(record.acceleration, record.dt, FrictionLaw.coulomb(mu), radius)):
                scalars = result["scalars"]
                assert scalars["energy_dissipated"] == pytest.approx(flat.energy_dissipated[-1], rel=1e-9)
                assert scalars["energy_input"] == pytest.approx(flat.energy_input[-1], rel=1e-9)
                assert scalars["sliding_path"] == pytest.approx(flat.sliding_path, rel=1e-9)
                assert scalars["peak_relative_displacement"] == pytest.approx(flat.peak_relative_displacement,
                                                                              rel=1e-9)
                assert scalars["n_slip_episodes"] == flat.n_slip_episodes
                assert scalars["slip_fraction"] == pytest.approx(flat.slip_time / record.duration, rel=1e-9)
                scale = np.max(np.abs(flat.relative_displacement))
                assert np.max(np.abs(result["relative_displacement"] - flat.relative_displacement)) <= 1e-9 * scale
                assert scalars["peak_base_shear"] == pytest.approx(mu, rel=1e-9)  # |ü| = μg while it slides


# --- free vibration --------------------------------------------------------------------------------------------------

def free_vibration(t, t0, x0, v0, mu, radius):
    """u(t) [m] of a friction pendulum on a ground at rest from u = x0, u̇ = v0 at t0, and its turning points [m].

    In each half-cycle the slider oscillates at ω = √(g/R) about the centre
    −s·μ·R (s its direction): u − centre = A·cos(ω(t − t_k) + φ_k), turning
    at rest where the phase reaches 0 (s = +1) or π (s = −1), at
    centre + s·A; it sticks there once |u| ≤ μR, the friction then holding
    the restoring force ω²|u| ≤ μg.
    """
    omega = math.sqrt(G / radius)
    out = np.full(np.shape(t), np.nan)
    turns = []
    start, x, v = t0, x0, v0
    while True:
        if v == 0.0:
            if abs(x) <= mu * radius:  # at rest for ever
                out[t >= start] = x
                return out, turns
            s = -1 if x > 0 else 1
        else:
            s = 1 if v > 0 else -1
        centre = -s * mu * radius
        amplitude = math.hypot(x - centre, v / omega)
        phase = math.atan2(-v / omega, x - centre)
        duration = ((0.0 if s > 0 else math.pi) - phase) % (2 * math.pi) / omega
        inside = (t >= start) & (t <= start + duration)
        out[inside] = centre + amplitude * np.cos(omega * (t[inside] - start) + phase)
        start, x, v = start + duration, centre + s * amplitude, 0.0
        turns.append(x)


def test_free_vibration_from_a_displacement_loses_four_mu_r_per_cycle_and_stops_within_mu_r():
    radius, mu = 1.0, 0.02
    omega = math.sqrt(G / radius)
    half_period = math.pi / omega
    dt = half_period / 200
    t = np.arange(0, 200 * 12 + 1) * dt
    amplitude0 = 0.35
    for result in (pendulum_history(np.zeros(t.size), dt, mu, radius, initial_displacement=amplitude0),
                   integrated_history(np.zeros(t.size), dt, FrictionLaw.coulomb(mu), radius,
                                      initial_displacement=amplitude0)):
        x = result["relative_displacement"]
        turns = x[::200]  # the turning points fall on samples: every half period 2π√(R/g)/2
        expected = [(-1) ** k * (amplitude0 - 2 * k * mu * radius) for k in range(turns.size)]
        stop = next(k for k, value in enumerate(expected) if abs(value) <= mu * radius)
        assert stop == 9  # |0.35 − 8·0.04| = 0.03 > μR = 0.02 turns back; |0.35 − 9·0.04| = 0.01 stays
        expected = np.array(expected[:stop + 1] + [expected[stop]] * (turns.size - stop - 1))
        assert np.max(np.abs(turns - expected)) <= 1e-9 * amplitude0
        per_cycle = np.abs(turns[0:stop - 1:2]) - np.abs(turns[2:stop + 1:2])
        assert np.allclose(per_cycle, 4 * mu * radius, rtol=0, atol=1e-9 * amplitude0)
        assert np.all(result["phase"][200 * stop + 1:] == 0)  # stuck for ever at the last turn (at a sample, to
        assert np.all(result["phase"][1:200 * stop] != 0)  # round-off either side of it)
        assert result["scalars"]["slip_fraction"] * t[-1] == pytest.approx(stop * half_period, rel=1e-9)
        law, law_turns = free_vibration(t, 0.0, amplitude0, 0.0, mu, radius)
        assert np.allclose(law_turns, expected[1:stop + 1], rtol=0, atol=1e-12)
        assert np.max(np.abs(x - law)) <= 1e-9 * amplitude0


def test_free_vibration_after_a_pulse_follows_the_friction_pendulum_law():
    radius, mu = 2.0, 0.015
    dt = 0.005
    t = np.arange(0.0, 30.0 + dt / 2, dt)
    pulse_end = 0.5
    acceleration = np.where(t <= pulse_end, 0.6 * G * np.sin(np.pi * t / pulse_end) ** 2, 0.0)
    for result in (pendulum_history(acceleration, dt, mu, radius),
                   integrated_history(acceleration, dt, FrictionLaw.coulomb(mu), radius)):
        end = round(pulse_end / dt)
        x = result["relative_displacement"]
        law, turns = free_vibration(t, t[end], x[end], result["relative_velocity"][end], mu, radius)
        assert len(turns) >= 8  # the pulse set it swinging for four cycles and more
        assert np.max(np.abs(x[end:] - law[end:])) <= 1e-9 * np.max(np.abs(turns))
        assert abs(x[-1]) <= mu * radius and result["phase"][-1] == 0
        assert np.all(np.abs(x[:end + 1]) < abs(turns[0]))  # the largest swing is the first after the pulse
        assert result["scalars"]["peak_relative_displacement"] == pytest.approx(abs(turns[0]), rel=1e-9)


# --- Den Hartog (1930) -----------------------------------------------------------------------------------------------

def den_hartog_steady_state(frequency_ratio, friction_over_force, radius, mu):
    """Den Hartog's steady state of ü + ω²u + F·sgn(u̇) = P·cos(Ωt + φ): (P, Ω, φ, X, u(t)).

    Two stops per cycle, u(t + π/Ω) = −u(t), u(0) = −X at a stop.  With
    β = Ω/ω, U = sin(π/β)/(1 + cos(π/β)): sin φ = (F/P)·(1 − β²)/β·U and
    X = (P/ω²)·√(1/(1 − β²)² − (F/P·U/β)²), X = −P·cos φ/(ω² − Ω²); between
    the stops u = P·cos(Ωt + φ)/(ω² − Ω²) − F/ω² + A·cos ωt + B·sin ωt with
    B = PΩ sin φ/(ω(ω² − Ω²)) and A from u(0) = −X (derived in docs/solvers.md).
    """
    w2 = G / radius
    omega = math.sqrt(w2)
    forcing_frequency = frequency_ratio * omega
    friction = mu * G
    force = friction / friction_over_force
    u = math.sin(math.pi / frequency_ratio) / (1 + math.cos(math.pi / frequency_ratio))
    detuning = w2 - forcing_frequency ** 2
    sin_phi = friction_over_force * (1 - frequency_ratio ** 2) / frequency_ratio * u
    amplitude = force / w2 * math.sqrt(1 / (1 - frequency_ratio ** 2) ** 2 - (friction_over_force * u
                                                                                / frequency_ratio) ** 2)
    cos_phi = -math.copysign(math.sqrt(1 - sin_phi ** 2), detuning)
    phi = math.atan2(sin_phi, cos_phi)
    b = force * forcing_frequency * sin_phi / (omega * detuning)
    a = -amplitude - force * cos_phi / detuning + friction / w2

    def displacement(t):
        half = math.pi / forcing_frequency
        count = np.floor(t / half)
        local = t - count * half
        value = (force * np.cos(forcing_frequency * local + phi) / detuning - friction / w2 + a * np.cos(omega * local)
                 + b * np.sin(omega * local))
        return np.where(count % 2 == 0, value, -value)

    return force, forcing_frequency, phi, amplitude, displacement


@pytest.mark.parametrize("frequency_ratio, friction_over_force", [(0.6, 0.3), (2.0, 0.3), (1.5, 0.4)])
def test_den_hartog_steady_state_of_coulomb_friction_under_harmonic_forcing(frequency_ratio, friction_over_force):
    """From a stop of the steady state, six cycles follow it; the record, a polygon, is off by O(dt²) (measured:
    3.3e-5, 8.3e-6, 2.1e-6 of X at 400, 800, 1,600 samples a cycle), which Richardson's extrapolation removes
    (measured: within 1.3e-11 of X)."""
    radius, mu = 1.0, 0.05
    force, frequency, phi, amplitude, displacement = den_hartog_steady_state(frequency_ratio, friction_over_force,
                                                                             radius, mu)
    period = 2 * math.pi / frequency
    grid = np.arange(0, 6 * 400 + 1) * period / 400
    # the steady state slides throughout: its stops reverse at once (no stick), its speed keeps one sign between
    between = np.linspace(1e-6, 0.5 * period - 1e-6, 5001)
    assert np.all(np.diff(displacement(between)) > 0)
    assert force * math.cos(phi) + G / radius * amplitude > mu * G
    for solve in (lambda a, dt: pendulum_history(a, dt, mu, radius, initial_displacement=-amplitude),
                  lambda a, dt: integrated_history(a, dt, FrictionLaw.coulomb(mu), radius,
                                                   initial_displacement=-amplitude)):
        at = {}
        for per_cycle in (800, 1600):
            dt = period / per_cycle
            t = np.arange(0, 6 * per_cycle + 1) * dt
            result = solve(-force * np.cos(frequency * t + phi), dt)
            assert np.max(np.abs(result["relative_displacement"] - displacement(t))) <= 2e-5 * amplitude
            assert set(result["phase"][1:-1].tolist()) == {-1, 1}  # never sticks
            at[per_cycle] = result["relative_displacement"][:: per_cycle // 400]
        extrapolated = (4 * at[1600] - at[800]) / 3
        assert np.max(np.abs(extrapolated - displacement(grid))) <= 1e-8 * amplitude


# --- the velocity-dependent law --------------------------------------------------------------------------------------

def test_a_constant_push_under_the_velocity_dependent_law_has_the_closed_form_speed():
    """Flat, a constant a = A > μ_fast·g: w = −u̇ obeys ẇ = c + d·e^{−r·w}, c = A − μ_fast·g, d = (μ_fast − μ_slow)·g,
    so w(t) = ln(((c + d)·e^{r·c·t} − d)/c)/r; u(t) = −∫w dt by quadrature."""
    law = FrictionLaw.velocity_dependent(0.04, 0.12, 25.0)
    push = 0.3 * G
    dt = 0.01
    t = np.arange(0.0, 3.0 + dt / 2, dt)
    c = push - law.mu_fast * G
    d = (law.mu_fast - law.mu_slow) * G
    speed = np.log(((c + d) * np.exp(law.rate * c * t) - d) / c) / law.rate
    result = integrated_history(np.full(t.size, push), dt, law)
    assert np.max(np.abs(-result["relative_velocity"] - speed)) <= 1e-9 * speed[-1]
    displacement = -np.array([quad(lambda s: np.log(((c + d) * np.exp(law.rate * c * s) - d) / c) / law.rate, 0, time,
                                   epsabs=1e-14, epsrel=1e-13)[0] for time in t[::30]])
    assert np.max(np.abs(result["relative_displacement"][::30] - displacement)) <= 1e-9 * abs(displacement[-1])
    mu_path = quad(lambda s: law.coefficient(np.log(((c + d) * np.exp(law.rate * c * s) - d) / c) / law.rate)
                   * np.log(((c + d) * np.exp(law.rate * c * s) - d) / c) / law.rate, 0, t[-1],
                   epsabs=1e-14, epsrel=1e-13)[0]
    assert result["scalars"]["energy_dissipated"] == pytest.approx(G * mu_path, rel=1e-9)
    assert result["scalars"]["peak_base_shear"] == pytest.approx(float(law.coefficient(speed[-1])), rel=1e-9)


def test_velocity_dependent_law_with_equal_coefficients_is_coulomb_friction(paper_records):
    record = paper_records["SLAMMER_Northridge_1994_NWH-090.txt"]
    coulomb = integrated_history(record.acceleration, record.dt, FrictionLaw.coulomb(0.08), 1.5)["scalars"]
    law = FrictionLaw.velocity_dependent(0.08, 0.08, 30.0)
    assert law.is_coulomb and law.rate == 0.0
    assert integrated_history(record.acceleration, record.dt, law, 1.5)["scalars"] == coulomb


def test_friction_law_values_and_its_bad_input():
    law = FrictionLaw.velocity_dependent(0.05, 0.1, 20.0)
    assert law.coefficient([0.0, -0.05, 1e3]) == pytest.approx([0.05, 0.1 - 0.05 * math.exp(-1.0), 0.1], rel=1e-15)
    with pytest.raises(StickslipError, match=r"--mu-slow.*positive finite"):
        FrictionLaw.velocity_dependent(-0.05, 0.1, 20.0)
    with pytest.raises(StickslipError, match=r"--rate.*positive finite"):
        FrictionLaw.velocity_dependent(0.05, 0.1, math.inf)
    with pytest.raises(StickslipError, match=r"--mu\).*positive finite"):
        FrictionLaw.coulomb(0.0)


# --- the two kernels against each other, the sweeps, the ledgers -----------------------------------------------------

def test_the_integrated_kernel_matches_the_closed_form_pendulum_on_real_records(three_component_sets):
    """Measured on the first horizontal component of the fifteen sets, μ = 0.03 and 0.1, R = 2 m: scalars within
    7.6e-13 (the potential energy ½·ω²·u(end)² and u(end), where u(end) is small; the others within 1.4e-14), u at
    the samples within 1.4e-14 of its peak."""
    for station in three_component_sets.values():
        first = station["H1"]
        for mu in (0.03, 0.1):
            exact = pendulum_history(first.acceleration, first.dt, mu, 2.0)
            integrated = integrated_history(first.acceleration, first.dt, FrictionLaw.coulomb(mu), 2.0)
            assert largest_relative_difference(integrated["scalars"], exact["scalars"], 1e-3) <= 1e-9
            scale = np.max(np.abs(exact["relative_displacement"]))
            assert np.max(np.abs(integrated["relative_displacement"] - exact["relative_displacement"])) <= 1e-9 * scale


@pytest.mark.parametrize("radius", [1.0, 3.0, math.inf])
def test_closed_form_ledger_closes_to_round_off(paper_records, radius):
    """Measured: at most 9.8e-15 of the largest |E_I| on the six paper records (R = 1 m, 3 m, ∞; μ = 0.05, 0.2)."""
    for record in paper_records.values():
        for mu in (0.05, 0.2):
            result = pendulum_history(record.acceleration, record.dt, mu, radius)
            assert np.max(np.abs(result["balance_residual"])) <= 1e-12 * np.max(np.abs(result["energy_input"]))
            assert np.all(np.diff(result["sliding_path"]) >= 0)
            assert result["potential_energy"][-1] == result["scalars"]["potential_energy_final"] == pytest.approx(
                0.5 * (0.0 if math.isinf(radius) else G / radius) * result["relative_displacement"][-1] ** 2,
                rel=1e-15, abs=1e-300)
            assert np.all(result["energy_input_vertical"] == 0.0)


def test_sweeps_equal_the_histories(paper_records):
    """The sweep kernels' shortcuts (a stick skipped by block extremes, a quiet slipping interval in one map)
    change no scalar beyond round-off (measured: 2.7e-15)."""
    records = [paper_records[name] for name in ORACLE_FILES]
    mus = np.array([0.02, 0.07, 0.2])
    radii = np.array([1.0, 2.5, math.inf])
    swept = pendulum_sweep([r.acceleration for r in records], [r.dt for r in records], mus, radii)
    integrated = integrated_sweep([r.acceleration for r in records], None, [r.dt for r in records],
                                  [FrictionLaw.velocity_dependent(m / 2, m, 20.0) for m in mus], radii)
    for i, record in enumerate(records):
        for j, (mu, radius) in enumerate(zip(mus, radii)):
            history = pendulum_history(record.acceleration, record.dt, mu, radius)["scalars"]
            assert swept[i, j] == pytest.approx([history[name] for name in SCALAR_NAMES], rel=1e-12, abs=1e-15)
            history = integrated_history(record.acceleration, record.dt,
                                         FrictionLaw.velocity_dependent(mu / 2, mu, 20.0), radius)["scalars"]
            assert integrated[i, j] == pytest.approx([history[name] for name in SCALAR_NAMES], rel=1e-12, abs=1e-15)


def test_a_surface_so_tight_that_a_sample_spans_quarter_periods_is_still_exact():
    """ω·dt from 1.6 to 7 (R = 10, 2 and 0.5 mm at dt = 0.05 s): the stop search cuts each interval into quarter
    periods and the φ-functions leave their series.  Measured: ledger within 2.6e-15, the integrated kernel
    within 1.8e-10, the sweep equal to the history within 2.8e-16."""
    acceleration = np.convolve(np.random.default_rng(1).normal(0.0, 3.0, 400), np.ones(3) / 3, "same")
    dt = 0.05
    for radius in (0.01, 0.002, 0.0005):
        for mu in (0.02, 0.1):
            exact = pendulum_history(acceleration, dt, mu, radius)
            assert np.max(np.abs(exact["balance_residual"])) <= 1e-12 * np.max(np.abs(exact["energy_input"]))
            assert 0.2 < exact["scalars"]["slip_fraction"] <= 1.0
            integrated = integrated_history(acceleration, dt, FrictionLaw.coulomb(mu), radius)
            scale = np.max(np.abs(exact["relative_displacement"]))
            assert np.max(np.abs(integrated["relative_displacement"] - exact["relative_displacement"])) <= 1e-9 * scale
            swept = pendulum_sweep([acceleration], dt, [mu], radius)[0, 0]
            assert swept == pytest.approx([exact["scalars"][name] for name in SCALAR_NAMES], rel=1e-12, abs=1e-15)


def test_phi_functions_are_the_integrals_of_the_cosine():
    """Against S_j = Σ_m (−ω²)^m·τ^(2m+j)/(2m+j)! summed in exact rational arithmetic, for ωτ from 0 to 50."""
    for w2 in (0.0, 1e-20, 9.81, 1e4):
        for tau in (0.0, 1e-3, 0.02, 0.5):
            values = phi_functions(w2, tau)
            for j in range(7):
                term = Fraction(tau) ** j / math.factorial(j)
                total = term
                m = 0
                while term != 0 and abs(term) > Fraction(1, 10 ** 40) * abs(total):
                    m += 1
                    term *= -Fraction(w2) * Fraction(tau) ** 2 / ((2 * m + j - 1) * (2 * m + j))
                    total += term
                assert values[j] == pytest.approx(float(total), rel=1e-12, abs=1e-300)


def test_a_bad_radius_is_one_clear_error():
    with pytest.raises(StickslipError, match=r"radius of the sliding surface \[m\] \(--radius\) must be positive"):
        pendulum_history(np.zeros(3), 0.01, 0.1, -1.0)
    with pytest.raises(StickslipError, match=r"\(--radius\) must be a number"):
        integrated_history(np.zeros(3), 0.01, FrictionLaw.coulomb(0.1), "big")
    with pytest.raises(StickslipError, match=r"--radius: expected one radius or 2"):
        pendulum_sweep([np.zeros(3)], 0.01, [0.1, 0.2], [1.0, 2.0, 3.0])
