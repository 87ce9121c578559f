"""Single solved cases (Figs. 2, 3, 11-12, 16), our model beside the paper's Tables 3 and 4, and the flexible ledgers."""

from __future__ import annotations

import csv

import pytest
import xarray as xr

from stickslip.reports import model_plots, plots
from stickslip.records.netcdf import write_missing_record, write_record
from stickslip.solvers.harmonic import PERMANENT_SLIP_THRESHOLD, harmonic_record, normalized_friction
from stickslip.studies.model_response.flexible_ledger import write_flexible_ledgers
from stickslip.studies.model_response.cases import CASES, friction_for, write_model_responses
from stickslip.studies.model_response.shaking_table import model_rows, write_shaking_table_comparison

SETTINGS = {
    "mu": 0.10,
    "harmonic": {"displacement_amplitude": 0.030, "frequency": 2.0, "duration": 2.0, "dt": 0.002},
    "seismic": {"record": "kobe_kjm090", "scale": 0.65},
    "fig2": {"displacement_amplitude": 0.030, "frequency": 2.0, "duration": 2.0, "dt": 0.001,
             "normalized_friction": [0.75, 0.42]},
    "fig3": {"record": "stand_in", "mu": 0.10, "time_step": 0.003, "reason": "a test"},
}


def _rows(path):
    with open(path, newline="") as handle:
        return {row["case"]: row for row in csv.DictReader(handle)}


@pytest.fixture(scope="module")
def solved(tmp_path_factory):
    """The cases with a harmonic stand-in for Fig. 3's record and a missing seismic record."""
    folder = tmp_path_factory.mktemp("model")
    fig3 = write_record(harmonic_record(0.02, 1.5, 4.0, 0.003), folder / "stand_in.nc")
    seismic = write_missing_record("kobe_kjm090", "record kobe_kjm090 not found. How to obtain it: ask",
                                   folder / "kobe_kjm090.nc")
    write_model_responses(fig3, seismic, folder / "model", folder / "model_responses.csv", SETTINGS, 5.10, 9.81)
    return folder


def test_friction_for_inverts_eq3():
    mu = friction_for(0.42, 0.030, 2.0, 9.81)
    assert normalized_friction(mu, 0.030, 2.0, 9.81) == pytest.approx(0.42)


def test_fig2_cases_show_the_regime_eq4_predicts(solved):
    rows = _rows(solved / "model_responses.csv")
    assert list(rows) == list(CASES)
    for case, regime in (("fig2_stick_slip", "stick_slip"), ("fig2_permanent_slip", "permanent_slip")):
        assert rows[case]["closed_form_regime"] == rows[case]["observed_regime"] == regime
    assert float(rows["fig2_permanent_slip"]["normalized_friction"]) < PERMANENT_SLIP_THRESHOLD
    # the block's absolute acceleration never exceeds the slip limit μ·g
    dataset = xr.load_dataset(solved / "model" / "fig2_permanent_slip.nc")
    limit = dataset.attrs["mu"] * dataset.attrs["g"]
    assert abs(dataset.absolute_acceleration).max() <= limit * (1 + 1e-9)


def test_algorithm1_at_its_step_is_close_to_the_exact_solution(solved):
    rows = _rows(solved / "model_responses.csv")
    assert rows["fig3_algorithm1"]["method"] == "newmark" and float(rows["fig3_algorithm1"]["time_step"]) == 0.003
    exact, newmark = float(rows["fig3_exact"]["energy_dissipated"]), float(rows["fig3_algorithm1"]["energy_dissipated"])
    assert newmark == pytest.approx(exact, rel=0.05)


