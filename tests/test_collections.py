"""Record collections: ids, the SLAMMER manifest, filters, the three kinds, the record store and the CLI."""

from __future__ import annotations

import functools
import http.server
import re
import shutil
import threading

import numpy as np
import pandas as pd
import pytest

from conftest import FIXTURES, assert_one_error_line, require_shared_records
from stickslip.collections import RecordFilter, load_collection, record_id
from stickslip.collections.collection import MIRROR_ENV, SkippedFile, not_a_record, slammer_table
from stickslip.collections.ids import ID_PATTERN
from stickslip.collections.slammer import SLAMMER_COMMIT, SLAMMER_REPOSITORY, slammer_manifest
from stickslip.collections.store import StoredRecord, read_record_store, write_record_store
from stickslip.errors import RecordError, RecordNotFoundError, StickslipError
from stickslip.records.record import Record, RecordMeta

#: The workflow's wildcard constraint for record ids (workflow/rules/common.smk).
WILDCARD = re.compile(r"^[A-Za-z0-9_.-]+$")


def shared_slammer_dir():
    return require_shared_records() / "slammer"


def test_record_id_of_a_slammer_folder_with_a_comma_and_blanks():
    assert record_id("Chi-Chi, Taiwan 1999", "CHY080-000") == "chi_chi_taiwan_1999_chy080_000"
    assert record_id("N. Palm Springs 1986", "WWT-180") == "n_palm_springs_1986_wwt_180"
    with pytest.raises(ValueError, match="no letter or digit"):
        record_id(", -", "")


def test_every_library_id_is_unique_and_safe_as_a_file_name_and_a_wildcard():
    ids = slammer_table()["id"]
    assert len(ids) == 2133 and ids.is_unique
    for value in ids:
        assert ID_PATTERN.match(value) and WILDCARD.match(value), value
        assert not set(value) & set("/\\ ,.{}*?:") and len(value) < 100


def test_manifest_of_a_small_database(tmp_path):
    (tmp_path / "eq.sql").write_text(
        "Chi-Chi, Taiwan 1999\tCHY080-000\t0.0050\t7.6\t5.123\t20.1\t0.902\t102.3\t0.75\t31.5\t34.0\t2.7"
        "\t553\t2\t3\tChiayi\tCWB\t23.5970\t120.6780\n"
        "Mammoth Lakes-2 1980\tBEN-270\t0.0050\t5.9\t0.133\t12.3\t0.109\t7.0\t0.42\t46.5\t48.6\t\t271\t4\t1"
        "\tBenton\tCGS\t37.8180\t-118.4750\n", encoding="utf-8")
    (tmp_path / "sha256.csv").write_text(
        "path,sha256,bytes,in_shared\n"
        f"\"Chi-Chi, Taiwan 1999/CHY080-000\",{'a' * 64},100,yes\nMammoth Lakes-2 1980/BEN-270,{'b' * 64},200,no\n",
        encoding="utf-8")
    table = slammer_manifest(tmp_path / "eq.sql", tmp_path / "sha256.csv")
    first, second = table.iloc[0], table.iloc[1]
    assert first["id"] == "chi_chi_taiwan_1999_chy080_000" and first["file"] == "Chi-Chi, Taiwan 1999/CHY080-000"
    assert (first["year"], first["dt"], first["mw"], first["rupture_distance"]) == (1999, 0.005, 7.6, 2.7)
    assert (first["site_class"], first["mechanism"], first["slammer_pga"]) == ("B", "reverse", 0.902)
    assert second["site_class"] == "D" and second["mechanism"] == "strike-slip"
    assert pd.isna(second["rupture_distance"]) and second["sha256"] == "b" * 64


def test_manifest_refuses_a_record_without_checksum_or_a_short_row(tmp_path):
    (tmp_path / "sha256.csv").write_text("path,sha256,bytes\n", encoding="utf-8")
    (tmp_path / "eq.sql").write_text("A 1999\tX-000\t0.01" + "\t1" * 16 + "\n", encoding="utf-8")
    with pytest.raises(StickslipError, match=r"eq.sql, line 1: no SHA-256 for the file 'A 1999/X-000'"):
        slammer_manifest(tmp_path / "eq.sql", tmp_path / "sha256.csv")
    (tmp_path / "eq.sql").write_text("A 1999\tX-000\t0.01\n", encoding="utf-8")
    with pytest.raises(StickslipError, match="line 1: 3 tab-separated fields, expected 19"):
        slammer_manifest(tmp_path / "eq.sql", tmp_path / "sha256.csv")


