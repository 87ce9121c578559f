"""``stickslip solve --pair`` and ``stickslip sweep --pair``: the plane beside each component, cubes, and mistakes.

The pair is made of two of pyslammer's sample motions written as a user's
files ``SITE-000.csv`` and ``SITE-090.csv`` (the names give the azimuths), so
that a stranger without the shared records runs every test.
"""

from __future__ import annotations

import html
import json
import re
from importlib.resources import files

import numpy as np
import pytest
import xarray as xr
from conftest import assert_one_error_line

import stickslip
from stickslip.records.readers import read_record
from stickslip.models.rigid.exact import record_scalars
from stickslip.models.rigid.history import SCALAR_NAMES
from stickslip.constants import DEFAULT_BLOCK_MASS

SAMPLES = files("pyslammer") / "sample_ground_motions"
FIRST, SECOND = "Northridge_1994_VSP-360.csv", "Loma_Prieta_1989_HSP-000.csv"


@pytest.fixture(scope="module")
def pair_files(tmp_path_factory):
    """Two components of one made-up station, SITE-000 and SITE-090 (0.005 s, in g), and a shorter SITE-090."""
    folder = tmp_path_factory.mktemp("pair")
    one, other = read_record(SAMPLES / FIRST), read_record(SAMPLES / SECOND)
    length = 4000
    paths = []
    for name, record, samples in (("SITE-000", one, length), ("SITE-090", other, length),
                                  ("SHORT-000", one, length), ("SHORT-090", other, length - 25)):
        path = folder / f"{name}.csv"
        time = np.arange(samples) * record.dt
        np.savetxt(path, np.column_stack([time, record.acceleration[:samples] / 9.80665]), delimiter=",",
                   header="time (s),acceleration (g)", comments="")
        paths.append(path)
    return paths


def test_solve_pair_prints_the_plane_beside_each_component_alone(run_cli, pair_files):
    code, out, err = run_cli("solve", pair_files[0], pair_files[1], "--pair", "--mu", "0.08")
    assert code == 0, err
    assert "in the plane: mu = 0.08" in out
    assert "SITE-000 alone" in out and "SITE-090 alone" in out
    assert "balance_residual" in out and "peak_displacement" in out


def test_solve_pair_json_is_the_library_and_the_one_dimensional_solver(run_cli, pair_files):
    code, out, err = run_cli("solve", pair_files[0], pair_files[1], "--pair", "--mu", "0.08", "--json")
    assert code == 0, err
    printed = json.loads(out)
    pair = stickslip.RecordPair(read_record(pair_files[0]), read_record(pair_files[1]))
    expected = stickslip.solve(pair, mu=0.08).scalars()
    assert {name: printed[name] for name in expected} == pytest.approx(expected, rel=1e-12)
    assert printed["units"]["peak_displacement"] == "m" and printed["separation"] == 90.0
    for name, component in (("SITE-000", pair.first), ("SITE-090", pair.second)):
        alone = dict(zip(SCALAR_NAMES, record_scalars(component.acceleration, pair.dt, 0.08, 9.81)))
        assert printed["components_alone"][name]["energy_dissipated"] == pytest.approx(
            DEFAULT_BLOCK_MASS * alone["energy_dissipated"], rel=1e-12)
        assert printed["components_alone"][name]["peak_displacement"] == pytest.approx(
            alone["peak_relative_displacement"], rel=1e-12)


def test_solve_pair_out_writes_the_histories_on_a_component_dimension(run_cli, pair_files, tmp_path):
    out_file = tmp_path / "plane.nc"
    code, _, err = run_cli("solve", pair_files[0], pair_files[1], "--pair", "--mu", "0.1", "--out", out_file)
    assert code == 0, err
    with xr.open_dataset(out_file) as dataset:
        assert dataset["relative_displacement"].dims == ("time", "component")
        assert list(dataset["component"].values) == ["SITE-000", "SITE-090"]
        assert dataset["relative_displacement"].attrs["units"] == "m"


