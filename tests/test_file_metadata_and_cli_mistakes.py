"""Where a user meets the readers and the command line: per-file time step and metadata, and the smaller mistakes.

Per-file time step and metadata (mixed formats in one call, the SLAMMER library manifest, a wrong --dt),
the smaller mistakes (solve --target-pga 0.6g, solve --json, Newmark sweep time step, mu beyond the PGA,
'| head'), and the hostile-input classes decided as a careful user would.
"""

from __future__ import annotations

import csv
import hashlib
import io
import json
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
from conftest import assert_one_error_line

from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import RecordError, StickslipWarning
from stickslip.records import library
from stickslip.records.readers import read_record, read_record_bytes

G = STANDARD_GRAVITY
STICKSLIP = str(Path(sys.executable).with_name("stickslip"))
VALUES = 0.2 * np.sin(np.arange(400) / 7.0) * np.exp(-np.arange(400) / 150.0)  # [g]


def one_column(values=VALUES) -> bytes:
    return ("\n".join(f"{value:.6f}" for value in values) + "\n").encode()


def at2(npts_dt: str | None = None, body: str | None = None, values=VALUES, dt: float = 0.005) -> bytes:
    head = ["PEER NGA STRONG MOTION DATABASE RECORD", "Quake 2020, 1/2/2020, Station Q, 000",
            "ACCELERATION TIME SERIES IN UNITS OF G", npts_dt or f"NPTS= {len(values)}, DT= {dt:.4f} SEC"]
    if body is None:
        body = "\n".join("".join(f"{value:15.7E}" for value in values[start:start + 5])
                         for start in range(0, len(values), 5))
    return ("\n".join([*head, body]) + "\n").encode()


@pytest.fixture
def library_file(tmp_path, monkeypatch):
    """A one-column file and a SLAMMER library manifest (two rows) that knows it: dt 0.01 s, event and station."""
    data = one_column()
    sha256 = hashlib.sha256(data).hexdigest()
    manifest = (
        "id,event,year,record,file,sha256,bytes,dt,station\n"
        f"other_1999_x_000,Other 1999,1999,X-000,Other 1999/X-000,{'0' * 64},10,0.02,Elsewhere\n"
        f'test_quake_2001_abc_090,"Test Quake, Somewhere 2001",2001,ABC-090,Test 2001/ABC-090,{sha256},'
        f'{len(data)},0.01,"Alpha, Main St."\n'
    )
    monkeypatch.setattr(library, "_manifest_text", lambda: manifest)
    path = tmp_path / "ABC-090"
    path.write_bytes(data)
    return path


# --- per-file time step and metadata ----------------------------------------------------------------------------


def test_a_library_file_takes_dt_and_metadata_from_the_shipped_manifest(library_file):
    record = read_record(library_file)
    assert record.dt == 0.01 and record.meta.record_id == "test_quake_2001_abc_090"
    assert (record.meta.event, record.meta.station, record.meta.component) == (
        "Test Quake, Somewhere 2001", "Alpha, Main St.", "ABC-090")
    assert record.meta.dt_source.startswith("the SLAMMER library manifest")
    assert read_record(library_file, dt=0.01).dt == 0.01  # the same dt is fine


def test_a_wrong_dt_for_a_known_file_is_an_error_naming_both_values(run_cli, library_file):
    code, out, err = run_cli("measures", library_file, "--dt", "0.02")
    assert_one_error_line(code, out, err, library_file,
                          "the SLAMMER library manifest says dt = 0.01 s for this file (record test_quake_2001_abc_090) "
                          "but dt = 0.02 s was given")


