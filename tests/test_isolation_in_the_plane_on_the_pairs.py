"""The isolation study in the plane on the SLAMMER library's station pairs, against each component alone.

On the first 4 s of Gilroy Array #6 (Coyote Lake 1979, components 230 and 320, 0.005 s; a ``pairs.csv`` row and a
record store, as the planar study leaves them): the pair job's answers are a direct ``stickslip.solve`` of the
padded pair in the plane; each component alone is the per-component study's cube and the ratio the plane's over
the larger of the two; the pair is near-fault by its rupture distance; a friction the per-component grid has not
gives no ratio; the jobs share the pairs by their samples; without the library the tables are empty; the index
names the ratios over all pairs, and nothing without them.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import stickslip
from conftest import read_shared_paper_record
from stickslip.collections.store import StoredRecord, write_record_store
from stickslip.plumbing.files import read_csv_rows, write_csv_atomic
from stickslip.records.pair import RecordPair
from stickslip.records.record import Record
from stickslip.studies.isolation.plane_pairs import (COMPARED, GROUPS, ROW_FIELDS, SUMMARY_FIELDS, pair_shares,
                                                     write_plane_pair_chunk_cube, write_plane_pair_tables)
from stickslip.studies.isolation.index import plane_pairs_sentence
from stickslip.studies.isolation.sweep import gather_isolation_study, write_pair_chunk_cube
from stickslip.sweeps import read_cube

G = 9.81
#: The first 4 s of each component, every 0.005 s.
SAMPLES = 801
FILES = {"G06-230": "SLAMMER_Coyote_Lake_1979_G06-230.txt", "G06-320": "SLAMMER_Coyote_Lake_1979_G06-320.txt"}
#: The per-component grid at T = 0.5 s has μ = 0.06 but not the in-plane part's 0.3.
SETTINGS = {"periods": [0.5], "radii": [2.0], "mu": [0.06], "mass_ratio": 4.0, "damping_ratio": 0.02,
            "vertical": {"periods": [0.5], "radii": [2.0], "mu": [0.06, 0.3], "chunks": 1}}
#: A row of ``pairs.csv`` as the planar study writes it (the columns the study reads).
ROW = {"pair": "Coyote Lake 1979/G06", "chunk": "000", "status": "ok", "event": "Coyote Lake 1979",
       "station": "Gilroy Array #6", "first": "G06-230", "second": "G06-320", "first_component": "G06-230",
       "second_component": "G06-320", "rupture_distance": "3.1", "npts_first": str(SAMPLES),
       "npts_second": str(SAMPLES)}


@pytest.fixture(scope="module")
def plane_study(paper_records_dir, tmp_path_factory):
    """The per-component job and the in-plane pair job at T = 0.5 s, and the in-plane tables."""
    folder = tmp_path_factory.mktemp("plane_pairs")
    records = {}
    for name, file in FILES.items():
        record = read_shared_paper_record(paper_records_dir, file)
        records[name] = Record(record.acceleration[:SAMPLES].copy(), record.dt, record.meta)
    write_record_store([StoredRecord(name, record, "ok") for name, record in records.items()], folder / "store.nc")
    write_csv_atomic(folder / "pairs.csv", [ROW, {**ROW, "pair": "not read", "status": "missing"}])
    write_pair_chunk_cube(folder / "pairs.csv", [folder / "store.nc"], folder / "components_0.5.nc", "000",
                          SETTINGS, 0.5, G)
    gather_isolation_study([folder / "components_0.5.nc"], folder / "isolation.nc", 1)
    write_plane_pair_chunk_cube(folder / "pairs.csv", [folder / "store.nc"], folder / "plane_0.5.nc", 0, SETTINGS,
                                0.5, G)
    paths = [folder / name for name in ("plane.nc", "rows.csv", "summary.csv")]
    write_plane_pair_tables([folder / "plane_0.5.nc"], folder / "isolation.nc", *paths, 1, 20.0)
    return {"records": records, "components": read_cube(folder / "isolation.nc"), "cube": read_cube(paths[0]),
            "rows": read_csv_rows(paths[1]), "summary": read_csv_rows(paths[2])}


def test_the_pair_s_answers_are_a_direct_solve_in_the_plane(plane_study):
    pair = RecordPair.padded(plane_study["records"]["G06-230"], plane_study["records"]["G06-320"])
    direct = stickslip.solve(pair, model="isolated", method="integrated", superstructure_period=0.5, stories=1,
                             radius=2.0, mu=0.06, mass_ratio=4.0, superstructure_damping=0.02, g=G).scalars()
    assert direct["n_slip_episodes"] > 0  # the bearing slides: the plane is not the fixed base
    row = next(row for row in plane_study["rows"] if float(row["mu"]) == 0.06)
    for name in ("peak_isolator_displacement", "peak_drift", "peak_floor_acceleration", "base_shear_coefficient"):
        assert float(row[name]) == pytest.approx(direct[name], rel=1e-12)
    assert list(plane_study["cube"].record.values) == ["Coyote Lake 1979/G06"]  # the pair not read is not here


def test_the_ratio_is_the_plane_over_the_larger_component_alone(plane_study):
    row = next(row for row in plane_study["rows"] if float(row["mu"]) == 0.06)
    components = plane_study["components"]
    for name in COMPARED:
        alone = [float(components[name].sel(record=record, period=0.5, radius=2.0, mu=0.06))
                 for record in ("G06-230", "G06-320")]
        assert [float(row[f"{name}_first"]), float(row[f"{name}_second"])] == pytest.approx(alone, rel=1e-15)
        assert float(row[f"{name}_ratio"]) == pytest.approx(float(row[name]) / max(alone), rel=1e-15)
        assert 0.0 < float(row[f"{name}_ratio"]) < math.inf


def test_the_pair_is_near_fault_by_its_rupture_distance_and_a_friction_off_the_grid_has_no_ratio(plane_study):
    rows = plane_study["rows"]
    assert [float(row["mu"]) for row in rows] == [0.06, 0.3]
    assert {row["distance_group"] for row in rows} == {"near-fault"}
    assert all(float(row["rupture_distance"]) == 3.1 for row in rows)
    off_grid = rows[1]
    assert all(math.isnan(float(off_grid[f"{name}_ratio"])) for name in COMPARED)
    assert np.isfinite(float(off_grid["peak_isolator_displacement"]))  # solved in the plane all the same
    summary = {(float(row["mu"]), row["group"], row["quantity"]): row for row in plane_study["summary"]}
    assert len(summary) == 2 * len(GROUPS) * len(COMPARED)
    near = summary[(0.06, "near-fault", "peak_drift_ratio")]
    assert int(near["pairs"]) == 1 and float(near["median"]) == pytest.approx(float(rows[0]["peak_drift_ratio"]))
    assert int(summary[(0.06, "far-field", "peak_drift_ratio")]["pairs"]) == 0
    assert int(summary[(0.3, "all", "peak_drift_ratio")]["pairs"]) == 0


def test_the_jobs_share_the_pairs_read_by_their_samples():
    rows = [{**ROW, "pair": name, "npts_first": str(first), "npts_second": str(second)}
            for name, first, second in (("a", 100, 900), ("b", 800, 800), ("c", 300, 200), ("d", 150, 150))]
    rows.append({**ROW, "pair": "e", "status": "missing", "npts_first": "5000", "npts_second": "5000"})
    shares = [[row["pair"] for row in share] for share in pair_shares(rows, 2)]
    assert shares == [["a", "d"], ["b", "c"]]  # 900 + 150 against 800 + 300, each in the file's order
    assert [[row["pair"] for row in share] for share in pair_shares(rows, 1)] == [["a", "b", "c", "d"]]


def test_without_the_library_the_tables_are_empty(tmp_path):
    paths = [tmp_path / name for name in ("plane.nc", "rows.csv", "summary.csv")]
    write_plane_pair_tables([], tmp_path / "isolation.nc", *paths, 1, 20.0)
    assert paths[0].exists()
    assert paths[1].read_text().strip() == ",".join(ROW_FIELDS)
    assert paths[2].read_text().strip() == ",".join(SUMMARY_FIELDS)


def test_the_index_names_the_pairs_ratios_over_all_pairs(tmp_path):
    summary = tmp_path / "summary.csv"
    rows = [{"period": 0.5, "radius": 2.0, "mu": 0.06, "group": group, "quantity": quantity, "pairs": pairs,
             "median": median, "p16": 0.9, "p84": p84}
            for group, pairs in (("near-fault", 3), ("far-field", 0), ("all", 3))
            for quantity, median, p84 in (("peak_isolator_displacement_ratio", 1.15, 1.4),
                                          ("peak_drift_ratio", 0.97, 1.1),
                                          ("peak_floor_acceleration_ratio", 0.98, 1.05))]
    write_csv_atomic(summary, rows, list(rows[0]))
    assert plane_pairs_sentence(summary) == (
        "<p>In the plane on 3 station pairs of the SLAMMER library, over the larger component alone (T = 0.5 s, "
        "R = 2 m), median and 84th percentile: μ = 0.06: isolator displacement 1.15 (84 %: 1.40), drift 0.97 "
        "(84 %: 1.10).</p>")
    write_csv_atomic(summary, [], list(rows[0]))
    assert plane_pairs_sentence(summary) == ""  # no library: no sentence