def test_sweep_pair_writes_a_cube_of_the_plane_and_each_component_and_the_turned_axes(run_cli, pair_files, tmp_path):
    out_file = tmp_path / "cube.nc"
    code, _, err = run_cli("sweep", pair_files[0], pair_files[1], "--pair", "--mu", "0.02:0.2:0.02", "--angles", "15",
                           "--out", out_file)
    assert code == 0, err
    with xr.open_dataset(out_file) as cube:
        assert cube["energy_dissipated"].dims == ("pair", "direction", "mu")
        assert list(cube["direction"].values) == ["plane", "first", "second"]
        assert cube.sizes["angle"] == 12 and cube["energy_dissipated"].attrs["units"] == "J"
        at = cube.sel(mu=0.08, method="nearest").isel(pair=0)
        pair = stickslip.RecordPair(read_record(pair_files[0]), read_record(pair_files[1]))
        assert float(at["energy_dissipated"].sel(direction="plane")) == pytest.approx(
            stickslip.solve(pair, mu=float(at["mu"])).scalars()["energy_dissipated"], rel=1e-12)
        # azimuths 0 and 90 are the two components themselves: the largest over the azimuths is at least either
        largest = cube["energy_dissipated_rotd100"].isel(pair=0)
        alone = cube["energy_dissipated"].isel(pair=0).sel(direction=["first", "second"]).max("direction")
        assert bool((largest >= alone * (1 - 1e-12)).all())
        assert bool((cube["energy_dissipated_rotd50"] <= cube["energy_dissipated_rotd100"]).all())
        assert np.isfinite(cube["mu_max"].values).all()


def test_pad_lets_components_of_different_lengths_pair(run_cli, pair_files):
    code, out, err = run_cli("solve", pair_files[2], pair_files[3], "--pair", "--pad", "--mu", "0.1", "--json")
    assert code == 0, err
    assert json.loads(out)["processing"] == [[], ["padded with 25 zeros at the end"]]


@pytest.mark.parametrize(("extra", "name", "phrase"), [
    ((), "SHORT-090", "different lengths (4,000 and 3,975 samples); pad the shorter"),
    (("--ky", "0.1"), "--ky", "--ky does not apply with --pair (the two horizontal components of one station, "
                              "solved in the plane: --model planar or pendulum or isolated or friction-tmd)"),
    (("--method", "newmark"), "--method newmark", "the planar model is solved by method exact"),
    (("--model", "coupled"), "--model coupled", "takes one horizontal component of a record, not the two"),
])
def test_solve_pair_mistakes_are_one_line(run_cli, pair_files, extra, name, phrase):
    arguments = ["solve", pair_files[2], pair_files[3], "--pair", *extra]
    if "--ky" not in extra:
        arguments += ["--mu", "0.1"]
    assert_one_error_line(*run_cli(*arguments), name, phrase)


def test_pair_files_from_two_events_and_odd_counts_are_refused(run_cli, pair_files):
    assert_one_error_line(*run_cli("solve", SAMPLES / FIRST, SAMPLES / SECOND, "--pair", "--pad", "--mu", "0.1"),
                          "different events", "Northridge")
    assert_one_error_line(*run_cli("solve", pair_files[0], "--pair", "--mu", "0.1"), "--pair", "but 1 was given")
    assert_one_error_line(*run_cli("solve", pair_files[0], "--pad", "--mu", "0.1"), "--pad", "applies with --pair")
    assert_one_error_line(*run_cli("sweep", pair_files[0], "--mu", "0.1:0.2:0.1", "--angles", "5", "--out", "x.nc"),
                          "--angles", "applies with --pair")


