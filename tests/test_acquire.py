"""Record acquisition: local folder, pyslammer package data, download from a local HTTP mirror."""

from __future__ import annotations

import functools
import hashlib
import http.server
import shutil
import threading
from dataclasses import replace

import numpy as np
import pytest
import xarray as xr
import yaml

from stickslip.errors import RecordError, RecordNotFoundError, StickslipError
from stickslip.records import manifest as manifest_module
from stickslip.records.acquire import MIRROR_ENV, acquire, acquire_with_source
from stickslip.records.manifest import load_manifest
from stickslip.records.netcdf import read_record_netcdf, record_status
from stickslip.records.readers import read_record

KOBE_FILE = "SLAMMER_Kobe_1995_KJM-090.txt"


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, format, *args):  # noqa: A002 - the base class's name
        pass


@pytest.fixture
def mirror(tmp_path, paper_records_dir, monkeypatch):
    """A local HTTP mirror laid out as {repo}/{commit}/{path}, holding copies of the shared files.

    Returns the served root folder; ``STICKSLIP_MIRROR_URL`` points at the server.
    """
    root = tmp_path / "mirror"
    for entry in load_manifest().values():
        for source in entry.downloads:
            local = paper_records_dir / source.file
            if local.is_file():
                target = root / source.repo / source.commit / source.path
                target.parent.mkdir(parents=True, exist_ok=True)
                shutil.copyfile(local, target)
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(QuietHandler, directory=str(root)))
    thread = threading.Thread(target=server.serve_forever, kwargs={"poll_interval": 0.05}, daemon=True)
    thread.start()
    monkeypatch.setenv(MIRROR_ENV, f"http://127.0.0.1:{server.server_address[1]}")
    yield root
    server.shutdown()
    server.server_close()
    thread.join(timeout=5)


@pytest.fixture
def empty_dir(tmp_path):
    folder = tmp_path / "no_records"
    folder.mkdir()
    return folder


def test_local_folder_serves_the_full_length_chichi(paper_records_dir):
    acquired = acquire_with_source("chichi_chy080n", records_dir=paper_records_dir, download=False)
    assert acquired.source_kind == "local"
    assert acquired.location == str(paper_records_dir / "CHY080-N.AT2")
    assert acquired.record.npts == 18000
    assert acquired.record.meta.record_id == "chichi_chy080n"


def test_records_dir_from_the_environment(paper_records_dir, monkeypatch):
    monkeypatch.setenv("STICKSLIP_RECORDS_DIR", str(paper_records_dir))
    acquired = acquire_with_source("kobe_kjm090", download=False)
    assert acquired.source_kind == "local" and acquired.record.npts == 2232


def test_pyslammer_sample_serves_cape_mendocino_without_a_local_folder(empty_dir, paper_records_dir):
    acquired = acquire_with_source("cape_mendocino", records_dir=empty_dir, download=False)
    assert acquired.source_kind == "pyslammer"
    assert acquired.location == "pyslammer:Cape_Mendocino_1992_PET-090.csv"
    record = acquired.record
    assert (record.npts, record.dt, record.meta.record_id) == (1800, 0.02, "cape_mendocino")
    reference = read_record(paper_records_dir / "SLAMMER_Cape_Mendocino_1992_PET-090.txt")
    np.testing.assert_array_equal(record.acceleration, reference.acceleration)


def test_pyslammer_sample_keeps_its_own_id():
    record = acquire("pyslammer_kobe_1995_tak_090", download=False)
    assert record.meta.record_id == "pyslammer_kobe_1995_tak_090"
    assert record.meta.format == "time_acc_csv" and record.dt == 0.01


