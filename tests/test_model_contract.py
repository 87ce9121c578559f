"""A model is its declaration: a toy model with its own objective, the smallest stroke, registered here, goes through
``solve``, ``sweep``, ``optimum`` (the command line, in-process), ``report`` (whose notebook finds it as an installed
package's model) and the workflow's sweep with no line of the command line, the reports or the design answer
naming it."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from stickslip.errors import StickslipError
from stickslip.models import MODELS, Scheme, solve
from stickslip.models.parameters import GRAVITY, MASS, MU
from stickslip.models.result import Result
from stickslip.models.swept import SweptModel
from stickslip.objectives import DISPLACEMENT, ENERGY
from stickslip.records.netcdf import write_record
from stickslip.records.record import Record, RecordMeta
from stickslip.studies.measures.record_measures import write_record_measures
from stickslip.studies.sweeps import sweep_record

G = 9.81
#: The toy record's amplitude [g]: the toy's stroke is smallest at mu = half of it.
AMPLITUDE = 0.3
BEST_MU = 0.5 * AMPLITUDE

#: The toy's end results: name -> (units, long name).
SCALARS = {"energy_dissipated": ("J", "energy dissipated (toy)"),
           "peak_relative_displacement": ("m", "stroke (toy)"),
           "residual_displacement": ("m", "displacement at the end (toy)"),
           "n_slip_episodes": ("1", "samples where the base outruns friction (toy)")}


def toy_scalars(acceleration: np.ndarray, dt: float, mu: float, mass: float, g: float) -> dict[str, float]:
    """The toy's end results: E_df = m mu g sum(max(|a| - mu g, 0)) dt^2 [J] (largest inside the grid), the stroke
    (mu - PGA/(2g))^2 + 0.01 [m] (smallest at mu = PGA/(2g)) and half of it back as the residual [m]."""
    excess = np.maximum(np.abs(acceleration) - mu * g, 0.0)
    stroke = (mu - 0.5 * np.max(np.abs(acceleration)) / g) ** 2 + 0.01
    return {"energy_dissipated": mass * mu * g * float(np.sum(excess)) * dt * dt,
            "peak_relative_displacement": stroke, "residual_displacement": -0.5 * stroke,
            "n_slip_episodes": int(np.count_nonzero(excess))}


@dataclass(frozen=True)
class ToyCase:
    mu: float
    mass: float
    g: float
    inverse = False

    def at(self, coefficient: str, value: float) -> ToyCase:
        return ToyCase(float(value), self.mass, self.g)

    def solved(self, acceleration):
        return acceleration

    def slides(self, motion) -> bool:
        return bool(np.any(np.abs(motion.acceleration) > self.mu * self.g))

    def still_reason(self, motion, where=None) -> str:
        return f"the PGA is at most mu*g at {where or f'mu = {self.mu:g}'}"

    def describe_sliding(self) -> str:
        return "a toy"

    def settings(self) -> dict:
        return {"mass": self.mass, "g": self.g}

    def settings_units(self) -> dict:
        return {"mass": "kg", "g": "m s-2"}


@dataclass(frozen=True)
class ToyResult(Result):
    block: ToyCase
    values: dict
    model = "toy"
    method = "exact"

    def scalars(self) -> dict:
        return dict(self.values)

    def scalar_units(self) -> dict:
        return {name: units for name, (units, _) in SCALARS.items()}

    def describe(self) -> str:
        return f"a toy block, mu = {self.block.mu:g}, mass = {self.block.mass:g} kg"

    def case(self) -> dict:
        return {"model": self.model, "method": self.method, "mu": self.block.mu, **self.block.settings()}

    def case_units(self) -> dict:
        return {"mu": "1", **self.block.settings_units()}

    def to_xarray(self):
        """The end results, and the stroke reached at the start and left at the end as the toy's history."""
        time = np.array([0.0, 1.0])
        stroke = self.values["peak_relative_displacement"]
        dataset = xr.Dataset({"relative_displacement": ("time", [stroke, self.values["residual_displacement"]],
                                                        {"units": "m"})}, coords={"time": ("time", time, {"units": "s"})})
        for name, value in self.values.items():
            dataset[name] = ((), value, {"units": SCALARS[name][0]})
        return dataset.assign_attrs(self.case())


class ToyScheme(Scheme):
    name = "exact"
    summary = "the toy's closed form"

    def solve(self, motion, case: ToyCase) -> ToyResult:
        return ToyResult(case, toy_scalars(motion.acceleration, motion.dt, case.mu, case.mass, case.g))