def test_report_pair_writes_one_page_with_the_plane_beside_each_component(run_cli, pair_files, tmp_path):
    from stickslip.reports.pair_report import figure_alts

    page = tmp_path / "pair.html"
    code, out, err = run_cli("report", pair_files[0], pair_files[1], "--pair", "--mu", "0.02:0.3:0.02", "--out", page)
    assert code == 0, err
    text = page.read_text()
    assert "Pair report: SITE-000 + SITE-090" in text
    assert "in the plane (both components)" in text
    assert re.search(r"1-D on the worst azimuth, \d+° clockwise from SITE-000 \(azimuth \d+°\)", text)
    assert "<th>μ_max on the grid [-]</th>" in text and "<th>E_df,max at the continuous μ_max [J/kg]</th>" in text
    assert "<th>μ_max, continuous [-]</th>" in text and "<th>near-optimal μ on the grid</th>" in text
    assert re.search(r"The plane's μ_max [\d.]+ lies (between the|above both|below both) components'", text)
    measures = re.search(r"Intensity measures of each component.*?(<table.*?</table>)", text, re.S).group(1)
    assert "<th>SITE-000</th>" in measures and "<th>SITE-090</th>" in measures  # both components, side by side
    pga = re.search(r"<th>peak ground acceleration</th>\s*<td>([^<]+)</td>\s*<td>([^<]+)</td>", measures)
    expected = [stickslip.intensity_measures(read_record(path)).pga for path in pair_files[:2]]
    assert [float(value) for value in pga.groups()] == pytest.approx(expected, rel=1e-5)
    assert not re.search(r"Fig\. ?\d", text)  # a user's page cites none of the paper's figures
    assert "largest |E_k - E_k(0) + E_df - E_I| over the samples" in text  # the ledger's scalars in words
    assert "balance_residual" not in text and "n_slip_episodes" not in text and not re.search(r"\de[+-]0\d<", text)
    assert re.search(r"μ = [\d.]+ \(the plane's μ_max, continuous\)", text)  # --mu-case: the plane's μ_max
    for alt in figure_alts("SITE-000_SITE-090").values():
        assert f'alt="{html.escape(alt)}"' in text, alt
    assert "Traceback" not in text


def test_report_pair_mistakes_are_one_line(run_cli, pair_files, tmp_path):
    assert_one_error_line(*run_cli("report", pair_files[2], pair_files[3], "--pair", "--out", tmp_path / "p.html"),
                          "SHORT-090", "different lengths")
    assert_one_error_line(*run_cli("report", pair_files[0], "--pad", "--out", tmp_path / "p.html"), "--pad",
                          "applies with --pair")


def test_optimum_pair_gives_the_design_answer_in_the_plane_and_on_each_axis(run_cli, pair_files):
    from stickslip.models.planar.design import pair_answers

    code, out, err = run_cli("optimum", pair_files[0], pair_files[1], "--pair", "--mu", "0.02:0.3:0.02",
                             "--angles", "30", "--json")
    assert code == 0, err
    document = json.loads(out)["pairs"][0]
    printed = document["results"]
    pair = stickslip.RecordPair(read_record(pair_files[0]), read_record(pair_files[1]))
    mu = np.arange(1, 16) * 0.02
    cube = stickslip.planar_sweep([pair], mu, progress=False)
    (answer,) = pair_answers(cube, [pair], 0.95, 0.1, 10)
    for label, direction in (("in the plane", "plane"), ("SITE-000 alone", "first"), ("SITE-090 alone", "second")):
        expected = answer.directions[direction].results
        for name in ("mu_max", "mu_max_continuous", "energy_dissipated_max_continuous", "mu_low", "mu_high",
                     "largest_stroke"):
            assert printed[label][name] == pytest.approx(expected[name], rel=1e-12), (label, name)
    assert document["relation"] == answer.relation
    plane = cube.isel(pair=0).sel(direction="plane")  # the continuous maximum beats the grid's
    assert printed["in the plane"]["energy_dissipated_max_continuous"] >= float(plane["energy_dissipated_max"])
    worst = next(label for label in printed if label.startswith("worst azimuth"))
    alone = cube.isel(pair=0)["energy_dissipated_max"].sel(direction=["first", "second"]).values  # the same grid
    assert printed[worst]["energy_dissipated_max"] >= float(np.max(alone))


def _component(name: str) -> stickslip.Record:
    """A short made-up component named ``name`` (its azimuth, when the name ends with one)."""
    return stickslip.Record(np.array([0.1, -0.2, 0.3]), 0.01, stickslip.RecordMeta(record_id=name, component=name))