def test_files_of_different_formats_mix_in_one_call(run_cli, library_file, tmp_path):
    at2_path = tmp_path / "quake.AT2"
    at2_path.write_bytes(at2())
    for command in (("measures",), ("records", "validate"), ("solve", "--mu", "0.05")):
        for path in (library_file, at2_path):
            code, out, err = run_cli(*command, path)
            assert code == 0 and err == "", (command, err)
    code, out, err = run_cli("measures", library_file, at2_path, "--json")  # one JSON object per file and line
    assert code == 0 and err == "", err
    rows = [json.loads(line) for line in out.splitlines()]
    assert [row["record"] for row in rows] == ["test_quake_2001_abc_090", "quake"]
    for row, path in zip(rows, (library_file, at2_path)):  # each the same as measuring the file alone
        assert json.loads(run_cli("measures", path, "--json")[1]) == row
    code, out, err = run_cli("solve", library_file, at2_path, "--mu", "0.05", "--json")
    assert code == 0 and err == "", err
    solved = [json.loads(line) for line in out.splitlines()]
    assert [row["source"] for row in solved] == [str(library_file), str(at2_path)]
    for row, path in zip(solved, (library_file, at2_path)):  # each the same as solving the file alone
        code, alone, _ = run_cli("solve", path, "--mu", "0.05", "--json")
        assert json.loads(alone) == row
    code, out, err = run_cli("solve", library_file, at2_path, "--mu", "0.05", "--out", tmp_path / "two.nc")
    assert code == 2 and out == "" and "--out writes the time histories of one record, but 2 files" in err
    assert not (tmp_path / "two.nc").exists()
    code, out, err = run_cli("records", "validate", library_file, at2_path)
    assert code == 0, err
    assert "record test_quake_2001_abc_090: event Test Quake, Somewhere 2001; station Alpha, Main St.; " \
           "component ABC-090; dt from the SLAMMER library manifest" in out
    assert "record quake: event Quake 2020; station Station Q; component 000; dt from the file" in out
    cube_path = tmp_path / "cube.nc"
    code, out, err = run_cli("sweep", library_file, at2_path, "--mu", "0.02:0.1:0.02", "--out", cube_path)
    assert code == 0, err
    cube = xr.load_dataset(cube_path)  # the metadata reach the cube
    assert list(cube.event.values) == ["Test Quake, Somewhere 2001", "Quake 2020"]
    assert list(cube.station.values) == ["Alpha, Main St.", "Station Q"]
    code, out, err = run_cli("optimum", library_file, at2_path, "--json")
    assert code == 0, err
    assert [row["dt"] for row in json.loads(out)["records"]] == [0.01, 0.005]


def test_dt_given_for_a_mix_is_refused_for_the_file_that_states_its_own(run_cli, library_file, tmp_path):
    at2_path = tmp_path / "quake.AT2"
    at2_path.write_bytes(at2())
    code, out, err = run_cli("optimum", library_file, at2_path, "--dt", "0.01")
    assert_one_error_line(code, out, err, at2_path, "the file says dt = 0.005 s but dt = 0.01 s was given")


def test_two_files_with_one_record_id_are_named(run_cli, tmp_path):
    first, second = tmp_path / "a" / "x.AT2", tmp_path / "b" / "x.AT2"
    for path in (first, second):
        path.parent.mkdir()
        path.write_bytes(at2())
    code, out, err = run_cli("optimum", first, second)
    assert_one_error_line(code, out, err, first, f"and {second} have the same record id 'x'")
    code, out, err = run_cli("sweep", first, first, "--mu-list", "0.1", "--out", tmp_path / "cube.nc")
    assert_one_error_line(code, out, err, first, "is given twice")


def test_a_file_that_no_manifest_knows_still_needs_dt(run_cli, tmp_path):
    path = tmp_path / "unknown.txt"
    path.write_bytes(one_column(VALUES * 1.5))
    code, out, err = run_cli("solve", path, "--mu", "0.1")
    assert_one_error_line(code, out, err, path, "no time step: a slammer_1col file has none and no manifest knows "
                                                "this file; pass --dt in seconds")


def test_the_shipped_library_manifest_knows_its_files_by_sha256():
    rows = list(csv.DictReader(io.StringIO(library._manifest_text())))
    assert len(rows) == 2133
    for row in (rows[0], rows[-1]):
        known = library.library_file(row["sha256"])
        assert (known.record_id, known.dt, known.station, known.units) == (row["id"], float(row["dt"]), row["station"], "g")
    assert library.library_file("f" * 64) is None and library.library_file("") is None


# --- smaller mistakes -------------------------------------------------------------------------------------------


@pytest.fixture
def record_file(tmp_path):
    path = tmp_path / "quake.AT2"
    path.write_bytes(at2())
    return path


