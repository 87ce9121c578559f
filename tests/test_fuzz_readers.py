"""A fuzz suite for every record reader: property-based round trips and a seeded mutation corpus.

Every case asserts its outcome: either the reader returns the right numbers
(the values written, or a prefix of them for a file cut at a line end that
no format can notice) with the right time step, or it raises our
:class:`RecordError`, which the command line turns into one line and exit 2.
No case may raise anything else, hang or give a number that is not finite.
"""

from __future__ import annotations

import json
import os
import random
import warnings
from dataclasses import dataclass

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from stickslip.constants import STANDARD_GRAVITY
from stickslip.errors import RecordError, StickslipWarning
from stickslip.records.numbers import compiled_conversion
from stickslip.records.readers import POSSIBLE_PGA, read_record, read_record_bytes

# The conversion fixture below is the same for every example of a case.
FUZZ_SETTINGS = settings(
    max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture]
)


@pytest.fixture(autouse=True, params=["numpy", "compiled"])
def conversion(request):
    """Every case twice: numbers converted by numpy, and by the compiled kernel (as read_records does)."""
    if request.param == "compiled":
        with compiled_conversion():
            yield
    else:
        yield


# --- writers of each format ---------------------------------------------------------------------------------


def fortran_e(value: float) -> str:
    """``value`` as Fortran's E14.7 writes it, without a leading blank: ``-.1000000E-01``, ``.0000000E+00``."""
    if value == 0.0:
        return ".0000000E+00"
    exponent = int(np.floor(np.log10(abs(value)))) + 1
    mantissa = round(abs(value) / 10.0**exponent * 1e7)
    if mantissa >= 10_000_000:
        mantissa, exponent = 1_000_000, exponent + 1
    return f"{'-' if value < 0 else ''}.{mantissa:07d}E{exponent:+03d}"


def write_number(value: float, style: str, decimals: int) -> str:
    if style == "fixed":
        return f"{value:.{decimals}f}"
    if style == "e":
        return f"{value:.{decimals}E}"
    if style == "d":
        return f"{value:.{decimals}E}".replace("E", "D")
    if style == "fortran":
        return fortran_e(value)
    return repr(value)


def as_float(token: str) -> float:
    return float(token.replace("D", "E"))


@dataclass(frozen=True)
class Written:
    """A record file and its truth: acceleration [m/s²], dt [s] and the read options it needs."""

    data: bytes
    acceleration: np.ndarray
    dt: float
    options: dict


def dress(lines: list[str], ending: str, bom: bool, ctrl_z: bool, final_newline: bool) -> bytes:
    text = ending.join(lines) + (ending if final_newline else "")
    return (b"\xef\xbb\xbf" if bom else b"") + text.encode("latin-1") + (b"\x1a" if ctrl_z else b"")


def write_at2(tokens: list[str], dt: float, per_line: int, glued: bool) -> list[str]:
    if glued:  # fixed width 13, as Fortran's E13.7: a negative value touches the one before it
        tokens = [f"{token:>13}" for token in tokens]
    body = [("" if glued else "  ").join(tokens[start:start + per_line]) for start in range(0, len(tokens), per_line)]
    return [
        "PEER STRONG MOTION DATABASE RECORD. PROCESSING BY PACIFIC ENGINEERING.",
        "FUZZ QUAKE 01/02/99, ESTACIÓN Ñ, N (NET)",
        "ACCELERATION TIME HISTORY IN UNITS OF G",
        f"NPTS= {len(tokens):6d}, DT= {dt:.5f} SEC",
        *body,
    ]


def write_csv(tokens: list[str], times: list[str], header_row: bool) -> list[str]:
    titles = ["time,acc (g)"] if header_row else ["# Time Series: Fuzz", "# Time (s),Acceleration (g's)"]
    return [*titles, *(f"{time},{token}" for time, token in zip(times, tokens))]


