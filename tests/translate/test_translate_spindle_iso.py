"""The spindle where the run had it at every move (a cycle's M5 in the cycle, M3 again after M6), ISO's
decimal points and integer S, DIN G88's stop as M0 (docs/translate.md; issue 16, rule 4)."""

from __future__ import annotations

from pathlib import Path

from ncvm.runtime.session import RunOptions
from ncvm.translate import translate


def _lines(tmp_path: Path, source: str, target: str, name: str = "p.din") -> list[str]:
    program = tmp_path / name
    program.write_text(source)
    out = tmp_path / f"{name}.{target}"
    translate(program, out, target, options=RunOptions(state_dir=tmp_path / "st"))
    return [ln.strip() for ln in out.read_text().splitlines()]


def test_g86_spindle_stops_at_the_bottom_before_the_rapid_out(tmp_path):
    code = _lines(tmp_path, "G90 G54\nS500 M3\nG0 X10 Y10 Z5\nG98 G86 X10 Y10 Z-10 R2 P0.5 F50\nG80\nM2\n", "iso")
    dwell = next(i for i, ln in enumerate(code) if ln.startswith("G4"))
    assert code[dwell + 1] == "M5", code  # before the rapid out of the bore, not after it
    assert code[dwell + 2].startswith("G0"), code


def test_spindle_restarted_after_a_tool_change_840d_m4(tmp_path):
    code = _lines(tmp_path, "G90 G54\nT1 M6\nS700 M4\nG0 X10 Z5\nT2 M6\nG1 Z-1 F100\nM2\n", "sinumerik840d")
    change = code.index("T2 M6")
    assert code[change + 1:change + 3] == ["D0", "M4 S700"], code  # the 840D's D after each tool change
    assert code.index("M4 S700", change) < code.index("G1 Z-1 F100"), code


def test_no_spindle_start_after_a_tool_change_when_it_stood(tmp_path):
    code = _lines(tmp_path, "G90 G54\nT1 M6\nS700 M3\nG0 X10 Z5\nM5\nT2 M6\nG0 Z20\nM2\n", "linuxcnc")
    assert code.count("M3 S700") == 1, code


def test_iso_s_is_an_integer_said_where_rounded_and_dwell_has_a_point(tmp_path):
    text = "\n".join(_lines(tmp_path, "G90 G54\nS1234.6 M3\nG0 X10\nG4 X2\nM2\n", "iso"))
    assert "M3 S1235" in text and "S1234.6 rounded to S1235" in text, text
    assert "G4 X2." in text and "G0 X10." in text, text


def test_g88_is_m0_after_the_feed_to_the_bottom_on_the_840d(tmp_path):
    code = _lines(tmp_path, "G90 G54\nS500 M3\nG0 X10 Y10 Z5\nG98 G88 X10 Y10 Z-10 R2 P0.5 F50\nG80\nM2\n",
                  "sinumerik840d")
    assert "M0" in code and "G88" not in code, code
    assert code.index("G1 Z-10 F50") < code.index("M0"), code
