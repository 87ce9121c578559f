"""Record readers: every shared record, both AT2 header variants, pySLAMMER CSV, two-column text."""

from __future__ import annotations

import csv
import warnings

import numpy as np
import pytest

from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import RecordError, StickslipWarning
from stickslip.records.acquire import pyslammer_sample
from stickslip.records.readers import detect_format, normalize_units, read_record, read_record_bytes

from conftest import FIXTURES

#: The values written in the hand-made AT2 fixtures, in g.
AT2_VALUES_G = np.array([0.01, -0.02, 0.03, -0.04, 0.05, -0.06, 0.07, -0.08, 0.09, -0.10, 0.11, -0.12, 0.13])


def shared_rows(shared_records):
    with open(shared_records / "manifest.csv", newline="", encoding="utf-8") as handle:
        return list(csv.DictReader(handle))


def test_every_shared_record_matches_the_shared_manifest(shared_records):
    rows = shared_rows(shared_records)
    assert len(rows) == 9
    for row in rows:
        record = read_record(shared_records / row["file"])
        assert record.meta.format == row["format"], row["file"]
        assert record.npts == int(row["npts"]), row["file"]
        assert record.dt == pytest.approx(float(row["dt_s"]), rel=1e-12), row["file"]
        assert record.meta.units == row["units"] == "g"
        assert record.meta.sha256 == row["sha256"]
        assert record.meta.source == str(shared_records / row["file"])
        if row["paper_key"]:
            assert record.meta.record_id == row["paper_key"]


def test_slammer_chichi_is_a_window_of_the_at2_to_six_significant_figures(paper_records_dir):
    full = read_record(paper_records_dir / "CHY080-N.AT2")
    window = read_record(paper_records_dir / "SLAMMER_Chi-Chi_1999_CHY080-000.txt")
    assert window.npts == 17349 - 3991 + 1
    np.testing.assert_allclose(window.acceleration, full.acceleration[3991:17350], rtol=5.0e-6, atol=0.0)
    # Shifted by one sample, the two do not agree: the test can tell windows apart.
    assert not np.allclose(window.acceleration, full.acceleration[3992:17351], rtol=5.0e-6, atol=0.0)


def test_slammer_petrolia_equals_the_pyslammer_csv(paper_records_dir):
    one_column = read_record(paper_records_dir / "SLAMMER_Cape_Mendocino_1992_PET-090.txt")
    csv_file = read_record(paper_records_dir / "pySLAMMER_Cape_Mendocino_1992_PET-090.csv")
    assert csv_file.dt == one_column.dt == 0.02
    np.testing.assert_array_equal(csv_file.acceleration, one_column.acceleration)
    assert (one_column.meta.format, csv_file.meta.format) == ("slammer_1col", "time_acc_csv")


def test_chichi_at2_header_and_conversion_to_si(paper_records_dir):
    record = read_record(paper_records_dir / "CHY080-N.AT2")
    assert (record.meta.event, record.meta.station, record.meta.component) == ("CHI-CHI", "CHY080", "N")
    # First and last values of the file (the last line must not be dropped).
    assert record.acceleration[0] == pytest.approx(0.4646742e-05 * STANDARD_GRAVITY, rel=1e-12)
    assert record.acceleration[-1] == pytest.approx(0.1271108e-04 * STANDARD_GRAVITY, rel=1e-12)


def test_nga_west2_sample_keeps_its_partial_last_line(shared_records):
    record = read_record(shared_records / "formats" / "RSN181_IMPVALL.H_H-E06230.AT2")
    assert record.npts == 7818
    assert record.acceleration[-1] == pytest.approx(0.8345234e-03 * STANDARD_GRAVITY, rel=1e-12)
    assert (record.meta.event, record.meta.station, record.meta.component) == (
        "Imperial Valley-06",
        "El Centro Array #6",
        "230",
    )
    assert record.meta.record_id == "RSN181_IMPVALL.H_H-E06230"


@pytest.mark.parametrize(
    ("name", "dt", "description"),
    [
        ("at2_nga_west1.AT2", 0.01, ("TEST QUAKE", "STATION A", "N")),
        ("at2_nga_west2.AT2", 0.005, ("Test Quake-02", "Station B #6", "230")),
        ("at2_old_npts_dt.AT2", 0.02, ("OLD QUAKE", "OLD STATION", "180")),
    ],
)
def test_at2_header_variants(name, dt, description):
    record = read_record(FIXTURES / name)
    assert record.meta.format == "peer_at2"
    assert record.dt == dt
    expected = np.abs(AT2_VALUES_G) if name.startswith("at2_old") else AT2_VALUES_G
    expected = -expected if name == "at2_nga_west2.AT2" else expected
    np.testing.assert_allclose(record.acceleration, expected * STANDARD_GRAVITY, rtol=1e-12)
    assert (record.meta.event, record.meta.station, record.meta.component) == description
    assert record.meta.units == "g"


