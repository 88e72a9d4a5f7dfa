"""``ncvm check`` (sin800) warns RUN002 "the run stops here" at a block selecting G81-G89 whose cycle program
L81-L89 is missing (docs/decisions.md "Issue 14: check and the drilling cycle programs": "it is the control's
own stop"). Issue 14 part 5: check is to see what run will refuse, so its warning must name a block where
the run really stops."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from review14b_run import SIN800_MACHINE, run


def check(tmp_path: Path, name: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "ncvm", "check", "--machine", str(tmp_path / "machine.toml"),
                           str(tmp_path / name)], capture_output=True, text=True, timeout=120)


def test_check_and_run_agree_on_a_block_with_g81_and_g80(tmp_path: Path) -> None:
    """``N2 G81 X10 G80``: the run takes G80 (group 9, L7406) and ends normally without L81; check says
    "the run stops here" at that block. One of the two is wrong: they must agree."""
    result, _, _ = run(tmp_path, "g81g80.mpf", "%MPF1\nN1 G0 X0 Y0 Z10\nN2 G81 X10 G80\nN3 M30\n",
                       SIN800_MACHINE)
    checked = check(tmp_path, "g81g80.mpf")
    run_stops = result["status"] != "ok"
    # since review 14c two functions of group 9 in one block are refused (SIN001), by run and check alike
    check_says_stop = "RUN002" in checked.stdout + checked.stderr or "error SIN001" in checked.stderr
    assert run_stops == check_says_stop, (result["status"], checked.stdout + checked.stderr)


def test_check_of_a_cl800_program_sees_the_missing_cycle_its_run_stops_on(tmp_path: Path) -> None:
    """Issue 14 part 5: "a clean check means the run will not stop". A CL 800 program whose DIN block
    ``(: G81 X10 :)`` selects the missing L81 checks clean (0 diagnostics, exit 0) and its run stops there
    with RUN002 (docs/decisions.md leaves CL 800 sources out of this warning; the user sees green, then red)."""
    program = ("PROGRAM 82;\nCHANNEL NC 0;\nBEGIN\n  LF; (: G90 G00 X0 Y0 Z10 :); LF;\n"
               "  (: R2=2 R3=-5 G81 X10 :); LF;\n  (: G80 :); LF;\nEND.\n")
    result, _, _ = run(tmp_path, "drill.cl8", program, SIN800_MACHINE)
    assert result["status"] != "ok" and result["error"]["code"] == "RUN002"   # the run stops: the premise
    checked = check(tmp_path, "drill.cl8")
    assert "RUN002" in checked.stdout + checked.stderr, checked.stdout + checked.stderr
