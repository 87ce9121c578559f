"""A pair is one station's two horizontal components: two stations, two events or a vertical component are refused.

The checks read what the records' headers, names and manifests say
(:mod:`stickslip.records.components`): ``CHY023-N.AT2`` and ``ILA061-W.AT2``
are two stations of Chi-Chi, ``...-UP.AT2`` is a vertical component.
``--any-pair`` pairs them all the same, and the output says so.  A component
that is zero throughout (a uniaxial test) pairs, and the block then slides as
under the other component alone.  A vertical component analysed alone is
named as such (a note on stderr, a field in JSON), and the collection study
counts vertical components apart from its horizontal relations.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from conftest import assert_one_error_line, shared_dir

import stickslip
from stickslip.collections.members import GROUPS, left_out, studied
from stickslip.errors import StickslipError
from stickslip.models.rigid.exact import record_scalars
from stickslip.models.rigid.history import SCALAR_NAMES
from stickslip.records.components import recording_mismatch, same_event, station_codes, vertical_component
from stickslip.records.pair import RecordPair
from stickslip.records.readers import read_record
from stickslip.records.record import Record, RecordMeta
from stickslip.constants import DEFAULT_BLOCK_MASS

DT = 0.005
SAMPLES = 2000


def motion(seed: int, pga_g: float = 0.3) -> np.ndarray:
    """A random broadband motion [g] of :data:`SAMPLES` samples with the PGA ``pga_g``, tapered at both ends."""
    values = np.random.default_rng(seed).normal(size=SAMPLES) * np.hanning(SAMPLES)
    return pga_g * values / np.max(np.abs(values))


def write_at2(path, description: str, values_g: np.ndarray):
    """``values_g`` as a PEER NGA-West2 AT2 file whose description line is ``description``."""
    rows = [" ".join(f"{value:15.7E}" for value in values_g[i:i + 5]) for i in range(0, values_g.size, 5)]
    path.write_text("\n".join(["PEER NGA STRONG MOTION DATABASE RECORD", description,
                               "ACCELERATION TIME SERIES IN UNITS OF G",
                               f"NPTS= {values_g.size:6d}, DT= {DT:.4f} SEC,", *rows]) + "\n", encoding="ascii")
    return path


@pytest.fixture(scope="module")
def station_files(tmp_path_factory):
    """AT2 files as PEER names them: Chi-Chi CHY023-N/E and ILA061-W, and RSN180/181's horizontals and vertical."""
    folder = tmp_path_factory.mktemp("stations")
    files = {
        "CHY023-N": ("CHI-CHI 09/20/99, CHY023, N (CWB)", 1),
        "CHY023-E": ("CHI-CHI 09/20/99, CHY023, E (CWB)", 2),
        "ILA061-W": ("CHI-CHI 09/20/99, ILA061, W (CWB)", 3),
        "RSN180_IMPVALL.H_H-E05140": ("Imperial Valley-06, 10/15/1979, El Centro Array #5, 140", 4),
        "RSN180_IMPVALL.H_H-E05230": ("Imperial Valley-06, 10/15/1979, El Centro Array #5, 230", 5),
        "RSN180_IMPVALL.H_H-E05-UP": ("Imperial Valley-06, 10/15/1979, El Centro Array #5, UP", 6),
        "RSN181_IMPVALL.H_H-E06230": ("Imperial Valley-06, 10/15/1979, El Centro Array #6, 230", 7),
        "RSN6_IMPVALL.I_I-ELC180": ("Imperial Valley-02, 5/19/1940, El Centro Array #9, 180", 8),
        "RSN30_PARKF_C05DWN": ("Parkfield, 6/28/1966, Cholame - Shandon Array #5, 85", 9),
    }
    return {name: write_at2(folder / f"{name}.AT2", description, motion(seed))
            for name, (description, seed) in files.items()}


@pytest.mark.parametrize(("meta", "expected"), [
    (RecordMeta(component="UP"), "its component is UP"),
    (RecordMeta(component="DWN"), "its component is DWN"),
    (RecordMeta(component="V"), "its component is V"),
    (RecordMeta(component="HNZ"), "its component is HNZ"),
    (RecordMeta(component="TAK-UP"), "its component is TAK-UP"),
    (RecordMeta(source="x/RSN1158_KOCAELI_DZC-UP.AT2"), "its file name RSN1158_KOCAELI_DZC-UP ends in UP"),
    (RecordMeta(source="RSN30_PARKF_C05DWN.AT2"), "its file name RSN30_PARKF_C05DWN ends in DWN"),
    (RecordMeta(source="RSN143_TABAS_TAB-V1.AT2"), "its file name RSN143_TABAS_TAB-V1 ends in V1"),
    (RecordMeta(source="G03UP.AT2"), "its file name G03UP ends in UP"),
    (RecordMeta(source="CI.PAS.HNZ.txt"), "its file name CI.PAS.HNZ ends in HNZ"),
])
def test_a_vertical_component_is_named_with_what_says_so(meta, expected):
    assert vertical_component(meta) == expected