def test_pyslammer_csv_with_byte_order_mark_and_crlf():
    record = read_record(FIXTURES / "pyslammer_bom_crlf.csv")
    assert record.meta.format == "time_acc_csv"
    assert record.dt == 0.02
    np.testing.assert_allclose(record.acceleration, np.array([0.01, -0.02, 0.03, -0.04, 0.05]) * STANDARD_GRAVITY)


@pytest.mark.parametrize("name", ["Northridge_1994_VSP-360.csv", "Coyote_Lake_1979_G02-050.csv"])
def test_pyslammer_package_files_with_bom_or_crlf(name):
    resource = pyslammer_sample(name)
    assert resource is not None, "pyslammer sample motions are not installed"
    data = resource.read_bytes()
    assert b"\r\n" in data
    record = read_record_bytes(data, name)
    assert record.meta.format == "time_acc_csv"
    assert record.dt == 0.005
    assert record.npts == len([line for line in data.splitlines() if line.strip()]) - 2


def test_two_column_text_needs_units_and_converts_them(tmp_path):
    untitled = tmp_path / "untitled.txt"
    untitled.write_text("".join((FIXTURES / "two_column.txt").read_text().splitlines(keepends=True)[1:]))
    with pytest.raises(RecordError, match="units unknown"):
        read_record(untitled)
    for path, units in ((untitled, "gal"), (FIXTURES / "two_column.txt", None)):  # its title says cm/s2
        record = read_record(path, units=units)
        assert record.meta.format == "two_column"
        assert record.dt == 0.01
        np.testing.assert_allclose(record.acceleration, [0.10, -0.20, 0.30, -0.40, 0.50], rtol=1e-12)
        assert record.meta.units == "cm/s2"


@pytest.mark.parametrize(
    ("spelling", "canonical"),
    [("g", "g"), ("G", "g"), ("g's", "g"), ("m/s^2", "m/s2"), ("M/S2", "m/s2"), ("cm/s²", "cm/s2"), ("gal", "cm/s2")],
)
def test_unit_aliases(spelling, canonical):
    assert normalize_units(spelling, "file") == canonical


def test_unknown_units_are_refused():
    with pytest.raises(RecordError, match="unknown units 'ft/s2'"):
        normalize_units("ft/s2", "file")


def test_one_column_dt_from_argument_or_manifest(tmp_path, paper_records_dir):
    path = tmp_path / "copy_with_other_bytes.txt"
    path.write_text("0.01\n-0.02\n0.03\n", encoding="utf-8")
    with pytest.raises(RecordError, match="no time step"):
        read_record(path)
    record = read_record(path, dt=0.01)
    assert record.dt == 0.01 and record.meta.record_id == "copy_with_other_bytes"
    known = read_record(paper_records_dir / "SLAMMER_Kobe_1995_KJM-090.txt")
    assert known.dt == 0.02 and known.meta.record_id == "kobe_kjm090"
    assert known.meta.station == "KJMA"


def test_given_dt_that_contradicts_the_header_is_refused():
    with pytest.raises(RecordError, match="file says dt = 0.01 s but dt = 0.02 s was given"):
        read_record(FIXTURES / "at2_nga_west1.AT2", dt=0.02)


def test_given_units_that_contradict_the_header_are_refused():
    with pytest.raises(RecordError, match="file says units g but units 'm/s2' were given"):
        read_record(FIXTURES / "at2_nga_west1.AT2", units="m/s2")


def test_fortran_d_exponents_are_read(tmp_path):
    path = tmp_path / "fortran.txt"
    path.write_text("0.1D-01\n-0.2D-01\n0.3d-01\n", encoding="utf-8")
    record = read_record(path, dt=0.01, units="g")
    np.testing.assert_allclose(record.acceleration, np.array([0.01, -0.02, 0.03]) * STANDARD_GRAVITY)


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("PEER NGA STRONG MOTION DATABASE RECORD\nx\ny\nNPTS= 2, DT= .01 SEC\n1 2\n", "peer_at2"),
        ("# comment\n0.0,0.1\n0.1,0.2\n", "time_acc_csv"),
        ("0.0 0.1\n0.1 0.2\n", "two_column"),
        ("0.0,0.1\n0.1,0.2\n", "two_column"),
        ("0.1\n0.2\n", "slammer_1col"),
    ],
)
def test_format_detection(text, expected):
    assert detect_format(text, "file") == expected


