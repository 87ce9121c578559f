"""The design answer per record (``stickslip.optimum``, ``stickslip optimum``): one definition of each quantity,
shared by the command, the sweep cubes, Tables 6-7 and the collection study; records too weak to slide."""

from __future__ import annotations

import csv
import json

import numpy as np
import pytest
import xarray as xr
import yaml

from conftest import REPO_ROOT
from stickslip.errors import StickslipError
from stickslip.analysis import mu_max_on_grid, mu_max_on_grid_edge, near_optimal_range
from stickslip.grids import Grid, grid_values
from stickslip.models.rigid import RIGID
from stickslip.collections.store import StoredRecord, write_record_store
from stickslip.optimum import (
    DEFAULT_MU,
    MIN_RANGE_POINTS,
    NEVER_SLIDES,
    NOT_SOLVED,
    RESULTS,
    STATUS,
    curves_of,
    optimum,
    range_sizes,
    refine_for_ranges,
    refine_mu_max,
    solve_curves,
)
from stickslip.reports.design_answer import shown
from stickslip.records.record import Record, RecordMeta
from stickslip.studies.collections.measures import write_chunk_measures
from stickslip.studies.collections.sweep import sweep_chunk
from stickslip.studies.mu_max import ranges_rows, results_rows
from stickslip.models import sweep, with_optimum
from stickslip.sweeps import write_cube

G = 9.81
MU = np.round(np.arange(0.02, 0.42, 0.02), 6)


def pulse(record_id: str, amplitude: float, seed: int = 1) -> Record:
    """A noisy pulse [m/s²] at dt = 0.01 s (6 s)."""
    rng = np.random.default_rng(seed)
    time = np.arange(600) * 0.01
    acceleration = amplitude * np.sin(2 * np.pi * 1.7 * time) * np.exp(-((time - 2.5) / 1.2) ** 2)
    acceleration += 0.05 * amplitude * rng.standard_normal(time.size)
    return Record(acceleration, 0.01, RecordMeta(record_id=record_id, event="Test 2024", station="S", component="E"))


@pytest.fixture(scope="module")
def records():
    """A record that slides, a stronger one, and one too weak to slide at any mu of MU (PGA about 0.01 g)."""
    return [pulse("strong", 4.0), pulse("stronger", 7.0, 2), pulse("weak", 0.1, 3)]


@pytest.fixture(scope="module")
def cube(records):
    return with_optimum(sweep(records, mu=MU, mass=5.1), records, q=0.9, reference=0.1)


def test_the_cube_holds_every_result_with_units_and_the_definitions(cube):
    for name, (units, _) in RESULTS.items():
        assert cube[name].dims == ("record",) and cube[name].attrs["units"] == units
    assert cube.attrs["near_optimal_fraction"] == 0.9 and cube.attrs["near_optimal_fraction_units"] == "1"
    assert cube.attrs["reference_mu"] == 0.1 and cube.attrs["reference_mu_units"] == "1"
    strong = cube.sel(record="strong")
    energy = strong.energy_dissipated
    assert float(strong.mu_max) == float(mu_max_on_grid(energy)) and float(strong.energy_dissipated_max) == float(energy.max())
    low, high, contiguous = near_optimal_range(energy, q=0.9)
    assert (float(strong.mu_low), float(strong.mu_high), float(strong.contiguous)) == (float(low), float(high), float(contiguous))
    assert float(strong.mu_max_at_grid_edge) == float(mu_max_on_grid_edge(energy))
    for at in ("mu_max", "mu_low", "mu_high"):
        mu = float(strong[at])
        assert float(strong[f"peak_relative_displacement_at_{at}"]) == float(strong.peak_relative_displacement.sel(mu=mu))
        assert float(strong[f"residual_displacement_at_{at}"]) == float(strong.residual_displacement.sel(mu=mu))
    found = refine_mu_max(pulse("strong", 4.0), RIGID.design(Grid("mu", MU), mass=5.1), energy.values)
    assert float(strong.mu_max_continuous) == found.argument and float(strong.energy_dissipated_max_continuous) == found.value
    assert float(strong.efficiency) == pytest.approx(float(energy.sel(mu=0.1)) / found.value, rel=1e-12)
    assert [str(status) for status in cube[STATUS].values[:2]] == ["ok", "ok"]