@pytest.mark.parametrize("meta", [
    RecordMeta(component="DWN-090", source="Landers 1992/DWN-090"),  # Downey, a horizontal
    RecordMeta(component="VER-180", source="Northridge 1994/VER-180"),  # Vernon
    RecordMeta(component="090", source="RSN30_PARKF_C05DWN.AT2"),  # the header's direction decides
    RecordMeta(component="L"), RecordMeta(source="CHY080-N.AT2"), RecordMeta(source="RSN77_SFERN_PUL164.AT2"),
    RecordMeta(),
])
def test_a_horizontal_or_unnamed_component_is_not_vertical(meta):
    assert vertical_component(meta) is None


def test_names_of_one_event_or_station_match_as_sources_spell_them():
    assert same_event("Chi-Chi, Taiwan 1999", "CHI-CHI") and same_event("SUPERST HILLS", "Superstition Hills-02")
    assert same_event("Kocaeli Turkey", "Kocaeli, Turkey 1999") and same_event("Northridge-01", "Northridge 1994")
    assert not same_event("Imperial Valley-02", "Imperial Valley-06") and not same_event("Kobe 1995", "Landers 1992")
    assert not same_event("Loma Prieta 1989", "Loma Prieta 1990")
    assert station_codes(RecordMeta(station="CHY080", source="CHY080-N.AT2", component="N")) == {"CHY080"}
    # the SLAMMER library names CHY080's region as its station: the codes decide
    assert recording_mismatch(RecordMeta(event="CHI-CHI", station="CHY080", component="N", source="CHY080-N.AT2"),
                              RecordMeta(event="Chi-Chi, Taiwan 1999", station="Chiayi", component="CHY080-090")) is None
    assert recording_mismatch(RecordMeta(station="El Centro Array #5"), RecordMeta(station="El Centro Array #6")) == \
        "different stations (El Centro Array #5 and El Centro Array #6)"
    assert recording_mismatch(RecordMeta(station="Pacoima Dam (upper left abut)"),
                              RecordMeta(station="Pacoima Dam (downstream)")) is not None
    assert recording_mismatch(RecordMeta(source="RSN180_A.AT2"), RecordMeta(source="RSN181_B.AT2")) == \
        "different PEER records (RSN180 and RSN181)"


@pytest.mark.parametrize(("first", "second", "phrase"), [
    ("CHY023-N", "ILA061-W", "the components come from different stations (CHY023 and ILA061)"),
    ("RSN180_IMPVALL.H_H-E05140", "RSN181_IMPVALL.H_H-E06230",
     "the components come from different stations (El Centro Array #5 and El Centro Array #6)"),
    ("RSN6_IMPVALL.I_I-ELC180", "RSN181_IMPVALL.H_H-E06230",
     "the components come from different events ('Imperial Valley-02' and 'Imperial Valley-06')"),
    ("RSN180_IMPVALL.H_H-E05140", "RSN180_IMPVALL.H_H-E05-UP", "the second is a vertical component (its component is UP)"),
    ("RSN30_PARKF_C05DWN", "RSN180_IMPVALL.H_H-E05140", "the first is a vertical component (its file name "
                                                        "RSN30_PARKF_C05DWN ends in DWN)"),
])
def test_a_pair_that_is_not_one_stations_two_horizontals_is_one_line_naming_both_files(run_cli, station_files, first,
                                                                                       second, phrase):
    code, out, err = run_cli("solve", station_files[first], station_files[second], "--pair", "--mu", "0.1")
    assert_one_error_line(code, out, err, f"{station_files[first]} and {station_files[second]}",
                          f"not one station's two horizontal components: {phrase} (--any-pair")
    with pytest.raises(StickslipError, match="not one station's two horizontal components"):
        RecordPair(read_record(station_files[first]), read_record(station_files[second]))


def test_one_stations_two_horizontals_pair(run_cli, station_files):
    code, out, err = run_cli("solve", station_files["CHY023-N"], station_files["CHY023-E"], "--pair", "--mu", "0.1",
                             "--json")
    assert code == 0 and err == "", err
    document = json.loads(out)
    assert document["any_pair"] is False and document["any_pair_note"] is None and document["separation"] == 90.0


