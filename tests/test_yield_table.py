"""A yield coefficient that varies with displacement (SLAMMER's "varies with displacement" table).

A table of one pair is the constant k_y, a table constant in k_y gives the
constant answer, a rectangular pulse that carries the block across a
breakpoint follows kinematics derived here, and ``stickslip solve
--ky-table`` takes a file or inline pairs and refuses bad tables in one line.
The exact schemes do not take a table (they refuse it naming the slammer
scheme), so the slammer scheme's convergence is measured against the derived
answer.  SLAMMER's verification results (the shared verification folder) hold no
analysis with a displacement-varying k_y, and pySLAMMER 0.2.3's table input
fails its own ``ky <= 0`` check, so neither gives a number to reproduce.
"""

from __future__ import annotations

import json
import math
from importlib.resources import files

import numpy as np
import pytest
from conftest import assert_one_error_line

from stickslip import Layer, YieldTable, read_record, solve, solve_flexible
from stickslip.errors import StickslipError
from stickslip.records.record import Record
from stickslip.models.rigid.resistance import Resistance

G = 9.80665
RECORD = files("pyslammer") / "sample_ground_motions" / "Cape_Mendocino_1992_PET-090.csv"
LAYER = Layer(20.0, 300.0, 600.0)

#: The pulse of the derived case: A = 0.5 g over (0, 0.5 s], then nothing until 3 s.
PULSE_ACCELERATION, PULSE_DURATION, RECORD_DURATION = 0.5 * G, 0.5, 3.0

#: k_y falls linearly from 0.3 at D = 0 to 0.1 at D = 2 cm and stays there.
SOFTENING = YieldTable((0.0, 0.02), (0.3, 0.1))


@pytest.fixture(scope="module")
def record() -> Record:
    return read_record(RECORD)


def pulse(dt: float) -> Record:
    """The rectangular pulse sampled at ``dt`` [s]: A at the samples in (0, 0.5 s], zero elsewhere."""
    acceleration = np.zeros(int(round(RECORD_DURATION / dt)) + 1)
    acceleration[1:int(round(PULSE_DURATION / dt)) + 1] = PULSE_ACCELERATION
    return Record(acceleration, dt)


def pulse_displacement() -> float:
    """The block's permanent downslope displacement D [m] under the pulse with :data:`SOFTENING`, derived.

    While D < D₁ = 2 cm, k_y = k₀ + m·D with m = (k₁ − k₀)/D₁ < 0, so
    D̈ = A − g·k_y(D) reads D̈ − λ²D = c with λ² = −g·m and c = A − g·k₀ > 0;
    from rest, D = (c/λ²)(cosh λt − 1), reaching D₁ at t₁ = arccosh(1 + λ²D₁/c)/λ
    with speed v₁ = (c/λ)·sinh λt₁.  Then k_y = k₁: D̈ = A − g·k₁ until the
    pulse ends (τ = T − t₁ later, speed v₂), and D̈ = −g·k₁ until the block
    stops, v₂²/(2g·k₁) further.
    """
    (k0, k1), d1 = SOFTENING.ky, SOFTENING.displacement[1]
    lam = math.sqrt(-G * (k1 - k0) / d1)
    c = PULSE_ACCELERATION - G * k0
    t1 = math.acosh(1.0 + lam * lam * d1 / c) / lam
    v1 = c / lam * math.sinh(lam * t1)
    tau = PULSE_DURATION - t1
    driving = PULSE_ACCELERATION - G * k1
    v2 = v1 + driving * tau
    return d1 + v1 * tau + 0.5 * driving * tau * tau + v2 * v2 / (2.0 * G * k1)


def rigid_pulse_displacement(dt: float) -> float:
    """The slammer scheme's D [m] on the pulse (zero samples integrated: SLAMMER would freeze after the pulse)."""
    response = solve(pulse(dt), ky=SOFTENING, method="slammer", g=G, skip_zero_samples=False)
    return response.scalars()["downslope_displacement"]


# ---------------------------------------------------------------- (a), (b): the constant k_y


