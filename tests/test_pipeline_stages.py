"""The library side of the workflow's stages: stored missing records, per-record sweeps, gathering, dependencies."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from stickslip.plumbing.dependencies import imported_modules, library_sources
from stickslip.errors import RecordNotFoundError
from stickslip.records.netcdf import read_record_netcdf, record_status, write_missing_record, write_record
from stickslip.records.record import Record, RecordMeta
from stickslip.solvers.harmonic import harmonic_record
from stickslip.studies.measures.record_measures import read_record_measures, write_record_measures
from stickslip.grids import grid_values
from stickslip.studies.sweeps import gather_grid, sweep_record
from stickslip.models import sweep
from stickslip.sweeps import available, missing_records, read_cube, scaled_measures, write_cube



@pytest.fixture
def stored(tmp_path):
    """A stored harmonic record with its measures, and a stored missing record with its measures."""
    motion = harmonic_record(0.03, 2.0, 4.0, 0.005, 0.0)
    record = Record(motion.acceleration, motion.dt, RecordMeta(record_id="harmonic", event="test"))
    paths = {"harmonic": write_record(record, tmp_path / "harmonic.nc", {"mw": 6.5}),
             "gone": write_missing_record("gone", "record gone not found. How to obtain it: ask", tmp_path / "gone.nc",
                                          {"event": "Nowhere"})}
    for record_id, path in paths.items():
        write_record_measures(path, tmp_path / f"{record_id}.json", 9.81)
    return tmp_path


def test_a_missing_record_is_stored_with_its_reason(stored):
    assert record_status(stored / "harmonic.nc") == "ok"
    assert record_status(stored / "gone.nc") == "missing: record gone not found. How to obtain it: ask"
    with pytest.raises(RecordNotFoundError, match="How to obtain it: ask"):
        read_record_netcdf(stored / "gone.nc")
    document = read_record_measures(stored / "gone.json")
    assert document == {"record": "gone", "event": "Nowhere", "status": record_status(stored / "gone.nc")}


def test_measures_documents_hold_values_and_units(stored):
    document = read_record_measures(stored / "harmonic.json")
    assert document["status"] == "ok" and document["mw"] == 6.5
    # sine of amplitude A = u_g0 (2 pi f)^2: PGA = A
    assert document["measures"]["pga"] == pytest.approx(0.03 * (2 * np.pi * 2.0) ** 2, rel=1e-3)
    assert document["units"]["pga"] == "m s-2"


def test_sweeps_reuse_the_stored_measures_and_scale_them(stored):
    measures = read_record_measures(stored / "harmonic.json")["measures"]
    record = read_record_netcdf(stored / "harmonic.nc")
    cube = sweep([record], mu=[0.1, 0.2], target_pga=[5.0], measures=[measures])
    computed = sweep([record], mu=[0.1, 0.2], target_pga=[5.0])
    for name in ("pga", "rms_acceleration", "arias_intensity", "significant_duration"):
        np.testing.assert_allclose(cube[name].values, computed[name].values, rtol=1e-9)
    assert scaled_measures({"pga": 2.0, "arias_intensity": 3.0, "t5": 1.0}, 2.0) == {
        "pga": 4.0, "arias_intensity": 12.0, "t5": 1.0}


def test_a_gathered_grid_keeps_missing_records_in_order(stored):
    grid = {"mu": {"start": 0.05, "stop": 0.3, "step": 0.05}, "refine": True}
    paths = []
    for record_id in ("gone", "harmonic"):
        cube = sweep_record(stored / f"{record_id}.nc", stored / f"{record_id}.json", grid, 5.1, 9.81)
        paths.append(write_cube(cube, stored / f"sweep_{record_id}.nc"))
    gathered = read_cube(gather_grid(paths, stored / "gathered.nc"))
    assert gathered.record.values.tolist() == ["gone", "harmonic"]
    assert missing_records(gathered) == {"gone": "missing: record gone not found. How to obtain it: ask"}
    assert np.isnan(gathered.energy_dissipated.sel(record="gone")).all()
    assert int(gathered.n_slip_episodes.sel(record="gone")[0]) == -1
    ok = available(gathered)
    assert ok.record.values.tolist() == ["harmonic"]
    np.testing.assert_allclose(ok.mu.values, grid_values(grid["mu"]))
    assert ok.energy_dissipated_max_continuous.item() >= float(ok.energy_dissipated.max())


def test_ids_of_different_lengths_survive_gathering(stored):
    short = sweep_record(stored / "gone.nc", stored / "gone.json", {"mu": [0.1, 0.2]}, 5.1, 9.81)
    paths = [write_cube(short, stored / "a.nc")]
    long_motion = read_record_netcdf(stored / "harmonic.nc")
    long_record = Record(long_motion.acceleration, long_motion.dt, RecordMeta(record_id="a_much_longer_record_id"))
    paths.append(write_cube(sweep([long_record], mu=[0.1, 0.2]), stored / "b.nc"))
    assert read_cube(gather_grid(paths, stored / "g.nc")).record.values.tolist() == ["gone", "a_much_longer_record_id"]


def _names(paths):
    from stickslip.plumbing.dependencies import SOURCE_ROOT

    return {Path(path).relative_to(SOURCE_ROOT).as_posix() for path in paths}


def test_dependencies_follow_imports_inside_functions_and_module_names():
    code = "def f():\n    from stickslip.models.rigid.exact import sweep_scalars\nSOLVERS = {'a': 'stickslip.models.rigid.newmark'}\n"
    assert {"stickslip.models.rigid.exact", "stickslip.models.rigid.newmark"} <= imported_modules(code)
    assert imported_modules("import numpy\nx = 'not.a.module'\n") == set()


def test_the_plots_are_a_dependency_of_the_reports_only():
    sweeps = _names(library_sources(["stickslip.studies.sweeps:write_record_sweep"]))
    assert "stickslip/models/rigid/exact.py" in sweeps and "stickslip/reports/plots.py" not in sweeps
    comparisons = _names(library_sources(["stickslip.studies.measures.records_table"]))
    assert "stickslip/models/rigid/exact.py" not in comparisons
    notebook = _names(library_sources(files=[Path(__file__).parents[1] / "notebooks" / "paper_figures.ipynb"]))
    assert "stickslip/reports/plots.py" in notebook


def test_the_dependencies_of_many_steps_parse_each_source_text_once(monkeypatch):
    import ast

    parsed = []
    parse = ast.parse
    monkeypatch.setattr(ast, "parse", lambda code, *args, **kwargs: parsed.append(code) or parse(code, *args, **kwargs))
    sweeps = library_sources(["stickslip.studies.sweeps:write_record_sweep"])
    parsed.clear()  # every file the sweeps import has been read by now
    assert library_sources(["stickslip.studies.sweeps:write_record_sweep"]) == sweeps and parsed == []
    mu_max = library_sources(["stickslip.studies.mu_max"])  # overlaps the sweeps: only its other files are parsed
    assert 0 < len(parsed) <= len(set(mu_max) - set(sweeps))
    edited = "import stickslip.models.rigid.exact\n"
    assert imported_modules(edited + "import stickslip.reports.plots\n") == {"stickslip.models.rigid.exact",
                                                                              "stickslip.reports.plots"}
    assert imported_modules(edited) == {"stickslip.models.rigid.exact"}  # a changed text is parsed afresh


def test_measures_files_are_json_with_finite_numbers(stored):
    text = (stored / "harmonic.json").read_text(encoding="utf-8")
    assert "NaN" not in text and "Infinity" not in text
    assert json.loads(text)["record"] == "harmonic"