class ToyModel(SweptModel):
    name = "toy"
    summary = "a toy block whose stroke is smallest at half the PGA"
    parameters = (MU, MASS, GRAVITY)
    schemes = (ToyScheme(),)
    result = ToyResult
    objectives = (DISPLACEMENT.name, ENERGY.name)

    def case(self, parameters) -> ToyCase:
        if parameters["mu"] is None:
            raise StickslipError("the toy model needs a friction ratio mu=")
        return ToyCase(parameters["mu"], parameters["mass"], parameters["g"])

    def variables(self, case) -> dict:
        return {name: {"units": units, "long_name": long_name} for name, (units, long_name) in SCALARS.items()}

    def cube_attrs(self, case, scheme, run_options) -> dict:
        return {"block_mass": case.mass, "block_mass_units": "kg", "gravity": case.g, "gravity_units": "m s-2"}

    def parameters_of(self, cube):
        return cube.attrs["solver"], {}, {"mass": float(cube.attrs["block_mass"]), "g": float(cube.attrs["gravity"])}


@pytest.fixture
def toy(monkeypatch):
    """The toy registered beside the real models, for this test only."""
    list(MODELS)  # the real ones first
    monkeypatch.setattr(MODELS, "_entries", dict(MODELS._entries))
    MODELS.register(ToyModel())
    return MODELS["toy"]


@pytest.fixture
def record() -> Record:
    time = np.arange(0.0, 4.0, 0.01)
    acceleration = AMPLITUDE * G * np.sin(2.0 * np.pi * 1.5 * time)
    return Record(acceleration, 0.01, RecordMeta(record_id="wave", source="wave.txt"))


@pytest.fixture
def record_file(tmp_path, record):
    path = tmp_path / "wave.txt"
    path.write_text("\n".join(f"{index * record.dt:.2f} {value / G:.9f}" for index, value in
                              enumerate(record.acceleration)) + "\n", encoding="ascii")
    return path


def test_the_toy_solves_through_the_one_route(toy, record):
    result = solve(record, model="toy", mu=BEST_MU)
    assert result.scalars()["peak_relative_displacement"] == pytest.approx(0.01, rel=1e-9)


def test_solve_and_sweep_on_the_command_line(toy, record_file, run_cli, tmp_path):
    code, out, err = run_cli("solve", record_file, "--model", "toy", "--mu", "0.1", "--units", "g", "--json")
    assert code == 0, err
    assert json.loads(out)["peak_relative_displacement"] == pytest.approx(0.05 ** 2 + 0.01, rel=1e-6)
    cube_path = tmp_path / "toy.nc"
    code, out, err = run_cli("sweep", record_file, "--model", "toy", "--mu", "0.05:0.25:0.05", "--units", "g",
                             "--out", cube_path)
    assert code == 0, err
    with xr.open_dataset(cube_path) as cube:
        assert cube.attrs["model"] == "toy"
        np.testing.assert_allclose(cube.peak_relative_displacement.values[0],
                                   (np.array([0.05, 0.1, 0.15, 0.2, 0.25]) - BEST_MU) ** 2 + 0.01, rtol=1e-6)


def test_optimum_answers_the_model_s_own_objective(toy, record_file, run_cli, tmp_path):
    cube_path = tmp_path / "optimum.nc"
    code, out, err = run_cli("optimum", record_file, "--model", "toy", "--mu", "0.01:0.3:0.01", "--units", "g",
                             "--json", "--out", cube_path)
    assert code == 0, err
    document = json.loads(out)
    assert document["settings"]["objective"] == "displacement"
    row = document["records"][0]
    assert row["mu_max"] == pytest.approx(BEST_MU)
    assert row["mu_max_continuous"] == pytest.approx(BEST_MU, abs=1e-5)
    assert row["peak_relative_displacement_at_mu_max"] == pytest.approx(0.01, rel=1e-6)
    # near-optimal: stroke <= 0.01 / 0.95, so |mu - 0.15| <= sqrt(0.01 / 0.95 - 0.01) = 0.0229; its five values of
    # the grid given are refined to steps of 0.002 (--range-points 10), which place its ends at 0.128 and 0.172
    assert (row["mu_low"], row["mu_high"], row["grid_values_in_range"]) == (pytest.approx(0.128), pytest.approx(0.172),
                                                                             23)
    with xr.open_dataset(cube_path) as cube:
        assert cube.attrs["objective"] == "displacement"
        assert float(cube.mu_max_continuous.item()) == pytest.approx(row["mu_max_continuous"], rel=1e-12)
        assert cube.mu_max.attrs["long_name"] == "friction ratio of the smallest stroke, on the grid"
    code, out, err = run_cli("optimum", record_file, "--model", "toy", "--mu", "0.01:0.3:0.01", "--units", "g")
    assert code == 0, err
    assert "objective: the smallest stroke; mu_max is the mu of the smallest stroke" in out