def test_any_pair_pairs_them_all_the_same_and_says_so(run_cli, station_files):
    files = station_files["RSN180_IMPVALL.H_H-E05140"], station_files["RSN180_IMPVALL.H_H-E05-UP"]
    code, out, err = run_cli("solve", *files, "--pair", "--any-pair", "--mu", "0.1", "--json")
    assert code == 0
    said = "although the second is a vertical component (its component is UP)"
    assert err == f"stickslip: note: {files[0]} and {files[1]}: paired with --any-pair, {said}\n"
    document = json.loads(out)
    assert document["any_pair"] is True and document["any_pair_note"] == said
    pair = RecordPair(read_record(files[0]), read_record(files[1]), any_pair=True)
    assert document["energy_dissipated"] == pytest.approx(stickslip.solve(pair, mu=0.1).scalars()["energy_dissipated"],
                                                          rel=1e-12)
    code, out, _ = run_cli("solve", *files, "--pair", "--any-pair", "--mu", "0.1")
    assert code == 0 and f"paired with --any-pair, {said}" in out.splitlines()[1]
    code, out, _ = run_cli("optimum", *files, "--pair", "--any-pair", "--mu", "0.02:0.3:0.02", "--json")
    assert code == 0 and json.loads(out)["pairs"][0]["any_pair_note"] == said
    for command in (("solve", files[0], "--mu", "0.1"), ("report", files[0], "--out", "page.html")):
        assert_one_error_line(*run_cli(*command, "--any-pair"), "--any-pair", "applies with --pair")


def test_a_pair_made_with_any_pair_stays_so_beside_its_vertical(station_files):
    from stickslip.records.vertical import WithVertical

    pair = RecordPair(read_record(station_files["CHY023-N"]), read_record(station_files["ILA061-W"]), any_pair=True)
    vertical = read_record(station_files["RSN180_IMPVALL.H_H-E05-UP"])  # another event's: taken with any_vertical
    motion = WithVertical.of(pair, vertical, pad=True, any_vertical=True)
    assert motion.horizontal.any_pair is True and motion.sense == "positive up (UP in its component)"
    assert motion.any_vertical is True and "different events" in motion.doubt


def test_sweep_and_report_take_any_pair_too(run_cli, station_files, tmp_path):
    import xarray as xr

    files = station_files["CHY023-N"], station_files["ILA061-W"]
    note = (f"stickslip: note: {files[0]} and {files[1]}: paired with --any-pair, although the components come from "
            "different stations (CHY023 and ILA061)\n")
    cube = tmp_path / "cube.nc"
    code, _, err = run_cli("sweep", *files, "--pair", "--any-pair", "--mu", "0.05:0.2:0.05", "--out", cube)
    assert code == 0 and err == note
    with xr.open_dataset(cube) as dataset:
        config = json.loads(dataset.attrs["config"])
        assert config["any_pair"] is True and config["pad"] is False and config["model"] == "planar"
    assert_one_error_line(*run_cli("report", *files, "--pair", "--out", tmp_path / "refused.html"),
                          f"{files[0]} and {files[1]}", "different stations (CHY023 and ILA061)")
    page = tmp_path / "pair.html"
    code, out, err = run_cli("report", *files, "--pair", "--any-pair", "--mu", "0.05:0.3:0.05", "--out", page)
    assert code == 0 and err.startswith(note) and page.is_file() and "Traceback" not in page.read_text()


def test_a_component_of_zeros_pairs_and_the_plane_is_the_one_dimensional_answer(run_cli, station_files, tmp_path):
    """A uniaxial test: the second component zero throughout; the block slides as under the first alone."""
    first = read_record(station_files["CHY023-N"])
    zeros = tmp_path / "CHY023-E.txt"
    np.savetxt(zeros, np.column_stack([first.time, np.zeros(first.npts)]), fmt="%.4f")
    code, out, err = run_cli("solve", station_files["CHY023-N"], zeros, "--pair", "--units", "g", "--mu", "0.02",
                             "--json")
    assert code == 0 and err == "", err
    plane = json.loads(out)
    line = dict(zip(SCALAR_NAMES, record_scalars(first.acceleration, first.dt, 0.02, 9.81)))
    assert line["sliding_path"] > 0.01  # the block slides
    assert plane["energy_dissipated"] == pytest.approx(DEFAULT_BLOCK_MASS * line["energy_dissipated"], rel=1e-9)
    assert plane["sliding_path"] == pytest.approx(line["sliding_path"], rel=1e-9)
    assert plane["peak_displacement"] == pytest.approx(line["peak_relative_displacement"], rel=1e-9)
    assert plane["residual_displacement"] == pytest.approx(abs(line["residual_displacement"]), rel=1e-9)
    assert plane["components_alone"]["CHY023-E"]["energy_dissipated"] == 0.0
    other = tmp_path / "CHY023-N.txt"
    other.write_bytes(zeros.read_bytes())
    assert_one_error_line(*run_cli("solve", other, zeros, "--pair", "--units", "g", "--mu", "0.05"),
                          f"{other} and {zeros}", "both components are zero throughout")
    assert_one_error_line(*run_cli("solve", zeros, "--units", "g", "--mu", "0.05"), zeros,
                          "every acceleration is zero: the file holds no ground motion")


