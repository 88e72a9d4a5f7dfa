"""A G0/G1 block of an axis @440 names (PRAP: the drilling cycles' infeed, ``G1 @440 K3 R62``) goes straight to
the kernel's straight-move path, as a block of constant axis words does (issue 18: the L81 cycle's 15 moves
a hole went through the kernel's general dispatch): a constant axis number names its axis when the program
compiles (dialects/sinumerik/codegen.py ``constant_axis``), one read from an R parameter when it runs
(``COMPUTED_AXIS_KEYS``). Each program here runs both ways -- that path, and every such block through
``NcKernel.execute`` with the axis named at run time -- and the JSON result, every trace record (each
move's time, entry and exit speed) and the G-code must be equal, not close: random deep-hole drilling with
the manual's L81, moves without their G code (G0/G1 modal, and a circle modal: the general path), two @440
words in one block, axis numbers in R parameters, an axis number the machine lacks, and the step limit
at every third step of two holes."""

from __future__ import annotations

import json
import random
from pathlib import Path

import pytest
from sin800_helpers import machine

from ncvm.api import run
from ncvm.dialects.sinumerik import codegen, compile_unit
from ncvm.runtime.session import RunOptions

L81 = (Path(__file__).parents[3] / "examples" / "cl800" / "L81.spf").read_text()

#: a sub-program of @440 moves: with G1, without a G code (modal G1, G0), two words (the last wins), after a
#: circle, axis numbers in R parameters
SPF90 = """%SPF90
G1 @440 K1 R1
@440 K2 R2
G0 @440 K3 R3 @440 K1 R4
@440 K2 R1
G1 @440 K3 R2 F{f}
R5=R4-2 R6=2 R7=3
G3 X=R5 I-1 J0
G1 @440 K1 R4
@440 K2 R3 @440 K2 R4
@440 R6 R1 @440 R7 R3
G0 @440 R7 R2
M17
"""


def drilling(seed: int) -> str:
    """Deep-hole drilling at random positions with random transfer parameters (L81), and now and then the
    @440 moves of L90."""
    rnd = random.Random(seed)
    start = rnd.choice((2, 3, 5))
    final = -rnd.choice((8, 11, 14, 20))
    lines = ["%MPF9100", f"N10 G17 G90 G94 S1000 M3 F{rnd.randint(60, 400)}", "N20 G0 X0 Y0 Z50",
             f"N30 R22={start} R24={rnd.choice((1, 2, 3))} R25={rnd.choice((3, 5, 7))} R26={final} "
             f"R27={rnd.choice((0, 0.5, 1))} R28={rnd.choice((0, 0.25))}"]
    for i in range(rnd.randint(4, 9)):
        x, y = round(rnd.uniform(-40, 40), 3), round(rnd.uniform(-40, 40), 3)
        lines.append(f"{'G81 ' if i == 0 else ''}X{x} Y{y}")
        if rnd.random() < 0.3:
            lines += ["G80", f"R1={x + 1} R2={y} R3={start + 4} R4={x}", "L90", f"G81 X{x} Y{y + 1}"]
        if rnd.random() < 0.2:
            lines.append(rnd.choice(("G64", "G60", "G9 X0 Y0", "M8", "M9")))
    return "\n".join(lines + ["G80", "M30"]) + "\n"


def _run(tmp_path: Path, text: str, name: str, *, gcode: bool = False, **options):
    folder = tmp_path / name
    folder.mkdir()
    (folder / "machine.toml").write_text(machine())
    (folder / "L81.spf").write_text(L81)
    (folder / "L90.spf").write_text(SPF90.format(f=random.Random(len(text)).randint(100, 900)))
    (folder / "prog.mpf").write_text(text)
    trace, out = folder / "t.jsonl", folder / "out.ngc"
    result, _ = run(folder / "prog.mpf", dialect="sin800", machine=folder / "machine.toml",
                    options=RunOptions(state_dir=folder / ".s", trace=trace, gcode=out if gcode else None, **options))
    here = str(folder)  # the folders differ: their paths are taken out
    return (json.loads(json.dumps(result).replace(here, "<dir>")), trace.read_text().replace(here, "<dir>"),
            out.read_text().replace(here, "<dir>") if out.exists() else None)


