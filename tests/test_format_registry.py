"""Record formats are registry entries: a toy format, one reader and one entry, is detected, read and offered
by the command line; the built-in formats' facts come from their entries."""

from __future__ import annotations

import numpy as np
import pytest

from stickslip.records.formats import FORMATS, Parsed, RecordFormat, known_formats
from stickslip.records.readers import detect_format, read_record


def _read_semicolons(decoded, source):
    """Time [s] and acceleration [g] separated by a semicolon, one pair per line."""
    rows = np.array([[float(field) for field in line.split(";")] for line in decoded.lines if line.strip()])
    return Parsed(rows[:, 1], float(rows[1, 0] - rows[0, 0]), "g")


@pytest.fixture
def semicolons(monkeypatch):
    entry = RecordFormat("semicolon", "time;acceleration per line", lambda head: ";" in head.data_line,
                         _read_semicolons, columns=2, units="g")
    monkeypatch.setitem(FORMATS, "semicolon", entry)
    return entry


@pytest.fixture
def semicolon_file(tmp_path):
    path = tmp_path / "wave.ssv"
    time = np.arange(0.0, 4.0, 0.01)
    path.write_text("\n".join(f"{t:.2f};{0.2 * np.sin(2 * np.pi * t):.6f}" for t in time) + "\n", encoding="ascii")
    return path


def test_a_new_format_is_one_reader_and_one_entry(semicolons, semicolon_file, run_cli):
    assert detect_format(semicolon_file.read_text(), str(semicolon_file)) == "semicolon"
    record = read_record(semicolon_file)
    assert record.meta.format == "semicolon" and record.dt == 0.01 and record.npts == 400
    assert np.max(np.abs(record.acceleration)) == pytest.approx(0.2 * 9.81, rel=1e-5)
    assert "semicolon" in known_formats()
    code, out, err = run_cli("measures", semicolon_file, "--format", "semicolon", "--json")
    assert code == 0, err
    assert '"record": "wave"' in out


def test_without_its_entry_the_file_is_unknown(semicolon_file):
    from stickslip.errors import RecordError

    with pytest.raises(RecordError, match="unknown format: .*known formats: peer_at2, slammer_1col, time_acc_csv, "
                                          "two_column$"):
        read_record(semicolon_file)


def test_each_built_in_format_declares_its_columns_and_implied_units():
    assert {name: (entry.columns, entry.units) for name, entry in FORMATS.items()} == {
        "peer_at2": (1, None), "time_acc_csv": (2, "g"), "two_column": (2, None), "slammer_1col": (1, "g")}
