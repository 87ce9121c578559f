"""Strict, fast reading of the numbers in the text of a record file.

A number is written ``[+-]digits[.digits][E|D[+-]digits]`` with ASCII digits
(a Fortran ``D`` exponent reads as ``E``).  Nothing else is a number: not
Python's ``1_0``, ``nan``, ``inf``, hexadecimal or non-ASCII digits.  Values
are separated by blanks, tabs or commas.  Fixed-width Fortran output whose
values touch (``-.1000047E+00-.1000046E+00``) is split at each sign that
starts a value with a decimal point.

The text is first checked and converted as a whole (about the speed of
``np.loadtxt``; inside :func:`compiled_conversion`, by the numba kernel of
:mod:`stickslip.records.compiled_numbers`, three times faster); only when that
fails is it read again line by line, to name the line and the value that is
wrong.  Text here has ``\\n`` line ends.
"""

from __future__ import annotations

import contextlib
import contextvars
import re
import warnings

import numpy as np

from stickslip.errors import RecordError

#: A number, in full.
NUMBER = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[EeDd][+-]?[0-9]+)?")

_GLUED_PART = re.compile(r"[+-]?(?:[0-9]+\.[0-9]*|\.[0-9]+)(?:[EeDd][+-]?[0-9]+)?")
_NUMERIC_BYTES = b"0123456789eEdD.+-, \t\n"
_D_TO_E = str.maketrans("Dd", "Ee")
_D_TO_E_BYTES = bytes.maketrans(b"Dd", b"Ee")
_NON_FINITE_WORDS = {"nan", "inf", "infinity"}
#: How many values before the last one show how many digits the file writes.
_DIGITS_SAMPLE = 50
#: Whether :func:`_parse_fast` converts with the compiled kernel (see :func:`compiled_conversion`).
_COMPILED = contextvars.ContextVar("stickslip_compiled_conversion", default=False)


@contextlib.contextmanager
def compiled_conversion():
    """Within this block, well-formed text is converted by the numba kernel of :mod:`~stickslip.records.compiled_numbers`.

    The values are the same; loading the kernel costs about a second once per
    process, so this is for reading many files (see
    :func:`stickslip.records.readers.read_records`).
    """
    token = _COMPILED.set(True)
    try:
        yield
    finally:
        _COMPILED.reset(token)


def parse_numbers(
    text: str, first_line: int, source: str, columns: int | None = None, commas: bool = False
) -> np.ndarray:
    """The numbers in ``text``, whose first line is line ``first_line`` (1-based) of ``source``.

    Values are separated by blanks, and by commas too when ``commas`` is set
    (a comma elsewhere is an error, not a separator that could hide a
    decimal comma).

    Blank lines and lines starting with ``#`` are skipped.  With ``columns``
    set, every other line must hold that many values and the result has
    shape (lines, columns); otherwise lines hold any number of values and the
    result is flat.  Raises :class:`RecordError` naming the line of the first
    value that is not a number, or of the first line with the wrong count, or
    of a last value cut short (see :func:`check_last_value_complete`).
    """
    check_last_value_complete(text, first_line, source)
    values = _parse_fast(text, columns, commas)
    if values is None:
        values = _parse_lines(text, first_line, source, columns, commas)
    return values.reshape(-1, columns) if columns else values


