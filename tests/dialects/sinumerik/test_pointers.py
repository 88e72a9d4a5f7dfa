"""Indirect addressing: an operand read or written through a pointer (P<n>: the R parameter whose number
R<n> holds) gives what the operand written directly gives (planning guide L1283-1285, L6378-6382).

The property test runs every @ code of the table that takes a <Var> or <Value> operand twice: once with
its operands as R parameters, once with one of them through a pointer, and compares everything the run
leaves (status, error, R parameters, position, operator output).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from sin800_helpers import R, run_mpf
from test_atcode_coverage import MACHINE

from ncvm.api import run
from ncvm.dialects.sinumerik.atcodes import AT_CODES
from ncvm.runtime.session import RunOptions


def test_l1283_cl800_pointer_read_transfers_the_contents(tmp_path: Path):
    """L1283-1285: ``R51 = 80; R71 = [R51];`` transfers the contents of R80 to R71 (here of R12 to R11,
    transfer parameters, which the program leaves behind)."""
    src = tmp_path / "ptr.cl8"
    src.write_text("PROGRAM 3; CHANNEL NC 0;\nPOINTER: R50, R51;\nPAR INTEGER: R10, R11, R12;\nBEGIN\n"
                   "  R12 = 33; R50 = 10; [R50] = 20; R51 = 12; R11 = [R51];\nEND.\n")
    result, _ = run(src, options=RunOptions(state_dir=tmp_path / ".s"))
    assert result["status"] == "ok", result["error"]
    assert R(result, 10) == 20.0 and R(result, 11) == 33.0


def test_l6480_assignment_from_a_pointer_into_a_named_r_parameter(tmp_path: Path):
    """@201 <Var> <Value> (L6480) with a pointer value: R22 = contents of R19; @610 and @630 likewise."""
    result = run_mpf(tmp_path, "%MPF1\nN1 R21=19 R19=-5\nN2 @201 R22 P21\nN3 @610 R23 P21 @630 R24 P21\nN4 M30\n",
                     ok=True)
    assert R(result, 22) == -5.0 and R(result, 23) == 5.0
    assert R(result, 24) == pytest.approx(-0.0871557427)


#: the values of the <Value> operands (R10..): 1 is a channel, an axis, a spindle, a bit number, a sine
_VALUES = (1.0, 1.0, 1.0, 1.0, 1.0, 1.0)
#: codes whose <Value> operands name data: ones that exist on the machine (operand index: value; the
#: MD/SD areas of L6500-6522; OUTP DATA the tool offsets, L4508-4517, not the program text itself)
_DATA = {"301": {1: 5002}, "302": {1: 5002}, "307": {1: 6000}, "308": {1: 6000}, "311": {1: 5013},
         "312": {1: 5013}, "304": {2: 801}, "305": {2: 801}, "314": {2: 802}, "315": {2: 802},
         "401": {0: 5002}, "402": {0: 5002}, "407": {0: 6000}, "408": {0: 6000}, "411": {0: 5013},
         "412": {0: 5013}, "404": {1: 801}, "405": {1: 801}, "414": {1: 802}, "415": {1: 802},
         "4c0": {0: 4000}, "a26": {0: 6}}
#: the value of the <Var> operands (R30..): a bit pattern, so that the pattern codes accept it
_VAR = 101.0


def _program(code: str, kinds: str, pointer: int | None) -> str:
    """A main program running @``code`` with its operands as R parameters, operand ``pointer`` (index)
    through a pointer (R40+i holds the number of the R parameter the direct form names)."""
    values = list(_VALUES)
    for i, v in _DATA.get(code, {}).items():
        values[i] = float(v)
    preset = " ".join(f"R{10 + i}={v:g} R{30 + i}={_VAR:g} R{40 + i}={(30 if k == 'V' else 10) + i}"
                      for i, (k, v) in enumerate(zip(kinds, values)))
    ops = []
    for i, k in enumerate(kinds):
        if k == "K":
            ops.append("K60" if AT_CODES[code].lower == "branch" else "K1")
        elif i == pointer:
            ops.append(f"P{40 + i}")
        else:
            ops.append(f"R{30 + i}" if k == "V" else f"R{10 + i}")
    return (f"%MPF1\nN10 G0 X1 Y2 Z3\nN20 {preset}\nN30 @{code} {' '.join(ops)}\nN40 R90=1\nN60 R91=1\n"
            "N70 M30\n")


def _outcome(tmp_path: Path, text: str) -> tuple:
    tmp_path.mkdir()
    result = run_mpf(tmp_path, text, machine_text=MACHINE, name="p.mpf", state=".s")
    err = result["error"]
    return (result["status"], err and (err["code"], err["message"], err["line"]), result["variables"],
            result["position"], result["output"])


_WITH_OPERANDS = sorted(c for c, row in AT_CODES.items()
                        if row.kinds and any(k in "VW" for k in row.kinds)
                        and row.lower not in ("rel", "inta", "io_in"))


@pytest.mark.parametrize("code", _WITH_OPERANDS)
def test_every_operand_through_a_pointer_gives_the_direct_result(tmp_path: Path, code: str):
    """L6378-6382: a <Var> or <Value> operand may be a pointer; the code's result is the same."""
    kinds = AT_CODES[code].kinds
    direct = _outcome(tmp_path / "direct", _program(code, kinds, None))
    for i, k in enumerate(kinds):
        if k in "VW":
            assert _outcome(tmp_path / f"p{i}", _program(code, kinds, i)) == direct, f"operand {i + 1}"