def test_shipped_manifest_is_what_the_script_makes_from_the_shared_database(tmp_path):
    import subprocess
    import sys

    from conftest import REPO_ROOT

    folder = shared_slammer_dir()
    output = tmp_path / "slammer_library.csv"
    subprocess.run([sys.executable, str(REPO_ROOT / "scripts" / "make-slammer-manifest.py"), str(folder), str(output)],
                   check=True, capture_output=True)
    shipped = REPO_ROOT / "src" / "stickslip" / "data" / "slammer_library.csv"
    assert output.read_bytes() == shipped.read_bytes()


def test_filters_select_the_near_fault_subset_and_more():
    library = load_collection("slammer")
    near = library.select(RecordFilter(max_rupture_distance=20.0))
    assert len(near.ids) == 521  # the library's near-fault records (README of the shared SLAMMER folder)
    assert (near.table["rupture_distance"] <= 20).all()
    kobe = library.select(RecordFilter.from_mapping({"events": ["kobe"], "site_classes": ["d"], "min_pga": 0.5}))
    assert set(kobe.table["event"]) == {"Kobe, Japan 1995"} and set(kobe.table["site_class"]) == {"D"}
    assert (kobe.table["listed_pga"] >= 0.5).all() and len(kobe.ids) >= 1
    strong = library.select(RecordFilter(min_magnitude=7.5, max_magnitude=7.6))
    assert strong.table["mw"].between(7.5, 7.6).all() and len(strong.ids) > 0
    with pytest.raises(StickslipError, match="unknown record filter"):
        RecordFilter.from_mapping({"max_distance": 20})


def test_pyslammer_collection_takes_the_slammer_metadata():
    samples = load_collection("pyslammer")
    assert len(samples.ids) == 18
    assert samples.table["mw"].notna().all() and samples.table["slammer_pga"].notna().all()
    record = samples.read("pyslammer_kobe_1995_tak_090")
    assert record.meta.event == "Kobe, Japan 1995" and record.dt == pytest.approx(0.01)
    assert np.max(np.abs(record.acceleration)) / 9.81 == pytest.approx(
        samples.table.at["pyslammer_kobe_1995_tak_090", "slammer_pga"], abs=5e-4)


def test_folder_collection_reads_headers_and_a_metadata_table(tmp_path):
    folder = tmp_path / "mine"
    (folder / "sub").mkdir(parents=True)
    shutil.copy(FIXTURES / "at2_nga_west1.AT2", folder / "first.AT2")
    shutil.copy(FIXTURES / "at2_nga_west2.AT2", folder / "sub" / "second.at2")
    metadata = tmp_path / "extra.csv"
    metadata.write_text("file,mw,rupture_distance,basin\nfirst.AT2,6.5,3.2,yes\n", encoding="utf-8")
    collection = load_collection("folder", folder, metadata)
    assert collection.ids == ["first", "sub_second"]
    assert collection.table.at["first", "mw"] == 6.5 and collection.table.at["first", "basin"] == "yes"
    assert pd.isna(collection.table.at["sub_second", "mw"])
    assert collection.read("sub_second").npts > 10
    assert collection.select(RecordFilter(max_rupture_distance=5)).ids == ["first"]
    metadata.write_text("file,mw\nnot_there.AT2,6\n", encoding="utf-8")
    with pytest.raises(StickslipError, match="no such file in the collection folder: not_there.AT2"):
        load_collection("folder", folder, metadata)


def _one_column(path, values, dt=None):
    """A headerless one-column file of ``values`` [g] (no time step in it)."""
    path.write_text("\n".join(f"{value:.6f}" for value in values) + "\n", encoding="ascii")
    return path


