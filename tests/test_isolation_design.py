"""The friction pendulum's equivalent-lateral-force design: each code's equation at the fixed point, the hand
calculation of docs/isolation_design.md, the torsion factor, the checks, and the command."""

from __future__ import annotations

import json
import math

import pytest

from stickslip.codes.damping import aashto_damping_coefficient, eurocode_damping_correction
from stickslip.codes.friction_pendulum import Plan, aashto, asce7_22, design, design_bound, en1998_2
from stickslip.codes.target_spectra import AashtoThreePoint, AsceTwoPeriod, Eurocode8, MultiPeriodTable
from stickslip.errors import StickslipError

G, RADIUS, MU = 9.81, 2.0, 0.06
ASCE = asce7_22(AsceTwoPeriod(1.5, 1.0, 8.0))


def test_the_asce_nominal_design_is_the_hand_calculation():
    """docs/isolation_design.md: D_M = 0.4979 m, T_M = 2.547 s, β_M = 0.1236, B_M = 1.271, V_b/W = 0.3090."""
    answer = design_bound(ASCE, RADIUS, MU, G)
    assert answer.design_displacement == pytest.approx(0.49794, abs=5e-5)
    assert answer.effective_period == pytest.approx(2.5467, abs=5e-4)
    assert answer.effective_damping == pytest.approx(0.12363, abs=5e-5)
    assert answer.damping_factor == pytest.approx(1.2709, abs=5e-4)
    assert answer.base_shear_coefficient == pytest.approx(0.30897, abs=5e-5)


@pytest.mark.parametrize("factor", [1.0, 1.8, 0.6])
def test_the_asce_fixed_point_satisfies_eq_17_5_1(factor):
    """D_M = g S_M1 T_M/(4π² B_M) with T_M = 2π sqrt(W/(K_M g)), K_M = W/R + μW/D_M, β_M = (2/π) μ/(μ + D_M/R),
    B_M by Table 17.5-1 (linear between 10 % 1.2, 20 % 1.5, 30 % 1.7)."""
    answer = design_bound(ASCE, RADIUS, MU, G, property_factor=factor)
    mu, d = MU * factor, answer.design_displacement
    period = 2 * math.pi * math.sqrt(1.0 / ((1 / RADIUS + mu / d) * G))
    beta = 2 / math.pi * mu / (mu + d / RADIUS)
    table = [(0.05, 1.0), (0.10, 1.2), (0.20, 1.5), (0.30, 1.7)]
    (b0, c0), (b1, c1) = next((low, high) for low, high in zip(table, table[1:]) if low[0] <= beta <= high[0])
    coefficient = c0 + (c1 - c0) * (beta - b0) / (b1 - b0)
    assert d == pytest.approx(G * 1.0 * period / (4 * math.pi**2 * coefficient), rel=1e-9)
    assert answer.effective_period == pytest.approx(period, rel=1e-12)
    assert answer.effective_stiffness == pytest.approx(1 / RADIUS + mu / d, rel=1e-12)


def test_the_aashto_fixed_point_satisfies_eq_7_1_4():
    """d = 9.79 S_D1 T_eff/B_L in inches, g S_D1 T_eff/(4π² B_L) in metres; B_L = (β/0.05)^0.3."""
    answer = design_bound(aashto(AashtoThreePoint(0.4, 1.0, 0.6)), RADIUS, MU, G)
    coefficient = aashto_damping_coefficient(answer.effective_damping)
    assert answer.damping_factor == pytest.approx((answer.effective_damping / 0.05) ** 0.3, rel=1e-12)
    assert answer.design_displacement == pytest.approx(
        G * 0.6 * answer.effective_period / (4 * math.pi**2 * coefficient), rel=1e-9)


def test_the_eurocode_fixed_point_satisfies_table_7_1():
    """T_C <= T_eff <= T_D: d_cd = (0.625/π²) a_g S η_eff T_C T_eff, η_eff = sqrt(0.10/(0.05 + ξ_eff))."""
    spectrum = Eurocode8.of_ground(0.4, "B")
    answer = design_bound(en1998_2(spectrum), 1.0, MU, G)
    assert spectrum.tc <= answer.effective_period <= spectrum.td
    eta = eurocode_damping_correction(answer.effective_damping)
    assert answer.damping_factor == eta
    assert answer.design_displacement == pytest.approx(
        0.625 / math.pi**2 * 0.4 * G * 1.2 * eta * 0.5 * answer.effective_period, rel=1e-9)