@pytest.mark.parametrize("method", ["exact", "slammer"])
def test_a_table_of_one_pair_is_the_constant_ky(record, method):
    table = solve(record, ky=YieldTable((0.0,), (0.1,)), method=method, g=G)
    constant = solve(record, ky=0.1, method=method, g=G)
    assert table.scalars() == constant.scalars()
    assert table.scalars()["downslope_displacement"] > 0.01


@pytest.mark.parametrize("model", ["decoupled", "coupled"])
@pytest.mark.parametrize("method", ["exact", "slammer"])
def test_a_flexible_table_of_one_pair_is_the_constant_ky(record, model, method):
    table = solve_flexible(record, YieldTable((0.0,), (0.1,)), LAYER, model, method, g=G)
    constant = solve_flexible(record, 0.1, LAYER, model, method, g=G)
    assert table.scalars() == constant.scalars() and table.ky == 0.1
    np.testing.assert_array_equal(table.block_displacement, constant.block_displacement)


#: k_y = 0.1 at three breakpoints, the last beyond any displacement of the record.
FLAT_TABLE = YieldTable((0.0, 0.01, 0.05, 10.0), (0.1, 0.1, 0.1, 0.1))


def test_a_table_constant_in_ky_gives_the_constant_answer(record):
    table = solve(record, ky=FLAT_TABLE, method="slammer", g=G)
    constant = solve(record, ky=0.1, method="slammer", g=G)
    np.testing.assert_array_equal(table.relative_displacement, constant.relative_displacement)
    assert table.scalars()["downslope_displacement"] > FLAT_TABLE.displacement[2]  # it crossed breakpoints
    # E_df integrates the table piece by piece: equal to round-off, not bit for bit
    assert table.scalars()["energy_dissipated"] == pytest.approx(constant.scalars()["energy_dissipated"], rel=1e-12)


@pytest.mark.parametrize("model", ["decoupled", "coupled"])
def test_a_flexible_table_constant_in_ky_gives_the_constant_answer(record, model):
    table = solve_flexible(record, FLAT_TABLE, LAYER, model, "slammer", g=G)
    constant = solve_flexible(record, 0.1, LAYER, model, "slammer", g=G)
    np.testing.assert_array_equal(table.block_displacement, constant.block_displacement)
    assert table.displacement > FLAT_TABLE.displacement[2]


def test_a_falling_ky_slides_further(record):
    """k_y falling past 5 cm gives more displacement than its first value, less than its last."""
    falling = YieldTable((0.0, 0.05, 0.1), (0.1, 0.1, 0.05))
    displacements = [solve(record, ky=ky, method="slammer", g=G).scalars()["downslope_displacement"]
                     for ky in (0.1, falling, 0.05)]
    assert displacements[0] < displacements[1] < displacements[2]


def test_python_and_compiled_steps_agree_on_a_table(record, monkeypatch):
    from stickslip.models.rigid import slammer

    resistance = Resistance.one_way(YieldTable((0.0, 0.05, 0.1), (0.1, 0.1, 0.05)), G)
    as_python = slammer.sliding_history(record.acceleration, record.dt, resistance)
    monkeypatch.setattr(slammer, "PYTHON_SAMPLES", record.npts - 1)
    as_compiled = slammer.sliding_history(record.acceleration, record.dt, resistance)
    assert as_python.relative_displacement[-1] < -0.1  # past the last breakpoint
    for name in ("relative_displacement", "relative_velocity", "energy_dissipated"):
        np.testing.assert_array_equal(getattr(as_python, name), getattr(as_compiled, name))


# ---------------------------------------------------------------- (c), (d): a breakpoint crossed, derived


def test_the_rigid_block_crosses_a_breakpoint_as_derived():
    expected = pulse_displacement()
    assert expected == pytest.approx(2.0304, abs=1e-4)  # the derivation's number, for the record
    assert rigid_pulse_displacement(1e-4) == pytest.approx(expected, rel=3e-4)


def test_the_slammer_scheme_converges_to_the_derived_answer_at_first_order():
    """The threshold follows the displacement one sample late: the error halves with dt."""
    expected = pulse_displacement()
    errors = [abs(rigid_pulse_displacement(dt) - expected) for dt in (2e-3, 1e-3, 5e-4, 2.5e-4)]
    ratios = [coarse / fine for coarse, fine in zip(errors, errors[1:])]
    assert all(1.8 < ratio < 2.2 for ratio in ratios), ratios
    assert errors[-1] / expected < 1e-3


