"""Triangle-compatible reading of lines and fields (spec §2.1).

Triangle reads a line, skips everything before the first character that can start
a number (a digit, ``.``, ``+`` or ``-``), and treats the line as blank when that
character is ``#`` or the line ends first.  A field runs from a number-start
character to the next space or tab; between fields any other character is skipped.
``#`` ends the line wherever it appears.  Integer fields are parsed like C
``strtol(s, &end, 0)`` and real fields like ``strtod``, both from the start of the
field, ignoring whatever follows the number.

Deliberate differences from Triangle, all of which turn silent misreadings into errors
or avoid them:

* a field that holds no number at all (``-``, ``.``, ``+x``) raises FormatError
  where C would read 0;
* integers that do not fit the target type raise FormatError instead of wrapping;
* lines are not cut at 1023 characters (Triangle's ``fgets`` buffer), so files with
  many attributes written by us read back correctly.
"""

from __future__ import annotations

import math
import os
import re
from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np

from .errors import FormatError

# One field: a number-start character, then anything up to a space or tab.
_FIELD = re.compile(r"[0-9.+\-][^ \t]*")
# '#' and NUL (the end of a C string) end a line.
_CUT = re.compile(r"[#\0][^\n]*")
# Text in which str.split() finds exactly Triangle's fields: only number characters
# and space/tab separators, and no field starting with an exponent letter.
_PLAIN_TEXT = re.compile(r"[0-9.eE+\- \t\n]*")
_E_FIELDS = (" e", " E", "\te", "\tE", "\ne", "\nE")
# A leading zero makes strtol read octal or hex, where Python's int() reads decimal.
# (searched in " " + tokens joined by spaces)
_LEADING_ZERO = re.compile(r" [+\-]?0[^ ]")

# The longest prefix strtol(base 0) accepts.  "0x" without hex digits reads as 0.
_INT = re.compile(r"([+-]?)(?:0[xX]([0-9a-fA-F]+)|(0[0-7]*)|([1-9][0-9]*))")

# The longest prefix strtod accepts: hex floats, decimals, inf/infinity, nan(...).
_REAL = re.compile(
    r"[+-]?(?:"
    r"(0x(?:[0-9a-f]+\.?[0-9a-f]*|\.[0-9a-f]+)(?:p[+-]?[0-9]+)?)"
    r"|(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:e[+-]?[0-9]+)?"
    r"|inf(?:inity)?"
    r"|(nan)(?:\([0-9a-z_]*\))?"
    r")",
    re.IGNORECASE,
)

_LONG_MIN = -(2**63)
_LONG_MAX = 2**63 - 1
INT32_MIN = -(2**31)
INT32_MAX = 2**31 - 1

# A declared attribute count fills missing fields with zeros, so it is not bounded
# by the file's length; cap the values it may create (see LineReader.check_table).
_MIN_TABLE_CAP = 1 << 20


def parse_int(text: str) -> int | None:
    """Value of the longest strtol(base 0) prefix of ``text``; None if there is none.

    ``010`` is octal 8, ``0x10`` is 16, ``08`` reads 0.  Like strtol, values beyond
    the 64-bit range are clamped.
    """
    m = _INT.match(text)
    if m is None:
        return None
    sign, hexd, octd, decd = m.groups()
    if hexd is not None:
        digits, base = hexd.lstrip("0"), 16
    elif octd is not None:
        digits, base = octd.lstrip("0"), 8
    else:
        digits, base = decd, 10
    # More than 22 digits is out of range in every base; avoid huge conversions.
    value = int(digits, base) if 0 < len(digits) <= 22 else (0 if not digits else 2**64)
    if sign == "-":
        value = -value
    return min(max(value, _LONG_MIN), _LONG_MAX)


def parse_real(text: str) -> float | None:
    """Value of the longest strtod prefix of ``text``; None if there is none.

    Overflow gives a signed infinity, as strtod does.
    """
    m = _REAL.match(text)
    if m is None:
        return None
    s = m.group(0)
    if m.group(2) is not None:
        return math.nan
    if m.group(1) is not None:
        try:
            return float.fromhex(s)
        except OverflowError:
            return -math.inf if s.startswith("-") else math.inf
    return float(s)


