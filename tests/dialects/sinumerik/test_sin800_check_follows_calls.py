"""``ncvm check`` of a sin800 main program checks the L sub-programs it calls by a literal ``L<n>`` (as the
CPL check follows CALL), warns RUN002 at a call whose sub-program is not on the program path, and warns
NC009 where the run cannot make a rounding (B on a G1 block, L4237; docs/sin800.md)."""

from __future__ import annotations

from pathlib import Path

from ncvm.api import check

MACHINE = '[[axis]]\nname = "X"\n[[axis]]\nname = "Y"\n[[axis]]\nname = "Z"\n'


def _check(tmp_path: Path, files: dict[str, str], main: str = "main.mpf"):
    (tmp_path / "machine.toml").write_text(MACHINE)
    for name, text in files.items():
        (tmp_path / name).write_text(text)
    return [(d.code, Path(d.span.file).name, d.span.line, d.span.column) for d in
            check(tmp_path / main, dialect="sin800", machine=tmp_path / "machine.toml")]


def test_called_sub_programs_are_checked_once_and_a_missing_one_is_warned(tmp_path):
    files = {"L50.spf": "%SPF50\nN10 G25 X100\nN20 M17\n",
             "main.mpf": "%MPF1\nN10 L50\nN20 L50\nN30 L51\nN40 M30\n"}
    assert _check(tmp_path, files) == [("RUN002", "main.mpf", 4, 5), ("NC004", "L50.spf", 2, 5)]


def test_roundings_the_run_cannot_make_are_warned_and_a_plain_one_is_clean(tmp_path):
    text = ("%MPF1\nN10 G0 X0 Y0 Z0\nN20 G1 X10 Y0 B5 F100\nN30 X10 Y10\n"  # a rounding the run makes
            "N40 X20 B2\nN50 G2 X30 Y20 I0 J10\n"  # before a circle
            "N60 G1 X40 B2\nN70 X50 Z-5\nN90 M30\n")  # leaves the plane
    assert _check(tmp_path, {"main.mpf": text}) == [("NC009", "main.mpf", 5, 9), ("NC009", "main.mpf", 7, 12)]
