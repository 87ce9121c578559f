"""Hostile and damaged input (cut files, overflowing values, pipes, size and memory limits, odd encodings), kept as regression tests.

Every case ends in the right numbers or in our one-line error with exit 2.
"""

from __future__ import annotations

import json
import os
import warnings

import numpy as np
import pytest
from conftest import assert_one_error_line

from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import RecordError, StickslipError, StickslipWarning
from stickslip.records.readers import read_record, read_record_bytes
from stickslip.records.record import Record
from stickslip.models import solve

VALUES = np.array([0.01, -0.02, 0.03, -0.04, 0.05, -0.06, 0.07, -0.08, 0.09, -0.10, 0.11, -0.12, 0.13])


def at2(npts_dt: str = "NPTS=    13, DT= .01000 SEC", values: str | None = None, head: tuple[str, ...] | None = None) -> bytes:
    """An NGA-West1 AT2 file of :data:`VALUES` (g) with the given NPTS/DT line."""
    if head is None:
        head = (
            "PEER STRONG MOTION DATABASE RECORD. PROCESSING BY PACIFIC ENGINEERING.",
            "TEST QUAKE 01/02/99, STATION A, N (NET)",
            "ACCELERATION TIME HISTORY IN UNITS OF G",
        )
    if values is None:
        values = "\n".join(
            "".join(f"{value:15.7E}" for value in VALUES[start:start + 5]) for start in range(0, VALUES.size, 5)
        )
    text = "\n".join([*head, npts_dt, values]) + "\n"
    return text.encode("latin-1" if all(ord(char) < 256 for char in text) else "utf-8")


def csv(title: str = "# Time (s),Acceleration (g's)", values=VALUES, dt: float = 0.01, time_format: str = "{:.2f}") -> bytes:
    rows = [f"{time_format.format(i * dt)},{value:.6f}" for i, value in enumerate(values)]
    return ("\n".join(["# Time Series: Test", title, *rows]) + "\n").encode()


# --- silently wrong ---------------------------------------------------------------------------------------


def test_csv_title_in_m_per_s_per_s_is_read_as_m_per_s2():
    record = read_record_bytes(csv("# Time (s),Acceleration (m/s/s)", VALUES * 50), "x.csv", manifest={})
    np.testing.assert_allclose(record.acceleration, VALUES * 50, rtol=1e-12)


def test_csv_title_in_unknown_units_is_refused_not_read_as_g():
    with pytest.raises(RecordError, match=r"names units 'in/s\^2' that stickslip does not know"):
        read_record_bytes(csv("# Time (s),Acceleration (in/s^2)"), "x.csv", manifest={})


@pytest.mark.parametrize("token", ["1_0", "nan", "inf", "-Infinity", "0x10", "١", "1.0e", "--1", "1.2.3", "1-2"])
def test_tokens_python_would_accept_are_refused_with_their_line(token):
    values = "  .1000000E-01" * 5 + f"\n {token} " + "  .1000000E-01" * 7
    with pytest.raises(RecordError, match="line 6: "):
        read_record_bytes(at2(values=values), "x.AT2", manifest={})


def test_a_value_that_overflows_in_m_per_s2_names_its_line():
    data = "\n".join(["0.1"] * 4 + ["1e308"] + ["0.1"] * 3) + "\n"
    with pytest.raises(RecordError, match="line 5: value 1e\\+308 overflows to infinity in m/s2"):
        read_record_bytes(data.encode(), "x.txt", dt=0.01, manifest={})


def test_a_value_beyond_double_precision_is_not_finite():
    with pytest.raises(RecordError, match="line 2: value inf is not a finite number"):
        read_record_bytes(b"0.1\n1e400\n0.2\n", "x.txt", dt=0.01, manifest={})


