"""The record manifest config/records.yaml: contents, checksums, expected measures, schema errors."""

from __future__ import annotations

import csv
import dataclasses
import hashlib
import re

import pytest
import yaml

from stickslip.errors import StickslipError
from stickslip.measures import intensity_measures
from stickslip.records.acquire import pyslammer_sample
from stickslip.records.formats import FORMATS
from stickslip.records.manifest import DEFAULT_MANIFEST, find_version, load_manifest
from stickslip.records.readers import read_record, read_record_bytes

PAPER_IDS = {
    "cape_mendocino",
    "chichi_chy080n",
    "coyote_g06_230",
    "coyote_g06_320",
    "kobe_kjm090",
    "mendoza_1985",
    "northridge_nwh090",
    "parkfield_c02_360",
}


def check_expected(entry, record):
    """Assert that the record's measures match the entry's expected values."""
    measures = intensity_measures(record).as_dict()
    assert set(entry.expected) == {"pga", "arias_intensity", "significant_duration"}
    for name, expected in entry.expected.items():
        assert expected.accepts(measures[name]), (entry.id, name, measures[name], expected)


def test_manifest_holds_the_paper_records_and_the_pyslammer_samples():
    manifest = load_manifest()
    assert PAPER_IDS <= set(manifest)
    pyslammer_ids = {record_id for record_id in manifest if record_id.startswith("pyslammer_")}
    assert len(pyslammer_ids) == 18
    assert "pyslammer_kobe_1995_tak_090" in pyslammer_ids
    assert len(manifest) == 26
    assert manifest["cape_mendocino"].mw == 7.01
    assert manifest["chichi_chy080n"].versions[0].file == "CHY080-N.AT2"  # full length preferred


def test_missing_records_say_how_to_obtain_them():
    manifest = load_manifest()
    assert "INPRES" in manifest["mendoza_1985"].obtain
    assert "NGA-West2" in manifest["parkfield_c02_360"].obtain
    assert manifest["mendoza_1985"].versions == ()


def test_shared_files_are_known_versions_with_their_npts_and_dt(shared_records):
    with open(shared_records / "manifest.csv", newline="", encoding="utf-8") as handle:
        rows = [row for row in csv.DictReader(handle) if row["paper_key"]]
    assert len(rows) == 8
    for row in rows:
        found = find_version(row["sha256"])
        assert found is not None, row["file"]
        entry, version = found
        assert entry.id == row["paper_key"]
        assert version.npts == int(row["npts"])
        assert version.format == row["format"]
        if version.format == "slammer_1col":
            assert version.dt == float(row["dt_s"])
        assert hashlib.sha256((shared_records / row["file"]).read_bytes()).hexdigest() == version.sha256


def test_expected_measures_hold_for_every_shared_version(paper_records_dir):
    manifest = load_manifest()
    checked = 0
    for path in sorted(paper_records_dir.iterdir()):
        record = read_record(path)
        check_expected(manifest[record.meta.record_id], record)
        checked += 1
    assert checked == 8


def test_pyslammer_samples_match_their_checksums_and_expected_measures():
    manifest = load_manifest()
    for entry in manifest.values():
        if not entry.id.startswith("pyslammer_"):
            continue
        resource = pyslammer_sample(entry.pyslammer_sample)
        assert resource is not None, entry.pyslammer_sample
        data = resource.read_bytes()
        version = entry.version_for(hashlib.sha256(data).hexdigest())
        assert version is not None, entry.id
        record = read_record_bytes(data, entry.pyslammer_sample, manifest=manifest)
        assert record.npts == version.npts
        check_expected(entry, record)


def test_download_urls_quote_the_path():
    source = load_manifest()["chichi_chy080n"].downloads[1]
    assert source.url() == (
        "https://raw.githubusercontent.com/maddyblue/slammer/4b98d112a165defbe6c837bec37a68e5b56dd464/"
        "records/Chi-Chi%2C%20Taiwan%201999/CHY080-000"
    )
    assert source.url("http://127.0.0.1:8000/").startswith("http://127.0.0.1:8000/maddyblue/slammer/")


def write_variant(tmp_path, change):
    document = yaml.safe_load(DEFAULT_MANIFEST.read_text(encoding="utf-8"))
    change(document)
    path = tmp_path / "records.yaml"
    path.write_text(yaml.safe_dump(document), encoding="utf-8")
    return path


@pytest.mark.parametrize(
    ("change", "message"),
    [
        (lambda d: d["records"][0].pop("versions"), "invalid at records/0: 'versions' is a required property"),
        (lambda d: d["records"][1]["versions"][0].update(sha256="abc"), "invalid at records/1/versions/0/sha256"),
        (lambda d: d["records"][0].update(format="mseed"), "invalid at records/0/format"),
        (lambda d: d["records"].append(dict(d["records"][0])), "duplicate ids: cape_mendocino"),
        (lambda d: d["records"][2]["versions"][0].pop("dt"), "needs dt"),
        (
            lambda d: d["records"][2]["sources"]["download"][0].update(file="other.txt"),
            "download file 'other.txt' is not one of its versions",
        ),
    ],
)
def test_invalid_manifest_gives_one_clear_error(tmp_path, change, message):
    path = write_variant(tmp_path, change)
    with pytest.raises(StickslipError, match=re.escape(message)) as caught:
        load_manifest(path)
    assert str(caught.value).startswith(str(path.resolve()))
    assert "\n" not in str(caught.value)


def test_manifest_that_is_not_yaml_or_missing(tmp_path):
    path = tmp_path / "records.yaml"
    path.write_text("records: [unclosed\n", encoding="utf-8")
    with pytest.raises(StickslipError, match="not valid YAML"):
        load_manifest(path)
    with pytest.raises(StickslipError, match="cannot read the record manifest"):
        load_manifest(tmp_path / "absent.yaml")


def test_whether_a_version_needs_dt_is_asked_of_its_format(tmp_path, monkeypatch):
    """A version of a format whose files state no time step needs dt; the manifest asks the format's entry."""
    (tmp_path / "one_column").mkdir()
    (tmp_path / "at2").mkdir()
    without_dt = write_variant(tmp_path / "one_column", lambda d: d["records"][2]["versions"][0].pop("dt"))
    as_shipped = write_variant(tmp_path / "at2", lambda d: None)
    monkeypatch.setitem(FORMATS, "slammer_1col", dataclasses.replace(FORMATS["slammer_1col"], states_dt=True))
    entry = list(load_manifest(without_dt).values())[2]
    assert entry.versions[0].format == "slammer_1col" and entry.versions[0].dt is None
    monkeypatch.setitem(FORMATS, "peer_at2", dataclasses.replace(FORMATS["peer_at2"], states_dt=False))
    with pytest.raises(StickslipError, match=r"invalid at \w+: version \S+\.AT2 \(peer_at2\) needs dt$"):
        load_manifest(as_shipped)
