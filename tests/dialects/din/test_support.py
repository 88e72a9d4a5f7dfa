"""Issue 14 part 5 for din: ``ncvm check`` warns of every G function and address the din profile refuses,
with the code the run stops with and "not supported by ncvm", so a check without warnings means the run
does not stop on an unsupported function."""

from __future__ import annotations

import json
import random

import pytest
from click.testing import CliRunner

from ncvm import cli
from ncvm.diagnostics import RuntimeFault
from ncvm.dialects.din import setup_kernel
from ncvm.dialects.din.support import G_FUNCTIONS
from ncvm.machine.config import machine_from_dict
from ncvm.nc.block import Block
from ncvm.nc.canon import Canon, Src
from ncvm.nc.kernel import NcKernel

#: every G number 0..99 and the decimal ones LinuxCNC has
CANDIDATES = [*range(100), 5.1, 5.2, 7.1, 28.1, 30.1, 33.1, 38.2, 38.3, 43.1, 43.2, 59.1, 59.2, 59.3, 61.1, 64.1,
              92.1, 92.2, 92.3, 96.1, 187, 253]
#: words that let each supported function run (a cycle's R, depth, Q, P; G10 L2 P1; G43 H1)
WORDS = {"X": 1.0, "Y": 1.0, "Z": -1.0, "R": 1.0, "Q": 0.5, "P": 1.0, "L": 2.0, "I": 0.5, "J": 0.5, "K": -0.5,
         "H": 1.0, "F": 100.0, "S": 1000.0}


def din_kernel() -> NcKernel:
    k = NcKernel(machine_from_dict({"axis": [{"name": a} for a in "XYZ"], "tool": [{"number": 1, "length": 5}]}),
                 Canon([]))
    setup_kernel(k)
    k.execute(Block((0,), (3,), {"Z": 5.0, "S": 1000.0}, None, None, Src("t", 1)))
    return k


@pytest.mark.parametrize("g", CANDIDATES)
def test_the_table_is_what_the_kernel_runs(g):
    """A G number out of the table faults in the kernel with NC004/NC005; one in it runs (or faults with the
    control's own error, such as a spindle turning the wrong way for G74)."""
    try:
        din_kernel().execute(Block((g,), (), dict(WORDS), None, None, Src("t", 2)))
        code = None
    except RuntimeFault as e:
        code = e.code
    assert (code in ("NC004", "NC005")) == (g not in G_FUNCTIONS), (g, code)


def ncvm(tmp_path, command: str, text: str, name: str = "p.din") -> tuple[int, dict]:
    (tmp_path / name).write_text(text)
    args = [command, str(tmp_path / name), "--json"] + (["--state", str(tmp_path / "st")] if command == "run" else [])
    r = CliRunner().invoke(cli.cli, args, catch_exceptions=False)
    return r.exit_code, json.loads(r.stdout)


def test_check_warns_of_each_refused_function_and_address(tmp_path):
    text = "G21 G90 F100\nG0 X0 Y0 Z5\nG1 X1 E5\nG5.1 X2\nG5 X3\nG5.1 X4\nG10 L1 P1 R2\nG62 (corner slowdown)\nM2\n"
    code, doc = ncvm(tmp_path, "check", text)
    diags = doc["files"][0]["diagnostics"]
    assert code == 0 and doc["files"][0]["ok"]
    assert [(d["severity"], d["code"], d["line"], d["column"]) for d in diags] == [
        ("warning", "NC007", 3, 7), ("warning", "NC004", 4, 1), ("warning", "NC004", 5, 1),
        ("warning", "NC004", 7, 1), ("warning", "NC004", 8, 1)]
    assert all("not supported by ncvm" in d["message"] for d in diags)
    assert "2 blocks use it" in diags[1]["message"]
    code, doc = ncvm(tmp_path, "run", text)
    assert code == 1 and (doc["error"]["code"], doc["error"]["line"], doc["error"]["column"]) == ("NC007", 3, 7)


def test_an_o_program_number_and_the_cycle_words_are_no_warning(tmp_path):
    code, doc = ncvm(tmp_path, "check", "O1234\nG21 F100 S500 M3\nG0 Z5\nG83 X1 Y1 Z-3 R1 Q1 L2\nG80\nM30\n")
    assert code == 0 and doc["files"][0]["diagnostics"] == []


def random_program(rnd: random.Random) -> str:
    out = ["G21 G90 F100 S500 M3", "G0 X0 Y0 Z5"]
    for _ in range(rnd.randint(2, 8)):
        pick = rnd.random()
        if pick < 0.15:
            out.append(f"G{rnd.choice((5, 7, 33.1, 5.1, 62, 93, 76))} X{rnd.randint(0, 9)}")
        elif pick < 0.25:
            out.append(f"G1 X{rnd.randint(0, 9)} E{rnd.randint(1, 9)}")
        elif pick < 0.4:
            out.append(f"G{rnd.choice((17, 18, 19))} G{rnd.choice((90, 91))} G{rnd.choice((54, 55, 64))}")
            out.append("G17 G90")
        else:
            out.append(f"G1 X{rnd.randint(0, 9)} Y{rnd.randint(0, 9)}")
    return "\n".join(out + ["M2"]) + "\n"


def test_a_clean_check_means_the_run_does_not_stop_on_an_unsupported_function(tmp_path):
    rnd = random.Random(5)
    clean = warned = 0
    for i in range(40):
        text = random_program(rnd)
        _c, checked = ncvm(tmp_path, "check", text, f"p{i}.din")
        warnings = checked["files"][0]["diagnostics"]
        _c, ran = ncvm(tmp_path, "run", text, f"p{i}.din")
        if not warnings:
            clean += 1
            assert ran["status"] == "ok", text
        else:
            warned += 1
            first = min(warnings, key=lambda d: d["line"])
            assert (ran["error"]["code"], ran["error"]["line"]) == (first["code"], first["line"]), text
    assert clean > 5 and warned > 5
