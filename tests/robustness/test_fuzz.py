"""Text built by hypothesis, per front end: whatever a file holds, ``check`` and a bounded ``run`` end
with diagnostics, a run-time fault or a usage error, never with an internal error.

The text is a soup of the dialect's own words, operators and numbers (some beyond every range),
arbitrary Latin-1 characters, and constructs nested far beyond any limit, sometimes inside the frame
of a valid program so that it reaches the checker and the code generator. ``CI=true`` selects a
derandomized profile without an example database (tests/conftest.py), so a failure there repeats.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ncvm.api import check, run
from ncvm.diagnostics import NcvmError
from ncvm.runtime.session import RunOptions

LATIN1 = st.characters(min_codepoint=0, max_codepoint=0xFF)
#: examples per front end: about 4 s each, 20 s in all
EXAMPLES = 150

#: dialect -> (file suffix, frame before, frame after, words, (opener, closer) pairs to nest)
DIALECTS = {
    "cpl": (".cpl", "10 A=1\n", "\nM30\n",
            ["10 ", "20 ", "\n", " ", ":", "A", "A%", "B!", "C$", "E?", "@1", "#G", "P1", ".L", "LABEL", "IF", "THEN",
             "ELSE", "ENDIF", "WHILE", "DO", "END", "REPEAT", "UNTIL", "FOR", "TO", "NEXT", "CASE", "OF", "GOTO",
             "CALL", "PRN#(0,", "DIM", "SIN(", "INT(", "MID$(", "=", "+", "-", "*", "/", "(", ")", "[", "]", ",",
             '"', "REM", "N10 ", "G1 ", "X", "Y[", "F100", "M30", "WAIT"],
            [("(", ")"), ("-", ""), ("SIN(", ")"), ("1 IF A=1 THEN\n", "1 ENDIF\n"), ("1 WHILE A<1 DO\n", "1 END\n")]),
    "cl800": (".cl8", "PROGRAM 9;\nCHANNEL NC 0;\nLOCAL REAL: R60, R61;\nBEGIN\n", "\nEND.\n",
              ["R60", "R61", "R 0", "B0101", "=", ":=", ";", ",", ".", "(", ")", "[", "]", "+", "-", "*", "/", "<>",
               "IF", "THEN", "ELSE", "ENDIF", "WHILE", "DO", "REPEAT", "UNTIL", "FOR", "TO", "CASE", "OF", "ENDCASE",
               "BEGIN", "END", "INC", "SIN", "ABS", "AND", "OR", "NOT", "(*", "*)", "(:", ":)", "G1 X10", "LF",
               "PROGRAM", "LOCAL", "REAL", "INTEGER", "\n", " "],
              [("(", ")"), ("-", ""), ("SIN(", ")"), ("IF R60 = 0 THEN\n", "ENDIF;\n"), ("BEGIN\n", "END;\n")]),
    "sin800": (".mpf", "%MPF1\n", "\nM30\n",
               ["N10 ", "R1=", "R2", "R999", "=", "+", "-", "*", "/", "@", "@200 ", "@100 ", "@620 ", "@041 ", "K",
                "K-5", "R", "P", "G0 ", "G1 ", "G2 ", "X", "Y", "Z", "I", "J", "F", "S", "M3 ", "M17", "L20 ", "(", ")",
                ";", "/", "%", "\n", " "],
               [("(", ")"), ("R1=", "+R1")]),
    "sympas": (".sap", "program p;\nvar i: integer; d: double;\nbegin\n", "\nend.\n",
               ["program", "begin", "end", "end.", "var", ":", ";", ":=", "i", "d", "integer", "double", "if", "then",
                "else", "while", "do", "repeat", "until", "for", "to", "goto", "and", "or", "not", "mod", "+", "-",
                "*", "/", "(", ")", "=", "<", ".", ",", "'", "{", "}", "{$TASK 1}", "A1", "A1.dp", "MLAW(A1 := ",
                "JAW(A1 := ", "WT(", "SIN(", "1e308", "$FF", "\n", " "],
               [("(", ")"), ("-", ""), ("SIN(", ")"), ("if i = 0 then begin\n", "end;\n"),
                ("while i < 0 do begin\n", "end;\n")]),
    "din": (".din", "%\n", "\nM30\n",
            ["N10 ", "G0 ", "G1 ", "G2 ", "G3 ", "G17 ", "G90 ", "G91 ", "X", "Y", "Z", "I", "J", "K", "R", "F", "S", "T",
             "M3 ", "M30", "(", ")", ";", "/", "%", "-", "+", ".", "\n", " "],
            [("(", ")")]),
}


#: NC addresses of blocks that read as words (so that the run starts), with numbers of any size
BLOCK_ADDRESSES = {"din": "GXYZIJKFSN", "sin800": ["G", "X", "Y", "Z", "F", "S", "N", "R1=", "R2=", "X=R"],
                   "cpl": ["G", "X", "Y", "Z", "F", "S"]}


def numbers() -> st.SearchStrategy[str]:
    """Numbers as a program writes them, some far beyond every range."""
    return st.one_of(
        st.integers(-10**12, 10**12).map(str),
        st.floats(allow_nan=False, allow_infinity=False).map(lambda f: f"{f:.6f}"),
        st.integers(1, 5000).map(lambda n: "1" * n),
        st.sampled_from(["0", "1.", ".5", "99999999", "123456789", "1e308", "1e400", "¹", "²³"]),
    )


def soup(words: list[str]) -> st.SearchStrategy[str]:
    word = st.sampled_from(words)
    piece = st.one_of(word, numbers(), st.text(LATIN1, max_size=4), st.tuples(word, numbers()).map("".join))
    return st.lists(piece, max_size=40).map("".join)


def nested(pairs, words) -> st.SearchStrategy[str]:
    return st.tuples(st.sampled_from(pairs), st.integers(1, 400), st.sampled_from(words)).map(
        lambda t: t[0][0] * t[1] + t[2] + t[0][1] * t[1])


def program(dialect: str) -> st.SearchStrategy[str]:
    _suffix, head, tail, words, pairs = DIALECTS[dialect]
    body = st.one_of(soup(words), nested(pairs, words), st.lists(st.one_of(soup(words), nested(pairs, words)),
                                                                   max_size=3).map("\n".join))
    if dialect in BLOCK_ADDRESSES:
        word = st.tuples(st.sampled_from(list(BLOCK_ADDRESSES[dialect])), numbers()).map("".join)
        body = st.one_of(body, st.lists(st.lists(word, min_size=1, max_size=4).map(" ".join), max_size=6)
                         .map("\n".join))
    return st.one_of(body, body.map(lambda b: head + b + tail))


def _fuzz(dialect: str, folder):
    suffix = DIALECTS[dialect][0]
    path = folder / f"fuzz{suffix}"

    @settings(max_examples=EXAMPLES, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                     HealthCheck.data_too_large])
    @given(program(dialect))
    def case(text: str) -> None:
        path.write_text(text, encoding="latin-1")
        try:
            check(path)
        except NcvmError:  # a diagnostic or a usage error: what a user may be told
            pass
        try:
            result, _ = run(path, options=RunOptions(state_dir=folder / ".ncvm", max_steps=2_000))
        except NcvmError:
            return
        assert math.isfinite(result["cycle_time_s"]), text  # the summary line shows it

    case()


@pytest.mark.parametrize("dialect", sorted(DIALECTS))
def test_fuzzed_text_never_raises_an_internal_error(tmp_path, dialect):
    _fuzz(dialect, tmp_path)