def test_solve_takes_a_target_pga_in_g(run_cli, record_file):
    _, in_g, _ = run_cli("solve", record_file, "--mu", "0.05", "--target-pga", "0.6g", "--json")
    _, in_si, _ = run_cli("solve", record_file, "--mu", "0.05", "--target-pga", f"{0.6 * G}m/s2", "--json")
    assert json.loads(in_g)["energy_dissipated"] == json.loads(in_si)["energy_dissipated"] > 0


def test_solve_json_echoes_the_case_with_units(run_cli, record_file):
    code, out, err = run_cli("solve", record_file, "--mu", "0.05", "--mass", "2", "--method", "newmark", "--json")
    assert code == 0, err
    document = json.loads(out)
    assert (document["record"], document["source"], document["mu"], document["mass"], document["method"]) == (
        "quake", str(record_file), 0.05, 2.0, "newmark")
    assert (document["dt"], document["dt_source"], document["time_step"], document["g"]) == (0.005, "the file", 0.001, G)
    units = document["units"]
    assert (units["dt"], units["mass"], units["time_step"], units["energy_dissipated"], units["mu"]) == (
        "s", "kg", "s", "J", "1")
    assert all(name in units for name, value in document.items() if isinstance(value, (int, float)))


def test_a_newmark_sweep_cube_records_its_time_step(run_cli, record_file, tmp_path):
    cube_path = tmp_path / "cube.nc"
    code, _, err = run_cli("sweep", record_file, "--mu", "0.05:0.1:0.05", "--method", "newmark", "--time-step",
                           "0.0025", "--out", cube_path)
    assert code == 0, err
    cube = xr.load_dataset(cube_path)
    assert cube.attrs["solver"] == "newmark" and cube.attrs["solver_time_step"] == 0.0025
    assert cube.attrs["solver_time_step_units"] == "s" and cube.attrs["solver_reading"] == "converging"
    code, out, err = run_cli("sweep", record_file, "--mu", "0.05", "--time-step", "0.001", "--out", cube_path)
    assert_one_error_line(code, out, err, "--time-step", "applies to --method newmark only")


def test_a_mu_whose_friction_exceeds_the_pga_gets_a_note(run_cli, record_file, tmp_path):
    pga = float(np.max(np.abs(VALUES))) * G  # about 0.19 g
    code, out, err = run_cli("solve", record_file, "--mu", "0.5", "--json")
    assert code == 0 and json.loads(out)["energy_dissipated"] == 0.0
    assert err == (f"stickslip: note: {record_file}: the block never slides at mu = 0.5: its PGA {pga:.4g} m/s2 "
                   f"({pga / G:.4g} g) is at most mu*g = {0.5 * G:.4g} m/s2 at mu = 0.5, so E_df = 0 there\n")
    code, _, err = run_cli("sweep", record_file, "--mu", "0.1:0.5:0.1", "--out", tmp_path / "cube.nc")
    assert code == 0 and err.count("\n") == 1
    assert "the block never slides at the 4 friction ratios from 0.2 to 0.5" in err


def test_a_closed_pipe_ends_the_command_quietly(tmp_path):
    path = tmp_path / "long.txt"
    path.write_text("\n".join(f"{value:.6f}" for value in np.resize(VALUES, 5000)) + "\n")
    with subprocess.Popen([STICKSLIP, "records", "validate", "--dt", "0.01", *[str(path)] * 4000],
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE) as process:
        process.stdout.readline()
        process.stdout.close()  # as `| head -1` does
        stderr = process.stderr.read()
        code = process.wait(timeout=60)
    assert (code, stderr) == (141, b"")


# --- hostile inputs, decided as a careful user would -------------------------------------------------------------


@pytest.mark.parametrize(("value", "phrase"), [
    ("1e160", "line 7: value 1e+160 g is a PGA of 1e+160 g, more than 100 g, which no ground motion comes near"),
    ("150.0", "line 7: value 150 g is a PGA of 150 g, more than 100 g"),
])
def test_an_absurd_pga_is_refused_naming_its_line(value, phrase):
    data = ("0.1\n0.2\n-0.1\n0.05\n0.0\n-0.2\n" + value + "\n0.1\n").encode()
    with pytest.raises(RecordError, match=phrase.replace("+", r"\+")):
        read_record_bytes(data, "x.txt", dt=0.01, manifest={})