def test_a_folder_collection_reads_every_format_and_keeps_a_row_for_each_unreadable_file(tmp_path):
    folder = tmp_path / "mine"
    (folder / ".git").mkdir(parents=True)
    (folder / ".git" / "config").write_text("[core]\n", encoding="ascii")  # hidden: not a record
    shutil.copy(FIXTURES / "at2_nga_west2.AT2", folder / "first.AT2")
    shutil.copy(FIXTURES / "two_column.txt", folder / "two_column.txt")
    wave = 0.3 * np.sin(np.linspace(0.0, 20.0, 400))
    _one_column(folder / "headless.txt", wave)
    _one_column(folder / "own_step.txt", 0.5 * wave)
    (folder / "notes.md").write_text("# my records\n", encoding="utf-8")
    metadata = folder / "table.csv"  # inside the folder: the table, not a record
    metadata.write_text("file,dt,units,mw\nown_step.txt,0.02,,6.1\ntwo_column.txt,,cm/s2,\n", encoding="utf-8")

    collection = load_collection("folder", folder, metadata, dt=0.01)
    table = collection.table
    assert sorted(collection.ids) == ["first", "headless", "own_step", "two_column"]
    assert collection.skipped == (SkippedFile("notes.md", "text without rows of numbers"),)
    assert table.at["headless", "dt"] == 0.01 and table.at["headless", "format"] == "slammer_1col"
    assert table.at["own_step", "dt"] == 0.02 and table.at["own_step", "mw"] == 6.1  # the file's row wins
    assert table.at["two_column", "units"] == "cm/s2" and table.at["first", "format"] == "peer_at2"
    assert (table["unreadable"] == "").sum() == 4
    assert collection.read("headless").npts == 400 and collection.read("own_step").dt == 0.02
    with pytest.raises(StickslipError, match=r"unknown record id 'notes' in the folder collection"):
        collection.read("notes")

    without_step = load_collection("folder", folder, metadata)
    assert without_step.table.at["headless", "unreadable"] == (
        "no time step: a slammer_1col file has none and no manifest knows this file; pass the folder's dt "
        "(collection_study.dt, or --dt of records list) or a dt column of the metadata table in seconds")
    assert without_step.table.at["own_step", "unreadable"] == ""


#: A PNG's first bytes, as any image file starts.
PNG_START = b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR\x00\x00\x00\x10"


@pytest.mark.parametrize(("name", "data", "reason"), [
    ("README.txt", b"My records\n==========\nDownloaded from PEER on 2024-05-01, 12 files.\n",
     "text without rows of numbers"),
    ("notes.md", b"# notes\n\n- Tabas is the strongest\n- 3 stations\n", "text without rows of numbers"),
    ("overview.png", PNG_START, "a PNG image"),
    ("photo.JPG", b"\xff\xd8\xff\xe0\x00\x10JFIF", "a JPEG image"),
    ("paper.pdf", b"%PDF-1.7\n%\xe2\xe3\xcf\xd3\n", "a PDF document"),
    ("table.xlsx", b"PK\x03\x04\x14\x00\x06\x00", "a ZIP archive (or a spreadsheet, a document)"),
    ("blob.bin", b"\x01\x02\x00\x00\x17", "binary data, not text"),
    ("empty.txt", b"\n\n", "an empty file"),
    ("meta.csv", b"file,mw,rupture_distance\nA.AT2,6.5,3.2\nB.AT2,7.1,12.0\n",
     "a table with a column 'file', as the folder's metadata table has, which collection_study.metadata or "
     "--metadata of records list names"),
    ("download.AT2.part", b"PEER NGA STRONG MOTION DATABASE RECORD\n", "the temporary .part file of an unfinished write"),
])
def test_a_file_that_is_no_record_says_what_it_is(name, data, reason):
    assert not_a_record(name, data) == reason