def test_the_bounds_scale_friction_by_lambda():
    answers = design(ASCE, RADIUS, MU, G, lambda_max=1.5, lambda_min=0.7)
    assert [answers[b].friction for b in ("nominal", "upper_bound", "lower_bound")] == pytest.approx([0.06, 0.09, 0.042])
    assert answers["upper_bound"].design_displacement < answers["nominal"].design_displacement \
        < answers["lower_bound"].design_displacement


def test_asces_torsion_divides_by_p_t_squared_and_has_a_floor():
    """Eq. 17.5-3: 1 + (y/P_T²)(12 e/(b² + d²)); e = 1 + 0.05·40 = 3 m, y = 20 m, b² + d² = 2500 m²."""
    plan = Plan(30.0, 40.0, 20.0, eccentricity=1.0, period_ratio=1.2)
    answer = design_bound(ASCE, RADIUS, MU, G, plan=plan)
    factor = 1 + 20.0 / 1.2**2 * 12 * 3.0 / 2500.0
    assert answer.total_displacement == pytest.approx(answer.design_displacement * factor, rel=1e-12)
    added = 1 + 20.0 * 12 * 3.0 / (1.2**2 + 2500.0)  # an open ASCE 7-16 script's P_T² added to b² + d²
    assert abs(factor - added) > 0.05
    small = design_bound(ASCE, RADIUS, MU, G, plan=Plan(30.0, 40.0, 1.0))
    assert small.total_displacement == pytest.approx(1.15 * small.design_displacement, rel=1e-12)


def test_the_eurocode_torsion_factor_has_no_period_ratio():
    plan = Plan(30.0, 40.0, 20.0, eccentricity=1.0, period_ratio=1.2)
    answer = design_bound(en1998_2(Eurocode8.of_ground(0.4, "B")), RADIUS, MU, G, plan=plan)
    assert answer.total_displacement == pytest.approx(answer.design_displacement * (1 + 20.0 * 12 * 3.0 / 2500.0))
    assert design_bound(aashto(AashtoThreePoint(0.4, 1.0, 0.6)), RADIUS, MU, G, plan=plan).total_displacement is None


def test_asces_superstructure_shear_has_the_sliders_exponent_and_the_activation_floor():
    """Eq. 17.5-7 with 1 − 3.5 β_M (abrupt pre-slip to post-slip), over R_I (Eq. 17.5-8); not below V_st of the
    activation force, max(λ_max, 1.5) μ W (§17.5.4.3)."""
    answer = design_bound(ASCE, RADIUS, MU, G, weight_ratio=0.8, response_modification=2.0)
    exponent = 1 - 3.5 * answer.effective_damping
    assert answer.superstructure_shear_exponent == pytest.approx(exponent, rel=1e-12)
    assert answer.superstructure_shear_coefficient == pytest.approx(
        answer.base_shear_coefficient * 0.8**exponent / 2.0, rel=1e-12)
    weak = design_bound(asce7_22(AsceTwoPeriod(0.3, 0.1, 8.0)), RADIUS, 0.1, G, weight_ratio=0.8,
                        response_modification=2.0, lambda_max=1.3)
    assert weak.base_shear_coefficient / 2.0 < 0.15
    assert weak.superstructure_shear_coefficient == pytest.approx(
        0.15 * 0.8 ** (1 - 3.5 * weak.effective_damping), rel=1e-12)
    upper = design_bound(asce7_22(AsceTwoPeriod(0.3, 0.1, 8.0)), RADIUS, 0.1, G, response_modification=2.0)
    assert upper.superstructure_shear_coefficient == pytest.approx(0.18, rel=1e-12)


def test_a_flat_pendulum_fails_the_restoring_checks():
    """R = 12 m under S_M1 = 0.3 g: D/(2R) < 0.025 (ASCE); 2π sqrt(R/g) = 6.95 s >= 6 s (AASHTO)."""
    spectrum = AsceTwoPeriod(0.5, 0.3, 8.0)
    asce = design_bound(asce7_22(spectrum), 12.0, 0.05, G)
    assert not asce.checks["restoring_force"]["passed"]
    assert asce.checks["restoring_force"]["value"] == pytest.approx(asce.design_displacement / 24.0)
    bridge = design_bound(aashto(AashtoThreePoint(0.2, 0.5, 0.3)), 12.0, 0.05, G)
    assert bridge.checks["restoring_period"]["value"] == pytest.approx(2 * math.pi * math.sqrt(12.0 / G))
    assert not bridge.checks["restoring_period"]["passed"]