def test_download_from_a_local_mirror_checks_and_caches(mirror, empty_dir, tmp_path, paper_records_dir):
    cache = tmp_path / "cache"
    acquired = acquire_with_source("kobe_kjm090", records_dir=empty_dir, cache_dir=cache)
    assert acquired.source_kind == "download"
    assert acquired.location.endswith("/maddyblue/slammer/4b98d112a165defbe6c837bec37a68e5b56dd464/records/Kobe%2C%20Japan%201995/KJM-090")
    assert acquired.record.npts == 2232 and acquired.record.dt == 0.02
    assert (cache / KOBE_FILE).read_bytes() == (paper_records_dir / KOBE_FILE).read_bytes()
    # Served from the cache once the mirror no longer has the file.
    shutil.rmtree(mirror / "maddyblue")
    again = acquire_with_source("kobe_kjm090", records_dir=empty_dir, cache_dir=cache)
    np.testing.assert_array_equal(again.record.acceleration, acquired.record.acceleration)


def test_download_with_a_wrong_checksum_is_refused(mirror, empty_dir, tmp_path):
    source = load_manifest()["kobe_kjm090"].downloads[0]
    served = mirror / source.repo / source.commit / source.path
    served.write_bytes(served.read_bytes().replace(b"4.07603E-6", b"4.07604E-6", 1))
    found = hashlib.sha256(served.read_bytes()).hexdigest()
    cache = tmp_path / "cache"
    with pytest.raises(RecordError) as caught:
        acquire("kobe_kjm090", records_dir=empty_dir, cache_dir=cache)
    message = str(caught.value)
    assert message.startswith("http://127.0.0.1:")
    assert f"SHA-256 {found} is not a known version of record kobe_kjm090" in message
    assert load_manifest()["kobe_kjm090"].versions[0].sha256 in message
    assert not (cache / KOBE_FILE).exists()


def test_local_file_with_a_wrong_checksum_is_refused_unless_accepted(tmp_path, paper_records_dir):
    folder = tmp_path / "records"
    folder.mkdir()
    original = (paper_records_dir / KOBE_FILE).read_bytes()
    (folder / KOBE_FILE).write_bytes(original + b"0.0\n")
    found = hashlib.sha256((folder / KOBE_FILE).read_bytes()).hexdigest()
    with pytest.raises(RecordError, match=f"SHA-256 {found} is not a known version") as caught:
        acquire("kobe_kjm090", records_dir=folder, download=False)
    assert str(caught.value).startswith(str(folder / KOBE_FILE))
    assert hashlib.sha256(original).hexdigest() in str(caught.value)
    record = acquire("kobe_kjm090", records_dir=folder, download=False, accept_unknown=True)
    assert (record.npts, record.dt, record.meta.record_id) == (2233, 0.02, "kobe_kjm090")


def test_missing_record_says_how_to_obtain_it(empty_dir):
    with pytest.raises(RecordNotFoundError) as caught:
        acquire("mendoza_1985", records_dir=empty_dir)
    message = str(caught.value)
    assert "record mendoza_1985 not found" in message
    assert "mendoza_1985.AT2" in message and "INPRES" in message


def test_unreachable_mirror_ends_in_not_found(mirror, empty_dir, tmp_path):
    shutil.rmtree(mirror / "maddyblue")
    with pytest.raises(RecordNotFoundError, match=r"download http://127\.0\.0\.1:\d+/maddyblue/.*failed \(HTTPError\)"):
        acquire("coyote_g06_230", records_dir=empty_dir, cache_dir=tmp_path / "cache")


def test_unknown_record_id():
    with pytest.raises(StickslipError, match="unknown record id 'nope'"):
        acquire("nope", download=False)


def test_fetch_writes_netcdf_that_reads_back(run_cli, paper_records_dir, tmp_path):
    out_dir = tmp_path / "out"
    code, out, err = run_cli(
        "records", "fetch", "chichi_chy080n", "kobe_kjm090", "--records-dir", paper_records_dir, "--out-dir", out_dir,
        "--no-download",
    )
    assert (code, err) == (0, "")
    assert sorted(p.name for p in out_dir.iterdir()) == ["chichi_chy080n.nc", "kobe_kjm090.nc"]
    original = read_record(paper_records_dir / "CHY080-N.AT2")
    stored = read_record_netcdf(out_dir / "chichi_chy080n.nc")
    np.testing.assert_array_equal(stored.acceleration, original.acceleration)
    assert stored.dt == original.dt == 0.005
    entry = load_manifest()["chichi_chy080n"]  # the stored record is described as the manifest describes it
    assert stored.meta == replace(original.meta, event=entry.event, station=entry.station, component=entry.component)
    with xr.open_dataset(out_dir / "kobe_kjm090.nc", engine="netcdf4") as dataset:
        assert dataset["acceleration"].dims == ("time",)
        assert dataset["acceleration"].attrs["units"] == "m s-2"
        assert (dataset.attrs["year"], dataset.attrs["mw"]) == (1995, load_manifest()["kobe_kjm090"].mw)
        assert dataset["time"].attrs["units"] == "s"
        assert dataset.attrs["sha256"] == load_manifest()["kobe_kjm090"].versions[0].sha256
        assert dataset.attrs["format"] == "slammer_1col"
        assert dataset.attrs["source"] == str(paper_records_dir / KOBE_FILE)
        assert "stickslip_version" in dataset.attrs and "git_commit" in dataset.attrs