@pytest.mark.parametrize(("name", "data"), [
    ("BROKEN.AT2", b"PEER NGA STRONG MOTION DATABASE RECORD\nTabas, Dayhook, L1\nUNITS OF G\n"),  # by its name
    ("empty.at2", b""),
    ("record.nc", PNG_START),  # a NetCDF record whatever its bytes: the reader says what is wrong
    ("headless.txt", b"0.01\n-0.02\n0.03\n"),  # a column of values without its time step
    ("two_columns.csv", b"time,acc\n0.00,0.01\n0.01,0.02\n0.02,oops\n0.03,0.01\n"),  # mostly rows of numbers
    ("peer.txt", b"PEER STRONG MOTION DATABASE RECORD\nsomething\nUNITS OF G\n"
                 b"0.1 0.2 0.3\n0.4 0.5 0.6\n0.7 0.8 0.9\n0.1 0.2 0.3\n"),
    ("utf16.txt", "0.01\n-0.02\n0.03\n".encode("utf-16")),
    ("unread.txt", None),  # bytes that could not be read: a record file until its name says otherwise
])
def test_a_record_file_that_cannot_be_read_is_never_taken_for_another_file(name, data):
    assert not_a_record(name, data) is None


def test_a_folder_lists_files_that_are_no_records_as_skipped_and_keeps_records_that_cannot_be_read(tmp_path):
    folder = tmp_path / "mine"
    (folder / "figures").mkdir(parents=True)
    shutil.copy(FIXTURES / "at2_nga_west2.AT2", folder / "first.AT2")
    (folder / "README.txt").write_text("My records\n==========\nFrom PEER, 2024.\n", encoding="utf-8")
    (folder / "figures" / "overview.png").write_bytes(PNG_START)
    (folder / "metadata.csv").write_text("file,mw\nfirst.AT2,6.5\n", encoding="utf-8")  # not named as the table
    header = (FIXTURES / "at2_nga_west2.AT2").read_text(encoding="ascii").splitlines()
    (folder / "BROKEN.AT2").write_text("\n".join(header[:3] + header[4:]) + "\n", encoding="ascii")  # no NPTS line
    _one_column(folder / "headless.txt", 0.3 * np.sin(np.linspace(0.0, 20.0, 400)))  # no dt: a record not read
    (folder / "listed.txt").write_text("see the paper\n", encoding="utf-8")
    table = folder / "mine.csv"
    table.write_text("file,mw\nlisted.txt,6.0\n", encoding="utf-8")  # a file the metadata table lists is a record

    collection = load_collection("folder", folder, table)
    assert collection.ids == ["broken", "first", "headless", "listed"]
    assert [(item.file, item.reason) for item in collection.skipped] == [
        ("README.txt", "text without rows of numbers"), ("figures/overview.png", "a PNG image"),
        ("metadata.csv", "a table with a column 'file', as the folder's metadata table has, which "
                         "collection_study.metadata or --metadata of records list names")]
    unreadable = collection.table["unreadable"]
    assert unreadable["broken"] == "PEER AT2 header has no 'NPTS=…, DT=…' line among its first lines"
    assert unreadable["headless"].startswith("no time step: a slammer_1col file has none")
    assert unreadable["listed"].startswith("unknown format: not a PEER AT2 file")
    assert unreadable["first"] == ""
    assert collection.select(RecordFilter(min_pga=0.0)).skipped == collection.skipped


def test_a_folder_without_a_record_file_is_one_error_naming_what_it_skipped(tmp_path):
    (tmp_path / "README.txt").write_text("nothing here yet\n", encoding="utf-8")
    (tmp_path / "logo.png").write_bytes(PNG_START)
    with pytest.raises(StickslipError, match=re.escape(
            f"{tmp_path}: no record file in the collection folder; skipped README.txt (text without rows of "
            "numbers); logo.png (a PNG image)")):
        load_collection("folder", tmp_path)


def test_records_list_names_each_skipped_file_and_counts_the_record_files_apart(run_cli, tmp_path):
    shutil.copy(FIXTURES / "at2_nga_west2.AT2", tmp_path / "first.AT2")
    (tmp_path / "README.txt").write_text("My records\n", encoding="utf-8")
    (tmp_path / "notes.md").write_text("# notes\n", encoding="utf-8")
    code, out, err = run_cli("records", "list", "--collection", "folder", "--folder", tmp_path)
    assert code == 0 and err == ""
    lines = out.splitlines()
    assert lines[-3:] == ["  README.txt: skipped, not a record file: text without rows of numbers",
                          "  notes.md: skipped, not a record file: text without rows of numbers",
                          f"1 records of the folder collection (all records); 1 here in {tmp_path}; 2 other files "
                          "skipped (above)"]
    assert not any(line.startswith(("readme", "notes")) for line in lines)