@pytest.mark.parametrize("rows", ["0,00;0,0123\n0,01;-0,0200\n", "0.00;0.0123\n0.01;-0.0200\n"])
def test_a_spreadsheets_semicolon_columns_are_refused_saying_how_to_save_them(tmp_path, rows):
    path = tmp_path / "export.csv"
    path.write_text(f"time;acc\n{rows}", encoding="utf-8")
    with pytest.raises(RecordError, match="separated by semicolons, as a spreadsheet writes them where the decimal "
                                          "mark is a comma: save it with commas or blanks"):
        read_record(path)


def test_unknown_format_lists_the_known_ones():
    with pytest.raises(RecordError, match="known formats: netcdf, peer_at2, slammer_1col, time_acc_csv, two_column"):
        detect_format("a b c\n", "file")
    with pytest.raises(RecordError, match="unknown format 'mseed'"):
        read_record(FIXTURES / "two_column.txt", format="mseed")


def test_pyslammer_csv_header_states_its_units():
    assert read_record(FIXTURES / "pyslammer_bom_crlf.csv", units="g").meta.units == "g"
    assert read_record(FIXTURES / "pyslammer_bom_crlf.csv", units="g's").meta.units == "g"
    with pytest.raises(RecordError, match="the file says units g but units 'cm/s2' were given"):
        read_record(FIXTURES / "pyslammer_bom_crlf.csv", units="cm/s2")


@pytest.mark.parametrize(
    ("title", "units"),
    [
        ("time,acc_ms2", "m/s2"),
        ("time [s],acceleration [m/s2]", "m/s2"),
        ("t,a (m/s^2)", "m/s2"),
        ("t [s] a [m s-2]", "m/s2"),
        ("time_s,accel_cm_s2", "cm/s2"),
        ("time; acc (gal)", "cm/s2"),
        ("# Time (s),Acceleration (g's)", "g"),
        ("time,acc [g]", "g"),
    ],
)
def test_a_column_title_that_names_the_units_gives_them(tmp_path, title, units):
    """A CSV whose title says m/s2 or cm/s2 is read in them, not in the format's g: 0.15 g in m/s2 is not 1.47 g."""
    factor = {"g": 1.0, "m/s2": STANDARD_GRAVITY, "cm/s2": 100.0 * STANDARD_GRAVITY}[units]
    path = tmp_path / "titled.csv"
    rows = "".join(f"{0.01 * i:.2f},{0.15 * factor * np.sin(0.3 * i):.6f}\n" for i in range(200))
    path.write_text(f"{title}\n{rows}", encoding="utf-8")
    record = read_record(path)
    assert record.meta.format == "time_acc_csv" and record.meta.units == units
    assert np.max(np.abs(record.acceleration)) / STANDARD_GRAVITY == pytest.approx(0.15, rel=1e-4)


@pytest.mark.parametrize("title", ["time,acceleration", "time,acc_x", "time,acc_g", "# Time series",
                                   "# T1, Dayhook (DAY)"])
def test_a_title_that_names_no_units_leaves_the_formats_own(tmp_path, title):
    """``acc_g`` may be the ground's acceleration in any unit: it states none, and --units m/s2 may say which."""
    path = tmp_path / "untitled.csv"
    path.write_text(f"{title}\n" + "".join(f"{0.01 * i:.2f},{0.2 * np.sin(0.3 * i):.6f}\n" for i in range(200)),
                    encoding="utf-8")
    assert read_record(path).meta.units == "g"
    assert read_record(path, units="m/s2").meta.units == "m/s2"


@pytest.mark.parametrize(("title", "seconds"), [("time [ms],acc [g]", 1e-3), ("t_ms,a_g", 1e-3),
                                              ("Time (s),Acceleration (g)", 1.0), ("time,acc", 1.0)])
def test_a_time_title_in_milliseconds_gives_the_step_in_seconds(tmp_path, title, seconds):
    """A shake table's log in ms, 10 ms apart, is sampled at 0.01 s, not 10 s."""
    path = tmp_path / "table.csv"
    path.write_text(f"{title}\n" + "".join(f"{10.0 * i:.1f},{0.2 * np.sin(0.3 * i):.6f}\n" for i in range(200)),
                    encoding="utf-8")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        record = read_record(path)
    assert record.dt == pytest.approx(10.0 * seconds, rel=1e-12)
    assert bool(caught) == (seconds == 1.0)  # 10 s between samples is doubted: "check that it is in seconds"
    path.write_text("time [min],acc [g]\n0,0.1\n1,0.2\n", encoding="utf-8")
    with pytest.raises(RecordError, match="names time units 'min' that stickslip does not know"):
        read_record(path)


