"""Triangle's rules for lines and fields (spec §2.1)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from ruppert_io.lines import Block, LineReader, parse_int, parse_real, split_fields
from ruppert_io.errors import FormatError


@pytest.mark.parametrize(
    "text, value",
    [
        ("12", 12),
        ("-7", -7),
        ("+3", 3),
        ("010", 8),  # octal
        ("0x10", 16),
        ("0X1f", 31),
        ("08", 0),  # strtol stops at the 8
        ("0x", 0),  # no hex digit: just the 0
        ("1.9", 1),
        ("3e5", 3),
        ("5,6", 5),
        ("-0", 0),
        ("99999999999999999999999", 2**63 - 1),  # clamped like strtol
        ("-99999999999999999999999", -(2**63)),
    ],
)
def test_parse_int_is_strtol_base_0(text, value):
    assert parse_int(text) == value


@pytest.mark.parametrize("text", ["-", "+", ".", ".5", "-x", "+-1"])
def test_parse_int_without_digits(text):
    assert parse_int(text) is None


@pytest.mark.parametrize(
    "text, value",
    [
        ("1.5e3", 1500.0),
        ("-.5", -0.5),
        ("5.", 5.0),
        ("1e", 1.0),
        ("2E-2x", 0.02),
        ("0x1.8p1", 3.0),
        ("0X10", 16.0),
        ("0x.8", 0.5),
        ("1,2", 1.0),
        ("1_0", 1.0),
        ("-inf", -math.inf),
        ("+Infinity", math.inf),
        ("1e999", math.inf),
        ("0x1p99999", math.inf),
        ("-0", -0.0),
    ],
)
def test_parse_real_is_strtod(text, value):
    got = parse_real(text)
    assert got == value and math.copysign(1, got) == math.copysign(1, value)


def test_parse_real_nan_and_no_number():
    assert math.isnan(parse_real("-nan(123)"))
    assert math.isnan(parse_real("+NaN"))
    for text in ("-", ".", "+.", "-e5", "+x"):
        assert parse_real(text) is None


@pytest.mark.parametrize(
    "line, fields",
    [
        ("1 2 3", ["1", "2", "3"]),
        ("  \t 1\t2", ["1", "2"]),
        ("", []),
        ("# comment 1 2", []),
        ("foo bar", []),  # a line of words is skipped
        ("v 1 0 0", ["1", "0", "0"]),  # junk before the first number
        ("1 2 # 3 4", ["1", "2"]),
        ("1 2#3", ["1", "2"]),
        ("1,2 3", ["1,2", "3"]),  # commas are no separators
        ("1 abc-5 2", ["1", "-5", "2"]),  # junk between fields is skipped
        ("1 inf 2 nan 3", ["1", "2", "3"]),  # bare inf/nan are words
        ("1 -inf 2", ["1", "-inf", "2"]),
        ("1 2\x003", ["1", "2"]),  # NUL ends a C string
        ("1 2\r", ["1", "2\r"]),
    ],
)
def test_split_fields(line, fields):
    assert split_fields(line) == fields


def test_reader_skips_blank_and_comment_lines():
    r = LineReader("f.node", b"# head\n\n  \n3 2 0 0 # count\nwords only\n1 0 0\n")
    line = r.next("a header")
    assert (line.number, line.fields) == (4, ["3", "2", "0", "0"])
    assert r.next("a vertex").number == 6
    assert r.at_end()


def test_reader_end_of_file_names_the_next_line():
    r = LineReader("f.poly", b"1\n2\n")
    r.next("x"), r.next("y")
    with pytest.raises(FormatError) as e:
        r.next("the number of holes")
    assert e.value.line == 3
    assert str(e.value) == "f.poly, line 3: unexpected end of file; expected the number of holes"


def test_reader_fails_fast_on_huge_counts():
    r = LineReader("f.node", b"1000000000000 2 0 0\n1 0 0\n")
    header = r.next("a header")
    with pytest.raises(FormatError, match="unexpected end of file"):
        r.take(header, 10**12, "vertex")


def test_reader_accepts_any_bytes():
    r = LineReader("f", bytes(range(256)) * 3)
    while not r.at_end():
        r.next("anything")


def test_crlf_and_old_mac_line_ends():
    r = LineReader("f", b"1 2\r\n3 4\r\n")
    assert [r.next("x").fields for _ in range(2)] == [["1", "2"], ["3", "4"]]
    # A lone '\r' does not end a line for fgets: one line.
    r = LineReader("f", b"1 2\r3 4\r")
    assert r.remaining() == 1


def test_field_errors_name_file_line_and_expectation():
    r = LineReader("A.poly", b"\n\n3 x -\n")
    line = r.next("a vertex")
    with pytest.raises(FormatError) as e:
        r.real_field(line, 1, "the x coordinate of vertex 3")
    assert (e.value.path, e.value.line) == ("A.poly", 3)
    assert str(e.value) == "A.poly, line 3: expected the x coordinate of vertex 3, found '-'"
    with pytest.raises(FormatError, match="expected the y coordinate of vertex 3$"):
        r.real_field(line, 2, "the y coordinate of vertex 3")
    assert r.real_field(line, 2, "y", required=False, default=7.0) == 7.0


def test_non_finite_reals_are_errors():
    r = LineReader("f", b"1 -inf +nan 1e999\n")
    line = r.next("x")
    for i in (1, 2, 3):
        with pytest.raises(FormatError, match="a finite number"):
            r.real_field(line, i, "a coordinate")


def test_int_range_is_checked():
    r = LineReader("f", b"1 4294967296 -5\n")
    line = r.next("x")
    with pytest.raises(FormatError, match=r"in \[-2147483648, 2147483647\], found 4294967296"):
        r.int_field(line, 1, "a marker")
    with pytest.raises(FormatError, match="found -5"):
        r.count_field(line, 2, "a count")


plain_token = st.one_of(
    st.integers(-(10**20), 10**20).map(str),
    st.floats(allow_nan=True, allow_infinity=True).map(repr),
    st.sampled_from(["010", "0x1A", "08", "-0", "+5", "1_0", "1e5", ".5", "-", "5\r", "0"]),
)


@given(st.lists(st.lists(plain_token, min_size=2, max_size=2), max_size=5))
def test_fast_columns_agree_with_field_parsing(rows):
    """Block.ints/reals either decline or give exactly what strtol/strtod give."""
    block = Block(list(range(1, len(rows) + 1)), rows)
    ints = block.ints(0, 2)
    if ints is not None:
        assert ints.tolist() == [[parse_int(t) for t in row] for row in rows]
    reals = block.reals(0, 2)
    if reals is not None:
        expected = np.array([[parse_real(t) for t in row] for row in rows]).reshape(-1, 2)
        assert np.array_equal(reals.view(np.uint64), expected.view(np.uint64))


@given(st.text(alphabet="0123456789.eE+- \t\n\r#x\0", max_size=80))
def test_reader_fast_split_matches_the_field_rules(text):
    """The str.split() shortcut for plain files finds exactly Triangle's fields."""
    data = text.encode("latin-1")
    r = LineReader("f", data)
    got = []
    while not r.at_end():
        line = r.next("x")
        got.append((line.number, [f.rstrip("\r") for f in line.fields]))
    expected = [
        (n, [f.rstrip("\r") for f in split_fields(t)])
        for n, t in enumerate(text.split("\n"), 1)
        if split_fields(t)
    ]
    assert got == expected