def test_the_user_may_name_another_objective_the_model_declares(toy, record_file, run_cli):
    code, out, err = run_cli("optimum", record_file, "--model", "toy", "--mu", "0.01:0.3:0.01", "--units", "g",
                             "--objective", "energy", "--json")
    assert code == 0, err
    document = json.loads(out)
    row = document["records"][0]
    assert document["settings"]["objective"] == "energy"
    assert row["energy_dissipated_max"] == max(toy_scalars(_read(record_file), 0.01, mu, 1.0, G)["energy_dissipated"]
                                               for mu in np.round(np.arange(1, 31) * 0.01, 12)) != 0.0
    assert row["mu_max"] != pytest.approx(BEST_MU)


def test_an_objective_the_model_does_not_declare_is_one_line(record_file, run_cli):
    code, out, err = run_cli("optimum", record_file, "--mu", "0.01:0.3:0.01", "--units", "g",
                             "--objective", "displacement")
    assert (code, out) == (2, "")
    assert err.strip() == ("stickslip: error: --objective displacement: the rigid model's optimum is energy (the "
                           "most energy dissipated by friction E_df (the paper's)), not the smallest stroke (peak |x|, "
                           "x the block's displacement relative to the base)")


def test_the_workflow_s_sweep_takes_the_model_and_its_objective(toy, record, tmp_path):
    record_path, measures_path = tmp_path / "wave.nc", tmp_path / "wave.json"
    write_record(record, record_path)
    write_record_measures(record_path, measures_path, G)
    grid = {"mu": {"start": 0.01, "stop": 0.3, "step": 0.01}, "refine": True, "near_optimal_fraction": 0.95,
            "model": "toy"}
    cube = sweep_record(record_path, measures_path, grid, 1.0, G, name="toy")
    assert cube.attrs["model"] == "toy" and cube.attrs["objective"] == "displacement"
    assert float(cube.mu_max.item()) == pytest.approx(BEST_MU)
    assert float(cube.mu_max_continuous.item()) == pytest.approx(BEST_MU, abs=1e-5)


def _read(path) -> np.ndarray:
    """The toy record's acceleration [m/s²] as the command line read it (9 decimals of g)."""
    return np.array([float(line.split()[1]) for line in path.read_text().splitlines()]) * G


def test_an_installed_package_s_model_is_reported(record_file, tmp_path, monkeypatch):
    """The report's notebook runs in its own process: the toy reaches it as another package's model would, through
    an entry point of ``stickslip.models``, and its page answers the toy's objective."""
    package = tmp_path / "site"
    (package / "toy_contract-0.dist-info").mkdir(parents=True)
    (package / "toy_contract-0.dist-info" / "METADATA").write_text("Metadata-Version: 2.1\nName: toy-contract\n"
                                                                   "Version: 0\n", encoding="utf-8")
    (package / "toy_contract-0.dist-info" / "entry_points.txt").write_text(
        "[stickslip.models]\ntoy = toy_contract\n", encoding="utf-8")
    (package / "toy_contract.py").write_text("from stickslip.models.registry import register\n"
                                             "from test_model_contract import ToyModel\n\n"
                                             "TOY = register(ToyModel())\n", encoding="utf-8")
    paths = [str(package), str(Path(__file__).parent), *filter(None, [os.environ.get("PYTHONPATH")])]
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join(paths))
    out = tmp_path / "toy.html"
    result = subprocess.run([sys.executable, "-m", "stickslip", "report", str(record_file), "--model", "toy",
                             "--units", "g", "--mu", "0.01:0.3:0.01", "--out", str(out)], capture_output=True,
                            text=True, env={**os.environ, "MPLBACKEND": "Agg"}, timeout=600)
    assert result.returncode == 0, result.stderr[-3000:]
    page = out.read_text(encoding="utf-8")
    assert "the toy model, a toy, block mass m = 1 kg" in page
    assert "Response at μ = 0.15 (the record's μ_max, continuous)" in page