def test_a_missing_record_gives_missing_rows_and_not_comparable_cells(solved, tmp_path):
    rows = _rows(solved / "model_responses.csv")
    assert rows["seismic_model"]["status"].startswith("missing: record kobe_kjm090 not found")
    assert xr.load_dataset(solved / "model" / "seismic_model.nc").attrs["status"].startswith("missing")
    table = model_rows(rows)
    assert {row["status"][:8] for row in table if row["row"] in ("Kobe", "Mendoza")} == {"missing:"}
    harmonic = [row for row in table if row["row"] == "Harmonic"]
    assert len(harmonic) == 2 and all(row["status"] == "ok" for row in harmonic)
    assert harmonic[0]["ours"] == pytest.approx(abs(float(rows["harmonic_model"]["residual_displacement"])))
    paths = write_shaking_table_comparison(solved / "model_responses.csv", tmp_path / "model.csv",
                                           tmp_path / "t3.csv", tmp_path / "t4.csv", {"default": 0.05})
    with open(paths[2], newline="") as handle:
        table4 = list(csv.DictReader(handle))
    assert len(table4) == 8 and all(row["status"].startswith("missing") for row in table4)  # Mendoza and Kobe rows


def test_the_figures_draw_from_the_stored_cases(solved, tmp_path):
    def load(case):
        return xr.load_dataset(solved / "model" / f"{case}.nc")

    figures = {
        "fig2": model_plots.plot_harmonic_regimes(load("fig2_stick_slip"), load("fig2_permanent_slip"),
                                                  PERMANENT_SLIP_THRESHOLD),
        "fig3": model_plots.plot_algorithm1(load("fig3_algorithm1"), load("fig3_exact"), "a test"),
        "fig16": model_plots.plot_friction_response(load("harmonic_model"), "harmonic"),
        "energy": model_plots.plot_energy_histories(load("harmonic_model"), "harmonic"),
    }
    for name, figure in figures.items():
        path = plots.save_figure(figure, tmp_path / f"{name}.png")
        assert path.stat().st_size > 8_000, name
        xlabels = [ax.get_xlabel() for ax in figure.axes if ax.get_xlabel()]  # shared axes label the bottom one
        assert xlabels and all(label.endswith("]") for label in xlabels), name
        for ax in figure.axes:
            assert ax.get_ylabel().endswith("]"), (name, ax.get_ylabel())
            assert ax.get_legend() is None  # legends sit below the axes, never over the data


FLEXIBLE = {"seismic": {"record": "stand_in", "scale": 0.65},
            "flexible": {"ky": 0.10, "height": 20.0, "vs": 300.0, "vs_base": 760.0, "damping": 0.05}}


def test_the_flexible_ledgers_are_stored_and_drawn(two_tone_record, tmp_path):
    record = write_record(two_tone_record, tmp_path / "stand_in.nc")
    paths = write_flexible_ledgers(record, tmp_path / "decoupled.nc", tmp_path / "coupled.nc", FLEXIBLE, 9.81)
    decoupled, coupled = (xr.load_dataset(path) for path in paths)
    for dataset, model in ((decoupled, "decoupled"), (coupled, "coupled")):
        assert dataset.attrs["status"] == "ok" and dataset.attrs["model"] == model and dataset.attrs["scale"] == 0.65
        assert float(dataset.displacement) > 0 and dataset.energy_input_per_mass.attrs["units"] == "J kg-1"
        assert float(dataset.balance_residual_per_mass) < 1e-12 * float(abs(dataset.energy_input_per_mass).max())
    assert "block_energy_input_per_mass" in decoupled and "block_energy_input_per_mass" not in coupled
    figure = model_plots.plot_flexible_ledger(decoupled, coupled, "stand-in")
    assert plots.save_figure(figure, tmp_path / "ledger.png").stat().st_size > 8_000
    assert all(ax.get_xlabel() == "time [s]" and ax.get_legend() is None for ax in figure.axes)
    assert figure.axes[0].get_ylabel() == "energy per unit mass [J/kg]"
    assert len(figure.legends[0].get_texts()) == 5  # E_I, E_I,block, E_df, E_d, E_k + E_s


def test_a_missing_record_leaves_the_flexible_ledgers_saying_so(tmp_path):
    record = write_missing_record("stand_in", "record stand_in not found. How to obtain it: ask", tmp_path / "s.nc")
    paths = write_flexible_ledgers(record, tmp_path / "decoupled.nc", tmp_path / "coupled.nc", FLEXIBLE, 9.81)
    for path in paths:
        assert xr.load_dataset(path).attrs["status"].startswith("missing: record stand_in not found")