def test_a_vertical_component_analysed_alone_is_named_vertical(run_cli, station_files):
    path = station_files["RSN180_IMPVALL.H_H-E05-UP"]
    note = f"stickslip: note: {path} is a vertical component (its component is UP)"
    for command in (("measures", path, "--json"), ("solve", path, "--mu", "0.1", "--json"),
                    ("optimum", path, "--mu", "0.02:0.3:0.02", "--json")):
        code, out, err = run_cli(*command)
        assert code == 0 and err.startswith(note), err
        document = json.loads(out)
        row = document["records"][0] if command[0] == "optimum" else document
        assert row["vertical"] == "its component is UP"
    code, out, err = run_cli("measures", station_files["RSN180_IMPVALL.H_H-E05140"], "--json")
    assert code == 0 and err == "" and json.loads(out)["vertical"] is None
    code, out, err = run_cli("records", "validate", path)
    assert code == 0 and "a vertical component (its component is UP)" in out


def test_the_collection_study_counts_vertical_components_apart():
    def row(record_id, vertical=""):
        return {"id": record_id, "event": "e", "status": "ok", "reason": "", "optimum_status": "ok",
                "vertical": vertical}

    rows = [row("h1"), row("h2"), row("up", "its component is UP")]
    assert [r["id"] for r in studied(rows)] == ["h1", "h2"]
    assert left_out(rows) == [{"id": "up", "event": "e", "group": "vertical", "reason": "its component is UP"}]
    assert "vertical" in GROUPS


def test_the_collection_study_of_a_folder_with_verticals_leaves_them_out_of_its_relations(station_files, tmp_path):
    from stickslip.studies.collections.measures import write_chunk_measures
    from stickslip.studies.collections.records import store_chunk
    from stickslip.studies.collections.sweep import gather_study, write_chunk_sweep

    folder = station_files["CHY023-N"].parent
    settings = {"kind": "folder", "folder": str(folder)}
    from stickslip.collections.collection import study_collection

    ids = study_collection(settings).ids
    store = store_chunk(ids, tmp_path / "store.nc", settings)
    write_chunk_measures(store, tmp_path / "measures.csv", 9.81)
    write_chunk_sweep(store, tmp_path / "measures.csv", tmp_path / "cube.nc", {"start": 0.02, "stop": 0.3, "step": 0.02},
                      5.1, 9.81, 0.95, 0.1)
    gather_study([tmp_path / "cube.nc"], [tmp_path / "measures.csv"], tmp_path / "study.nc", tmp_path / "records.csv",
                 tmp_path / "skipped.csv", settings, 9.81)
    from stickslip.plumbing.files import read_csv_rows

    rows = read_csv_rows(tmp_path / "records.csv")
    vertical = {row["file"]: row["vertical"] for row in rows if row["vertical"]}
    assert vertical == {"RSN180_IMPVALL.H_H-E05-UP.AT2": "its component is UP",
                        "RSN30_PARKF_C05DWN.AT2": "its file name RSN30_PARKF_C05DWN ends in DWN"}
    assert len(studied(rows)) == len(rows) - 2
    assert [row["group"] for row in left_out(rows)] == ["vertical", "vertical"]


def test_the_shared_three_component_stations_pair_by_station():
    """Fifteen PEER stations with both horizontals and the vertical (../shared/records/three_component)."""
    folder = shared_dir() / "records" / "three_component"
    if not (folder / "manifest.csv").is_file():
        pytest.skip(f"the shared three-component records are not at {folder}")
    import csv

    with open(folder / "manifest.csv", newline="", encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    sets: dict[str, dict[str, Record]] = {}
    for row in rows:
        sets.setdefault(row["set"], {})[row["component"]] = read_record(folder / row["file"])
    assert len(sets) == 15
    for name, components in sets.items():
        RecordPair.padded(components["H1"], components["H2"])  # one station's two horizontals pair
        assert vertical_component(components["UP"].meta) is not None, name
        assert vertical_component(components["H1"].meta) is None, name
        with pytest.raises(StickslipError, match="the second is a vertical component"):
            RecordPair.padded(components["H1"], components["UP"])
    names = sorted(sets)
    for one, other in zip(names, names[1:]):  # any two stations are refused
        with pytest.raises(StickslipError, match="not one station's two horizontal components: the components come "
                                                 "from different"):
            RecordPair.padded(sets[one]["H1"], sets[other]["H2"])
