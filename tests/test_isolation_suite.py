"""``stickslip isolation suite``: the suite scaled to the target, its statistic against a direct solve of each scaled
pair, the mean of seven pairs and the maximum of fewer, the JSON keys, the page and the one-line errors."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from conftest import assert_one_error_line, require_shared_records
from stickslip import solve
from stickslip.codes.friction_pendulum import aashto, asce7_22, design
from stickslip.codes.response_history import scaled_motion
from stickslip.codes.target_spectra import AashtoThreePoint, AsceTwoPeriod
from stickslip.records.pair import RecordPair
from stickslip.records.readers import read_record
from stickslip.records.vertical import WithVertical

G, RADIUS, MU = 9.81, 2.0, 0.06
TARGET = ("--sms", "1.5", "--sm1", "1.0", "--tl", "8")
ISOLATOR = ("--radius", str(RADIUS), "--mu", str(MU), "--lambda-max", "1.8", "--lambda-min", "0.6")
DT, DURATION = 0.02, 10.0


def write_at2(path: Path, station: str, component: str, acceleration_g: np.ndarray) -> Path:
    """A PEER NGA AT2 file of ``acceleration_g`` [g] at :data:`DT`, one station's ``component``."""
    lines = ["PEER NGA STRONG MOTION DATABASE RECORD", f"Synthetic 2001, 1/1/2001, {station}, {component}",
             "ACCELERATION TIME SERIES IN UNITS OF G", f"NPTS= {acceleration_g.size:6d}, DT= {DT:.4f} SEC,"]
    lines += ["".join(f"{value:15.7E}" for value in acceleration_g[start:start + 5])
              for start in range(0, acceleration_g.size, 5)]
    path.write_text("\n".join(lines) + "\n", encoding="ascii")
    return path


def motion(rng: np.random.Generator, peak_g: float) -> np.ndarray:
    """Sines from 0.2 to 3 Hz with random phases under a rise-and-decay envelope, scaled to ``peak_g`` [g]."""
    time = np.arange(0.0, DURATION, DT)
    frequencies = np.geomspace(0.2, 3.0, 12)
    wave = np.sum(np.sin(2 * np.pi * frequencies[:, None] * time + rng.uniform(0, 2 * np.pi, (12, 1))), axis=0)
    wave *= time * np.exp(-0.5 * time)
    return peak_g * wave / np.max(np.abs(wave))


def station_files(folder: Path, count: int, seed: int = 7) -> tuple[list[Path], list[Path]]:
    """``count`` stations' horizontal pairs (X1 Y1 X2 Y2 ...) and their verticals."""
    rng = np.random.default_rng(seed)
    pairs, verticals = [], []
    for index in range(count):
        station = f"Station {index}"
        pairs += [write_at2(folder / f"S{index}_000.AT2", station, "000", motion(rng, rng.uniform(0.2, 0.5))),
                  write_at2(folder / f"S{index}_090.AT2", station, "090", motion(rng, rng.uniform(0.2, 0.5)))]
        verticals.append(write_at2(folder / f"S{index}_UP.AT2", station, "UP", motion(rng, 0.15)))
    return pairs, verticals


@pytest.fixture(scope="module")
def three_stations(tmp_path_factory):
    return station_files(tmp_path_factory.mktemp("three"), 3)


@pytest.fixture(scope="module")
def seven_stations(tmp_path_factory):
    return station_files(tmp_path_factory.mktemp("seven"), 7)


def suite_json(run_cli, files, *options):
    code, out, err = run_cli("isolation", "suite", *files, "--pair", *TARGET, *ISOLATOR, "--json", *options)
    assert code == 0, err
    return json.loads(out)


def direct(pair_files, vertical_file, factor: float, mu: float) -> dict:
    """The pendulum's end results on the pair (and vertical) scaled by ``factor``, solved directly."""
    pair = RecordPair(read_record(pair_files[0], g=G), read_record(pair_files[1], g=G))
    whole = pair if vertical_file is None else WithVertical.of(pair, read_record(vertical_file, g=G))
    return solve(scaled_motion(whole, factor), model="pendulum", radius=RADIUS, mu=mu, g=G).scalars()