def test_a_record_too_weak_to_slide_has_no_optimum_and_says_why(cube, records):
    weak = cube.sel(record="weak")
    status = str(weak[STATUS].values)
    pga = float(np.max(np.abs(records[2].acceleration)))
    assert status.startswith(f"{NEVER_SLIDES}: ") and f"PGA {pga:.4g} m/s2" in status
    assert f"mu*g = {MU[0] * G:.4g} m/s2 at the grid's smallest mu, {MU[0]:g}" in status
    for name in ("mu_max", "mu_max_continuous", "mu_low", "mu_high", "contiguous", "mu_max_at_grid_edge",
                 "efficiency", "peak_relative_displacement_at_mu_max", "residual_displacement_at_mu_high"):
        assert np.isnan(float(weak[name])), name  # never the grid's first mu
    assert float(weak.energy_dissipated_max) == 0.0 == float(weak.energy_dissipated_reference)


def test_a_mu_max_on_the_grid_edge_is_flagged(records):
    coarse = with_optimum(sweep(records[:1], mu=[0.01, 0.02, 0.03]), records[:1])
    assert coarse.mu_max.item() == 0.03 and coarse.mu_max_at_grid_edge.item() == 1.0


def test_the_results_without_a_cube_are_the_cubes(cube, records):
    design = RIGID.design(Grid("mu", MU), mass=5.1, g=G)
    results, statuses = optimum(records, solve_curves(records, design), design, q=0.9, reference=0.1)
    for name in RESULTS:
        np.testing.assert_array_equal(results[name], cube[name].values, err_msg=name)
    assert statuses == [str(status) for status in cube[STATUS].values]


def test_scaled_versions_each_get_their_results(records):
    scaled = with_optimum(sweep(records[:2], mu=MU, target_pga=[3.0, 6.0]), records[:2])
    assert scaled.mu_max.dims == ("record", "target_pga") and scaled[STATUS].dims == ("record", "target_pga")
    # the same record scaled to twice the PGA: mu_max doubles (an exact property of Eq. 1)
    assert float(scaled.mu_max_continuous.sel(record="strong", target_pga=6.0)) == pytest.approx(
        2 * float(scaled.mu_max_continuous.sel(record="strong", target_pga=3.0)), rel=1e-4)


def test_the_design_answer_is_the_cube_s_own_model_s(records):
    cube = sweep(records[:1], mu=[0.05, 0.1], mass=5.1)
    answered = with_optimum(cube, records[:1], q=0.9)
    assert answered.attrs["model"] == "rigid" and str(answered[STATUS].values[0]) == "ok"
    xr.testing.assert_identical(answered, RIGID.design_answer(cube, records[:1], 0.9))
    with pytest.raises(StickslipError, match="^the planar model has no design answer over a grid$"):
        with_optimum(xr.Dataset(attrs={"model": "planar"}), records[:1])


def test_a_record_that_could_not_be_swept_is_not_solved(records, tmp_path):
    from stickslip.sweeps import gather

    cube = gather([sweep(records[:1], mu=MU), RIGID.missing_cube("gone", "missing: not here", mu=MU)])
    result = with_optimum(cube, records[:1])
    assert str(result[STATUS].sel(record="gone").values) == NOT_SOLVED
    assert np.isnan(float(result.mu_max.sel(record="gone")))
    write_cube(result, tmp_path / "cube.nc")  # the text variable is written as CF characters
    assert str(xr.load_dataset(tmp_path / "cube.nc")[STATUS].sel(record="gone").values) == NOT_SOLVED