def test_records_list_names_each_unreadable_file_of_a_folder_and_counts_them(run_cli, tmp_path):
    shutil.copy(FIXTURES / "at2_nga_west2.AT2", tmp_path / "first.AT2")
    _one_column(tmp_path / "headless.txt", 0.3 * np.sin(np.linspace(0.0, 20.0, 400)))
    code, out, err = run_cli("records", "list", "--collection", "folder", "--folder", tmp_path)
    assert code == 0 and err == ""
    assert "  headless.txt: cannot be read: no time step" in out
    assert out.splitlines()[-1] == (f"2 records of the folder collection (all records); 2 here in {tmp_path}; "
                                    "1 readable, 1 not (above)")
    code, out, err = run_cli("records", "list", "--collection", "folder", "--folder", tmp_path, "--dt", "0.01")
    assert code == 0 and "cannot be read" not in out and out.splitlines()[-1].endswith(f"2 here in {tmp_path}")


def test_the_study_stores_an_unreadable_folder_file_as_rejected_with_its_reason(tmp_path):
    from stickslip.studies.collections.records import store_chunk

    folder = tmp_path / "mine"
    folder.mkdir()
    shutil.copy(FIXTURES / "at2_nga_west2.AT2", folder / "first.AT2")
    (folder / "broken.txt").write_text("0.01\n0.02\ngarbage\n0.03\n", encoding="ascii")  # values with a bad line
    settings = {"kind": "folder", "folder": str(folder), "metadata": None, "dt": None, "units": None}
    store = read_record_store(store_chunk(["broken", "first"], tmp_path / "store.nc", settings))
    rows = {row.record_id: row for row in store}
    assert rows["first"].status == "ok" and rows["broken"].status == "rejected"
    assert rows["broken"].reason.startswith(f"{folder / 'broken.txt'}: line 3")


@pytest.mark.parametrize(("options", "phrase"), [
    ({"dt": -0.01}, "the folder's time step must be a positive number of seconds, got -0.01"),
    ({"units": "furlongs"}, "the folder's units: unknown units 'furlongs'"),
])
def test_a_folder_s_bad_default_is_one_error_naming_the_folder(tmp_path, options, phrase):
    shutil.copy(FIXTURES / "at2_nga_west2.AT2", tmp_path / "first.AT2")
    with pytest.raises(StickslipError, match=re.escape(phrase)) as raised:
        load_collection("folder", tmp_path, **options)
    assert str(tmp_path) in str(raised.value)


def test_a_slammer_library_file_in_a_folder_takes_the_library_s_time_step_and_metadata(tmp_path):
    library = shared_slammer_dir() / "records"
    shutil.copy(library / "Kobe, Japan 1995" / "TAK-000", tmp_path / "TAK-000")
    collection = load_collection("folder", tmp_path)
    row = collection.table.loc["tak_000"]
    assert row["format"] == "slammer_1col" and row["dt"] == 0.01 and row["unreadable"] == ""
    assert row["event"] == "Kobe, Japan 1995" and row["mw"] == 6.9 and row["site_class"] == "E"
    same = load_collection("slammer", shared_slammer_dir()).read("kobe_japan_1995_tak_000")
    np.testing.assert_array_equal(collection.read("tak_000").acceleration, same.acceleration)


def test_a_changed_library_file_is_rejected_by_its_checksum(tmp_path):
    library = load_collection("slammer", tmp_path)
    file = library.table.at["kobe_japan_1995_kjm_090", "file"]
    (tmp_path / "records" / file).parent.mkdir(parents=True)
    (tmp_path / "records" / file).write_text("0.1\n0.2\n0.3\n", encoding="utf-8")
    with pytest.raises(RecordError, match="SHA-256 .* is not that of record kobe_japan_1995_kjm_090"):
        library.read("kobe_japan_1995_kjm_090")
    with pytest.raises(RecordNotFoundError, match="stickslip records fetch --collection slammer"):
        library.read("kobe_japan_1995_kjm_000")