def _show(text: str) -> str:
    """A field for an error message, shortened if it is long."""
    return repr(text if len(text) <= 40 else text[:37] + "...")


@dataclass(frozen=True, slots=True)
class Line:
    """A line holding at least one field."""

    number: int  # 1-based physical line number
    fields: list[str]


def split_fields(text: str) -> list[str]:
    """The fields of one physical line, as Triangle sees them."""
    return _FIELD.findall(_CUT.sub("", text))


class Block:
    """Consecutive data lines holding the items of one section."""

    def __init__(self, numbers: list[int], fields: list[list[str]]) -> None:
        self.numbers = numbers
        self.fields = fields

    def __len__(self) -> int:
        return len(self.fields)

    def __iter__(self) -> Iterator[Line]:
        return map(Line, self.numbers, self.fields)

    # Fast paths: whole columns at once when every token is plain decimal, where
    # Python's int()/float() and C's strtol/strtod agree.  They return None when
    # anything is unusual; the caller then reads line by line, which reports errors.

    def _tokens(self, start: int, stop: int) -> tuple[list[str], str] | None:
        if any(len(f) < stop for f in self.fields):
            return None
        tokens = [t for f in self.fields for t in f[start:stop]]
        joined = " ".join(tokens)
        if "_" in joined:  # int()/float() accept "1_0", strtol/strtod stop at "_"
            return None
        return tokens, joined

    def ints(self, start: int, stop: int) -> np.ndarray | None:
        """Fields ``start:stop`` of every line as an int64 array, if all are plain."""
        got = self._tokens(start, stop)
        if got is None or _LEADING_ZERO.search(" " + got[1]):
            return None
        try:
            values = np.array(list(map(int, got[0])), dtype=np.int64)
        except (ValueError, OverflowError):
            return None
        return values.reshape(len(self.fields), stop - start)

    def reals(self, start: int, stop: int) -> np.ndarray | None:
        """Fields ``start:stop`` of every line as a float64 array, if all are finite."""
        got = self._tokens(start, stop)
        if got is None:
            return None
        try:
            values = np.array(list(map(float, got[0])), dtype=np.float64)
        except ValueError:
            return None
        if not np.isfinite(values).all():
            return None
        return values.reshape(len(self.fields), stop - start)


