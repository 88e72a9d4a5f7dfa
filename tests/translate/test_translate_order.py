"""What a translation keeps of the program and never invents (docs/translate.md, safety rules 1, 3, 6 and 7):
program order (M5/M9, tool length after its M6, FROZEN marks), the programmed axes alone, feed per
revolution, cutter radius compensation refused, rw_SymPas homing, --frame machine on the 840D."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from ncvm.runtime.session import RunOptions
from ncvm.translate import TranslationRefused, translate

EX = Path(__file__).parents[2] / "examples"
TARGETS = ["linuxcnc", "sinumerik840d", "iso"]
AXES = "[[axis]]\nname = \"X\"\n[[axis]]\nname = \"Y\"\n[[axis]]\nname = \"Z\"\n"


def _code(text: str) -> list[str]:
    """The output's lines without comments, ISO's decimal point of whole numbers (``X10.``) taken off: these
    tests compare positions (tests/review16c/test_iso_decimal_point.py checks the point)."""
    out = []
    for line in text.splitlines():
        code = re.sub(r"\b([XYZIJKR]-?\d+)\.(?!\d)", r"\1", line.split("(")[0].split(";")[0].strip())
        if code and code != "%":
            out.append(code)
    return out


def _run(tmp_path: Path, name: str, source: str, target: str = "linuxcnc", machine: Path | None = None,
         **options) -> str:
    program = tmp_path / name
    program.write_text(source)
    out = tmp_path / f"{name}.{target}"
    translate(program, out, target, machine=machine, options=RunOptions(state_dir=tmp_path / "st", **options))
    return out.read_text()


@pytest.mark.parametrize("target", TARGETS)
def test_m5_before_the_next_blocks_zero_offset_and_move(tmp_path, target):
    """N30 stops the spindle with its move; N40 selects G55 and moves: M5 stays between N30's move and G55."""
    code = _code(_run(tmp_path, "o.din", "G90 G54\nS500 M3\nN30 G1 X5 F100 M5\nN40 G55 G0 X10\nM2\n", target))
    assert code.index("G1 X5 F100") < code.index("M5") < code.index("G55") < code.index("G0 X10"), code


@pytest.mark.parametrize("target", TARGETS)
def test_a_tool_length_programmed_before_the_tool_change_stays_before_it(tmp_path, target):
    """``G43 H2`` in a block of its own before ``T2 M6``: written where the program put it (the program's
    order, even where it is unusual); only a tool length in the tool change's own block follows the M6."""
    table = tmp_path / "machine.toml"
    table.write_text(AXES + "[[tool]]\nnumber = 2\nlength = 40.0\n[[tool]]\nnumber = 3\nlength = 30.0\n")
    text = _run(tmp_path, "t.din", "G90 G54\nN10 G43 H2\nN20 T2 M6\nN30 G0 Z5\nN40 T3 M6 G43 H3\nN50 G0 Z6\nM2\n",
                target, machine=table)
    code = _code(text)
    h2, h3 = ("D2", "D3") if target == "sinumerik840d" else ("G43 H2", "G43 H3")
    assert code.index(h2) < code.index("T2 M6") < code.index("T3 M6") < code.index(h3), code


@pytest.mark.parametrize("target", TARGETS)
def test_only_moving_axes_are_written(tmp_path, target):
    """A first move of X alone writes X alone (Y and Z stand wherever the new control has them), and a block
    that programs Y alone writes Y alone, in every target."""
    code = _code(_run(tmp_path, "a.din", "G90 G54\nG0 X10\nG0 Y20 Z5\nG1 Y30 F100\nM2\n", target))
    moves = [c for c in code if c.startswith(("G0", "G1"))]
    assert moves == ["G0 X10", "G0 Y20 Z5", "G1 Y30 F100"], moves


@pytest.mark.parametrize("target", TARGETS)
def test_feed_per_revolution_written_as_programmed(tmp_path, target):
    """G95 F0.2 becomes the target's G95 with F0.2 (mm/rev), G94 and the mm/min feed again after it."""
    code = _code(_run(tmp_path, "f.din", "G90 G54\nS800 M3\nG95 G1 X10 F0.2\nX20\nG94 G1 X30 F300\nM2\n", target))
    i = code.index("G95")
    assert code[i + 1:i + 3] == ["G1 X10 F0.2", "G1 X20"] and code[i + 3:i + 5] == ["G94", "G1 X30 F300"], code