@pytest.mark.parametrize("model", ["decoupled", "coupled"])
def test_a_stiff_layer_crosses_a_breakpoint_as_the_rigid_block(model):
    """A layer of period 4 ms (16 samples of 0.25 ms) slides as the rigid block: within 0.3 % of the derived D."""
    result = solve_flexible(pulse(2.5e-4), SOFTENING, Layer(1.0, 1000.0, 1000.0), model, "slammer", g=G)
    assert result.displacement == pytest.approx(pulse_displacement(), rel=3e-3)


# ---------------------------------------------------------------- the table itself


@pytest.mark.parametrize(
    ("displacement", "ky", "phrase"),
    [
        ((), (), "needs at least one pair"),
        ((0.0, 0.1), (0.2,), "2 displacements but 1 values of k_y"),
        ((0.01, 0.1), (0.2, 0.1), "the first displacement must be 0 m"),
        ((0.0, 0.1, 0.05), (0.2, 0.1, 0.1), "displacements must increase strictly: pair 3 has 0.05 m after 0.1 m"),
        ((0.0, 0.1, 0.1), (0.2, 0.1, 0.1), "pair 3 has 0.1 m after 0.1 m"),
        ((0.0, 0.1), (0.2, 0.0), "pair 2: k_y must be positive, got 0"),
        ((0.0, 0.1), (0.2, -0.1), "pair 2: k_y must be positive, got -0.1"),
        ((0.0, math.inf), (0.2, 0.1), "pair 2 (inf m, 0.1) is not finite"),
        ((0.0, 0.1), (0.2, math.nan), "is not finite"),
        ((0.0, "a"), (0.2, 0.1), "must be numbers"),
    ],
)
def test_bad_tables_are_refused_in_one_line(displacement, ky, phrase):
    with pytest.raises(StickslipError, match="^yield table: ") as error:
        YieldTable(displacement, ky)
    assert phrase in str(error.value) and "\n" not in str(error.value)


def test_ky_is_linear_between_pairs_and_constant_past_the_last():
    table = YieldTable((0.0, 0.1, 0.3), (0.2, 0.1, 0.15))
    np.testing.assert_allclose(table.at([0.0, 0.05, 0.1, 0.2, 0.3, 5.0]), [0.2, 0.15, 0.1, 0.125, 0.15, 0.15])
    assert table.thresholds(10.0) == ((0.0, 0.1, 0.3), (2.0, 1.0, 1.5))
    assert YieldTable.parse("0:0.2, 0.1:0.1,0.3:0.15") == table


def test_the_exact_schemes_refuse_a_table_naming_the_slammer_scheme(record):
    with pytest.raises(StickslipError, match="exact .* solves a constant yield coefficient, not ky.D. = 0:0.3, "
                                             "0.02:0.1 .*; use method slammer$"):
        solve(record, ky=SOFTENING)
    with pytest.raises(StickslipError, match="method exact solves a constant yield coefficient.*use method slammer$"):
        solve_flexible(record, SOFTENING, LAYER, "coupled", "exact")
    with pytest.raises(StickslipError, match="applies to one-way .downslope. sliding, not to direction 'both'"):
        solve(record, ky=SOFTENING, method="slammer", direction="both")


def test_the_results_record_the_table(record):
    attrs = solve(record, ky=SOFTENING, method="slammer", g=G).to_xarray().attrs
    assert list(attrs["ky"]) == [0.3, 0.1] and list(attrs["ky_displacement"]) == [0.0, 0.02]
    flexible = solve_flexible(record, SOFTENING, LAYER, "decoupled", "slammer", g=G).to_xarray().attrs
    assert list(flexible["ky"]) == [0.3, 0.1] and list(flexible["ky_displacement"]) == [0.0, 0.02]


# ---------------------------------------------------------------- (f) the command line


def solved_json(run_cli, *args) -> dict:
    code, out, err = run_cli("solve", RECORD, "--json", *args)
    assert code == 0, err
    return json.loads(out)