def _parse_fast(text: str, columns: int | None, commas: bool) -> np.ndarray | None:
    """The numbers of ``text`` when it is plainly well formed; ``None`` when a closer look is needed."""
    try:
        raw = text.encode("ascii")
    except UnicodeEncodeError:
        return None
    if b"," in raw:
        if not commas:
            return None
        raw = raw.replace(b",", b" ")
    if columns is not None and not _rows_of(raw, columns):
        return None
    if _COMPILED.get():
        from stickslip.records.compiled_numbers import convert

        return convert(raw)
    if raw.translate(None, _NUMERIC_BYTES):
        return None  # a character that is in no number: a comment, a word, nan, 1_0…
    if b"d" in raw or b"D" in raw:
        raw = raw.translate(_D_TO_E_BYTES)
    if not raw.strip():
        return np.empty(0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # numpy warns, and stops, at text that is not a number
        try:
            return np.fromstring(raw, dtype=np.float64, sep=" ")
        except (ValueError, DeprecationWarning):
            return None


def _rows_of(raw: bytes, columns: int) -> bool:
    """Whether every non-blank line of ``raw`` (blank-separated ASCII) holds ``columns`` fields."""
    if columns == 1 and b" " not in raw and b"\t" not in raw:
        return True
    codes = np.frombuffer(raw, dtype=np.uint8)
    separator = (codes == 32) | (codes == 9) | (codes == 10)
    starts = ~separator
    starts[1:] &= separator[:-1]
    line = np.cumsum(codes == 10)
    counts = np.bincount(line[starts], minlength=int(line[-1]) + 1)
    return bool(np.all((counts == 0) | (counts == columns)))


def _parse_lines(text: str, first_line: int, source: str, columns: int | None, commas: bool) -> np.ndarray:
    """Line by line, naming the line of the first problem."""
    values: list[float] = []
    for number, line in enumerate(text.split("\n"), start=first_line):
        stripped = line.strip()
        if not stripped or stripped.startswith("#"):
            continue
        fields = (stripped.replace(",", " ") if commas else stripped).split()
        row = [value for field in fields for value in _field_values(field, number, source)]
        if columns is not None and len(row) != columns:
            raise RecordError(source, f"line {number}: expected {columns} value(s), found {len(row)}")
        values.extend(row)
    return np.array(values, dtype=np.float64)


def _field_values(field: str, number: int, source: str) -> list[float]:
    """The value(s) of one blank-separated field: a number, or numbers glued by fixed-width output."""
    if NUMBER.fullmatch(field):
        return [float(field.translate(_D_TO_E))]
    parts = _glued_parts(field)
    if parts:
        return [float(part.translate(_D_TO_E)) for part in parts]
    shown = repr(field if len(field) <= 40 else field[:37] + "...")
    if field.lower().lstrip("+-") in _NON_FINITE_WORDS:
        raise RecordError(source, f"line {number}: value {shown} is not a finite number")
    raise RecordError(source, f"line {number}: non-numeric value {shown}")


def line_of_value(text: str, first_line: int, index: int) -> int:
    """The line number holding the value number ``index`` (0-based) of ``text`` (as :func:`parse_numbers` counts)."""
    seen = 0
    for number, line in enumerate(text.split("\n"), start=first_line):
        stripped = line.strip()
        if not stripped or stripped.startswith("#"):
            continue
        seen += sum(len(_GLUED_PART.findall(field)) or 1 for field in stripped.replace(",", " ").split())
        if seen > index:
            return number
    return first_line + text.count("\n")


def check_last_value_complete(text: str, first_line: int, source: str) -> None:
    """Refuse a file that ends without a newline in the middle of its last number.

    The last value is taken as cut when it has fewer digits after the decimal
    point than every one of the values written before it in its column, or
    an exponent of one digit where they have two, or no exponent where they
    all have one (a column being every k-th value, k the number
    of values on the last line).  A text that ends with a newline passes: its
    last line is whole.  ``text`` starts at line ``first_line`` of ``source``.
    """
    if not text or text.endswith("\n"):
        return
    last_fields = len(_values_text(text[text.rfind("\n") + 1:])) or 1
    tail = _values_text(text[-40 * last_fields * (_DIGITS_SAMPLE + 1):])
    if len(tail) <= last_fields:
        return
    # the values written before it in the same column (every value, for a file of one column or rows of any length)
    same_column = [token for token in tail[-1 - last_fields::-last_fields][:_DIGITS_SAMPLE] if NUMBER.fullmatch(token)]
    if not same_column:
        return
    last, before = _digits(tail[-1]), [_digits(token) for token in same_column]
    fewer_decimals = last[0] < min(digits[0] for digits in before)
    exponents = [digits[1] for digits in before if digits[1] is not None]
    # exponents are written with two digits or more (E+00, E-120): a cut one has fewer than two
    fewer_exponent_digits = last[1] is not None and bool(exponents) and last[1] < min(2, *exponents)
    lost_exponent = last[1] is None and len(exponents) == len(before)
    if fewer_decimals or fewer_exponent_digits or lost_exponent:
        last_line = first_line + text.count("\n")
        raise RecordError(
            source,
            f"line {last_line}: the last value {tail[-1]!r} has fewer digits than the values before it and the file "
            "has no final newline: the file looks cut short (if it is complete, end it with a newline)",
        )


def _values_text(text: str) -> list[str]:
    """The written values of ``text``, glued fixed-width values taken apart."""
    return [part for field in text.replace(",", " ").split() for part in _glued_parts(field) or [field]]


def _glued_parts(field: str) -> list[str] | None:
    """The values of a field of glued fixed-width values (``-.1E+00-.2E+00``), or None if it is not one."""
    parts = _GLUED_PART.findall(field)
    if len(parts) > 1 and "".join(parts) == field and all(part[0] in "+-" for part in parts[1:]):
        return parts
    return None


def _digits(token: str) -> tuple[int, int | None]:
    """(digits after the decimal point, exponent digits or None) of a written number."""
    mantissa, marker, exponent = token.translate(_D_TO_E).upper().partition("E")
    decimals = len(mantissa.partition(".")[2])
    return decimals, (len(exponent.lstrip("+-")) if marker else None)