@pytest.mark.parametrize("frame", ["work", "machine"])
def test_cutter_radius_compensation_is_refused_at_its_block(tmp_path, frame):
    """G41 with a tool radius: the run's tool-centre path holds the simulated radius; refused (TRN001) at
    the G41 block, nothing written, in either frame. G41 with radius 0 compensates nothing: translated."""
    table = tmp_path / "machine.toml"
    table.write_text(AXES + "[[tool]]\nnumber = 1\nradius = 4.0\n[[tool]]\nnumber = 2\n")
    program = tmp_path / "c.din"
    program.write_text("G90 G54\nT1 M6\nG0 X-10 Y-10\nG41 D1 G1 X0 Y0 F100\nX20\nG40 G0 X-10 Y-10\nM2\n")
    with pytest.raises(TranslationRefused) as e:
        translate(program, tmp_path / "c.ngc", frame=frame, machine=table,
                  options=RunOptions(state_dir=tmp_path / "st"))
    d = e.value.diagnostic
    assert d.code == "TRN001" and d.span.line == 4 and "cutter radius compensation G41" in d.message
    assert "radius 4 mm" in d.message and not (tmp_path / "c.ngc").exists()
    program.write_text("G90 G54\nT2 M6\nG0 X-10 Y-10\nG41 D2 G1 X0 Y0 F100\nX20\nG40 G0 X-10 Y-10\nM2\n")
    translate(program, tmp_path / "c.ngc", frame=frame, machine=table, options=RunOptions(state_dir=tmp_path / "st"))
    assert "G1 X20" in (tmp_path / "c.ngc").read_text()


CPL_LONG = """(an input read with blocks queued before it)
N10 G90 G0 X0 Y0 Z5
N20 G1 X10 F100
N30 G1 Y10
40 IF IC(1,1,1) THEN
N50 G1 Z-10
60 ELSE
N70 G1 Z-1
80 ENDIF
N90 G1 X0
N100 G0 Z5
M30
"""


def test_frozen_mark_after_every_block_prepared_before_the_read(tmp_path):
    """CPL prepares blocks ahead of their execution: the IC read of line 5 comes before N20 and N30 execute;
    the mark stands after their moves and before N70's, which the read decided."""
    program = tmp_path / "ic.cpl"
    program.write_text(CPL_LONG)
    out = tmp_path / "ic.ngc"
    scenario = tmp_path / "late.scenario.toml"  # an event after the run: the input stands at its rest value
    scenario.write_text('[[scenario]]\ntime = 1000\nkind = "input"\naddress = "IC(1,1,1)"\nvalue = true\n')
    translate(program, out, machine=EX / "cpl" / "machine.toml", source_comments=True,
              options=RunOptions(state_dir=tmp_path / "st", scenario=scenario))
    lines = out.read_text().splitlines()
    mark = next(i for i, line in enumerate(lines) if line.startswith("(FROZEN"))
    assert "ic.cpl:5" in lines[mark]
    assert lines[mark - 1].endswith("(ic.cpl:4)") and lines[mark + 1].endswith("(ic.cpl:8)"), lines


@pytest.mark.parametrize("target", TARGETS)
def test_sympas_homing_is_a_comment_and_positions_are_the_programs(tmp_path, target):
    """pick_place.sap homes Z, X and Y: no move of the home search is written (each is a HOMING comment and
    the header says to home them), the positions after it are the program's (MLAW A1 := 50 is X50), and
    the trace names each home search before its move."""
    out, trace = tmp_path / "p.out", tmp_path / "t.jsonl"
    translate(EX / "sympas" / "pick_place.sap", out, target, machine=EX / "sympas" / "machine.toml",
              options=RunOptions(state_dir=tmp_path / "st", trace=trace))
    text = out.read_text()
    assert sum(line.startswith(("(HOMING", "; HOMING")) for line in text.splitlines()) == 3
    assert "the program homes X Y Z" in text and "G28" not in text
    moves = [c for c in _code(text) if c.startswith(("G0", "G1"))]
    # F as programmed (TRVL 100 mm/s, the default, then 200), not the peak a short move reaches on the card
    assert moves[:3] == ["G1 Z0 F6000", "G1 X50 Y40 F12000", "G1 Z-60"], moves
    records = [json.loads(line) for line in trace.read_text().splitlines()]
    homing = [r for r in records if r["call"] == "homing"]
    assert [r["axes"] for r in homing] == [["Z"], ["X"], ["Y"]]
    first_feed = next(r for r in records if r["call"] == "feed")
    assert first_feed["work"]["Z"] == 0.0 and first_feed["end"]["Z"] == 5.0