def test_an_iteration_that_does_not_settle_says_so():
    with pytest.raises(StickslipError, match=r"ASCE 7-22 Ch. 17, R = 2 m, mu = 0.06: the iteration in D has no fixed "
                                             r"point: not settled after 3 steps"):
        design_bound(ASCE, RADIUS, MU, G, max_iterations=3)


def test_the_command_gives_three_codes_three_bounds_in_json(run_cli):
    code, out, err = run_cli("isolation", "design", "--sms", "1.5", "--sm1", "1.0", "--tl", "8", "--radius", "2",
                             "--mu", "0.06", "--lambda-max", "1.8", "--lambda-min", "0.6", "--json")
    assert code == 0, err
    document = json.loads(out)
    for key in ("asce7_22", "aashto", "en1998_2"):
        for bound in ("nominal", "upper_bound", "lower_bound"):
            answer = document[key][bound]
            assert {"design_displacement", "effective_period", "effective_damping", "damping_factor",
                    "base_shear_coefficient", "checks"} <= set(answer)
    assert document["asce7_22"]["nominal"]["design_displacement"] == pytest.approx(0.49794, abs=5e-5)
    assert document["asce7_22"]["upper_bound"]["friction"] == pytest.approx(0.108)
    assert document["units"]["design_displacement"] == "m" and document["units"]["effective_period"] == "s"
    assert document["aashto"]["spectrum_source"] == "derived from ASCE's S_MS and S_M1"


def test_the_derived_spectra_are_the_asce_spectrum_at_5_percent():
    """A_s = 0.4 S_MS, S_DS = S_MS, S_D1 = S_M1; EN a_g S = S_MS/2.5, T_C = S_M1/S_MS, T_B = T_C/5, T_D = T_L."""
    import argparse

    from stickslip.cli.isolation import procedures_from_args

    args = argparse.Namespace(sms=1.5, sm1=1.0, tl=8.0, asce_table=None, a_s=None, sds=None, sd1=None, ag=None,
                              ground=None, spectrum_type=1, soil_factor=None, tb=None, tc=None, td=None)
    procedures, _ = procedures_from_args(args)
    periods = [0.0, 0.1, 0.5, 1.0, 3.0, 9.0]
    asce = procedures[0].spectrum(periods)
    assert procedures[2].spectrum(periods) == pytest.approx(asce, rel=1e-12)
    assert procedures[1].spectrum(periods[:5]) == pytest.approx(asce[:5], rel=1e-12)


def test_the_command_prints_a_table(run_cli):
    code, out, _ = run_cli("isolation", "design", "--sms", "1.5", "--sm1", "1.0", "--tl", "8", "--radius", "2",
                           "--mu", "0.06")
    assert code == 0
    row = next(line for line in out.splitlines() if line.startswith("D [m]"))
    assert row.split()[2:] == ["0.4979", "0.3493", "0.6291"]


@pytest.mark.parametrize("options, message", [
    (("--sms", "1.5", "--radius", "2", "--mu", "0.06"),
     "the ASCE 7-22 spectrum needs --sms, --sm1 and --tl (or a multi-period table, --asce-table)"),
    (("--sms", "1.5", "--sm1", "1", "--tl", "8", "--radius", "2", "--mu", "0.06", "--sds", "1"),
     "AASHTO's spectrum needs all three of --as, --sds and --sd1 (or none: derived from ASCE's)"),
    (("--sms", "1.5", "--sm1", "1", "--tl", "8", "--radius", "-2", "--mu", "0.06"),
     "--radius -2: expected a positive number"),
    (("--sms", "1.5", "--sm1", "1", "--tl", "8", "--radius", "2", "--mu", "0.06", "--lambda-max", "0.9"),
     "lambda_min 0.6 and lambda_max 0.9: expected lambda_min <= 1 <= lambda_max"),
    (("--sms", "1.5", "--sm1", "1", "--tl", "8", "--radius", "2", "--mu", "0.06", "--offset", "3"),
     "--offset applies with --plan B D (the plan dimensions)"),
])
def test_the_command_refuses_bad_input_in_one_line(run_cli, options, message):
    code, _, err = run_cli("isolation", "design", *options)
    assert code == 2
    assert err.strip() == f"stickslip: error: {message}"