def test_fewer_than_seven_pairs_take_the_maximum_of_direct_solves(run_cli, three_stations):
    pairs, verticals = three_stations
    document = suite_json(run_cli, pairs, "--vertical", *verticals)
    assert document["suite_size"] == 3 and document["statistic"] == "max"
    for bound, mu in (("upper_bound", 1.8 * MU), ("lower_bound", 0.6 * MU)):
        solved = [direct(pairs[2 * i:2 * i + 2], verticals[i], document["pairs"][i]["scale_factor"], mu)
                  for i in range(3)]
        displacements = [result["peak_relative_displacement"] for result in solved]
        shears = [result["peak_base_shear"] for result in solved]
        assert [pair["peak_displacement"][bound] for pair in document["pairs"]] == pytest.approx(displacements, rel=1e-12)
        assert [pair["base_shear_coefficient"][bound] for pair in document["pairs"]] == pytest.approx(shears, rel=1e-12)
        response = document["response"][bound]
        assert response["peak_displacement"]["statistic"] == pytest.approx(max(displacements), rel=1e-12)
        assert response["base_shear_coefficient"]["statistic"] == pytest.approx(max(shears), rel=1e-12)
        assert max(displacements) > np.mean(displacements)  # the maximum, not the mean


def test_the_two_tabas_stations_with_their_verticals_against_direct_solves(run_cli):
    """Two real PEER stations (33 s and 21 s at 0.02 s), verticals labelled V (positive up as given)."""
    folder = require_shared_records() / "three_component"
    stations = [(folder / "Tabas_Tabas", "RSN143_TABAS_TAB"), (folder / "Tabas_Dayhook", "RSN139_TABAS_DAY")]
    pairs = [station / f"{stem}-{axis}1.AT2" for station, stem in stations for axis in "LT"]
    verticals = [station / f"{stem}-V1.AT2" for station, stem in stations]
    document = suite_json(run_cli, pairs, "--vertical", *verticals, "--vertical-positive", "up")
    assert [pair["name"] for pair in document["pairs"]] == ["Tabas (L + T)", "Dayhook (L + T)"]
    assert document["statistic"] == "max" and document["spectrum_check"]["passed"] is True
    for index, pair in enumerate(document["pairs"]):
        pair_files = pairs[2 * index:2 * index + 2]
        record = RecordPair(read_record(pair_files[0], g=G), read_record(pair_files[1], g=G))
        whole = WithVertical.of(record, read_record(verticals[index], g=G), "up")
        solved = solve(scaled_motion(whole, pair["scale_factor"]), model="pendulum", radius=RADIUS, mu=0.6 * MU,
                       g=G).scalars()
        assert pair["peak_displacement"]["lower_bound"] == pytest.approx(solved["peak_relative_displacement"],
                                                                         rel=1e-12)
        assert pair["base_shear_coefficient"]["lower_bound"] == pytest.approx(solved["peak_base_shear"], rel=1e-12)
    assert document["response"]["lower_bound"]["peak_displacement"]["statistic"] == max(
        pair["peak_displacement"]["lower_bound"] for pair in document["pairs"])


def test_the_verticals_change_the_runs(run_cli, three_stations):
    pairs, verticals = three_stations
    with_vertical = suite_json(run_cli, pairs, "--vertical", *verticals)
    without = suite_json(run_cli, pairs)
    assert [p["scale_factor"] for p in with_vertical["pairs"]] == [p["scale_factor"] for p in without["pairs"]]
    assert [p["vertical"] for p in with_vertical["pairs"]] == ["S0_UP", "S1_UP", "S2_UP"]
    assert [p["vertical"] for p in without["pairs"]] == [None, None, None]
    assert (with_vertical["pairs"][0]["base_shear_coefficient"]["upper_bound"]
            != without["pairs"][0]["base_shear_coefficient"]["upper_bound"])
    solved = direct(pairs[:2], None, without["pairs"][0]["scale_factor"], 1.8 * MU)
    assert without["pairs"][0]["peak_displacement"]["upper_bound"] == pytest.approx(
        solved["peak_relative_displacement"], rel=1e-12)


def test_seven_pairs_take_the_mean_and_the_average_spectrum_touches_the_target(run_cli, seven_stations):
    pairs, _ = seven_stations
    document = suite_json(run_cli, pairs)
    assert document["suite_size"] == 7 and document["statistic"] == "mean"
    for bound in ("upper_bound", "lower_bound"):
        for name in ("peak_displacement", "base_shear_coefficient"):
            values = [pair[name][bound] for pair in document["pairs"]]
            assert document["response"][bound][name]["statistic"] == pytest.approx(np.mean(values), rel=1e-12)
    spectra = document["spectra"]
    periods, average, target = (np.array(spectra[key]) for key in ("periods", "average", "target"))
    low, high = document["period_range"]
    inside = (periods >= low) & (periods <= high)
    assert np.min(average[inside] / target[inside]) == pytest.approx(1.0, rel=1e-10)
    assert document["spectrum_check"]["passed"] is True
    scaled = np.array(spectra["scaled_rotd100"])
    assert np.allclose(scaled.mean(axis=0), average, rtol=1e-12)