def _both(tmp_path: Path, monkeypatch, text: str, **options):
    fast = _run(tmp_path, text, "fast", **options)
    monkeypatch.setattr(codegen, "COMPUTED_AXIS_KEYS", ())  # every @440 block through NcKernel.execute,
    monkeypatch.setattr(codegen, "constant_axis", lambda axes, op: None)  # its axis named at run time
    general = _run(tmp_path, text, "general", **options)
    return fast, general


def _same(fast, general) -> None:
    assert fast == general


def test_the_fast_path_is_generated_for_computed_axes():
    """L81's infeed blocks call the straight-move path (``_lin``) with the axis @440 K3 names, Z; an axis number
    in an R parameter is named at run time, and its block goes the same way."""
    source = compile_unit("L81.spf", L81, ("X", "Y", "Z"), "L81").source.text()
    assert "_lin(_K, 1, {'Z': _w0}" in source and "axis_name" not in source
    source = compile_unit("L90.spf", SPF90.format(f=100), ("X", "Y", "Z"), "L90").source.text()
    assert "_lin(_K, 0, {_rt.positions.axis_name(r7, " in source
    source = compile_unit("L90.spf", SPF90.format(f=100), ("X", "Y"), "L90").source.text()  # no third axis
    assert "{_rt.positions.axis_name(3.0, " in source


@pytest.mark.parametrize("seed", range(8))
@pytest.mark.parametrize("model", ["lookahead", "rest-to-rest"])
def test_computed_axis_moves_equal_the_general_path(tmp_path, monkeypatch, seed, model):
    fast, general = _both(tmp_path, monkeypatch, drilling(seed), time_model=model)
    assert fast[0]["status"] == "ok", fast[0]["error"]
    assert fast[0]["motion"]["feed_moves"] > 20
    _same(fast, general)


@pytest.mark.parametrize("seed", range(3))
def test_computed_axis_moves_translated_equal_the_general_path(tmp_path, monkeypatch, seed):
    """With --gcode: the translation hears each block's axis words (an axis standing where it is written)."""
    fast, general = _both(tmp_path, monkeypatch, drilling(20 + seed), gcode=True)
    assert fast[0]["status"] == "ok", fast[0]["error"]
    assert fast[2]
    _same(fast, general)


def test_an_axis_number_the_machine_lacks_is_refused_alike(tmp_path, monkeypatch):
    text = drilling(3).replace("N20 G0 X0 Y0 Z50", "N20 G0 X0 Y0 Z50\nR9=7 G1 @440 K4 R9")
    fast, general = _both(tmp_path, monkeypatch, text)
    assert fast[0]["status"] == "error" and fast[0]["error"]["line"] == 4
    _same(fast, general)


def test_a_circle_modal_sends_the_block_to_the_kernel_alike(tmp_path, monkeypatch):
    """An @440 block without a G code under modal G3 is a circle without its centre: NC003 both ways."""
    text = drilling(4).replace("N20 G0 X0 Y0 Z50", "N20 G0 X0 Y0 Z50\nG3 X2 Y0 I1 J0\nR9=1 @440 K1 R9")
    fast, general = _both(tmp_path, monkeypatch, text)
    assert fast[0]["status"] == "error" and (fast[0]["error"]["code"], fast[0]["error"]["line"]) == ("NC003", 5)
    _same(fast, general)


def test_step_limit_at_every_step_of_a_hole(tmp_path, monkeypatch):
    """--max-steps anywhere in the first two holes (in the cycle's infeed, at a dwell, in L90)."""
    text = "%MPF9101\nN10 G17 G90 G94 F100\nN20 R22=2 R24=2 R25=5 R26=-14 R27=0.5 R28=0.25\n" \
           "R1=3 R2=4 R3=6 R4=1 L90\nG81 X10 Y10\nX20\nG80\nM30\n"
    steps = _run(tmp_path, text, "all")[0]["steps"]
    assert steps > 80
    for limit in range(1, steps + 1, 3):
        (tmp_path / str(limit)).mkdir()
        with monkeypatch.context() as m:
            fast, general = _both(tmp_path / str(limit), m, text, max_steps=limit)
        _same(fast, general)
        assert (fast[0]["status"] == "error") == (limit < steps), limit
