"""Sinks: JSONL trace, flat G-code (read back by ncvm itself), plots, the travel-limit check, the step hook."""

from __future__ import annotations

import json
import math

import pytest

from ncvm.machine.config import machine_from_dict

PART = """(MSG, start)
T1 M6
S1200 M3
G54 G0 X0 Y0 Z5
G1 Z-1 F200
G2 X10 Y10 I10 J0
G18 G3 X20 Z-1 I5 K0
G19 G2 Y0 Z-1 J-5 K0
G17 G91 G1 X-5 Y-5
G4 P1.5
M9
M30
"""

def shop_machine():
    """A fresh machine per run: programs may change its offset tables (G10), as on a real control."""
    return machine_from_dict({"axis": [{"name": n, "min": -50.0, "max": 50.0} for n in "XYZ"],
                              "offsets": {"G54": [100.0, 0.0, -20.0]}, "tool": [{"number": 1, "length": 10.0}]})


def test_trace_has_one_line_per_call_with_source_line(run_text, tmp_path):
    trace = tmp_path / "t.jsonl"
    run_text(PART, trace=trace)
    recs = [json.loads(x) for x in trace.read_text().splitlines()]
    assert recs[0] == {"call": "begin", "position": {"X": 0.0, "Y": 0.0, "Z": 0.0}}
    calls = [(r["call"], r.get("line")) for r in recs[1:]]
    assert calls == [("message", 1), ("tool_change", 2), ("spindle", 3), ("rapid", 4), ("feed", 5), ("arc", 6),
                     ("arc", 7), ("arc", 8), ("feed", 9), ("dwell", 10), ("coolant", 11), ("program_end", 12)]
    arc = recs[6]
    assert arc["end"] == {"X": 10.0, "Y": 10.0, "Z": -1.0} and arc["center"] == [10.0, 0.0] and arc["cw"] is True
    assert recs[7]["plane"] == ["Z", "X"] and recs[8]["plane"] == ["Y", "Z"]
    assert all(r["file"].endswith("prog.din") for r in recs[1:])


def test_gcode_export_reproduces_the_toolpath(run_text, tmp_path):
    """The G-code (the LinuxCNC translation, in work coordinates), run again on the same machine, gives the
    same moves, lengths and extents in machine coordinates; it writes no offset table (issue 16: the G10
    that zeroed G54 overwrote the receiving control's offsets)."""
    ngc = tmp_path / "flat.ngc"
    first = run_text(PART, machine=shop_machine(), gcode=ngc)
    text = ngc.read_text()
    moves = [line for line in text.splitlines() if line.startswith(("G0", "G1", "G2", "G3"))]
    assert "G10" not in text and "\nG54\n" in text  # the program's zero offset selected, never written
    assert not any("X100" in line for line in moves)  # the program's numbers, without G54's X100
    assert "G91" not in text and "G18" in text and "G19" in text
    assert "G4 P1.5" in text and "T1 M6" in text and "M3 S1200" in text
    again = run_text(text, name="flat.din", machine=shop_machine())
    assert again["status"] == "ok"
    for key in ("rapid_moves", "feed_moves", "arc_moves"):
        assert again["motion"][key] == first["motion"][key]
    assert again["motion"]["feed_length"] == pytest.approx(first["motion"]["feed_length"], abs=1e-3)
    for axis, (lo, hi) in first["motion"]["bounds"].items():
        assert again["motion"]["bounds"][axis] == pytest.approx([lo, hi], abs=1e-3)
    # machine coordinates: the G54 shift of X100 is in the numbers
    assert first["motion"]["bounds"]["X"][1] == pytest.approx(120.0)


def test_limit_check_reports_first_block_per_axis(run_text):
    m = machine_from_dict({"axis": [{"name": "X", "min": 0.0, "max": 100.0},
                                    {"name": "Y", "min": 0.0, "max": 100.0}, {"name": "Z"}]})
    # the arc from (95,50) around (90,50) bulges to X=95 only; the move to X=120 leaves at line 3,
    # the arc below Y=0 (centre (50,5), radius 10) leaves at line 5
    r = run_text("G1 X95 Y50 F1000\nG2 X85 Y50 I-5 J0\nG1 X120\nX60 Y5\nG2 X40 Y5 I-10 J0\nG1 X110\n", machine=m)
    assert r["status"] == "ok"
    v = r["limit_violations"]
    assert len(v) == 2
    assert v[0].startswith("axis X reaches 120.0000, above its soft limit 100.0000") and v[0].endswith(":3)")
    assert v[1].startswith("axis Y reaches -5.0000, below its soft limit 0.0000") and v[1].endswith(":5)")


@pytest.mark.parametrize("suffix, magic", [(".png", b"\x89PNG"), (".svg", b"<?xml")])
def test_plot_writes_a_real_picture(tmp_path, suffix, magic):
    from ncvm.api import run
    from ncvm.runtime.session import RunOptions
    from ncvm.sinks.plot import plot_toolpath

    prog = tmp_path / "p.din"
    prog.write_text(PART)
    _, session = run(prog, machine=shop_machine(), options=RunOptions(keep_toolpath=True, state_dir=tmp_path / "s"))
    out = tmp_path / ("plot" + suffix)
    plot_toolpath(session.recorder, out, title="p")
    data = out.read_bytes()
    assert data.startswith(magic) and len(data) > 10_000


def test_full_circle_bounds_include_every_quadrant(run_text):
    r = run_text("G0 X10\nG2 X10 Y0 I-10 J0 F100\n")
    assert r["motion"]["bounds"]["X"] == pytest.approx([-10, 10])
    assert r["motion"]["bounds"]["Y"] == pytest.approx([-10, 10])
    assert r["motion"]["feed_length"] == pytest.approx(2 * math.pi * 10)


def test_step_hook_sees_every_block_in_order(run_text, tmp_path):
    seen = []
    r = run_text("G0 X1\n/G0 X2\nG0 X3\nM2\n", hook=lambda f, line, v: seen.append((line, dict(v))))
    assert r["status"] == "ok"
    assert [line for line, _ in seen] == [1, 3, 4]
    assert seen[1][1]["X"] == pytest.approx(1.0)  # the hook runs before its block


def test_step_hook_may_stop_the_run(run_text):
    from ncvm.diagnostics import RuntimeFault

    def stop_at_3(file, line, variables):
        if line == 3:
            raise RuntimeFault("RUN004", "stopped at breakpoint", None)

    r = run_text("G0 X1\nG0 X2\nG0 X3\n", hook=stop_at_3)
    assert r["error"]["code"] == "RUN004" and r["position"]["X"] == pytest.approx(2.0)