@st.composite
def written_records(draw) -> Written:
    """Any record file stickslip must read, with the numbers it must give."""
    format = draw(st.sampled_from(["peer_at2", "slammer_1col", "time_acc_csv", "two_column"]))
    magnitudes = st.floats(-3.0, 3.0, allow_nan=False).map(lambda value: 0.0 if abs(value) < 1e-30 else value)
    values = draw(st.lists(magnitudes, min_size=2, max_size=120))
    final_newline = draw(st.booleans())
    styles = ["fixed", "e", "d"] + (["fortran"] if format == "peer_at2" else []) + (["repr"] if final_newline else [])
    style = draw(st.sampled_from(styles))
    decimals = draw(st.integers(2, 9))
    tokens = [write_number(value, style, decimals) for value in values]
    truth = np.array([as_float(token) for token in tokens])
    assume(np.max(np.abs(truth)) >= POSSIBLE_PGA[0])  # a file of zeros holds no ground motion: refused
    dt = draw(st.sampled_from([0.005, 0.01, 0.02, 0.0025]))
    ending = draw(st.sampled_from(["\n", "\r\n", "\r"]))
    bom, ctrl_z = draw(st.booleans()), draw(st.booleans())
    if format == "peer_at2":
        glued = style == "fortran" and draw(st.booleans())
        lines = write_at2(tokens, dt, draw(st.integers(1, 8)), glued)
        options = {}
    elif format == "slammer_1col":
        lines, options = tokens, {"dt": dt}
    else:
        float32 = draw(st.booleans())
        times = [repr(float(np.float32(i * dt))) if float32 else f"{i * dt:.4f}" for i in range(len(tokens))]
        if format == "time_acc_csv":
            lines, options = write_csv(tokens, times, draw(st.booleans())), {}
        else:
            separator = draw(st.sampled_from([" ", "\t", "  ", ", "]))
            lines, options = [f"{time}{separator}{token}" for time, token in zip(times, tokens)], {"units": "g"}
    data = dress(lines, ending, bom, ctrl_z, final_newline)
    return Written(data, truth * STANDARD_GRAVITY, dt, options)


@FUZZ_SETTINGS
@given(written_records())
def test_every_well_formed_file_reads_to_the_numbers_written(written):
    record = read_record_bytes(written.data, "fuzz", manifest={}, **written.options)
    np.testing.assert_array_equal(record.acceleration, written.acceleration)
    assert record.dt == pytest.approx(written.dt, rel=1e-9)


@FUZZ_SETTINGS
@given(
    npts=st.integers(8, 3000),
    dt=st.sampled_from([0.001, 0.005, 0.01, 0.02, 1 / 3]),
    float32=st.booleans(),
    data=st.data(),
)
def test_a_time_column_missing_a_sample_is_refused(npts, dt, float32, data):
    """Uniform times read; the same times with one sample left out are refused, whatever their precision."""
    missing = data.draw(st.integers(1, npts - 2))
    times = np.arange(npts) * dt
    written = [repr(float(np.float32(t))) if float32 else f"{t:.6f}" for t in times]
    rows = [f"{time},0.01" for time in written]
    uniform = ("# Time (s),Acceleration (g)\n" + "\n".join(rows) + "\n").encode()
    assert read_record_bytes(uniform, "fuzz", manifest={}).dt == pytest.approx(dt, rel=1e-6)
    gap = ("# Time (s),Acceleration (g)\n" + "\n".join(rows[:missing] + rows[missing + 1:]) + "\n").encode()
    with pytest.raises(RecordError, match="non-uniform time step"):
        read_record_bytes(gap, "fuzz", manifest={})


# --- the seeded mutation corpus -----------------------------------------------------------------------------


def base_files() -> dict[str, Written]:
    """One small, well-formed file of each format (and a glued AT2), with its truth."""
    rng = np.random.default_rng(10)
    values = np.round(rng.normal(scale=0.2, size=23), 6)
    fixed = [f"{value:.6f}" for value in values]
    truth = np.array([float(token) for token in fixed]) * STANDARD_GRAVITY
    times = [f"{i * 0.01:.2f}" for i in range(values.size)]
    fortran = [fortran_e(value) for value in values]
    return {
        "at2": Written(dress(write_at2(fortran, 0.01, 5, False), "\n", False, False, True),
                       np.array([as_float(t) for t in fortran]) * STANDARD_GRAVITY, 0.01, {}),
        "at2_glued": Written(dress(write_at2(fortran, 0.01, 5, True), "\r\n", False, False, True),
                             np.array([as_float(t) for t in fortran]) * STANDARD_GRAVITY, 0.01, {}),
        "one_column": Written(dress(fixed, "\n", False, False, True), truth, 0.01, {"dt": 0.01}),
        "csv": Written(dress(write_csv(fixed, times, False), "\n", True, False, True), truth, 0.01, {}),
        "two_column": Written(dress([f"{t} {v}" for t, v in zip(times, fixed)], "\n", False, False, True),
                              truth, 0.01, {"units": "g"}),
    }


BASES = base_files()