@pytest.mark.parametrize(("first", "second", "angle", "words"), [
    ("228", "318", 160.0, "160° clockwise from 228° (azimuth 28°)"),  # a bare azimuth gets its degree sign
    ("TAK-090", "TAK-000", 30.0, "30° counterclockwise from TAK-090 (azimuth 60°)"),
    ("LCN-260", "LCN-345", 45.0, "45° clockwise from LCN-260 (azimuth 305°)"),  # 85° apart: axis 2 resolved
    ("PAR-L", "PAR-T", 75.0, "75° from PAR-L towards PAR-T"),  # no azimuths in the names
])
def test_the_worst_azimuth_is_named_from_the_first_component(first, second, angle, words):
    from stickslip.reports.pair_report import turned_axis

    assert turned_axis(stickslip.RecordPair(_component(first), _component(second)), angle) == words


def test_both_pair_pages_say_how_components_not_a_right_angle_apart_are_resolved():
    from stickslip.reports.pair_report import resolution_sentence

    resolved = stickslip.RecordPair(_component("LCN-260"), _component("LCN-345"))
    assert resolution_sentence(resolved) == (
        " The components are 85° apart: the second axis of the plane, 90° from LCN-260 towards LCN-345, carries the "
        "acceleration resolved onto it, (a₂ − a₁·cos Δ)/sin Δ.")
    assert resolution_sentence(stickslip.RecordPair(_component("TAK-000"), _component("TAK-090"))) == ""
    notebooks = files("stickslip.reports") / "notebooks"
    for page in ("pair_report.ipynb", "record_report.ipynb"):  # the flat pair's page and the pendulum pair's
        assert "resolution_sentence(" in (notebooks / page).read_text(encoding="utf-8")


def test_the_path_and_the_orbit_name_the_components_on_their_axes(pair_files):
    from stickslip.reports.planar_plots import axis_names, plot_acceleration_orbit, plot_path

    pair = stickslip.RecordPair(read_record(pair_files[0]), read_record(pair_files[1]))
    response = stickslip.solve(pair, mu=0.1)
    path, orbit = plot_path(response, "path").axes[0], plot_acceleration_orbit(response, "orbit").axes[0]
    assert (path.get_xlabel(), path.get_ylabel()) == ("displacement along SITE-000 [m]",
                                                      "displacement along SITE-090 [m]")
    assert (orbit.get_xlabel(), orbit.get_ylabel()) == ("ground acceleration along SITE-000 [m/s²]",
                                                        "ground acceleration along SITE-090 [m/s²]")
    resolved = stickslip.RecordPair(_component("LCN-260"), _component("LCN-345"))
    assert axis_names(resolved) == ("LCN-260", "90° from LCN-260 towards LCN-345")


@pytest.mark.parametrize(("name", "label"), [("0", "0°"), ("090", "90°"), ("360", "0°"), ("TAK-090", "TAK-090"),
                                             ("N", "N"), ("UP", "UP"), ("720", "720"), ("", "")])
def test_a_component_named_by_a_bare_azimuth_is_written_with_its_degree_sign(name, label):
    from stickslip.records.components import component_label
    from stickslip.reports.planar_plots import axis_names

    assert component_label(name) == label
    if name.isdigit() and int(name) <= 270:
        quarter = str(int(name) + 90)
        assert axis_names(stickslip.RecordPair(_component(name), _component(quarter))) == (label, f"{int(quarter)}°")


def test_the_ledger_draws_the_balance_residual_on_its_own_axis_with_a_legend_entry(pair_files):
    from stickslip.reports.planar_plots import plot_ledger

    pair = stickslip.RecordPair(read_record(pair_files[0]), read_record(pair_files[1]))
    response = stickslip.solve(pair, mu=0.1, mass=5.1)
    energies, residual = plot_ledger(response, "ledger").axes  # two panels, no second scale over the energies
    assert [text.get_text() for text in energies.get_legend().get_texts()] == [
        "input E_I", "dissipated by friction E_df", "kinetic E_k"]
    assert [text.get_text() for text in residual.get_legend().get_texts()] == [
        "balance residual E_k − E_k(0) + E_df − E_I"]
    np.testing.assert_array_equal(residual.get_lines()[0].get_ydata(), response.balance_residual)
    assert energies.get_ylabel() == "energy [J]" and residual.get_ylabel() == "residual [J]"
    assert plot_ledger(stickslip.solve(pair, mu=0.1), "ledger").axes[0].get_ylabel() == "energy [J/kg]"  # 1 kg