def test_the_range_and_the_elf_values_are_the_codes(run_cli, three_stations):
    pairs, _ = three_stations
    document = suite_json(run_cli, pairs, "--scaling", "common")
    designs = design(asce7_22(AsceTwoPeriod(1.5, 1.0, 8.0)), RADIUS, MU, G, lambda_max=1.8, lambda_min=0.6)
    assert document["period_range"] == pytest.approx(
        [0.75 * designs["upper_bound"].effective_period, 1.25 * designs["lower_bound"].effective_period], rel=1e-12)
    assert len({pair["scale_factor"] for pair in document["pairs"]}) == 1
    for bound in ("upper_bound", "lower_bound"):
        displacement = document["response"][bound]["peak_displacement"]
        assert displacement["elf"] == pytest.approx(designs[bound].design_displacement, rel=1e-12)
        assert displacement["ratio"] == pytest.approx(displacement["statistic"] / displacement["elf"], rel=1e-12)
        assert displacement["floor"] == 0.8 and displacement["passed"] == (displacement["ratio"] >= 0.8)
        assert displacement["design_value"] == max(displacement["statistic"], 0.8 * displacement["elf"])
        shear = document["response"][bound]["base_shear_coefficient"]
        assert shear["elf"] == pytest.approx(designs[bound].base_shear_coefficient, rel=1e-12)
        assert shear["floor"] == 0.9
    assert document["friction"]["upper_bound"] == pytest.approx(1.8 * MU)


def test_period_scaling_matches_each_pair_at_t_m(run_cli, three_stations):
    pairs, _ = three_stations
    document = suite_json(run_cli, pairs, "--scaling", "period")
    spectra = document["spectra"]
    periods = np.array(spectra["periods"])
    at = int(np.flatnonzero(periods == document["design_period"]["nominal"])[0])
    assert [row[at] for row in spectra["scaled_rotd100"]] == pytest.approx([spectra["target"][at]] * 3, rel=1e-12)


def test_the_json_keys_and_units(run_cli, three_stations):
    pairs, _ = three_stations
    document = suite_json(run_cli, pairs)
    assert set(document) == {"code", "code_title", "target", "target_source", "isolator", "radius", "mu", "g",
                             "friction", "design_period", "period_range", "range_factors", "scaling", "suite_size",
                             "minimum_pairs_for_mean", "statistic", "spectrum_check", "pairs", "response", "elf",
                             "spectra", "units"}
    assert set(document["pairs"][0]) == {"name", "event", "station", "records", "vertical", "vertical_sense",
                                         "scale_factor", "peak_displacement", "base_shear_coefficient"}
    assert document["pairs"][0]["name"] == "Station 0 (000 + 090)"
    assert set(document["response"]["upper_bound"]["peak_displacement"]) == {
        "statistic", "elf", "ratio", "floor", "passed", "design_value"}
    units = document["units"]
    assert (units["scale_factor"], units["peak_displacement"], units["base_shear_coefficient"]) == ("1", "m", "1")
    assert units["spectra"] == {"periods": "s", "target": "g", "average": "g", "scaled_rotd100": "g"}
    assert units["period_range"] == "s" and units["elf"]["design_displacement"] == "m"


def test_the_text_table_and_the_page(run_cli, three_stations, tmp_path):
    pairs, _ = three_stations
    code, out, err = run_cli("isolation", "suite", *pairs, "--pair", *TARGET, *ISOLATOR, "--page", tmp_path / "page",
                             "--plot", tmp_path / "suite.png")
    assert code == 0, err
    assert "statistic: the maximum over 3 pairs (fewer than 7: the maximum, not the mean)" in out
    assert "D ratio, limit >= 0.80" in out and "V_b/W ratio, limit >= 0.90" in out
    assert "Station 2 (000 + 090)" in out
    page = (tmp_path / "page" / "index.html").read_text(encoding="utf-8")
    assert '<img src="suite_spectra.png"' in page and "D, ELF [m]" in page and 'href="suite.json"' in page
    document = json.loads((tmp_path / "page" / "suite.json").read_text(encoding="utf-8"))
    assert document["suite_size"] == 3
    for figure in (tmp_path / "page" / "suite_spectra.png", tmp_path / "suite.png"):
        assert figure.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_a_label_up_or_dwn_is_read_and_vertical_positive_gives_the_others(run_cli, three_stations, tmp_path):
    pairs, verticals = three_stations
    rng = np.random.default_rng(5)
    down = write_at2(tmp_path / "S1_DWN.AT2", "Station 1", "DWN", motion(rng, 0.15))
    untold = write_at2(tmp_path / "S2_V.AT2", "Station 2", "V", motion(rng, 0.15))
    document = suite_json(run_cli, pairs, "--vertical", verticals[0], down, untold, "--vertical-positive", "up")
    senses = [pair["vertical_sense"] for pair in document["pairs"]]
    assert senses == ["positive up (UP in its component)", "positive down (DWN in its component), turned positive up",
                      "positive up (as given)"]
    code, out, err = run_cli("isolation", "suite", *pairs, "--pair", *TARGET, *ISOLATOR, "--vertical", verticals[0],
                             down, untold)
    assert_one_error_line(code, out, err, "S2_V", "say it, up or down (--vertical-positive)")