def outcome(data: bytes, options: dict):
    """The record read from ``data``, or the RecordError; anything else fails the test."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", StickslipWarning)
            return read_record_bytes(data, "mutant", manifest={}, **options)
    except RecordError as error:
        assert "\n" not in str(error)
        return error


def assert_right_or_refused(result, base: Written, *, prefix_allowed: bool) -> None:
    """Our error, or the true numbers (a prefix of them only where a cut at a line end cannot be seen)."""
    if isinstance(result, RecordError):
        return
    values = result.acceleration
    assert np.all(np.isfinite(values))
    assert result.dt == pytest.approx(base.dt, rel=1e-9)
    if prefix_allowed:
        assert 2 <= values.size <= base.acceleration.size
        np.testing.assert_array_equal(values, base.acceleration[: values.size])
    else:
        np.testing.assert_array_equal(values, base.acceleration)


@pytest.mark.parametrize("name", sorted(BASES))
def test_the_bases_read_correctly(name):
    base = BASES[name]
    assert_right_or_refused(outcome(base.data, base.options), base, prefix_allowed=False)
    assert not isinstance(outcome(base.data, base.options), RecordError)


@pytest.mark.parametrize("name", sorted(BASES))
def test_truncation_at_every_byte(name):
    base = BASES[name]
    for end in range(len(base.data)):
        result = outcome(base.data[:end], base.options)
        assert_right_or_refused(result, base, prefix_allowed=True)
        if name.startswith("at2") and not isinstance(result, RecordError):
            assert base.data[end:].strip() == b""  # an AT2 file is whole or refused


def header_edits(lines: list[bytes], header_lines: int, rng: random.Random) -> list[tuple[str, list[bytes]]]:
    """Named edits of the header lines (deleted, duplicated, swapped, emptied) and junk inserted after line 1."""
    edits = []
    for index in range(header_lines):
        edits.append((f"delete line {index + 1}", lines[:index] + lines[index + 1:]))
        edits.append((f"duplicate line {index + 1}", lines[:index + 1] + lines[index:]))
        edits.append((f"empty line {index + 1}", lines[:index] + [b""] + lines[index + 1:]))
    if header_lines >= 2:
        edits.append(("swap lines 1 and 2", [lines[1], lines[0], *lines[2:]]))
    junk = rng.choice([b"NPTS=", b"DT=", b"nan", b"# comment", b"time,acc", b"\xff\xfe", b"PEER", b"UNITS OF FURLONGS"])
    edits.append((f"insert {junk!r}", [lines[0], junk, *lines[1:]]))
    return edits


NUMBER_EDITS = {
    # edit -> whether the value keeps its meaning
    "D exponent": (lambda t: t.replace(b"E", b"D"), True),
    "plus sign": (lambda t: t if t.startswith(b"-") else b"+" + t, True),
    "underscore": (lambda t: t[:2] + b"_" + t[2:], False),
    "nan": (lambda t: b"nan", False),
    "inf": (lambda t: b"-inf", False),
    "overflow": (lambda t: b"1e999", False),
    "double sign": (lambda t: b"--" + t.lstrip(b"-"), False),
    "two points": (lambda t: t + b".5", False),
    "decimal comma": (lambda t: t.replace(b".", b","), False),
    "arabic digit": (lambda t: "١".encode() + t, False),
    "hex": (lambda t: b"0x1F", False),
    "letter": (lambda t: t[:-1] + b"O", False),
    "exponent alone": (lambda t: b"E5", False),
    "nul byte": (lambda t: t + b"\x00", False),
    "control byte": (lambda t: t + b"\x07", False),
}


def data_token_spans(data: bytes, skip_lines: int) -> list[tuple[int, int]]:
    """(start, end) byte offsets of the numbers after the first ``skip_lines`` lines."""
    spans, offset = [], 0
    for number, line in enumerate(data.split(b"\n")):
        if number >= skip_lines:
            import re

            spans.extend((offset + m.start(), offset + m.end()) for m in re.finditer(rb"[^\s,]+", line))
        offset += len(line) + 1
    return spans


HEADER_LINES = {"at2": 4, "at2_glued": 4, "one_column": 0, "csv": 2, "two_column": 0}


@pytest.mark.parametrize("name", sorted(BASES))
def test_seeded_mutations(name):
    base = BASES[name]
    rng = random.Random(f"issue 10 {name}")
    lines = base.data.split(b"\n")
    for label, edited in header_edits(lines, HEADER_LINES[name], rng):
        result = outcome(b"\n".join(edited), base.options)
        assert_right_or_refused(result, base, prefix_allowed=False)
    spans = data_token_spans(base.data.replace(b"\r", b""), HEADER_LINES[name])
    data = base.data.replace(b"\r", b"")
    for label, (edit, keeps_meaning) in NUMBER_EDITS.items():
        for start, end in rng.sample(spans, 3):
            mutant = data[:start] + edit(data[start:end]) + data[end:]
            result = outcome(mutant, base.options)
            if name == "at2_glued" and label in ("plus sign", "double sign"):
                continue  # a sign inside glued values separates them: either outcome is a reading
            assert_right_or_refused(result, base, prefix_allowed=False)
            if not keeps_meaning:
                assert isinstance(result, RecordError), (label, mutant[start - 5:end + 5])


@pytest.mark.parametrize("name", sorted(BASES))
@pytest.mark.parametrize(
    "encode",
    [
        pytest.param(lambda d: d.replace(b"\n", b"\r\n"), id="crlf"),
        pytest.param(lambda d: d.replace(b"\n", b"\r"), id="cr"),
        pytest.param(lambda d: b"\xef\xbb\xbf" + d, id="bom"),
        pytest.param(lambda d: d + b"\x1a", id="ctrl-z"),
        pytest.param(lambda d: d + b"\n\n  \n", id="blank lines at the end"),
        pytest.param(lambda d: d.decode("latin-1").encode("utf-16"), id="utf-16"),
        pytest.param(lambda d: b"\x1a" + d, id="ctrl-z first"),
        pytest.param(lambda d: d.replace(b"\n", b"\n\x0c", 1), id="form feed"),
    ],
)
def test_encodings_and_line_ends(name, encode):
    base = BASES[name]
    data = base.data.replace(b"\r\n", b"\n")
    assert_right_or_refused(outcome(encode(data), base.options), base, prefix_allowed=False)


def test_accepted_encodings_read_every_base():
    for base in BASES.values():
        data = base.data.replace(b"\r\n", b"\n").removeprefix(b"\xef\xbb\xbf")
        for variant in (data.replace(b"\n", b"\r\n"), data.replace(b"\n", b"\r"), b"\xef\xbb\xbf" + data, data + b"\x1a"):
            assert not isinstance(outcome(variant, base.options), RecordError)


# --- special files, and the command line ---------------------------------------------------------------------


def special_files(folder) -> dict[str, str]:
    """Name -> path of files that are not regular record files."""
    fifo = folder / "pipe"
    os.mkfifo(fifo)
    (folder / "dir").mkdir()
    (folder / "empty").write_bytes(b"")
    (folder / "blank").write_bytes(b" \n\t\n")
    os.symlink(folder / "nowhere", folder / "dangling")
    os.symlink(folder / "dir", folder / "link-to-dir")
    part = folder / ".record.txt.host-1.abc.part"
    part.write_bytes(BASES["one_column"].data)
    paths = {name: str(folder / name) for name in ("pipe", "dir", "empty", "blank", "dangling", "link-to-dir")}
    paths["part"] = str(part)
    if os.path.exists("/dev/null"):
        paths["dev-null"] = "/dev/null"
    if os.path.exists("/dev/zero"):
        paths["dev-zero"] = "/dev/zero"
    return paths


def test_special_files_are_refused_by_the_reader_and_the_command_line(tmp_path, run_cli):
    for name, path in special_files(tmp_path).items():
        with pytest.raises(RecordError):
            read_record(path, dt=0.01)
        code, out, err = run_cli("measures", path, "--dt", "0.01", "--json")
        assert code == 2 and out == "" and len(err.splitlines()) == 1, name
        assert err.startswith("stickslip: error: ") and "Traceback" not in err


def test_a_symlink_to_a_record_is_read(tmp_path):
    target = tmp_path / "record.txt"
    target.write_bytes(BASES["one_column"].data)
    os.symlink(target, tmp_path / "link.txt")
    record = read_record(tmp_path / "link.txt", dt=0.01)
    np.testing.assert_array_equal(record.acceleration, BASES["one_column"].acceleration)


@pytest.mark.parametrize("name", sorted(BASES))
def test_the_command_line_gives_the_numbers_or_one_line_and_exit_2(tmp_path, run_cli, name):
    """A sample of the cut and mutated files through ``measures --json``: exit 0 with finite numbers, or 2 and one line."""
    base = BASES[name]
    rng = random.Random(f"cli {name}")
    options = [item for key, value in base.options.items() for item in (f"--{key}", str(value))]
    mutants = [base.data[: rng.randrange(len(base.data))] for _ in range(15)]
    mutants += [base.data.replace(b"0", b"O", 1), base.data + b"\x00", base.data.replace(b"\n", b"\n1_0\n", 6)]
    for index, mutant in enumerate(mutants):
        path = tmp_path / f"{name}-{index}.txt"
        path.write_bytes(mutant)
        code, out, err = run_cli("measures", path, "--json", *options)
        if code == 0:
            values = json.loads(out)
            assert values.pop("source") == str(path) and values.pop("record") == path.stem
            assert values.pop("vertical") is None
            assert values.pop("read") == {key: value for key, value in base.options.items()}  # as given
            assert set(values.pop("units")) == set(values)  # every measure's units, as text
            # null only for the mean period of a record with no frequency in its band
            assert all(np.isfinite(value) for key, value in values.items() if value is not None or key != "mean_period")
        else:
            assert code == 2 and out == "" and len(err.splitlines()) == 1, err
            assert err.startswith(f"stickslip: error: {path}") or "Arias" in err or "finite" in err