def test_tables_6_and_7_take_the_same_definitions(records):
    grid = sweep(records, mu=MU)
    fine = with_optimum(sweep(records, mu=np.round(np.arange(0.01, 0.41, 0.005), 6)), records, q=0.95)
    defined = with_optimum(grid, records, q=0.95)
    rows = {row["record"]: row for row in results_rows(grid, fine)}
    ranges = {row["record"]: row for row in ranges_rows(grid, fine, 0.95)}
    for record_id in ("strong", "stronger"):
        assert rows[record_id]["mu_max"] == float(defined.mu_max.sel(record=record_id))
        assert rows[record_id]["mu_max_on_grid_edge"] is bool(defined.mu_max_at_grid_edge.sel(record=record_id))
        assert ranges[record_id]["mu_low"] == float(defined.mu_low.sel(record=record_id))
        assert ranges[record_id]["mu_high"] == float(defined.mu_high.sel(record=record_id))
        for column, name in (("mu_max_fine", "mu_max"), ("mu_max_continuous", "mu_max_continuous"),
                             ("energy_dissipated_max_continuous", "energy_dissipated_max_continuous")):
            assert rows[record_id][column] == float(fine[name].sel(record=record_id))
        assert ranges[record_id]["mu_low_fine"] == float(fine.mu_low.sel(record=record_id))
    assert np.isnan(rows["weak"]["mu_max"]) and rows["weak"]["mu_max_on_grid_edge"] == ""
    with pytest.raises(StickslipError, match="for q = 0.95, not 0.9: rerun its sweep"):
        ranges_rows(grid, fine, 0.9)


def test_the_collection_chunk_names_a_record_too_weak_to_slide(records, tmp_path):
    store = write_record_store([StoredRecord("strong", records[0], "ok"), StoredRecord("weak", records[2], "ok"),
                                StoredRecord("gone", None, "missing", "not in the folder")], tmp_path / "store.nc")
    measures = write_chunk_measures(store, tmp_path / "measures.csv", G)
    cube = sweep_chunk(store, measures, {"start": 0.02, "stop": 0.4, "step": 0.02}, 5.1, G, 0.95, 0.1)
    statuses = dict(zip(cube.record.values, map(str, cube[STATUS].values)))
    assert statuses["strong"] == "ok" and statuses["gone"] == NOT_SOLVED
    assert statuses["weak"].startswith(f"{NEVER_SLIDES}: E_df = 0 at every mu of the grid; its PGA ")
    assert np.isnan(float(cube.efficiency.sel(record="weak"))) and np.isnan(float(cube.mu_max.sel(record="weak")))


def test_the_default_grid_is_the_collection_studys():
    study = yaml.safe_load((REPO_ROOT / "config" / "config.yaml").read_text(encoding="utf-8"))["collection_study"]
    assert study["mu"] == DEFAULT_MU and study["reference_mu"] == 0.10


def test_curves_of_a_cube_run_record_major(records):
    cube = sweep(records[:2], mu=MU, scale=[1.0, 2.0])
    curves = curves_of(cube)
    assert curves.energy_dissipated.shape == (4, MU.size)
    np.testing.assert_array_equal(curves.energy_dissipated[1], cube.energy_dissipated.sel(record="strong", scale=2.0))


# --- the command ------------------------------------------------------------------------------------------------


def write_one_column(path, record: Record) -> None:
    path.write_text("\n".join(f"{value / G:.8e}" for value in record.acceleration) + "\n")


def write_at2(path, record: Record) -> None:
    values = record.acceleration / G
    lines = ["PEER NGA STRONG MOTION DATABASE RECORD", "Test Quake 2024, 1/2/2024, Station Z, 090",
             "ACCELERATION TIME SERIES IN UNITS OF G", f"NPTS= {values.size}, DT= {record.dt:.4f} SEC"]
    lines += ["".join(f"{value:15.7E}" for value in values[start:start + 5]) for start in range(0, values.size, 5)]
    path.write_text("\n".join(lines) + "\n")


