"""SINUMERIK programs that ``ncvm check`` passes clean and ``ncvm run`` stops on an unsupported function.

Issue 14 §5: "`ncvm check` reports every G/M function and address the profile refuses ... so that a clean
check means the run will not stop on an unsupported function". The CPL check follows CALL into the called
program and warns there (the same program written as CPL gets NC004 from check); the sin800 check of the
main program does not look into the L sub-program it calls, nor does it say that a called L sub-program is
missing, although it does warn (RUN002) when G81's cycle program L81 is missing."""

from __future__ import annotations

import pytest
from review14d_run import check, run, write

MAIN_CALLS_L50 = "%MPF1\nN10 G0 X0 Y0 Z0\nN20 L50\nN30 M30\n"


def _check_clean(tmp_path, name):
    proc = check(tmp_path, name, "sin800")
    return proc.returncode == 0 and " 0 diagnostic(s)" in proc.stderr


def test_check_of_a_main_program_sees_the_refused_function_of_its_l_sub_program(tmp_path):
    """L50 (on the program path, as the run finds it) holds G25, which the profile refuses (NC004): the run of
    the main program stops there; its check must not be clean."""
    files = {"L50.spf": "%SPF50\nN10 G25 X100\nN20 M17\n"}
    write(tmp_path, {**files, "main.mpf": MAIN_CALLS_L50})
    result, _rows, _stderr = run(tmp_path, "main.mpf", MAIN_CALLS_L50, files)
    assert result["error"]["code"] == "NC004"  # the run stops: G25 is not supported by ncvm
    assert not _check_clean(tmp_path, "main.mpf"), "check of main.mpf is clean; its run stops with NC004 in L50"


def test_check_warns_of_a_missing_l_sub_program_as_it_warns_of_a_missing_l81(tmp_path):
    """The run stops with RUN002 at `N20 L51` (no L51 on the program path); check warns of the same stop for
    `G81` without L81 (docs/decisions.md "Issue 14: check and the drilling cycle programs") but is clean here."""
    text = "%MPF1\nN10 G0 X0 Y0 Z0\nN20 L51\nN30 M30\n"
    write(tmp_path, {"main.mpf": text})
    result, _rows, _stderr = run(tmp_path, "main.mpf", text)
    assert result["error"]["code"] == "RUN002"
    assert not _check_clean(tmp_path, "main.mpf"), "check is clean; the run stops with RUN002 at N20 L51"


@pytest.mark.parametrize("blocks", [
    # a rounding (B on a straight block, L4237) between moves that leave the plane: the run says
    # "a rounding between moves that leave the plane is not supported by ncvm"
    "N20 G1 X10 Y0 B5 F100\nN30 G1 X10 Y0 Z-5\n",
    # a rounding before a circle ("the next block N30 is not a straight move at feed"): ncvm's limit, not the
    # control's (docs/sin800.md: "The run stops with NC009 where ncvm cannot make the rounding")
    "N20 G1 X10 Y0 B5 F100\nN30 G2 X20 Y10 I0 J10\n",
], ids=["rounding-out-of-plane", "rounding-before-circle"])
def test_check_warns_where_the_run_cannot_make_a_rounding(tmp_path, blocks):
    text = "%MPF1\nN10 G0 X0 Y0 Z0\n" + blocks + "N90 M30\n"
    write(tmp_path, {"p.mpf": text})
    result, _rows, _stderr = run(tmp_path, "p.mpf", text)
    assert result["error"]["code"] == "NC009"
    assert not _check_clean(tmp_path, "p.mpf"), f"check is clean; the run stops: {result['error']['message']}"
