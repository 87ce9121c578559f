"""The codes' elastic spectra and damping factors, against their equations evaluated by hand."""

from __future__ import annotations

import math

import numpy as np
import pytest

from stickslip.codes.damping import aashto_damping_coefficient, asce_damping_coefficient, eurocode_damping_correction
from stickslip.codes.target_spectra import AashtoThreePoint, AsceTwoPeriod, Eurocode8, MultiPeriodTable
from stickslip.errors import StickslipError


@pytest.mark.parametrize("damping, coefficient", [(0.0, 0.8), (0.02, 0.8), (0.05, 1.0), (0.15, 1.35), (0.25, 1.6),
                                                  (0.45, 1.95), (0.7, 2.0)])
def test_asce_b_m_is_table_17_5_1_interpolated(damping, coefficient):
    assert asce_damping_coefficient(damping) == pytest.approx(coefficient, rel=1e-12)


@pytest.mark.parametrize("damping, coefficient", [(0.05, 1.0), (0.10, 2**0.3), (0.20, 4**0.3), (0.40, 1.7)])
def test_aashto_b_l_is_a_power_law_bounded_at_1_7(damping, coefficient):
    assert aashto_damping_coefficient(damping) == pytest.approx(coefficient, rel=1e-12)


@pytest.mark.parametrize("damping, eta", [(0.05, 1.0), (0.10, math.sqrt(10 / 15)), (0.28, math.sqrt(10 / 33)),
                                          (0.40, 0.55)])
def test_eurocode_eta_is_eq_3_6_bounded_at_0_55(damping, eta):
    assert eurocode_damping_correction(damping) == pytest.approx(eta, rel=1e-12)


def test_the_asce_two_period_spectrum_has_its_four_branches():
    """S_MS 1.5, S_M1 1.0, T_L 8: T_S = 2/3 s, T_0 = 2/15 s."""
    spectrum = AsceTwoPeriod(1.5, 1.0, 8.0)
    values = spectrum([0.0, 1 / 15, 0.4, 2.0, 10.0])
    np.testing.assert_allclose(values, [0.6, 1.05, 1.5, 0.5, 1.0 * 8 / 100], rtol=1e-12)
    # 20 % damping: B_M 1.5 divides the branches from T_0 on; S_a(0) is the ground's
    np.testing.assert_allclose(spectrum([0.0, 0.4, 2.0], 0.20), [0.6, 1.0, 0.5 / 1.5], rtol=1e-12)


def test_the_aashto_spectrum_has_no_long_period_branch():
    spectrum = AashtoThreePoint(0.4, 1.0, 0.6)
    np.testing.assert_allclose(spectrum([0.0, 0.06, 0.3, 3.0, 12.0]), [0.4, 0.7, 1.0, 0.2, 0.05], rtol=1e-12)


def test_the_eurocode_type_1_spectrum_on_ground_c():
    """a_g 0.3 g, ground C (S 1.15, T_B 0.2, T_C 0.6, T_D 2.0): Eqs. 3.2-3.5 by hand, and η at 10 %."""
    spectrum = Eurocode8.of_ground(0.3, "c")
    peak = 0.3 * 1.15
    np.testing.assert_allclose(spectrum([0.0, 0.1, 0.4, 1.0, 3.0]),
                               [peak, peak * 1.75, 2.5 * peak, 2.5 * peak * 0.6, 2.5 * peak * 0.6 * 2.0 / 9.0],
                               rtol=1e-12)
    eta = math.sqrt(10 / 15)
    assert spectrum([1.0], 0.10)[0] == pytest.approx(2.5 * peak * eta * 0.6, rel=1e-12)
    assert Eurocode8.of_ground(0.3, "D", 2).tc == 0.30


def test_a_multi_period_table_is_read_from_csv_and_interpolated(tmp_path):
    path = tmp_path / "mcer.csv"
    path.write_text("period,sa\n0.0,0.6\n1.0,1.2\n2.0,0.6\n")
    spectrum = MultiPeriodTable.from_csv(path)
    np.testing.assert_allclose(spectrum([0.5, 1.5]), [0.9, 0.9], rtol=1e-12)
    assert spectrum([1.0], 0.20)[0] == pytest.approx(1.2 / 1.5, rel=1e-12)
    with pytest.raises(StickslipError, match=r"period outside the table's 0-2 s"):
        spectrum([3.0])


@pytest.mark.parametrize("text, message", [("period,sa\n1.0,0.5\n", "needs two or more rows"),
                                           ("0.0,0.6\n1.0,x\n", "line 2: expected two numbers"),
                                           ("1.0,0.6\n0.5,0.3\n", "strictly increasing")])
def test_bad_tables_are_refused_naming_the_file(tmp_path, text, message):
    path = tmp_path / "bad.csv"
    path.write_text(text)
    with pytest.raises(StickslipError, match=f"bad.csv.*{message}"):
        MultiPeriodTable.from_csv(path)


def test_unknown_eurocode_ground_types_are_refused():
    with pytest.raises(StickslipError, match="ground type 'S1': expected one of A, B, C, D, E"):
        Eurocode8.of_ground(0.3, "S1")
