"""Program text as the controls read it (ncvm.source)."""

from __future__ import annotations

import pytest

from ncvm.diagnostics import Diagnostic, Span, read_lines
from ncvm.source import DIGITS, LETTERS, NAME_CHARS, decades, int_literal, is_digits, read_text, upper, word_number


def test_a_leading_byte_order_mark_is_dropped_and_nothing_else(tmp_path):
    path = tmp_path / "p.din"
    path.write_bytes(b"\xef\xbb\xbfG0 X1 (\xef\xbb\xbf \xe9)\n")
    assert read_text(path) == "G0 X1 (ï»¿ é)\n"
    assert read_lines(str(path)) == ["G0 X1 (ï»¿ é)"]


def test_a_diagnostic_shows_the_first_line_without_the_mark(tmp_path):
    path = tmp_path / "p.din"
    path.write_bytes(b"\xef\xbb\xbfG0 X\xe9\n")
    text = Diagnostic("NC001", "cannot read", Span(str(path), 1, 5)).render()
    assert text.splitlines()[1:] == ["    G0 Xé", "        ^"]


@pytest.mark.parametrize("data", [
    b"\xef\xbb\xbfG0 X1\r\nG1 Y2\rG1 \x0cZ3\n\n(\xe9)\r\n\rlast",  # LF, CR LF, lone CR, a form feed kept
    b"one\ntwo\n",
    b"",
])
def test_lines_at_and_stretches_read_the_lines_a_text_splits_into(tmp_path, data):
    """A diagnostic's source line (lines_at) and a streamed DIN run (stretches) read a file as lines() splits
    its text."""
    from ncvm.source import lines, lines_at, open_program, stretches

    path = tmp_path / "p.din"
    path.write_bytes(data)
    expected = lines(read_text(path))
    assert lines_at(path, set(range(0, len(expected) + 3))) == dict(enumerate(expected, 1))
    assert lines_at(path, set()) == {}
    with open_program(path) as file:
        for chars in (1, 3, 1 << 18):
            pieces = list(stretches(file, chars))
            assert lines("".join(pieces)) == expected
            assert all(p.endswith("\n") for p in pieces[:-1])


def test_only_ascii_letters_and_digits_count():
    latin1 = {chr(c) for c in range(0x80, 0x100)}
    assert not latin1 & (DIGITS | LETTERS | NAME_CHARS)
    assert "é".isalpha() and "¹".isdigit()  # what str offers, and why the sets exist
    assert NAME_CHARS == set("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_")
    assert is_digits("0123") and not is_digits("") and not is_digits("1²") and not is_digits("12a")


def test_upper_keeps_one_character_for_one():
    assert upper("aßz é") == "AßZ é"
    assert len(upper("ß" * 5)) == 5 and len("ß".upper()) == 2


@pytest.mark.parametrize("digits, ceiling, value", [
    ("0", 10, 0), ("000", 10, 0), ("0009", 10, 9), ("10", 10, 10), ("11", 10, 10), ("999", 1000, 999),
    ("1" * 5000, 1000, 1000), ("0" * 5000 + "7", 1000, 7), ("1" * 400, 10 ** 309, 10 ** 309),
])
def test_int_literal_stops_at_its_ceiling(digits, ceiling, value):
    assert int_literal(digits, ceiling) == value


@pytest.mark.parametrize("text, places, value", [
    ("12.5", 2, 12.5), ("-0012.5", 2, -12.5), ("+3", 1, 3.0), (".5", 0, 0.5), ("99999999.999", 8, 99999999.999),
    ("00000000099999999", 8, 99999999.0), ("123456789", 9, None), ("-123456789.5", 9, None), ("1" * 400, 400, None),
])
def test_an_nc_word_has_at_most_8_decades(text, places, value):
    assert decades(text) == places
    assert word_number(text) == value


def test_the_lines_of_a_piped_program_are_kept_until_a_file_is_read(tmp_path):
    """A diagnostic of a program from a FIFO shows its line from the text read once (opening the FIFO again
    would wait for a writer that is gone); once a file is read, the FIFO's lines are gone and asking for them
    returns none at once instead of waiting."""
    import os
    import threading

    from ncvm.api import resolve_run
    from ncvm.source import lines_at, read_piped

    fifo = tmp_path / "p.ngc"
    os.mkfifo(fifo)

    def write():
        with open(fifo, "wb") as pipe:
            pipe.write(b"\xef\xbb\xbfG0 X1\r\nG1 Y2 (\xe9)\rM2\n")

    threading.Thread(target=write, daemon=True).start()
    assert read_piped(fifo) == "G0 X1\r\nG1 Y2 (é)\rM2\n"
    assert lines_at(fifo, {2, 3}) == {2: "G1 Y2 (é)", 3: "M2"}
    (tmp_path / "q.ngc").write_text("G0 X5\n")
    resolve_run(tmp_path / "q.ngc", None)
    assert lines_at(fifo, {2}) == {}  # no writer: it would block if it were opened
