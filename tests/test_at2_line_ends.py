"""An AT2 file reads the same whatever ends its lines: LF, CR LF, CR CR LF (a CR LF file converted once more) or CR.

A CR CR LF file used to read as a blank line after every line, which pushed
the NPTS line past the header's first lines: "no NPTS line" for a file that
has one.
"""

from __future__ import annotations

import numpy as np
import pytest

from stickslip.records.readers import read_record_bytes

from conftest import FIXTURES


@pytest.mark.parametrize("line_end", [b"\n", b"\r\n", b"\r\r\n", b"\r"])
def test_an_at2_file_reads_the_same_with_any_line_ends(line_end):
    data = FIXTURES.joinpath("at2_nga_west2.AT2").read_bytes()
    lines = data.replace(b"\r\n", b"\n").split(b"\n")
    expected = read_record_bytes(data, "as_shipped.AT2")
    record = read_record_bytes(line_end.join(lines), "ends.AT2")
    assert (record.npts, record.dt, record.meta.component) == (13, 0.005, "230")
    np.testing.assert_array_equal(record.acceleration, expected.acceleration)


def test_a_blank_line_between_cr_lf_lines_is_still_a_blank_line():
    data = FIXTURES.joinpath("at2_nga_west2.AT2").read_bytes()
    header, _, values = data.partition(b"SEC")
    spaced = header + b"SEC" + values.replace(b"\r\n", b"\r\n\r\n", 1)  # a blank line before the values
    record = read_record_bytes(spaced, "spaced.AT2")
    assert record.npts == 13
