"""The isolation study's part in the plane: the one-story building under a station's two horizontals, with and
without its vertical, by the integrated scheme both times.

On the first 5 s of two three-component stations (Tabas and Dayhook, Tabas 1978, every 0.02 s), each in its own
chunk of stations: a vertical of zero gives the "with" equal to the "without"; the table's ratio is the ratio of
two direct ``stickslip.solve`` of the pair and of the pair with its vertical; the chunks share out the manifest's
fifteen stations; without the records the cube and the tables are empty and the figure says why.
"""

from __future__ import annotations

import numpy as np
import pytest

import stickslip
from stickslip.collections.store import StoredRecord, write_record_store
from stickslip.plumbing.files import read_csv_rows
from stickslip.records.pair import RecordPair
from stickslip.records.record import Record
from stickslip.records.vertical import WithVertical
from stickslip.reports.plots import NotDrawn
from stickslip.studies.isolation.index import vertical_sentence
from stickslip.studies.isolation.plots import plot_vertical_ratios
from stickslip.studies.isolation.with_vertical import (ANSWERS, RATIOS, station_chunks, vertical_cube,
                                                       write_vertical_chunk_cube, write_vertical_tables)
from stickslip.studies.vertical.records import acquired_row, manifest_rows, stations
from stickslip.sweeps import read_cube

G = 9.81
#: The first 5 s of each station, every 0.02 s.
SAMPLES = 251
STATIONS = ("Tabas_Tabas", "Tabas_Dayhook")
SETTINGS = {"periods": [0.3], "radii": [1.0], "mu": [0.05], "mass_ratio": 4.0, "damping_ratio": 0.02,
            "vertical": {"periods": [0.5], "radii": [2.0], "mu": [0.06, 0.12], "chunks": 2}}
#: The solver's parameters of the study's building at the study's point compared.
BUILDING = {"model": "isolated", "method": "integrated", "superstructure_period": 0.5, "stories": 1, "radius": 2.0,
            "mass_ratio": 4.0, "superstructure_damping": 0.02, "g": G}


@pytest.fixture(scope="module")
def store(shared_records, tmp_path_factory):
    """A record store of the two stations' first 5 s, as the vertical study's acquisition writes it."""
    folder = shared_records / "three_component"
    rows = []
    for entry in manifest_rows():
        if entry["set"] in STATIONS:
            row = acquired_row(folder, entry, G)
            assert row.status == "ok" and row.record.dt == 0.02
            rows.append(StoredRecord(row.record_id, Record(row.record.acceleration[:SAMPLES].copy(), row.record.dt,
                                                           row.record.meta), "ok"))
    path = tmp_path_factory.mktemp("store") / "records.nc"
    write_record_store(rows, path)
    return path


@pytest.fixture(scope="module")
def study(store, tmp_path_factory):
    """Both chunk jobs and the tables, on the two stations."""
    folder = tmp_path_factory.mktemp("vertical")
    cubes = [write_vertical_chunk_cube(folder / f"{chunk}.nc", SETTINGS, 0.5, G, chunk, "up", store)
             for chunk in range(2)]
    paths = [folder / name for name in ("isolation_vertical.nc", "ratios.csv", "summary.csv")]
    write_vertical_tables(cubes, *paths, periods=1)
    return {"chunks": [read_cube(path) for path in cubes], "cube": read_cube(paths[0]),
            "ratios": read_csv_rows(paths[1]), "summary": read_csv_rows(paths[2]), "summary_path": paths[2]}


def test_a_vertical_of_zero_leaves_the_building_as_without_it(store):
    found, _ = stations(store)
    station = dict(found["Tabas_Tabas"])
    station["UP"] = station["UP"].derive(np.zeros(station["UP"].npts), step="zeroed")
    cube = vertical_cube({"Tabas_Tabas": station}, SETTINGS, 0.5, G, "up")
    without, with_zero = (cube.sel(vertical=which) for which in ("without", "with"))
    assert float(without.peak_isolator_displacement.max()) > 0.05  # it slides
    for name in ANSWERS:
        assert np.allclose(with_zero[name], without[name], rtol=1e-12, atol=0.0), name
    assert np.all(with_zero.liftoff_time.values == 0.0)


