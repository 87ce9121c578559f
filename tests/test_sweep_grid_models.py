"""The model each sweep grid of the workflow sweeps (``sweep_grids`` of the configuration): the schema knows the
registry's names, the sweep stage checks the model and its parameters in one line naming the key, a grid of
another model is swept by the workflow with it, and a bad one stops the workflow before any job."""

from __future__ import annotations

import importlib

import numpy as np
import pytest
import yaml
from conftest import CONFIG_SCHEMA, PROJECT_CONFIG, REPO_ROOT, snakemake

from stickslip.errors import StickslipError
from stickslip.models import MODELS
from stickslip.models.registry import MODEL_MODULES
from stickslip.plumbing.config import load_config
from stickslip.studies.sweeps import grid_model

TEST_CONFIG = REPO_ROOT / ".test" / "config" / "config.yaml"
PENDULUM = {"model": "pendulum", "parameters": {"radius": 2.0}}


def _with_grids(source, folder, sweep_grids):
    """The configuration file ``source`` with ``sweep_grids``, written in ``folder``."""
    settings = yaml.safe_load(source.read_text(encoding="utf-8"))
    settings["sweep_grids"] = sweep_grids
    path = folder / "config.yaml"
    path.write_text(yaml.safe_dump(settings), encoding="utf-8")
    return path


def test_the_schema_names_the_models_of_the_registry():
    schema = yaml.safe_load(CONFIG_SCHEMA.read_text(encoding="utf-8"))
    named = schema["$defs"]["sweep_model"]["properties"]["model"]["enum"]
    shipped = [name for name, entry in MODELS.items() if importlib.import_module(type(entry).__module__).__name__
               .startswith(MODEL_MODULES)]
    assert named == shipped


def test_the_default_config_sweeps_every_grid_with_the_rigid_block():
    config = load_config(PROJECT_CONFIG, CONFIG_SCHEMA)
    assert config["sweep_grids"] == {}
    assert grid_model({"mu": config["mu_grid"]}, "sweep_grids.paper").name == "rigid"


@pytest.mark.parametrize(("sweep_grids", "phrase"), [
    ({"fine": {"model": "no-such-model"}}, "at sweep_grids/fine/model: 'no-such-model' is not one of"),
    ({"finest": PENDULUM}, "sweep_grids: Additional properties are not allowed ('finest' was unexpected)"),
    ({"fine": {"model": "pendulum", "radius": 2.0}}, "at sweep_grids/fine: Additional properties are not allowed"),
    ({"fine": {"model": "pendulum", "parameters": {"radius": [1, 2]}}}, "at sweep_grids/fine/parameters/radius"),
])
def test_a_sweep_grid_that_breaks_the_schema_is_refused_in_one_line(tmp_path, sweep_grids, phrase):
    path = _with_grids(PROJECT_CONFIG, tmp_path, sweep_grids)
    with pytest.raises(StickslipError) as error:
        load_config(path, CONFIG_SCHEMA)
    assert str(path) in str(error.value) and phrase in str(error.value) and "\n" not in str(error.value)


@pytest.mark.parametrize(("grid", "phrase"), [
    ({"model": "coupled"}, "sweep_grids.fine: the coupled model sweeps no friction ratio mu of a block of a given "
                           "mass; a grid's model is one of rigid, pendulum, spring, isolated, friction-tmd"),
    ({"model": "planar"}, "sweep_grids.fine: the planar model takes the two horizontal components of one station"),
    ({"model": "pendulum", "parameters": {"period": 1.0}}, "the pendulum model does not take period; its "
                                                           "parameters: mu_fast, mu_slow, mu_slow_ratio, radius, rate"),
    ({"model": "pendulum", "parameters": {"mass": 2.0}}, "sweep_grids.fine.parameters: mass is the grid's own"),
    ({"model": "pendulum", "parameters": {"radius": -2.0}}, "sweep_grids.fine: radius of the sliding surface [m] "
                                                            "(--radius) must be positive"),
    ({"model": "isolated"}, "sweep_grids.fine: the isolated model needs a friction ratio mu= and the "
                            "superstructure's fixed-base period"),
])
def test_a_grid_s_model_that_cannot_sweep_it_is_one_line_naming_the_key(grid, phrase):
    with pytest.raises(StickslipError) as error:
        grid_model({"mu": [0.05, 0.1], **grid}, "sweep_grids.fine")
    assert phrase in str(error.value) and "\n" not in str(error.value)


def test_parameters_alone_choose_the_model_as_the_command_line_does():
    assert grid_model({"mu": [0.05, 0.1], "parameters": {"radius": 2.0}}, "sweep_grids.fine").name == "pendulum"


def test_the_workflow_sweeps_a_grid_with_its_model(tmp_path):
    import xarray as xr

    import stickslip
    from stickslip.records.netcdf import read_record_netcdf

    config = _with_grids(TEST_CONFIG, tmp_path, {"paper": PENDULUM})
    result = snakemake(tmp_path, config, "results/sweeps/paper/cape_mendocino.nc")
    assert result.returncode == 0, result.stderr[-3000:]
    settings = yaml.safe_load(config.read_text(encoding="utf-8"))
    with xr.open_dataset(tmp_path / "results" / "sweeps" / "paper" / "cape_mendocino.nc") as cube:
        assert cube.attrs["model"] == "pendulum" and cube.attrs["radius"] == 2.0
        record = read_record_netcdf(tmp_path / "results" / "records" / "cape_mendocino.nc")
        solved = stickslip.sweep([record], model="pendulum", mu=settings["mu_grid"], radius=2.0,
                                 mass=settings["block_mass"], g=settings["gravity"])
        np.testing.assert_allclose(cube.mu.values, settings["mu_grid"])
        for name in ("energy_dissipated", "peak_relative_displacement", "peak_base_shear"):
            np.testing.assert_allclose(cube[name].values, solved[name].values, rtol=1e-12, err_msg=name)
            assert cube[name].values.max() > 0.0


def test_a_grid_s_model_that_cannot_sweep_it_stops_the_workflow_before_any_job(tmp_path):
    config = _with_grids(TEST_CONFIG, tmp_path, {"fine": {"model": "pendulum", "parameters": {"period": 1.0}}})
    result = snakemake(tmp_path, config, "--dry-run")
    message = result.stdout + result.stderr
    assert result.returncode != 0
    assert "configuration: sweep_grids.fine: the pendulum model does not take period" in message
    assert not (tmp_path / "results").exists()
