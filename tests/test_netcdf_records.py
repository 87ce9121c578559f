"""Records in every form the tool writes: the NetCDF records of ``stickslip records fetch`` and the workflow.

``results/records/{id}.nc`` is a format of the reader's registry (``netcdf``,
recognised by its first bytes): every command reads it as a record, with the
metadata of its source (record id, event, station, component, dt, units and
provenance), and answers as for the source file itself.  A record stored
converted with one g and read with another is converted again, and says so.
The records are pyslammer's sample motions, so that a stranger runs every test.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from conftest import assert_one_error_line

from stickslip.errors import RecordNotFoundError
from stickslip.records.acquire import acquire
from stickslip.records.formats import FORMATS, binary_format
from stickslip.records.netcdf import write_missing_record
from stickslip.records.readers import read_record

RECORD_ID = "pyslammer_kobe_1995_tak_090"
SLAMMER_G = 9.80665


@pytest.fixture(scope="module")
def fetched(tmp_path_factory):
    """``stickslip records fetch`` of pyslammer's Kobe TAK-090 into a folder: the stored file and its source record."""
    from stickslip.cli import main

    folder = tmp_path_factory.mktemp("fetched")
    assert main(["records", "fetch", RECORD_ID, "--out-dir", str(folder), "--no-download"]) == 0
    return folder / f"{RECORD_ID}.nc", acquire(RECORD_ID, download=False)


def test_a_stored_record_is_a_format_read_with_its_metadata(fetched):
    stored, source = fetched
    assert binary_format(stored.read_bytes()) == "netcdf" and FORMATS["netcdf"].binary
    record = read_record(stored)
    np.testing.assert_array_equal(record.acceleration, source.acceleration)
    assert record.dt == source.dt == 0.01 and record.meta.stored_in == str(stored)
    for name in ("record_id", "event", "station", "component", "source", "sha256", "units", "format", "dt_source",
                 "gravity"):
        assert getattr(record.meta, name) == getattr(source.meta, name), name
    assert (record.meta.record_id, record.meta.station, record.meta.component, record.meta.units) == (
        RECORD_ID, "TAK", "090", "g")
    assert record.meta.event.startswith("Kobe")


@pytest.mark.parametrize("command", [
    ("measures", "--json"),
    ("solve", "--mu", "0.1", "--json"),
    ("solve", "--ky", "0.1", "--json"),
    ("optimum", "--mu", "0.02:0.4:0.02", "--json"),
    ("displacements", "--ky", "0.05,0.1", "--json"),
])
def test_every_command_answers_for_the_stored_record_as_for_its_source(run_cli, fetched, tmp_path, command):
    stored, source = fetched
    copy = tmp_path / "TAK-090.csv"  # the source's samples as the user's own file, in g
    np.savetxt(copy, np.column_stack([source.time, source.acceleration / 9.81]), delimiter=",",
               header="time (s),acceleration (g)", comments="", fmt=["%.3f", "%.17g"])
    code, from_stored, err = run_cli(command[0], stored, *command[1:])
    assert code == 0 and err == "", err
    code, from_copy, err = run_cli(command[0], copy, *command[1:])
    assert code == 0, err

    def numbers(document, path: str = "") -> dict[str, float]:
        """Every number of a JSON document by its path (``records.0.mu_max``)."""
        items = document.items() if isinstance(document, dict) else enumerate(document) if isinstance(document, list) else ()
        found = {path: float(document)} if isinstance(document, (int, float)) and not isinstance(document, bool) else {}
        for key, value in items:
            found.update(numbers(value, f"{path}.{key}"))
        return found

    expected = numbers(json.loads(from_copy))
    assert len(expected) > 5 and numbers(json.loads(from_stored)) == pytest.approx(expected, rel=1e-12)


def test_sweep_and_validate_read_a_stored_record(run_cli, fetched, tmp_path):
    stored, _ = fetched
    code, out, err = run_cli("sweep", stored, "--mu", "0.05:0.2:0.05", "--out", tmp_path / "cube.nc")
    assert code == 0 and err == "", err
    code, out, err = run_cli("records", "validate", stored)
    assert code == 0 and err == ""
    assert f"stored in {stored} (from pyslammer:Kobe_1995_TAK-090.csv)" in out and "station TAK; component 090" in out
    assert out.count(": ok") == 3  # the manifest's published measures, checked on the stored record


def test_a_stored_record_read_with_another_g_is_converted_again(fetched):
    stored, source = fetched
    record = read_record(stored, g=SLAMMER_G)
    direct = acquire(RECORD_ID, download=False, g=SLAMMER_G)
    np.testing.assert_allclose(record.acceleration, direct.acceleration, rtol=1e-15)
    assert record.meta.gravity == SLAMMER_G
    assert record.meta.processing == ("converted from g with g = 9.80665 m/s2 (stored converted with 9.81 m/s2)",)


def test_a_missing_or_broken_stored_record_is_one_line(run_cli, tmp_path):
    missing = write_missing_record("gone", "no source had it; put gone.AT2 in the records folder", tmp_path / "gone.nc")
    with pytest.raises(RecordNotFoundError, match="no source had it"):
        read_record(missing)
    assert_one_error_line(*run_cli("solve", missing, "--mu", "0.1"), "no source had it", "put gone.AT2")
    broken = tmp_path / "broken.nc"
    broken.write_bytes(missing.read_bytes()[:200])
    assert_one_error_line(*run_cli("measures", broken), broken, "not a readable NetCDF file")
    text = tmp_path / "text.txt"
    text.write_text("0.1\n0.2\n")
    assert_one_error_line(*run_cli("measures", text, "--format", "netcdf"), text, "not a readable NetCDF file")