def test_cli_reads_a_file_or_inline_pairs(run_cli, record, tmp_path):
    path = tmp_path / "ky.txt"
    path.write_text("# D [m]  ky\n0     0.15\n\n0.05, 0.10   # softened\n0.20  0.08\n")
    from_file = solved_json(run_cli, "--ky-table", path, "--method", "slammer")
    inline = solved_json(run_cli, "--ky-table", "0:0.15,0.05:0.10,0.2:0.08", "--method", "slammer")
    expected = solve(record, ky=YieldTable((0.0, 0.05, 0.2), (0.15, 0.1, 0.08)), method="slammer")
    assert from_file == inline
    assert from_file["downslope_displacement"] == expected.scalars()["downslope_displacement"] > 0.0
    assert from_file["ky"] == [0.15, 0.1, 0.08] and from_file["ky_displacement"] == [0.0, 0.05, 0.2]
    assert from_file["units"]["ky_displacement"] == "m"


def test_cli_one_pair_is_the_constant_ky(run_cli):
    assert solved_json(run_cli, "--ky-table", "0:0.15") == solved_json(run_cli, "--ky", "0.15")


@pytest.mark.parametrize("model", ["decoupled", "coupled"])
def test_cli_flexible_models_take_a_table(run_cli, record, model):
    printed = solved_json(run_cli, "--ky-table", "0:0.1,0.02:0.05", "--model", model, "--height", "20", "--vs", "300",
                          "--vs-base", "600", "--method", "slammer")
    expected = solve_flexible(record, YieldTable((0.0, 0.02), (0.1, 0.05)), LAYER, model, "slammer")
    assert printed["displacement"] == expected.displacement > 0.0
    assert printed["ky"] == [0.1, 0.05] and printed["units"]["ky_displacement"] == "m"


def test_cli_help_names_the_units(capsys):
    from stickslip.cli import main

    with pytest.raises(SystemExit):
        main(["solve", "--help"])
    help_text = " ".join(capsys.readouterr().out.split())
    assert "--ky-table TABLE" in help_text and "(D [m], k_y [-];" in help_text and "D in m, not cm" in help_text


@pytest.mark.parametrize(
    ("lines", "phrase"),
    [
        ("0 0.15\n0.1 abc\n", "line 2: '0.1:abc' is not two numbers"),
        ("0 0.15\n0.1\n", "line 2: expected two numbers, displacement D [m] and k_y"),
        ("0 0.15\n0.1 0.1\n0.05 0.1\n", "displacements must increase strictly: pair 3 has 0.05 m after 0.1 m"),
        ("0 0.15\n0.1 0\n", "pair 2: k_y must be positive, got 0"),
        ("0.1 0.15\n", "the first displacement must be 0 m"),
        ("# nothing\n", "no pairs of displacement D [m] and k_y"),
    ],
)
def test_cli_bad_table_files_are_one_line_errors(run_cli, tmp_path, lines, phrase):
    path = tmp_path / "ky.txt"
    path.write_text(lines)
    code, out, err = run_cli("solve", RECORD, "--ky-table", path, "--method", "slammer")
    assert_one_error_line(code, out, err, path, phrase)


@pytest.mark.parametrize(
    ("args", "name", "phrase"),
    [
        (("--ky-table", "absent.txt"), "absent.txt", "file not found"),
        (("--ky-table", "0:0.15,0.1"), "--ky-table '0:0.15,0.1'", "pair 2 '0.1' is not D:KY"),
        (("--ky-table", "0:0.15,0.1:-1"), "--ky-table", "pair 2: k_y must be positive, got -1"),
        (("--ky-table", "0:0.15,0.1:0.1"), "exact", "use method slammer"),
        (("--ky-table", "0:0.15,0.1:0.1", "--method", "slammer", "--direction", "both"), "yield table",
         "applies to one-way (downslope) sliding"),
    ],
)
def test_cli_bad_tables_are_one_line_errors(run_cli, args, name, phrase):
    code, out, err = run_cli("solve", RECORD, *args)
    assert_one_error_line(code, out, err, name, phrase)
