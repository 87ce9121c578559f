"""A PEER velocity (.VT2) or displacement (.DT2) file is named as such, not as a file of unknown units.

PEER's downloads put the three series of a component side by side; given one
of the other two, the reader says what it is and what stickslip reads.
"""

from __future__ import annotations

import pytest
from conftest import FIXTURES, assert_one_error_line

from stickslip.errors import RecordError
from stickslip.records.readers import read_record_bytes


def other_series(units_line: bytes) -> bytes:
    """The NGA-West2 AT2 fixture with its units line replaced by ``units_line``."""
    data = FIXTURES.joinpath("at2_nga_west2.AT2").read_bytes()
    return data.replace(b"ACCELERATION TIME SERIES IN UNITS OF G", units_line)


@pytest.mark.parametrize(("units_line", "name", "what"), [
    (b"VELOCITY TIME SERIES IN UNITS OF CM/S", "RSN181_E06230.VT2", "velocity record (VEL, cm/s)"),
    (b"VELOCITY TIME SERIES IN UNITS OF CM/SEC", "RSN181_E06230.VT2", "velocity record (VEL, cm/s)"),
    (b"DISPLACEMENT TIME SERIES IN UNITS OF CM", "RSN181_E06230.DT2", "displacement record (DISP, cm)"),
    (b"TIME SERIES IN UNITS OF CM/S", "other.txt", "velocity record (VEL, cm/s)"),
])
def test_a_velocity_or_displacement_record_is_named_as_one(units_line, name, what):
    with pytest.raises(RecordError) as caught:
        read_record_bytes(other_series(units_line), name)
    assert str(caught.value) == f"{name}: the file is a PEER {what}; stickslip reads accelerations (.AT2)"


def test_the_command_line_says_so_in_one_line(run_cli, tmp_path):
    path = tmp_path / "RSN181_E06230.VT2"
    path.write_bytes(other_series(b"VELOCITY TIME SERIES IN UNITS OF CM/S"))
    assert_one_error_line(*run_cli("measures", path), str(path),
                          "the file is a PEER velocity record (VEL, cm/s); stickslip reads accelerations (.AT2)")
    with pytest.raises(RecordError, match="unknown units 'FURLONGS'"):  # other units stay unknown units
        read_record_bytes(other_series(b"ACCELERATION TIME SERIES IN UNITS OF FURLONGS"), "odd.AT2")