def test_fetch_without_ids_reports_the_missing_paper_records(run_cli, paper_records_dir, tmp_path):
    out_dir = tmp_path / "out"
    code, out, err = run_cli("records", "fetch", "--records-dir", paper_records_dir, "--out-dir", out_dir, "--no-download")
    assert (code, err) == (0, "")
    assert len(list(out_dir.glob("*.nc"))) == 8  # the two missing records are stored with their status
    assert "mendoza_1985: MISSING" in out and "parkfield_c02_360: MISSING" in out
    assert record_status(out_dir / "mendoza_1985.nc").startswith("missing: record mendoza_1985 not found")
    assert record_status(out_dir / "kobe_kjm090.nc") == "ok"


def test_fetch_of_a_named_missing_record_fails_in_one_line(run_cli, paper_records_dir, tmp_path):
    out_dir = tmp_path / "out"
    code, out, err = run_cli("records", "fetch", "mendoza_1985", "--records-dir", paper_records_dir,
                             "--out-dir", out_dir, "--no-download")
    assert code == 2 and out == "" and "record mendoza_1985 not found" in err and len(err.splitlines()) == 1
    assert not out_dir.exists() or not any(out_dir.iterdir())


def test_list_shows_where_each_record_is(run_cli, paper_records_dir, empty_dir):
    code, out, _ = run_cli("records", "list", "--records-dir", paper_records_dir)
    rows = {line.split()[0]: line for line in out.splitlines()[1:]}
    assert code == 0 and len(rows) == 26
    assert rows["chichi_chy080n"].endswith("local CHY080-N.AT2")
    assert rows["mendoza_1985"].endswith("missing")
    _, out, _ = run_cli("records", "list", "--records-dir", empty_dir)
    rows = {line.split()[0]: line for line in out.splitlines()[1:]}
    assert rows["cape_mendocino"].endswith("pyslammer Cape_Mendocino_1992_PET-090.csv")
    assert rows["kobe_kjm090"].endswith("download")


def test_validate_checks_known_files_against_expected_measures(run_cli, paper_records_dir):
    path = paper_records_dir / KOBE_FILE
    code, out, err = run_cli("records", "validate", path)
    assert (code, err) == (0, "")
    assert f"{path}: slammer_1col, npts=2232, dt=0.02 s" in out
    assert out.count(": ok") == 3 and "MISMATCH" not in out


def test_validate_reports_a_measure_mismatch(run_cli, tmp_path, monkeypatch, paper_records_dir):
    """A manifest whose expected PGA is off makes validate exit 1 and say MISMATCH."""
    document = yaml.safe_load(manifest_module.DEFAULT_MANIFEST.read_text(encoding="utf-8"))
    kobe = next(item for item in document["records"] if item["id"] == "kobe_kjm090")
    kobe["expected"]["pga"]["value"] *= 1.1
    altered = tmp_path / "records.yaml"
    altered.write_text(yaml.safe_dump(document), encoding="utf-8")
    monkeypatch.setattr(manifest_module, "DEFAULT_MANIFEST", altered)
    code, out, _ = run_cli("records", "validate", paper_records_dir / KOBE_FILE)
    assert code == 1
    assert "pga = 5.8714 m/s2" in out and "MISMATCH" in out
