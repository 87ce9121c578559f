"""The flexible block's energy ledger (exact scheme): it closes, it agrees with quadrature, it ignores the sampling."""

from __future__ import annotations

import json

import numpy as np
import pytest
from scipy.integrate import cumulative_trapezoid, trapezoid

from stickslip.records.process import resample
from stickslip.models.layer import solve_flexible
from stickslip.models.layer.layer import Layer
from stickslip.models.yield_table import YieldTable

G = 9.80665


LAYERS = {
    "thick linear": Layer(50.0, 400.0, 800.0, 0.05),
    "thin linear": Layer(5.0, 200.0, 600.0, 0.05),  # T = 0.1 s, ten samples a period
    "equivalent-linear": Layer(30.0, 250.0, 600.0, 0.03, "equivalent-linear", 0.05),
}


@pytest.mark.parametrize("layer", LAYERS.values(), ids=LAYERS.keys())
@pytest.mark.parametrize("model", ["decoupled", "coupled"])
def test_the_ledger_closes_to_round_off(two_tone_record, model, layer):
    result = solve_flexible(two_tone_record, 0.1, layer, model, g=G)
    ledger = result.ledger
    scale = max(np.abs(ledger.energy_input).max(), np.abs(ledger.kinetic_energy).max())
    assert result.displacement > 0 and ledger.energy_dissipated[-1] == pytest.approx(0.1 * G * result.displacement)
    assert ledger.energy_damped[-1] > 0 and np.all(np.diff(ledger.energy_damped) >= 0)
    assert set(ledger.residuals()) == ({"system"} if model == "coupled" else {"layer", "block"})
    assert ledger.balance_residual < 1e-12 * scale
    assert result.scalars()["balance_residual_per_mass"] == ledger.balance_residual


@pytest.mark.parametrize("model", ["decoupled", "coupled"])
def test_the_ledger_does_not_depend_on_the_sampling(two_tone_record, model):
    """Resampling the record linearly to dt/7 changes no energy at the end of the record."""
    layer = LAYERS["equivalent-linear"]
    coarse = solve_flexible(two_tone_record, 0.1, layer, model, g=G).scalars()
    fine = solve_flexible(resample(two_tone_record, two_tone_record.dt / 7), 0.1, layer, model, g=G).scalars()
    for name in ("energy_input_per_mass", "energy_damped_per_mass", "energy_dissipated_per_mass"):
        assert fine[name] == pytest.approx(coarse[name], rel=1e-9), name


def test_the_layer_s_input_is_the_quadrature_of_its_average_acceleration_times_the_ground_velocity(two_tone_record):
    """E_I of the decoupled layer is ∫k·g v_g dt: the trapezoid rule on the record resampled to dt/20 agrees to 1e-4."""
    fine = resample(two_tone_record, two_tone_record.dt / 20)
    result = solve_flexible(fine, 0.1, LAYERS["thick linear"], "decoupled", g=G)
    ground_velocity = cumulative_trapezoid(fine.acceleration, dx=fine.dt, initial=0.0)
    quadrature = trapezoid(result.average_acceleration * ground_velocity, dx=fine.dt)
    assert result.ledger.energy_input[-1] == pytest.approx(quadrature, rel=1e-4)


def test_a_block_that_never_slides_leaves_the_coupled_ledger_the_layer_s(two_tone_record):
    """Above the layer's peak, the coupled block sticks and its ledger is the decoupled layer's, with no friction."""
    layer = LAYERS["thick linear"]
    coupled = solve_flexible(two_tone_record, 3.0, layer, "coupled", g=G).ledger
    decoupled = solve_flexible(two_tone_record, 3.0, layer, "decoupled", g=G).ledger
    assert not coupled.energy_dissipated.any()
    for name in ("energy_input", "kinetic_energy", "strain_energy", "energy_damped"):
        np.testing.assert_allclose(getattr(coupled, name), getattr(decoupled, name), rtol=0, atol=1e-13)


def test_the_slammer_scheme_keeps_no_ledger_and_says_so(two_tone_record, tmp_path, run_cli):
    result = solve_flexible(two_tone_record, 0.1, LAYERS["thick linear"], "coupled", "slammer", g=G)
    assert result.ledger is None and "energy_input_per_mass" not in result.scalars()
    # the friction's work needs no ledger: k_y g D, or ∫ k_y(D) g dD for a table (0.3 to 0.1 over 2 cm, then 0.1)
    assert result.scalars()["energy_dissipated_per_mass"] == pytest.approx(0.1 * G * result.displacement)
    table = solve_flexible(two_tone_record, YieldTable((0.0, 0.02), (0.3, 0.1)), LAYERS["thick linear"], "coupled",
                           "slammer", g=G)
    assert table.displacement > 0.02
    assert table.scalars()["energy_dissipated_per_mass"] == pytest.approx(
        G * (0.5 * (0.3 + 0.1) * 0.02 + 0.1 * (table.displacement - 0.02)))
    path = tmp_path / "wave.txt"
    path.write_text("\n".join(f"{a / G:.10f}" for a in two_tone_record.acceleration) + "\n", encoding="ascii")
    layer = ["--model", "coupled", "--height", "50", "--vs", "400", "--vs-base", "800", "--damping", "0.05"]
    common = ("solve", path, "--dt", "0.01", "--units", "g", "--g", str(G), "--ky", "0.1", *layer)
    code, stdout, stderr = run_cli(*common, "--method", "slammer")
    assert code == 0 and "no energy ledger: method slammer keeps none (method exact does)" in stdout, stderr
    code, stdout, stderr = run_cli(*common, "--json")
    document = json.loads(stdout)
    assert code == 0 and document["units"]["energy_dissipated_per_mass"] == "J kg-1"
    assert document["energy_dissipated_per_mass"] == pytest.approx(0.1 * G * document["displacement"])