def test_a_second_title_naming_an_unknown_acceleration_unit_is_refused(tmp_path):
    path = tmp_path / "inches.csv"
    path.write_text("t,a (in/s^2)\n0.00,0.1\n0.01,0.2\n0.02,0.1\n", encoding="utf-8")
    with pytest.raises(RecordError, match="names units 'in/s\\^2' that stickslip does not know"):
        read_record(path)


def test_given_dt_or_units_that_contradict_the_manifest_are_refused(paper_records_dir):
    path = paper_records_dir / "SLAMMER_Kobe_1995_KJM-090.txt"
    assert read_record(path, dt=0.02, units="g").dt == 0.02  # the same values are fine
    with pytest.raises(RecordError, match="the manifest says dt = 0.02 s for this version of record kobe_kjm090 "
                                          "but dt = 0.01 s was given"):
        read_record(path, dt=0.01)
    with pytest.raises(RecordError, match="the manifest says units g for this version of record kobe_kjm090 "
                                          "but units 'm/s2' were given"):
        read_record(path, units="m/s2")


def _time_column_file(path, times, values):
    """A time-and-acceleration CSV [s, g] with its times printed to six decimals."""
    lines = ["# Time Series: jitter test", "# Time (s),Acceleration (g's)"]
    lines += [f"{t:.6f},{a:.6f}" for t, a in zip(times, values)]
    path.write_text("\n".join(lines) + "\n", encoding="ascii")
    return path


def test_a_time_column_printed_with_jitter_within_one_percent_of_dt_is_read_as_uniform(tmp_path):
    dt, n = 0.005, 2001
    jitter = np.random.default_rng(3).uniform(-0.004, 0.004, n) * dt  # up to 0.4 % of a step
    jitter[[0, -1]] = 0.0
    times = np.arange(n) * dt + jitter
    times[1] = dt - 0.000004  # a step of 0.004996 s, as printed by a clock with rounding jitter
    values = 0.2 * np.sin(2 * np.pi * np.arange(n) * dt)
    record = read_record(_time_column_file(tmp_path / "jitter.csv", times, values))
    assert record.dt == dt and record.npts == n


@pytest.mark.parametrize(("off", "phrase"), [
    (0.015, "line 303: t=1.50008 s lies 1.5% of a step off the uniform grid of step 0.005 s through the first and "
            "last times (up to 1% is taken as rounding)"),
    (0.5, "line 303: non-uniform time step: 0.0075 s between t=1.495 s and t=1.502 s, where the other steps are "
          "0.005 s (up to 1% of a step off the grid is taken as rounding)"),
])
def test_a_time_column_more_than_one_percent_off_the_grid_is_refused_naming_the_line(tmp_path, off, phrase):
    dt, n = 0.005, 1001
    times = np.arange(n) * dt
    times[300] += off * dt  # on line 303 (two title lines, then sample 1 on line 3)
    path = _time_column_file(tmp_path / "skewed.csv", times, 0.1 * np.sin(np.arange(n) * dt))
    with pytest.raises(RecordError) as raised:
        read_record(path)
    assert str(raised.value) == f"{path}: {phrase}"


def test_a_blank_line_among_one_column_values_is_skipped_with_a_warning_naming_it(tmp_path):
    path = tmp_path / "gappy.txt"
    path.write_text("0.01\n0.02\n\n0.03\n-0.01\n\n0.02\n\n", encoding="ascii")
    with pytest.warns(StickslipWarning, match=r"gappy.txt: line 3: blank line among the values skipped "
                                              r"\(2 blank lines in all\); a one-column file has no time column"):
        record = read_record(path, dt=0.01)
    assert record.npts == 5
    path.write_text("0.01\n0.02\n0.03\n\n\n", encoding="ascii")  # blank lines after the last value are no gap
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert read_record(path, dt=0.01).npts == 3


def test_records_validate_notes_the_blank_line_and_a_user_s_own_file_without_alarm(run_cli, tmp_path):
    path = tmp_path / "gappy.txt"
    path.write_text("0.01\n0.02\n\n0.03\n-0.01\n", encoding="ascii")
    code, out, err = run_cli("records", "validate", path, "--dt", "0.01")
    assert code == 0
    assert err.splitlines() == [f"stickslip: warning: {path}: line 3: blank line among the values skipped; a "
                                "one-column file has no time column, so a missing value would shift every later "
                                "sample"]
    assert "dt given, values in g" in out and "as for any file of your own" in out and "SHA-256" not in out
