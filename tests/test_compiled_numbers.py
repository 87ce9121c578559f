"""The compiled conversion of record text: the values of np.fromstring and float, bit for bit, and read_records."""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from stickslip.errors import RecordError, StickslipError
from stickslip.records.compiled_numbers import convert
from stickslip.records.readers import read_record, read_records

digits = st.text("0123456789", min_size=1, max_size=24)
numbers = st.builds(
    lambda sign, whole, point, fraction, exponent: sign + whole + point + fraction + exponent,
    st.sampled_from(["", "-", "+"]),
    digits,
    st.sampled_from(["", "."]),
    st.text("0123456789", max_size=24),
    st.one_of(st.just(""), st.builds(lambda e, s, d: e + s + d, st.sampled_from("EeDd"), st.sampled_from(["", "-", "+"]),
                                     st.integers(0, 400).map(str))),
)


def bits(values) -> np.ndarray:
    return np.asarray(values, dtype=np.float64).view(np.int64)


@settings(max_examples=500, deadline=None)
@given(st.lists(st.one_of(numbers, st.floats(allow_nan=False, allow_infinity=False).map(repr)), min_size=1, max_size=20),
       st.sampled_from([" ", "\n", "\t", "  \n"]))
def test_well_formed_text_converts_as_float_does(tokens, separator):
    text = separator.join(tokens) + "\n"
    expected = [float(token.replace("D", "E").replace("d", "e")) for token in tokens]
    np.testing.assert_array_equal(bits(convert(text.encode())), bits(expected))


@pytest.mark.parametrize("text", [b"1.2.3", b"1-2", b"--1", b"1e", b"1E+", b".", b"-", b"1 # c", b"1,2", b"1\r\n2",
                                  b"nan", b"inf", b"0x1F", b"1_0", b"E5"])
def test_text_that_is_not_plainly_numbers_is_left_to_the_careful_reader(text):
    assert convert(text) is None


def test_blank_text_has_no_numbers():
    assert convert(b"").size == 0
    assert convert(b" \n\t\n").size == 0


def slammer_files(folder: Path, count: int) -> tuple[list[Path], list[float]]:
    """About ``count`` files of the shared SLAMMER near-fault records in ``folder``, and their time steps [s]."""
    with open(folder / "eq.sql", newline="", encoding="utf-8") as handle:
        dt_of = {(row[0], row[1]): float(row[2]) for row in csv.reader(handle, delimiter="\t")}
    paths = sorted((folder / "records").glob("*/*"))[:: max(1, 521 // count)]
    return paths, [dt_of[(path.parent.name, path.name)] for path in paths]


def test_read_records_equals_read_record_file_by_file(shared_records):
    paths, dts = slammer_files(shared_records / "slammer", 60)
    records = read_records(paths, dts, format="slammer_1col", units="g")
    for path, dt, record in zip(paths, dts, records, strict=True):
        one = read_record(path, format="slammer_1col", dt=dt, units="g")
        np.testing.assert_array_equal(bits(record.acceleration), bits(one.acceleration))
        assert (record.dt, record.meta) == (one.dt, one.meta)


def test_read_records_gives_read_records_error_message(tmp_path):
    bad = tmp_path / "bad.txt"
    bad.write_text("0.1\n0.2\n0.3x\n0.4\n")
    with pytest.raises(RecordError) as one:
        read_record(bad, dt=0.01, units="g")
    with pytest.raises(RecordError) as bulk:
        read_records([bad], [0.01], units="g")
    assert str(bulk.value) == str(one.value)
    assert "line 3" in str(one.value)


def test_read_records_wants_a_time_step_per_file(tmp_path):
    with pytest.raises(StickslipError, match="2 files but 1 time steps"):
        read_records([tmp_path / "a", tmp_path / "b"], [0.01])