class LineReader:
    """Walks the data lines of one file and parses their fields.

    All problems are reported as FormatError naming the file and the line.
    """

    def __init__(self, path: str | os.PathLike[str], data: bytes) -> None:
        self.path = os.fspath(path)
        self.size = len(data)
        # latin-1 maps every byte to one character, so any bytes decode.  Only
        # '\n' ends a line, as for fgets.
        text = data.decode("latin-1")
        if "#" in text or "\0" in text:
            text = _CUT.sub("", text)
        physical = text.split("\n")
        self.last_line = len(physical) - (1 if physical[-1] == "" else 0)
        if "\r" in text:  # CRLF: "\r" only ever ends the last field of a line
            text = text.replace("\r\n", "\n")
        if (
            _PLAIN_TEXT.fullmatch(text)
            and text[:1] not in ("e", "E")
            and not any(e in text for e in _E_FIELDS)
        ):
            fields = [t.split() for t in text.split("\n")]
        else:
            findall = _FIELD.findall
            fields = [findall(t) for t in physical]
        self._numbers = [i for i, f in enumerate(fields, 1) if f]
        self._fields = [f for f in fields if f]
        self._pos = 0

    @classmethod
    def open(cls, path: str | os.PathLike[str]) -> LineReader:
        """Read a whole file (OSError if it cannot be opened)."""
        with open(path, "rb") as f:
            return cls(path, f.read())

    # -- lines -----------------------------------------------------------------

    def at_end(self) -> bool:
        return self._pos >= len(self._fields)

    def remaining(self) -> int:
        return len(self._fields) - self._pos

    def next(self, expected: str) -> Line:
        """The next data line; at the end of the file, FormatError."""
        if self._pos >= len(self._fields):
            raise self.error(None, expected, problem="unexpected end of file")
        line = Line(self._numbers[self._pos], self._fields[self._pos])
        self._pos += 1
        return line

    def take(self, header: Line, count: int, what: str) -> Block:
        """The next ``count`` data lines, the items announced on ``header``.

        Fails fast when the file holds fewer lines than announced, so no allocation
        ever exceeds what the file size allows.
        """
        if count > self.remaining():
            raise self.error(
                None,
                f"{count} {what} lines (the count on line {header.number})",
                problem="unexpected end of file",
                found=f"{self.remaining()}",
            )
        start, self._pos = self._pos, self._pos + count
        return Block(self._numbers[start : self._pos], self._fields[start : self._pos])

    def check_table(self, line: Line, rows: int, columns: int, what: str) -> None:
        """Refuse a declared column count that would fill memory with defaults."""
        cap = max(_MIN_TABLE_CAP, self.size)
        if columns > cap or rows * columns > cap:  # even 0 rows: numpy caps the shape
            raise self.error(
                line,
                f"at most {cap // max(rows, 1)} {what} for a file of {self.size} bytes",
                found=str(columns),
            )

    # -- fields ----------------------------------------------------------------

    def error(
        self,
        line: Line | None,
        expected: str,
        *,
        problem: str | None = None,
        found: str | None = None,
    ) -> FormatError:
        """A FormatError at ``line`` (None: at the end of the file)."""
        number = line.number if line is not None else self.last_line + 1
        return FormatError(self.path, number, expected, problem=problem, found=found)

    def int_field(
        self,
        line: Line,
        index: int,
        expected: str,
        *,
        low: int = INT32_MIN,
        high: int = INT32_MAX,
        required: bool = True,
        default: int = 0,
    ) -> int:
        """Field ``index`` of ``line`` as an integer in ``[low, high]``.

        A missing field is an error if ``required``, else ``default``.
        """
        if index >= len(line.fields):
            if required:
                raise self.error(line, expected)
            return default
        text = line.fields[index]
        value = parse_int(text)
        if value is None:
            raise self.error(line, expected, found=_show(text))
        if not low <= value <= high:
            raise self.error(line, f"{expected} in [{low}, {high}]", found=str(value))
        return value

    def index_field(self, line: Line, index: int, expected: str) -> int:
        """A required integer of any size (an index or item number the caller checks)."""
        return self.int_field(line, index, expected, low=_LONG_MIN, high=_LONG_MAX)

    def numbering_base(self, block: Block, what: str, default: int) -> int:
        """The base set by the first item's number: 0 or 1, else ``default`` (spec §2.1)."""
        if not len(block):
            return default
        number = self.index_field(next(iter(block)), 0, f"the number of the first {what}")
        return number if number in (0, 1) else default

    def real_field(
        self,
        line: Line,
        index: int,
        expected: str,
        *,
        required: bool = True,
        default: float = 0.0,
    ) -> float:
        """Field ``index`` of ``line`` as a finite float.

        A missing field is an error if ``required``, else ``default``.  NaN and
        infinities are errors (only signed ones can get here: Triangle's scanner
        skips a bare ``inf`` or ``nan`` like any other word).
        """
        if index >= len(line.fields):
            if required:
                raise self.error(line, expected)
            return default
        text = line.fields[index]
        value = parse_real(text)
        if value is None:
            raise self.error(line, expected, found=_show(text))
        if not math.isfinite(value):
            raise self.error(line, f"a finite number for {expected}", found=_show(text))
        return value

    def count_field(
        self, line: Line, index: int, expected: str, *, default: int | None = None
    ) -> int:
        """A non-negative count (required unless ``default`` is given).

        Any size is accepted here: ``take`` then reports a count larger than the
        file as an unexpected end of file.
        """
        return self.int_field(
            line,
            index,
            expected,
            low=0,
            high=_LONG_MAX,
            required=default is None,
            default=default or 0,
        )