def test_a_pga_beyond_any_recorded_warns_about_units():
    with pytest.warns(StickslipWarning, match="line 2: PGA 8.8 g if the values are in g; 0.897 g if they are in m/s2"):
        read_record_bytes(b"0.1\n8.8\n-0.3\n", "x.txt", dt=0.01, manifest={})


@pytest.mark.parametrize(("values", "phrase"), [
    ("5e-324\n-4.9e-324\n1e-320\n", "a PGA of 1e-320 g, below the 1e-06 g that an accelerograph resolves"),
    ("1e-300\n-2e-300\n", "below the 1e-06 g"),
    ("0.0\n0.0\n0.0\n", "every acceleration is zero: the file holds no ground motion"),
])
def test_a_record_without_ground_motion_is_refused(run_cli, tmp_path, values, phrase):
    path = tmp_path / "silent.txt"
    path.write_text(values)
    code, out, err = run_cli("solve", path, "--dt", "0.01", "--mu", "0.1")
    assert_one_error_line(code, out, err, path, phrase)


@pytest.mark.parametrize(("dt", "phrase"), [("1.0E-9", "time step dt = 1e-09 s (the file) is outside the 1e-06 to 10 s"),
                                            ("1.0E6", "time step dt = 1e+06 s (the file) is outside the 1e-06 to 10 s")])
def test_an_impossible_time_step_is_refused(run_cli, tmp_path, dt, phrase):
    path = tmp_path / "bad.AT2"
    path.write_bytes(at2(npts_dt=f"NPTS= {VALUES.size}, DT= {dt} SEC"))
    code, out, err = run_cli("measures", path)
    assert_one_error_line(code, out, err, path, phrase)


@pytest.mark.parametrize("npts", ["400.0", "400.", "400.000"])
def test_npts_written_with_a_zero_fraction_is_read(npts):
    record = read_record_bytes(at2(npts_dt=f"NPTS= {npts}, DT= 0.0050 SEC"), "x.AT2", manifest={})
    assert record.npts == 400


def test_values_separated_by_commas_are_read():
    body = "\n".join(", ".join(f"{value:.7E}" for value in VALUES[start:start + 5]) + ","
                     for start in range(0, VALUES.size, 5))
    record = read_record_bytes(at2(body=body), "x.AT2", manifest={})
    np.testing.assert_array_equal(record.acceleration, np.array([float(f"{value:.7E}") for value in VALUES]) * G)


@pytest.mark.parametrize("body", ["0,0123  0,0456", ",1234567E-01  .1E-01", "0.1,,0.2"])
def test_a_comma_that_separates_nothing_or_a_decimal_comma_is_refused(body):
    values = "\n".join(["  .1000000E-01  .2000000E-01"] + [body])
    with pytest.raises(RecordError, match="line 6: a comma that does not separate two values"):
        read_record_bytes(at2(npts_dt="NPTS= 4, DT= 0.0050 SEC", body=values), "x.AT2", manifest={})


@pytest.mark.parametrize(("dt", "style"), [(0.004, "%.7g"), (0.005, "%.6E"), (0.0025, "%.5E"), (1 / 3, "%.5E")])
def test_a_time_column_rounded_in_print_is_read(dt, style):
    times = (np.arange(2000) * np.float32(dt)).astype(np.float32).astype(float)
    rows = "\n".join(f"{style % time},{value:.6f}" for time, value in zip(times, np.resize(VALUES, times.size)))
    record = read_record_bytes(f"# Time (s),Acceleration (g)\n{rows}\n".encode(), "x.csv", manifest={})
    assert record.dt == pytest.approx(dt, rel=1e-5) and record.npts == 2000
    missing = rows.split("\n")
    del missing[1200]  # a missing sample is still refused
    with pytest.raises(RecordError, match="non-uniform time step"):
        read_record_bytes(("# Time (s),Acceleration (g)\n" + "\n".join(missing) + "\n").encode(), "x.csv", manifest={})


def test_warnings_are_not_errors_for_usual_records():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert read_record_bytes(at2(), "x.AT2", manifest={}).npts == VALUES.size