@pytest.fixture
def files(tmp_path, records):
    """An AT2 file, a one-column file (needs --dt), and a record too weak to slide, as AT2."""
    paths = [tmp_path / "strong.AT2", tmp_path / "weak.AT2"]
    write_at2(paths[0], records[0])
    write_at2(paths[1], records[2])
    return paths


def test_optimum_prints_the_design_answer_of_each_record(run_cli, files):
    code, out, err = run_cli("optimum", *files, "--mu", "0.02:0.4:0.02")
    assert code == 0 and "Traceback" not in err
    lines = out.splitlines()
    assert lines[0].startswith("friction grid: 20 values of mu from 0.02 to 0.4, step 0.02")
    strong = [line for line in lines if line.startswith("strong ")]
    assert len(strong) == 3 and all(len(line.split()) >= 7 for line in strong)  # design, stroke, residual
    weak = [line for line in lines if line.startswith("weak ")]
    assert len(weak) == 3 and all(f"{NEVER_SLIDES}: " in line for line in weak)
    assert "strong: Test Quake 2024, Station Z, 090" in out and "; peer_at2, dt = 0.01 s from the file" in out
    assert "the block never slides at any of the 20 friction ratios" in err  # --mu given: one note per record


def test_optimum_json_csv_and_cube_agree(run_cli, files, tmp_path):
    table, cube_path = tmp_path / "out" / "optimum.csv", tmp_path / "out" / "cube.nc"
    code, out, err = run_cli("optimum", *files, "--mu-list", *map(str, MU), "--q", "0.9", "--json",
                             "--csv", table, "--out", cube_path)
    assert code == 0, err
    document = json.loads(out)
    settings = document["settings"]
    assert settings["near_optimal_fraction"] == 0.9 and settings["given_mu"] == list(MU)
    assert document["units"]["peak_relative_displacement_at_mu_max"] == "m" and document["units"]["pga"] == "m s-2"
    strong, weak = document["records"]
    assert strong[STATUS] == "ok" and weak["mu_max"] is None and weak["efficiency"] is None
    # the grid of 0.02 is refined around the strong record's range; JSON, CSV and cube are all on the refined grid
    (refinement,) = settings["grid_refinements"]
    assert refinement["record"] == "strong" and refinement["grid_values_in_range_before"] < 10
    assert strong["grid_values_in_range"] == refinement["grid_values_in_range"] >= 10
    assert set(MU) < set(settings["mu"]) and len(settings["mu"]) == len(MU) + refinement["values_added"]
    cube = xr.load_dataset(cube_path)
    np.testing.assert_array_equal(cube.mu.values, settings["mu"])
    assert cube.attrs["range_points"] == 10 and cube.attrs["grid_refinement"].startswith("strong: ")
    with open(table, newline="", encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    for name in RESULTS:
        assert strong[name] == pytest.approx(float(cube[name].sel(record="strong")), rel=1e-15)
        assert float(rows[0][name]) == pytest.approx(strong[name], rel=1e-15)
    assert int(rows[0]["grid_values_in_range"]) == strong["grid_values_in_range"]
    inside = (cube.mu >= strong["mu_low"]) & (cube.mu <= strong["mu_high"])
    assert int(inside.sum()) == strong["grid_values_in_range"]
    assert rows[1][STATUS] == weak[STATUS] and rows[1]["mu_max"] == ""
    assert str(cube[STATUS].sel(record="weak").values) == weak[STATUS]


def test_optimum_without_mu_uses_the_default_grid_and_prints_no_note(run_cli, files):
    code, out, err = run_cli("optimum", files[0])
    assert code == 0 and err == ""
    assert out.startswith("friction grid: 400 values of mu from 0.0025 to 1, step 0.0025")


@pytest.mark.parametrize(("args", "phrase"), [
    (("--q", "0"), "--q 0: the near-optimal fraction must be in (0, 1]"),
    (("--reference-mu", "-1"), "--reference-mu -1: a friction ratio must be a positive number"),
    (("--target-pga", "0.6G", "x"), "--target-pga 'x': expected a number in units of g (0.4, or 0.4g) or an acceleration with its unit (3.92m/s2, "
     "392cm/s2)"),
    (("--range-points", "-1"), "--range-points -1: expected 0 (no refinement) or more grid values, such as 10"),
])
def test_optimum_bad_options_are_one_line(run_cli, files, args, phrase):
    code, out, err = run_cli("optimum", files[0], *args)
    assert code == 2 and out == "" and len(err.splitlines()) == 1 and phrase in err


def test_sweep_cube_answers_the_question_on_its_own(run_cli, files, tmp_path):
    out_path = tmp_path / "cube.nc"
    code, _, err = run_cli("sweep", files[0], "--mu", "0.02:0.4:0.02", "--reference-mu", "0.06", "--out", out_path)
    assert code == 0, err
    cube = xr.load_dataset(out_path)
    assert set(RESULTS) <= set(cube.data_vars) and cube.attrs["reference_mu"] == 0.06
    assert cube.energy_dissipated_reference.item() == pytest.approx(cube.energy_dissipated.sel(mu=0.06).item(), rel=1e-12)


# --- a grid too coarse for a weak record's near-optimal range -----------------------------------------------------


@pytest.fixture(scope="module")
def weakish():
    """A pulse of PGA 0.066 g: μ_max near 0.02, its near-optimal range four values of the default grid."""
    return pulse("weakish", 0.6, 4)


def test_a_weak_record_s_range_holds_ten_grid_values_on_the_refined_grid(weakish, records):
    versions = [weakish, records[0], pulse("still", 0.02, 5)]  # weak, strong, and one that never slides (0.002 g)
    given = Grid("mu", grid_values(DEFAULT_MU))
    design = RIGID.design(given, mass=5.1, g=G)
    coarse = solve_curves(versions, design)
    assert list(range_sizes(coarse)) == [4, 25, 0]
    refined, refinements = refine_for_ranges(versions, coarse, design)
    assert list(range_sizes(refined) >= MIN_RANGE_POINTS) == [True, True, False]  # never sliding: no range
    (refinement,) = refinements
    assert (refinement.case, refinement.before, refinement.after) == (0, 4, range_sizes(refined)[0])
    assert refinement.step == 0.0005 and refinement.start < refinement.stop
    assert refinement.added == refined.grid.values.size - given.values.size
    assert np.isin(given.values, refined.grid.values).all()  # the grid as given, and values between
    direct = solve_curves(versions, design.with_values(refined.grid.values))  # the merged curves are the solver's on the refined grid
    for name in ("energy_dissipated", "peak_relative_displacement", "residual_displacement"):
        np.testing.assert_array_equal(getattr(refined, name), getattr(direct, name))
    assert refinement.describe("mu", 10) == (
        f"{refinement.added} values of mu added from {refinement.start:g} to {refinement.stop:g} (step 0.0005): its "
        f"near-optimal range holds {refinement.after} grid values (4 before)")


def test_a_yield_grid_is_refined_as_a_friction_grid_is(weakish):
    design = RIGID.design(Grid("ky", grid_values(DEFAULT_MU)), mass=5.1, g=G, direction="both")
    coarse = solve_curves([weakish], design)
    refined, (refinement,) = refine_for_ranges([weakish], coarse, design)
    assert refined.grid.name == "ky"
    two_way = solve_curves([weakish], design.with_values(refined.grid.values))  # the values added slide both ways
    np.testing.assert_array_equal(refined.energy_dissipated, two_way.energy_dissipated)
    assert refinement.before == 4 and range_sizes(refined)[0] >= MIN_RANGE_POINTS


def test_a_model_s_demands_are_refined_with_its_curves(weakish):
    from stickslip.models.pendulum import PENDULUM

    design = PENDULUM.design(Grid("mu", grid_values(DEFAULT_MU)), mass=5.1, g=G, radius=2.0)
    coarse = solve_curves([weakish], design)
    refined, (refinement,) = refine_for_ranges([weakish], coarse, design)
    assert refinement.after >= MIN_RANGE_POINTS and list(refined.demands) == ["peak_base_shear"]
    direct = solve_curves([weakish], design.with_values(refined.grid.values))  # V/W at the values added too
    for name in ("energy_dissipated", "peak_relative_displacement", "residual_displacement"):
        np.testing.assert_array_equal(getattr(refined, name), getattr(direct, name))
    np.testing.assert_array_equal(refined.demands["peak_base_shear"], direct.demands["peak_base_shear"])


def test_the_grid_stays_as_given_when_nothing_is_asked_or_nothing_can_be_gained(weakish):
    design = RIGID.design(Grid("mu", grid_values(DEFAULT_MU)), mass=5.1, g=G)
    coarse = solve_curves([weakish], design)
    for q, points in ((0.95, 0), (0.95, 1), (1.0, MIN_RANGE_POINTS)):  # q = 1: the range is μ_max alone
        refined, refinements = refine_for_ranges([weakish], coarse, design, q, points)
        assert refined is coarse and refinements == []


def test_optimum_says_which_records_it_refined_and_prints_e_df_at_the_continuous_mu_max(run_cli, weakish, tmp_path):
    path = tmp_path / "weakish.AT2"
    write_at2(path, weakish)
    code, out, err = run_cli("optimum", path, "--json")
    assert code == 0, err
    document = json.loads(out)
    row, (refinement,) = document["records"][0], document["settings"]["grid_refinements"]
    code, out, err = run_cli("optimum", path)
    assert code == 0 and err == ""
    lines = out.splitlines()
    assert lines[1] == ("refined where a near-optimal range held fewer than 10 grid values (--range-points), for "
                        f"every record: {len(document['settings']['mu'])} values of mu in all")
    assert lines[2] == (f"  weakish: {refinement['values_added']} values of mu added from {refinement['start']:g} to "
                        f"{refinement['stop']:g} (step 0.0005): its near-optimal range holds "
                        f"{row['grid_values_in_range']} grid values (4 before)")
    cells = next(line for line in lines if line.startswith("weakish ")).split("  ")
    cells = [cell.strip() for cell in cells if cell.strip()]
    assert cells[3] == shown(row, "mu_max_continuous")
    assert cells[4] == shown(row, "energy_dissipated_max_continuous")  # beside the continuous μ_max, E_df there
    assert cells[5] == f"{shown(row, 'mu_low')} to {shown(row, 'mu_high')}"
    assert cells[6] == str(row["grid_values_in_range"]) and row["grid_values_in_range"] >= 10
    code, out, err = run_cli("optimum", path, "--range-points", "0", "--json")
    assert code == 0, err
    as_given = json.loads(out)
    settings = as_given["settings"]
    assert settings["mu"] == settings["given_mu"] and settings["grid_refinements"] == []
    assert as_given["records"][0]["grid_values_in_range"] == 4


def test_the_continuous_mu_max_is_refined_to_the_tolerance_asked(two_tone_record):
    """cube_with_optimum's xatol reaches the refinement: one wider than the grid's cells leaves mu_max on the grid."""
    import stickslip
    from stickslip.models import design_of
    from stickslip.optimum import cube_with_optimum

    grid = np.round(np.arange(0.02, 0.6, 0.02), 12)
    cube = stickslip.sweep([two_tone_record], mu=grid)
    design = design_of(cube)
    coarse = cube_with_optimum(cube, [two_tone_record], design, xatol=0.05)
    fine = cube_with_optimum(cube, [two_tone_record], design, xatol=1e-6)
    on_grid = float(coarse.mu_max.item())
    assert float(coarse.mu_max_continuous.item()) == on_grid
    assert float(coarse.energy_dissipated_max_continuous.item()) == float(coarse.energy_dissipated_max.item())
    assert 0.0 < abs(float(fine.mu_max_continuous.item()) - on_grid) < 0.02
    assert float(fine.energy_dissipated_max_continuous.item()) > float(fine.energy_dissipated_max.item())