def test_another_codes_target_and_elf(run_cli, three_stations):
    pairs, _ = three_stations
    document = suite_json(run_cli, pairs, "--code", "aashto")
    designs = design(aashto(AashtoThreePoint(0.6, 1.5, 1.0)), RADIUS, MU, G, lambda_max=1.8, lambda_min=0.6)
    assert document["code"] == "aashto" and document["target_source"] == "derived from ASCE's S_MS and S_M1"
    assert document["response"]["lower_bound"]["peak_displacement"]["elf"] == pytest.approx(
        designs["lower_bound"].design_displacement, rel=1e-12)
    assert document["design_period"]["upper_bound"] == pytest.approx(designs["upper_bound"].effective_period, rel=1e-12)


def test_a_codes_own_spectrum_needs_no_other(run_cli, three_stations):
    pairs, _ = three_stations
    code, out, err = run_cli("isolation", "suite", *pairs, "--pair", "--code", "aashto", "--as", "0.4", "--sds", "1.0",
                             "--sd1", "0.6", *ISOLATOR, "--json")
    assert code == 0, err
    document = json.loads(out)
    assert document["target_source"] == "given"
    designs = design(aashto(AashtoThreePoint(0.4, 1.0, 0.6)), RADIUS, MU, G, lambda_max=1.8, lambda_min=0.6)
    assert document["response"]["upper_bound"]["base_shear_coefficient"]["elf"] == pytest.approx(
        designs["upper_bound"].base_shear_coefficient, rel=1e-12)


def test_a_multi_period_target_is_used_within_its_table(run_cli, three_stations, tmp_path):
    pairs, _ = three_stations
    table = tmp_path / "target.csv"
    table.write_text("period,sa\n0.5,1.5\n1.0,1.0\n2.0,0.5\n4.0,0.25\n6.0,0.16\n", encoding="utf-8")
    code, out, err = run_cli("isolation", "suite", *pairs, "--pair", "--asce-table", table, *ISOLATOR, "--json")
    assert code == 0, err
    spectra = json.loads(out)["spectra"]
    periods = np.array(spectra["periods"])
    assert periods.min() >= 0.5 and periods.max() <= 6.0
    assert spectra["target"] == pytest.approx(np.interp(periods, [0.5, 1, 2, 4, 6], [1.5, 1, 0.5, 0.25, 0.16]).tolist(),
                                              rel=1e-12)


@pytest.mark.parametrize("options, name, phrase", [
    ((), "isolation suite", "give the files two by two with --pair"),
    (("--pair", "--vertical", "V.AT2"), "--vertical", "1 file(s) for 3 pair(s): give one vertical per pair"),
    (("--pair", "--mu", "-0.06"), "--mu", "expected a positive number"),
    (("--pair", "--scaling", "nearest"), "--scaling", "invalid choice"),
    (("--pair", "--g", "-9.81"), "--g -9.81", "expected a positive gravity"),
])
def test_bad_input_is_one_line(run_cli, three_stations, options, name, phrase):
    pairs, _ = three_stations
    isolator = [item for item in ISOLATOR if item not in ("--mu", str(MU))] if "--mu" in options else list(ISOLATOR)
    code, out, err = run_cli("isolation", "suite", *pairs, *TARGET, *isolator, *options)
    assert_one_error_line(code, out, err, name, phrase)


def test_an_odd_number_of_files_and_a_missing_target_are_one_line(run_cli, three_stations, tmp_path):
    pairs, _ = three_stations
    code, out, err = run_cli("isolation", "suite", *pairs[:3], "--pair", *TARGET, *ISOLATOR)
    assert_one_error_line(code, out, err, "--pair", "two by two")
    code, out, err = run_cli("isolation", "suite", *pairs, "--pair", *ISOLATOR)
    assert_one_error_line(code, out, err, "ASCE 7-22 spectrum", "needs --sms, --sm1 and --tl")
    (tmp_path / "file").write_text("x", encoding="utf-8")
    code, out, err = run_cli("isolation", "suite", *pairs, "--pair", *TARGET, *ISOLATOR, "--page", tmp_path / "file" / "p")
    assert_one_error_line(code, out, err, "file", "cannot write the suite's page")