@pytest.mark.parametrize(("values", "dt"), [([0.1, 0.2, 1e200, 0.1], 0.01), ([0.1, 0.2, 0.3], 1e-300)])
def test_measures_json_never_prints_infinity(run_cli, tmp_path, values, dt):
    path = tmp_path / "huge.txt"
    path.write_text("\n".join(map(repr, values)) + "\n")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", StickslipWarning)
        code, out, err = run_cli("measures", path, "--dt", repr(dt), "--json")
    if code == 0:
        document = json.loads(out)
        document.pop("units")  # the units of the measures: text
        # null only for a measure that is undefined (the mean period of a record with no frequency in its band)
        assert all(np.isfinite(value) for key, value in document.items() if value is not None or key != "mean_period")
    else:
        assert code == 2 and out == "" and "Infinity" not in out and len(err.splitlines()) >= 1
        assert err.splitlines()[-1].startswith("stickslip: error: ")


def test_solve_refuses_results_that_are_not_finite():
    record = Record(np.array([0.0, 1e300, -1e300, 1e300, 0.0]), dt=0.01)
    with pytest.raises(StickslipError, match="not finite"):
        solve(record, mu=0.1)


def test_sweep_writes_no_cube_with_inf_or_nan(run_cli, tmp_path):
    path = tmp_path / "record.txt"
    path.write_text("0.1\n-0.2\n0.3\n-0.1\n0.0\n")
    out_path = tmp_path / "cube.nc"  # scaled by 1e160, the squares of the accelerations overflow
    code, out, err = run_cli("sweep", path, "--dt", "0.01", "--mu", "0.1:0.2:0.1", "--scale", "1e160", "--out", out_path)
    assert code == 2 and "not finite" in err
    assert not out_path.exists()


@pytest.mark.parametrize("cut", ["0.0", "0.04", "-", "0.0456", "4.5E-0"])
def test_one_column_file_cut_in_its_last_number_is_noticed(cut):
    data = "0.012345\n-0.023456\n0.034567\n1.23456E-04\n" + cut
    with pytest.raises(RecordError, match="line 5: "):
        read_record_bytes(data.encode(), "x.txt", dt=0.01, manifest={})


def test_one_column_file_without_a_final_newline_but_whole_is_read():
    record = read_record_bytes(b"0.012345\n-0.023456\n0.034567", "x.txt", dt=0.01, units="m/s2", manifest={})
    np.testing.assert_array_equal(record.acceleration, [0.012345, -0.023456, 0.034567])


def test_csv_cut_in_its_last_number_is_noticed():
    data = csv()[:-3]
    with pytest.raises(RecordError, match="looks cut short"):
        read_record_bytes(data, "x.csv", manifest={})


def test_a_known_record_cut_at_a_line_end_is_noticed_from_the_manifest(tmp_path, paper_records_dir):
    name = "SLAMMER_Kobe_1995_KJM-090.txt"
    lines = (paper_records_dir / name).read_text().splitlines(keepends=True)
    copy = tmp_path / name
    copy.write_text("".join(lines[:-100]))
    with pytest.raises(RecordError, match=r"2132 samples read, but the known file .* has 2232: the file looks cut short"):
        read_record(copy, dt=0.02)


# --- hangs and unbounded memory ----------------------------------------------------------------------------


def test_a_named_pipe_is_refused_without_blocking(run_cli, tmp_path):
    fifo = tmp_path / "record.fifo"
    os.mkfifo(fifo)
    code, out, err = run_cli("measures", fifo, "--dt", "0.01")
    assert_one_error_line(code, out, err, fifo, "is a named pipe, not a regular file")


@pytest.mark.skipif(not os.path.exists("/dev/zero"), reason="no /dev/zero")
def test_dev_zero_is_refused(run_cli):
    code, out, err = run_cli("measures", "/dev/zero", "--dt", "0.01")
    assert_one_error_line(code, out, err, "/dev/zero", "is a device, not a regular file")


def test_a_file_over_the_size_limit_is_refused(run_cli, tmp_path):
    path = tmp_path / "big.txt"
    path.write_text("0.1\n" * 1000)
    code, out, err = run_cli("measures", path, "--dt", "0.01", "--max-file-size", "1K")
    assert_one_error_line(code, out, err, path, "larger than the limit of 1 KiB")