def test_sympas_frozen_only_for_what_the_program_reads(tmp_path):
    """The example scenario's input A3.1 is never read by pick_place.sap: no FROZEN mark."""
    out = tmp_path / "p.ngc"
    translate(EX / "sympas" / "pick_place.sap", out, machine=EX / "sympas" / "machine.toml",
              options=RunOptions(state_dir=tmp_path / "st"))
    assert "FROZEN" not in out.read_text()


def test_840d_machine_frame_cancels_the_tool_length(tmp_path):
    """--frame machine on the 840D selects G500 and D0 (no zero offset, no tool length) before the first move."""
    out = tmp_path / "m.mpf"
    translate(EX / "sin800" / "flange.mpf", out, "sinumerik840d", frame="machine",
              machine=EX / "sin800" / "machine.toml", options=RunOptions(state_dir=tmp_path / "st"))
    code = _code(out.read_text())
    assert code[1] == "G500 D0" and not any(c.startswith("D1") for c in code), code[:4]


G53_RETRACT = "%MPF101\nN10 G17 G71 G90 G54 G94\nN20 T1 M6 D1\nN40 G0 X10 Y20 Z50\nN50 G53 G0 Z0\nN60 G0 X30 Y40\nN70 M30\n"


def test_g53_retract_keeps_the_tool_length_on_the_840d(tmp_path):
    """SINUMERIK ``G53 G0 Z0`` keeps the tool length in force (CL 800 manual L4083; flange machine: tool
    length 85.1): the 840D's SUPA keeps it too, so ``SUPA G0 Z0`` with D1 left on; the next move's X/Y
    alone, no Z re-expressed through the simulated tool length."""
    code = _code(_run(tmp_path, "g53.mpf", G53_RETRACT, "sinumerik840d", machine=EX / "sin800" / "machine.toml"))
    i = code.index("G0 X10 Y20 Z50")
    assert code[i + 1:i + 3] == ["SUPA G0 Z0", "G0 X30 Y40"], code


@pytest.mark.parametrize("target", ["linuxcnc", "iso"])
def test_g53_retract_with_the_tool_length_kept_is_refused_where_g53_drops_it(tmp_path, target):
    """LinuxCNC's and ISO's G53 drop the tool length that the SINUMERIK G53 keeps: writing the slide's
    position would carry the simulated tool length into the program, so the block is refused (TRN001)."""
    with pytest.raises(TranslationRefused) as e:
        _run(tmp_path, "g53.mpf", G53_RETRACT, target, machine=EX / "sin800" / "machine.toml")
    d = e.value.diagnostic
    assert d.code == "TRN001" and d.span.line == 5 and "tool length kept" in d.message
    assert not (tmp_path / f"g53.mpf.{target}").exists()


G53_DIN = "G21 G90 G17 G54\nT1 M6 G43 H1\nG0 X10 Y20 Z50\nG53 G0 Z0\nG0 X30 Y40\nM2\n"


@pytest.mark.parametrize(("target", "retract"), [("linuxcnc", ["G53 G0 Z0"]), ("iso", ["G53 G0 Z0"]),
                                                 ("sinumerik840d", ["D0", "SUPA G0 Z0", "D1"])])
def test_din_g53_retract_is_the_machine_position_alone(tmp_path, target, retract):
    """A din ``G53 G0 Z0`` drops the tool length, as LinuxCNC's: Z alone to machine Z0; the 840D keeps the
    tool length in SUPA, so the translation switches it off for that move (D0) and on again after it."""
    code = _code(_run(tmp_path, "g53.ngc", G53_DIN, target))
    i = code.index("G0 X10 Y20 Z50")
    assert code[i + 1:i + 2 + len(retract)] == retract + ["G0 X30 Y40"], code
