"""The planar study: station pairs formed from a collection's members, swept in chunks, analysed.

The pairing rules run on a synthetic set of members (names as the SLAMMER
library spells them); the analysis on a small cube swept from synthetic
accelerations (never presented as records: the workflow's pairs are real
stations only).  The workflow target on the .test configuration, whose
pyslammer collection has no pair, is checked in test_workflow.py; on real
pairs, the shared SLAMMER folder cut to one earthquake, here.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from stickslip.models.planar import planar_sweep
from stickslip.models.planar.sweep import azimuths
from stickslip.plumbing.files import read_csv_rows
from stickslip.records.pair import RecordPair
from stickslip.records.record import Record, RecordMeta
from stickslip.studies.planar import plots as planar_study_plots
from stickslip.studies.planar.index import headline_items, pairing_sentences
from stickslip.studies.planar.analysis import write_planar_analysis
from stickslip.studies.planar.pairs import component_direction, form_pairs, pair_chunks
from stickslip.studies.planar.ratios import pair_rows, ratio_rows
from stickslip.studies.planar.sweep import _component_rms, gather_planar_study, pair_measures
from stickslip.sweeps import write_cube

G = 9.81


def member(record: str, event: str = "Kobe 1995", dt: float = 0.01, distance: float = 5.0) -> dict:
    return {"id": f"{event}:{record}", "event": event, "record": record, "station": "", "dt": dt,
            "rupture_distance": distance}


@pytest.mark.parametrize("name, expected", [
    ("TAK-000", ("TAK", "azimuth", 0.0)), ("TAK-090", ("TAK", "azimuth", 90.0)),
    ("CHY028-N", ("CHY028", "azimuth", 0.0)), ("CHY028-W", ("CHY028", "azimuth", 270.0)),
    ("PAR-L", ("PAR", "longitudinal", None)), ("PAR-T", ("PAR", "transverse", None)),
    ("CLW-LN", ("CLW", "longitudinal", None)), ("CLW-TR", ("CLW", "transverse", None)),
    ("BAJ-L1", ("BAJ", "longitudinal", None)), ("BAJ-T1", ("BAJ", "transverse", None)),
    ("LCN-345", ("LCN", "azimuth", 345.0)), ("TCU-UP", None), ("station", None),
])
def test_a_component_id_gives_its_station_prefix_and_direction(name, expected):
    assert component_direction(name) == expected


def test_two_horizontal_components_of_one_station_pair_and_every_other_member_is_listed_with_its_reason():
    members = [
        member("TAK-000"), member("TAK-090"),
        member("CHY028-N", "Chi-Chi 1999"), member("CHY028-W", "Chi-Chi 1999"),
        member("PAR-L", "Northridge 1994"), member("PAR-T", "Northridge 1994"),
        member("LCN-260", "Landers 1992"), member("LCN-345", "Landers 1992"),
        member("TAK-000", "Another 2000"), member("TAK-090", "Another 2000"),  # the same station, another event
        member("QKP-085", "Imperial Valley 1979"),
        member("E02-140", "Imperial Valley 1979", dt=0.005), member("E02-230", "Imperial Valley 1979", dt=0.01),
        member("XYZ-000"), member("XYZ-045"), member("XYZ-090"),
        member("ABC-L"), member("ABC-090"),
        member("DEF-000"), member("DEF-010"),
        member("GHI-UP"),
    ]
    pairs, unpaired = form_pairs(members)
    formed = {pair["pair"]: pair for pair in pairs}
    assert list(formed) == ["Kobe 1995/TAK", "Chi-Chi 1999/CHY028", "Northridge 1994/PAR", "Landers 1992/LCN",
                            "Another 2000/TAK"]
    assert (formed["Kobe 1995/TAK"]["first_component"], formed["Kobe 1995/TAK"]["second_component"]) == ("TAK-000",
                                                                                                        "TAK-090")
    # W (270) then N (0): the second lies a quarter turn clockwise from the first
    assert formed["Chi-Chi 1999/CHY028"]["first_component"] == "CHY028-W"
    assert formed["Chi-Chi 1999/CHY028"]["orthogonal"] and formed["Chi-Chi 1999/CHY028"]["separation"] == 90.0
    assert formed["Northridge 1994/PAR"]["first_component"] == "PAR-L"
    assert "taken as orthogonal" in formed["Northridge 1994/PAR"]["directions"]
    lucerne = formed["Landers 1992/LCN"]
    assert lucerne["separation"] == 85.0 and not lucerne["orthogonal"] and "resolved" in lucerne["directions"]
    groups = {row["component"] + "@" + row["event"]: row["group"] for row in unpaired}
    assert groups == {
        "QKP-085@Imperial Valley 1979": "single",
        "E02-140@Imperial Valley 1979": "different dt", "E02-230@Imperial Valley 1979": "different dt",
        "XYZ-000@Kobe 1995": "more than two", "XYZ-045@Kobe 1995": "more than two", "XYZ-090@Kobe 1995": "more than two",
        "ABC-L@Kobe 1995": "unrelated directions", "ABC-090@Kobe 1995": "unrelated directions",
        "DEF-000@Kobe 1995": "too close", "DEF-010@Kobe 1995": "too close",
        "GHI-UP@Kobe 1995": "no direction",
    }
    assert all(row["reason"] for row in unpaired)
    assert "0.005 s and 0.01 s" in next(row["reason"] for row in unpaired if row["group"] == "different dt")
    # every member is either in one pair or listed once
    paired = [pair[side] for pair in pairs for side in ("first", "second")]
    assert sorted(paired + [row["id"] for row in unpaired]) == sorted(m["id"] for m in members)


def test_pairs_fall_in_balanced_chunks_none_larger_than_asked():
    pairs = [{"pair": str(k)} for k in range(7)]
    chunks = pair_chunks(pairs, 3)
    assert [len(chunk) for chunk in chunks] == [3, 3, 1]
    assert [pair for chunk in chunks for pair in chunk] == pairs
    assert pair_chunks([], 3) == []


def _noise(seed: int, npts: int = 1200, dt: float = 0.01, amplitude: float = 3.0) -> np.ndarray:
    """A smooth synthetic acceleration [m/s²] with a rising and decaying envelope (a test input, not a record)."""
    rng = np.random.default_rng(seed)
    time = np.arange(npts) * dt
    smooth = np.convolve(rng.standard_normal(npts), np.hanning(15), mode="same")
    envelope = (time / time[-1]) * np.exp(-4 * time / time[-1]) * 10
    return amplitude * smooth / np.abs(smooth).max() * envelope


def _pair(name: str, first: np.ndarray, second: np.ndarray, dt: float = 0.01) -> RecordPair:
    meta = [RecordMeta(record_id=f"{name}_{azimuth}", event="Synthetic", station=name, component=f"{name}-{azimuth}")
            for azimuth in ("000", "090")]
    return RecordPair(Record(first, dt, meta[0]), Record(second, dt, meta[1]))


@pytest.fixture(scope="module")
def synthetic_cube():
    """A small cube of synthetic pairs; the last has a zero second component."""
    pairs = [_pair(f"S{k}", _noise(2 * k), _noise(2 * k + 1)) for k in range(4)]
    pairs.append(_pair("ONE", _noise(9), np.zeros(1200)))
    cube = planar_sweep(pairs, np.arange(0.02, 0.42, 0.02), mass=5.1, g=G, angles=azimuths(30), progress=False)
    return cube.assign_coords(pair_id=("pair", [f"Synthetic/{pair.first.meta.station}" for pair in pairs]),
                              rupture_distance=("pair", [5.0, 10.0, 30.0, 50.0, 8.0]),
                              rms_plane=("pair", [pair_measures(pair)["rms_plane"] for pair in pairs]),
                              rms_first=("pair", [_component_rms(p.first.acceleration, p.dt) for p in pairs]),
                              rms_second=("pair", [np.nan] * len(pairs)))


def test_the_azimuths_include_both_components_so_their_largest_response_bounds_each_components(synthetic_cube):
    assert {0.0, 90.0} <= set(azimuths(7)) and set(azimuths(30)) == {0.0, 30.0, 60.0, 90.0, 120.0, 150.0}
    rows = pair_rows(synthetic_cube, 20.0, G)
    for row in rows:
        assert row["energy_dissipated_max_worst_azimuth"] >= max(row["energy_dissipated_max_first"],
                                                                 row["energy_dissipated_max_second"]) * (1 - 1e-9)
        assert row["energy_dissipated_max_worst_azimuth"] >= row["energy_dissipated_max_rotd50"]
        assert row["ratio_azimuths"] <= row["ratio_components"] * (1 + 1e-9)
        assert row["pga_plane"] >= row["pga_larger"]
    rotd100 = synthetic_cube.peak_displacement_rotd100.values
    components = synthetic_cube.peak_displacement.sel(direction=["first", "second"]).values.max(axis=1)
    assert np.all(rotd100 >= components * (1 - 1e-9))


def test_with_one_component_at_rest_the_plane_is_the_one_dimensional_block(synthetic_cube):
    row = pair_rows(synthetic_cube, 20.0, G)[-1]
    assert row["pair"] == "Synthetic/ONE" and row["status"] == "ok"
    assert row["mu_max_plane"] == row["mu_max_first"]
    assert row["ratio_components"] == pytest.approx(1.0, rel=1e-6)
    assert row["energy_dissipated_max_plane"] == pytest.approx(row["energy_dissipated_max_first"], rel=1e-6)
    # the vector's RMS is the component's when the other is at rest
    assert row["rms_plane"] == pytest.approx(row["rms_first"], rel=1e-12)


def test_the_ratio_against_mu_counts_the_pairs_and_orders_its_quantiles(synthetic_cube):
    rows = ratio_rows(synthetic_cube, min_records=3)
    assert [row["mu"] for row in rows] == pytest.approx(synthetic_cube.mu.values)
    sliding = (synthetic_cube.peak_displacement.values[:, 0, :] > 0).sum(axis=0)
    for row, count in zip(rows, sliding):
        assert row["pairs_sliding_in_plane"] == count
        assert row["ratio_components_n"] <= count and row["ratio_azimuths_n"] <= count
        if row["ratio_components_n"] >= 3:
            assert row["ratio_components_q10"] <= row["ratio_components_q50"] <= row["ratio_components_q90"]
        else:
            assert np.isnan(row["ratio_components_q50"])


def _write_analysis(cube, folder, pairs=(), unpaired=()):
    from stickslip.plumbing.files import write_csv_atomic

    write_cube(cube, folder / "chunk.nc")
    gather_planar_study([folder / "chunk.nc"], folder / "planar.nc")
    write_csv_atomic(folder / "pairs.csv", list(pairs), ["pair", "status", "reason", "separation", "orthogonal",
                                                         "directions", "padded_samples"])
    write_csv_atomic(folder / "unpaired.csv", list(unpaired), ["id", "event", "component", "group", "reason"])
    names = ("pair_results.csv", "ratio_by_mu.csv", "relations.csv", "near_far.csv", "design.json", "summary.json")
    write_planar_analysis(folder / "planar.nc", folder / "pairs.csv", folder / "unpaired.csv",
                          *[folder / name for name in names], n_boot=100, seed=0, min_records=3, reference_mu=0.1,
                          near_optimal_fraction=0.95, efficiency_target=0.9, coverage_target=0.8,
                          pga_bands_g=[0.0, 0.4, 3.0], near_fault_km=20.0, g=G)
    return json.loads((folder / "summary.json").read_text(encoding="utf-8"))


def test_the_analysis_writes_every_table_and_fits_the_plane_beside_the_components(synthetic_cube, tmp_path):
    pairs = [{"pair": name, "status": "ok", "reason": "", "separation": 90.0, "orthogonal": True,
              "directions": "azimuths, orthogonal", "padded_samples": 0} for name in synthetic_cube.pair_id.values]
    summary = _write_analysis(synthetic_cube, tmp_path, pairs)
    assert summary["status"] == "ok" and summary["pairs_studied"] == 5
    assert summary["near_fault_pairs"] == 3 and summary["far_pairs"] == 2
    ratio = summary["ratio_components_at_mu_max_plane"]
    assert ratio["n"] == 5 and ratio["q10"] <= ratio["q50"] <= ratio["q90"]
    relations = {(row["response"], row["predictor"]): row for row in read_csv_rows(tmp_path / "relations.csv")}
    assert relations[("mu_max_plane", "pga_plane")]["status"] == "ok"
    # both components of every pair, less the one at rest (it never slides, so has no mu_max)
    assert int(relations[("mu_max_components", "pga")]["n"]) == 9
    design = json.loads((tmp_path / "design.json").read_text(encoding="utf-8"))
    assert design["plane"]["status"] == "ok" and design["plane"]["n"] == 5
    assert design["plane"]["coverage"][0]["pga_band"] == "all records"
    items = headline_items(summary, G)
    assert any("R over the two components" in item for item in items)
    figure = planar_study_plots.plot_design_chart(design, G)
    assert len(figure.axes) == 2


def test_without_any_pair_every_table_is_written_and_says_why(tmp_path):
    import xarray as xr

    unpaired = [{"id": f"r{k}", "event": f"E{k}", "component": f"S{k}-000", "group": "single",
                 "reason": "no other horizontal component"} for k in range(3)]
    summary = _write_analysis(xr.Dataset(attrs={"status": "no pair"}), tmp_path, unpaired=unpaired)
    assert summary["status"].startswith("no pair: none of the 3 records") and summary["unpaired"] == {"single": 3}
    assert read_csv_rows(tmp_path / "pair_results.csv") == []
    assert headline_items(summary, G) == []
    assert any("3 records left unpaired" in line for line in pairing_sentences(summary, "pyslammer"))
    figure = planar_study_plots.plot_ratio_distribution([])
    assert "Not drawn" in figure.axes[0].texts[0].get_text()


def test_the_planar_target_on_real_pairs_of_one_earthquake(tmp_path):
    """The workflow's planar study on the shared SLAMMER folder cut to Coyote Lake 1979 (7 station pairs), on the
    .test grids: the pairs are formed, swept and analysed, and the page gives their numbers."""
    import yaml
    from conftest import REPO_ROOT, require_shared_records, snakemake

    slammer = require_shared_records() / "slammer"
    config = yaml.safe_load((REPO_ROOT / ".test" / "config" / "config.yaml").read_text(encoding="utf-8"))
    config["collection_study"].update(collection="slammer", filters={"events": ["Coyote Lake"]})
    configfile = tmp_path / "config.yaml"
    configfile.write_text(yaml.safe_dump(config), encoding="utf-8")
    done = snakemake(tmp_path, configfile, "reports/html/planar_study.html", slammer_dir=slammer)
    assert done.returncode == 0, done.stderr[-3000:]
    planar = tmp_path / "results" / "collections" / "slammer" / "planar"
    summary = json.loads((planar / "summary.json").read_text(encoding="utf-8"))
    assert summary["status"] == "ok" and summary["pairs_formed"] == summary["pairs_studied"] == 7
    rows = read_csv_rows(planar / "pair_results.csv")
    assert {row["pair"] for row in rows} >= {"Coyote Lake 1979/G06", "Coyote Lake 1979/CYC"}
    for row in rows:
        assert float(row["energy_dissipated_max_plane"]) > 0.0
        assert float(row["mu_max_plane"]) > 0.0
    assert max(summary["largest_balance_residual"].values()) < 1e-9  # the ledger closes on every pair and mu
    median = summary["ratio_components_at_mu_max_plane"]["q50"]
    assert 0.5 < median < 3.0
    page = (tmp_path / "reports" / "html" / "planar_study.html").read_text(encoding="utf-8")
    assert "7 station pairs" in page and "Traceback" not in page