def test_newmark_with_a_tiny_time_step_is_refused_before_allocating(run_cli, paper_records_dir):
    path = paper_records_dir / "SLAMMER_Kobe_1995_KJM-090.txt"
    code, out, err = run_cli("solve", path, "--mu", "0.1", "--method", "newmark", "--time-step", "1e-7")
    assert code == 2 and out == ""
    assert "would need about" in err and "--memory-limit" in err and len(err.splitlines()) == 1


def test_a_sweep_over_the_memory_limit_is_refused(run_cli, paper_records_dir, tmp_path):
    path = paper_records_dir / "SLAMMER_Kobe_1995_KJM-090.txt"
    code, out, err = run_cli(
        "sweep", path, "--mu", "0.01:0.4:0.0001", "--out", tmp_path / "c.nc", "--memory-limit", "600K"
    )
    assert code == 2 and "a sweep of 1 record(s) x 1 scaling(s) x 3,901 friction ratios would need" in err


# --- tracebacks and unclear messages -----------------------------------------------------------------------


@pytest.mark.parametrize(
    ("line", "phrase"),
    [
        ("NPTS=    13, DT= . SEC", "line 4: DT='.' is not a positive number of seconds"),
        ("NPTS=    13, DT= 0.005.1 SEC", "DT='0.005.1' is not a positive number"),
        ("NPTS=    13, DT= E-3 SEC", "DT='E-3' is not a positive number"),
        ("NPTS=    13, DT=- .005 SEC", "DT='-' is not a positive number"),
        ("NPTS=    13, DT= NaN SEC", "DT='NaN' is not a positive number"),
        ("NPTS=    13, DT= -0.01 SEC", "DT='-0.01' is not a positive number"),
        ("NPTS= -18000, DT= .01 SEC", "NPTS='-18000' is not a whole number"),
        ("NPTS= abc, DT= .01 SEC", "NPTS='abc' is not a whole number"),
        ("NPTS= 1e12, DT= .01 SEC", "NPTS='1e12' is not a whole number"),
        ("NPTS= 13.5, DT= .01 SEC", "NPTS='13.5' is not a whole number"),
        ("NPTS= 99999999999, DT= .01 SEC", "NPTS='99999999999' is not a whole number"),
    ],
)
def test_bad_npts_or_dt_fields_are_named(run_cli, tmp_path, line, phrase):
    path = tmp_path / "bad.AT2"
    path.write_bytes(at2(line))
    code, out, err = run_cli("measures", path, "--json")
    assert_one_error_line(code, out, err, path, phrase)


def test_latin1_header_text_is_read():
    head = (
        "PEER STRONG MOTION DATABASE RECORD. PROCESSING BY PACIFIC ENGINEERING.",
        "TEST QUAKE 01/02/99, ESTACIÓN AÑO, N (NET)",
        "ACCELERATION TIME HISTORY IN UNITS OF G",
    )
    record = read_record_bytes(at2(head=head), "x.AT2", manifest={})
    assert record.meta.station == "ESTACIÓN AÑO"
    np.testing.assert_allclose(record.acceleration, VALUES * STANDARD_GRAVITY, rtol=1e-12)


def test_non_uniform_time_message_shows_distinct_numbers():
    times = np.arange(20) * 0.02
    times[10:] += 0.005
    rows = "\n".join(f"{t:.4f},0.1" for t in times)
    with pytest.raises(RecordError) as caught:
        read_record_bytes(f"# Time (s),Acceleration (g)\n{rows}\n".encode(), "x.csv", manifest={})
    message = str(caught.value)
    assert "line 12: non-uniform time step: 0.025 s between t=0.18 s and t=0.205 s, where the other steps are 0.02 s" in message


@pytest.mark.parametrize(
    ("args", "phrase"),
    [
        (("--dt", "abc"), "argument --dt: 'abc': expected a number with its unit, such as 1s, 1ms, 1min or a bare number "
                          "in s"),
        (("--format", "nonsense"), "argument --format: invalid choice: 'nonsense'"),
        (("--memory-limit", "lots"), "argument --memory-limit"),
    ],
)
def test_bad_options_are_one_line(run_cli, paper_records_dir, args, phrase):
    code, out, err = run_cli("measures", paper_records_dir / "SLAMMER_Kobe_1995_KJM-090.txt", *args)
    assert code == 2 and out == "" and len(err.splitlines()) == 1
    assert err.startswith("stickslip: error: stickslip measures: ") and phrase in err