def test_the_table_s_ratios_are_two_direct_solves(store, study):
    found, _ = stations(store)
    station = found["Tabas_Dayhook"]
    pair = RecordPair(station["H1"], station["H2"])
    without = stickslip.solve(pair, mu=0.06, **BUILDING).scalars()
    with_vertical = stickslip.solve(WithVertical(pair, station["UP"], "positive up"), mu=0.06, **BUILDING).scalars()
    row = next(row for row in study["ratios"] if row["station"] == "Tabas_Dayhook" and float(row["mu"]) == 0.06)
    for name in RATIOS:
        assert float(row[f"{name}_without"]) == pytest.approx(without[name], rel=1e-12), name
        assert float(row[f"{name}_with"]) == pytest.approx(with_vertical[name], rel=1e-12), name
        assert float(row[f"{name}_ratio"]) == pytest.approx(with_vertical[name] / without[name], rel=1e-12), name
    # the vertical changes the answers here: the comparison is not of two equal solves
    assert abs(float(row["peak_drift_ratio"]) - 1.0) > 1e-3


def test_each_station_is_solved_in_its_chunk_and_summarised(study):
    assert [list(cube.record.values) for cube in study["chunks"]] == [["Tabas_Tabas"], ["Tabas_Dayhook"]]
    cube = study["cube"]
    assert dict(cube.sizes) == {"record": 2, "period": 1, "radius": 1, "mu": 2, "vertical": 2}
    assert cube.peak_drift.attrs["units"] == "m" and cube.liftoff_time.attrs["units"] == "s"
    assert len(study["ratios"]) == 4
    for row in study["summary"]:
        values = [float(case[row["quantity"]]) for case in study["ratios"] if case["mu"] == row["mu"]]
        assert int(row["stations"]) == 2
        assert float(row["median"]) == pytest.approx(np.mean(values), rel=1e-12)


def test_the_chunks_share_out_the_fifteen_stations_by_their_samples():
    chunks = station_chunks(2)
    names = [row["set"] for row in manifest_rows() if row["component"] == "H1"]
    assert sorted(name for chunk in chunks for name in chunk) == sorted(names) and len(names) == 15
    samples = {row["set"]: int(row["npts"]) for row in manifest_rows() if row["component"] == "H1"}
    loads = [sum(samples[name] for name in chunk) for chunk in chunks]
    assert abs(loads[0] - loads[1]) <= max(samples.values())
    assert station_chunks(1) == [names]


def test_without_the_records_the_cube_and_the_tables_are_empty(tmp_path):
    cubes = [write_vertical_chunk_cube(tmp_path / f"{chunk}.nc", SETTINGS, 0.5, G, chunk, "up") for chunk in range(2)]
    paths = [tmp_path / name for name in ("isolation_vertical.nc", "ratios.csv", "summary.csv")]
    write_vertical_tables(cubes, *paths, periods=1)
    assert read_cube(paths[0]).sizes["record"] == 0
    assert read_csv_rows(paths[1]) == [] and read_csv_rows(paths[2]) == []
    assert vertical_sentence(paths[2]) == ""  # the index then says nothing of the plane
    figure = plot_vertical_ratios([])
    assert isinstance(figure, NotDrawn) and "three-component records were not available" in figure.sentence


def test_the_index_gives_the_drift_and_base_shear_ratios_of_the_summary(study):
    sentence = vertical_sentence(study["summary_path"])
    assert sentence.startswith("<p>In the plane on the 2 three-component stations, with the vertical over without it "
                               "(T = 0.5 s, R = 2 m)")
    for row in study["summary"]:
        if row["quantity"] in ("peak_drift_ratio", "base_shear_coefficient_ratio"):
            word = "drift" if row["quantity"] == "peak_drift_ratio" else "V_b/W"
            assert f"{word} {float(row['median']):.2f} (84 %: {float(row['p84']):.2f})" in sentence
