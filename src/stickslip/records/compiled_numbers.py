"""Plainly well-formed record text to numbers by a numba kernel, for reading many files in one process.

:func:`convert` gives exactly the values of ``np.fromstring(raw, sep=" ")``
(and of Python's ``float``), about three times as fast as ``np.loadtxt`` or
``np.fromstring`` on the SLAMMER library.  A value whose significant digits fit in
2⁵³ and whose power of ten is at most 22 in size is one correctly rounded
IEEE multiplication or division of two exact doubles (Clinger's fast path);
any other value (17 significant digits, a large exponent) is converted by
Python's ``float`` afterwards.  Loading the kernel costs about a second once
per process (importing numba and its cache), which pays off only over many
megabytes: :func:`stickslip.records.numbers.parse_numbers` uses it inside
:func:`stickslip.records.numbers.compiled_conversion` only.
"""

from __future__ import annotations

import numba
import numpy as np

#: 10**k [-] for k = 0..22, each exact in double precision.
_POWERS_OF_TEN = np.array([10.0**k for k in range(23)])
#: Digits (leading zeros included) an int64 holds for sure.
_MAX_DIGITS = 18
#: 2**53: integers below it are exact doubles.
_EXACT_INTEGERS = 9007199254740992

_SPACE, _TAB, _NEWLINE = 32, 9, 10
_PLUS, _MINUS, _POINT, _ZERO, _NINE = 43, 45, 46, 48, 57
_E, _LOWER_E, _D, _LOWER_D = 69, 101, 68, 100
_D_TO_E = bytes.maketrans(b"Dd", b"Ee")


@numba.njit(cache=True)
def _is_separator(code):
    return code == _SPACE or code == _NEWLINE or code == _TAB


@numba.njit(cache=True)
def _is_exponent_marker(code):
    return code == _E or code == _LOWER_E or code == _D or code == _LOWER_D


@numba.njit(cache=True)
def _convert_kernel(codes, out):
    """Numbers of the ASCII ``codes`` into ``out``: ``(count, off_fast_path)``, count −1 if not plainly well formed.

    Values are ``[+-]digits[.digits][E|e|D|d[+-]digits]`` (at least one
    mantissa digit) separated by blanks, tabs and newlines.  A value off the
    fast path is written as NaN, for the caller to convert; ``off_fast_path``
    counts them.
    """
    n = codes.size
    i = 0
    count = 0
    off_fast_path = 0
    while True:
        while i < n and _is_separator(codes[i]):
            i += 1
        if i == n:
            return count, off_fast_path
        negative = codes[i] == _MINUS
        if negative or codes[i] == _PLUS:
            i += 1
        mantissa, scale = 0, 0  # mantissa wraps past 18 digits, and is then not used
        first_digit = i
        while i < n and _ZERO <= codes[i] <= _NINE:
            mantissa = mantissa * 10 + (codes[i] - _ZERO)
            i += 1
        if i < n and codes[i] == _POINT:
            i += 1
            first_decimal = i
            while i < n and _ZERO <= codes[i] <= _NINE:
                mantissa = mantissa * 10 + (codes[i] - _ZERO)
                i += 1
            scale = first_decimal - i
            digits = i - first_digit - 1
        else:
            digits = i - first_digit
        if digits == 0:
            return -1, off_fast_path
        if i < n and _is_exponent_marker(codes[i]):
            i += 1
            exponent_negative = i < n and codes[i] == _MINUS
            if i < n and (exponent_negative or codes[i] == _PLUS):
                i += 1
            exponent, exponent_digits = 0, 0
            while i < n and _ZERO <= codes[i] <= _NINE:
                exponent = min(exponent * 10 + (codes[i] - _ZERO), 100_000)
                exponent_digits += 1
                i += 1
            if exponent_digits == 0:
                return -1, off_fast_path
            scale += -exponent if exponent_negative else exponent
        if i < n and not _is_separator(codes[i]):
            return -1, off_fast_path
        if digits > _MAX_DIGITS or mantissa >= _EXACT_INTEGERS or abs(scale) > 22:
            value = np.nan
            off_fast_path += 1
        elif mantissa == 0:
            value = 0.0
        elif scale >= 0:
            value = mantissa * _POWERS_OF_TEN[scale]
        else:
            value = mantissa / _POWERS_OF_TEN[-scale]
        out[count] = -value if negative else value
        count += 1


def convert(raw: bytes) -> np.ndarray | None:
    """The numbers of the ASCII text ``raw`` (blank, tab and newline separated), or ``None`` if it is not plainly well formed."""
    out = np.empty((len(raw) + 1) // 2)
    count, off_fast_path = _convert_kernel(np.frombuffer(raw, dtype=np.uint8), out)
    if count < 0:
        return None
    values = out[:count]  # a view: readers scale the values into a new array at once
    if off_fast_path:
        tokens = raw.split()
        for index in np.flatnonzero(np.isnan(values)):
            values[index] = float(tokens[index].translate(_D_TO_E))
    return values