# --- too strict where real files are valid -----------------------------------------------------------------


def test_a_float32_time_column_is_accepted():
    dt = 0.005
    times = (np.arange(6000) * dt).astype(np.float32)
    rows = "\n".join(f"{float(t)!r},{value:.6f}" for t, value in zip(times, np.resize(VALUES, times.size)))
    record = read_record_bytes(f"# Time (s),Acceleration (g)\n{rows}\n".encode(), "x.csv", manifest={})
    assert record.dt == dt and record.npts == 6000


def fortran_e(value: float) -> str:
    """``value`` as Fortran's E14.7 writes it: ``-.1000000E-01``, a leading blank only for a positive value."""
    exponent = int(np.floor(np.log10(abs(value)))) + 1
    return f"{'-' if value < 0 else ' '}.{round(abs(value) / 10.0**exponent * 1e7):07d}E{exponent:+03d}"


def test_glued_fixed_width_fortran_values_are_split():
    values = "\n".join("".join(fortran_e(-value) for value in VALUES[start:start + 5]) for start in range(0, 13, 5))
    assert "E-01-." in values
    record = read_record_bytes(at2(values=values), "x.AT2", manifest={})
    np.testing.assert_allclose(record.acceleration, -VALUES * STANDARD_GRAVITY, rtol=1e-12)


def test_a_time_acc_header_row_is_accepted():
    rows = "\n".join(f"{i * 0.01:.2f},{value}" for i, value in enumerate(VALUES))
    record = read_record_bytes(f"time,acc\n{rows}\n".encode(), "x.csv", manifest={})
    assert record.meta.format == "time_acc_csv" and record.dt == 0.01
    np.testing.assert_allclose(record.acceleration, VALUES * STANDARD_GRAVITY, rtol=1e-12)


def test_a_trailing_dos_end_of_file_byte_is_accepted():
    record = read_record_bytes(at2() + b"\x1a", "x.AT2", manifest={})
    np.testing.assert_allclose(record.acceleration, VALUES * STANDARD_GRAVITY, rtol=1e-12)


def test_an_unusual_time_step_warns_in_one_line(run_cli, tmp_path):
    path = tmp_path / "slow.AT2"
    path.write_bytes(at2("NPTS=    13, DT= 2.0 SEC"))
    code, out, err = run_cli("measures", path, "--json")
    assert code == 0
    assert err == f"stickslip: warning: {path}: time step dt = 2 s is outside the usual 0.0001 to 1 s of " \
        "strong-motion records; check that it is in seconds\n"


def test_the_event_is_not_taken_from_the_units_line_when_the_first_line_is_missing():
    head = ("TEST QUAKE 01/02/99, STATION A, N (NET)", "ACCELERATION TIME HISTORY IN UNITS OF G")
    record = read_record_bytes(at2(head=head), "x.AT2", manifest={})
    assert (record.meta.event, record.meta.station, record.meta.component) == ("TEST QUAKE", "STATION A", "N")
    no_description = read_record_bytes(at2(head=head[1:]), "x.AT2", manifest={})
    assert no_description.meta.event == ""


@pytest.mark.parametrize(("args", "phrase"), [(("--scale", "1e308"), "scaling by 1e+308 overflows"),
                                              (("--target-pga", "1e300"), "more than 100 g, which no ground motion")])
def test_solve_with_an_overflowing_scale_is_one_line(run_cli, paper_records_dir, args, phrase):
    code, out, err = run_cli("solve", paper_records_dir / "SLAMMER_Kobe_1995_KJM-090.txt", "--mu", "0.1", "--json", *args)
    assert code == 2 and out == "" and len(err.splitlines()) == 1 and phrase in err