def test_record_store_keeps_missing_rows_and_samples(tmp_path):
    first = Record(np.array([0.1, -0.2, 0.3]), 0.01, RecordMeta(record_id="a", sha256="x" * 64, source="a.txt"))
    second = Record(np.array([1.0, 2.0]), 0.02, RecordMeta(record_id="c", source="c.txt"))
    rows = [StoredRecord("a", first, "ok"), StoredRecord("b", None, "missing", "not here"),
            StoredRecord("c", second, "ok")]
    path = write_record_store(rows, tmp_path / "store.nc")
    back = read_record_store(path)
    assert [row.record_id for row in back] == ["a", "b", "c"]
    assert back[1].record is None and back[1].reason == "not here"
    np.testing.assert_array_equal(back[2].record.acceleration, [1.0, 2.0])
    assert back[0].record.dt == 0.01 and back[0].record.meta.sha256 == "x" * 64


def test_records_list_of_a_collection_with_filters(run_cli):
    code, out, err = run_cli("records", "list", "--collection", "slammer", "--event", "Kobe",
                             "--max-rupture-distance", "1.2")
    assert code == 0, err
    lines = out.splitlines()
    assert lines[0].split()[:3] == ["id", "event", "record"]
    assert "kobe_japan_1995_kjm_090" in out and "tak" not in out
    assert lines[-1].startswith("4 records of the slammer collection (max rupture distance 1.2; events Kobe)")


def test_records_list_refuses_a_bad_pga_floor_in_one_line(run_cli):
    assert_one_error_line(*run_cli("records", "list", "--collection", "slammer", "--min-pga", "0.3G0"),
                          "--min-pga", "expected a number")


@pytest.fixture
def slammer_mirror(tmp_path, monkeypatch):
    """A local HTTP server holding two SLAMMER library files at the source repository's layout."""
    folder = shared_slammer_dir()
    root = tmp_path / "mirror"
    for name in ("Kobe, Japan 1995/KJM-090", "Kobe, Japan 1995/KJM-000"):
        target = root / SLAMMER_REPOSITORY / SLAMMER_COMMIT / "records" / name
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(folder / "records" / name, target)
    handler = functools.partial(_QuietHandler, directory=str(root))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    monkeypatch.setenv(MIRROR_ENV, f"http://127.0.0.1:{server.server_address[1]}")
    yield root
    server.shutdown()


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, format, *args):  # noqa: A002 - the base class's name
        pass


def test_fetch_downloads_checks_and_lays_out_a_slammer_folder(run_cli, slammer_mirror, tmp_path):
    out = tmp_path / "library"
    code, printed, err = run_cli("records", "fetch", "--collection", "slammer", "kobe_japan_1995_kjm_090",
                                 "kobe_japan_1995_kjm_000", "--out-dir", out, "--cache-dir", tmp_path / "cache")
    assert code == 0, err
    assert printed.splitlines() == [str(out / "records" / "Kobe, Japan 1995" / "KJM-090"),
                                    str(out / "records" / "Kobe, Japan 1995" / "KJM-000")]
    library = load_collection("slammer", out)
    assert library.local_ids() == ["kobe_japan_1995_kjm_000", "kobe_japan_1995_kjm_090"]
    assert library.read("kobe_japan_1995_kjm_090").npts > 1000


def test_download_of_a_changed_file_is_refused(slammer_mirror, tmp_path):
    served = slammer_mirror / SLAMMER_REPOSITORY / SLAMMER_COMMIT / "records" / "Kobe, Japan 1995" / "KJM-090"
    served.write_text("0.1\n0.2\n", encoding="utf-8")
    (tmp_path / "nothing").mkdir()
    library = load_collection("slammer", tmp_path / "nothing")
    with pytest.raises(RecordError, match="is not the SLAMMER library's Kobe, Japan 1995/KJM-090"):
        library.read("kobe_japan_1995_kjm_090", download=True, cache_dir=tmp_path / "cache")