def test_a_flat_slider_with_a_recentring_device_is_designed_as_the_pendulum_of_its_period(run_cli):
    """k_r = W/R: T_R = 2π sqrt(R/g), so T_R = 2π sqrt(2/9.81) s gives the R = 2 m pendulum's design."""
    period = 2 * math.pi * math.sqrt(2.0 / 9.81)
    code, out, _ = run_cli("isolation", "design", "--sms", "1.5", "--sm1", "1.0", "--tl", "8", "--recentring-period",
                           repr(period), "--mu", "0.06", "--json")
    assert code == 0
    document = json.loads(out)
    assert document["isolator"] == "flat slider with a re-centring device"
    assert document["radius"] == pytest.approx(2.0, rel=1e-12) and document["units"]["recentring_period"] == "s"
    assert document["asce7_22"]["nominal"]["design_displacement"] == pytest.approx(
        design_bound(ASCE, RADIUS, MU, G).design_displacement, rel=1e-9)


def test_the_codes_own_spectra_are_taken_when_given(run_cli, tmp_path):
    """--as/--sds/--sd1 for AASHTO, --ag/--ground and the user's corner periods for EN, a multi-period table for
    ASCE; each design as its procedure gives it on that spectrum."""
    table = tmp_path / "mcer.csv"
    table.write_text("period [s],S_a [g]\n0.0,0.6\n0.2,1.5\n0.6667,1.5\n1.0,1.0\n2.0,0.5\n3.0,0.33333\n")
    code, out, err = run_cli("isolation", "design", "--asce-table", table, "--sms", "1.5", "--sm1", "1.0", "--radius",
                             "2", "--mu", "0.06", "--as", "0.4", "--sds", "1.0", "--sd1", "0.6", "--ag", "0.4",
                             "--ground", "B", "--td", "3", "--json")
    assert code == 0, err
    document = json.loads(out)
    bridge = design_bound(aashto(AashtoThreePoint(0.4, 1.0, 0.6)), RADIUS, MU, G)
    assert document["aashto"]["nominal"]["design_displacement"] == pytest.approx(bridge.design_displacement, rel=1e-12)
    euro = design_bound(en1998_2(Eurocode8(0.4, 1.2, 0.15, 0.5, 3.0)), RADIUS, MU, G)
    assert document["en1998_2"]["nominal"]["design_displacement"] == pytest.approx(euro.design_displacement, rel=1e-12)
    assert document["en1998_2"]["spectrum"] == "EN 1998-1 elastic spectrum (type 1, ground type B, with the user's td 3)"
    building = design_bound(asce7_22(MultiPeriodTable.from_csv(table)), RADIUS, MU, G)
    assert document["asce7_22"]["nominal"]["design_displacement"] == pytest.approx(building.design_displacement,
                                                                                  rel=1e-12)
    # between 2 and 3 s the table is linear, above S_M1/T: D is 6 % above the two-period spectrum's 0.4979 m
    assert document["asce7_22"]["nominal"]["design_displacement"] == pytest.approx(0.5286, abs=5e-5)


def test_the_hand_calculations_of_aashto_and_en_on_the_derived_spectra(run_cli):
    code, out, _ = run_cli("isolation", "design", "--sms", "1.5", "--sm1", "1.0", "--tl", "8", "--radius", "2",
                           "--mu", "0.06", "--json")
    document = json.loads(out)
    assert document["aashto"]["nominal"]["design_displacement"] == pytest.approx(0.47447, abs=5e-5)
    assert document["aashto"]["nominal"]["damping_factor"] == pytest.approx(1.3274, abs=5e-4)
    assert document["en1998_2"]["nominal"]["design_displacement"] == pytest.approx(0.46944, abs=5e-5)
    assert document["en1998_2"]["nominal"]["damping_factor"] == pytest.approx(0.74616, abs=5e-5)


def test_a_long_period_transition_below_t_s_cannot_give_en_its_t_d(run_cli):
    code, _, err = run_cli("isolation", "design", "--sms", "1.0", "--sm1", "1.5", "--tl", "1.2", "--radius", "2",
                           "--mu", "0.06")
    assert code == 2
    assert err.strip() == "stickslip: error: --tl 1.2: EN's T_D = T_L must exceed T_C = S_M1/S_MS = 1.5 s; give --ag"
