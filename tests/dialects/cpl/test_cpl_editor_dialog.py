"""The editor dialog end to end (manual §7.2, L4503-4532, and the PRN#(0) example L4780-4786):
``ncvm run --editor-block TEXT`` gives the program the selected NC block; INP#(0) reads its call
parameters, PRN#(0) overwrites it, and the result reports the block as it stands."""

from __future__ import annotations

import json
from pathlib import Path

from click.testing import CliRunner

from ncvm.cli import cli

# L4780-4786, with INP#(0) first so the values of the block are shown and only changed ones typed
D4 = ('10 INP#(0,WI,DP)\n20 DLG\n30 PRN(8,4,"MAX.CUTTING WIDTH: ###.### MM",WI)\n'
      '40 PRN(10,4,"MAX. CUTTING DEPTH: ###.### MM",DP)\n50 INP(WI):INP(DP)\n60 ENDDLG\n'
      '80 PRN#(0,"Q900[",WI,",",DP,"]")\nM30\n')


def ncvm_run(tmp_path: Path, program: str, *args: str, keys: str | None = None):
    prog = tmp_path / "dlg.cpl"
    prog.write_text(program, encoding="latin-1")
    extra = []
    if keys is not None:
        (tmp_path / "dlg.keys").write_text(keys)
        extra = ["--keys", str(tmp_path / "dlg.keys")]
    return CliRunner().invoke(cli, ["run", str(prog), "--state", str(tmp_path / "st"), *extra, *args],
                              catch_exceptions=False)


def test_manual_q900_dialog_reads_and_overwrites_the_block(tmp_path):
    # the block holds WI = 12.5 and DP = 3: ENTER keeps WI, the operator types DP = 3.25
    r = ncvm_run(tmp_path, D4, "--editor-block", "N20 Q900[12.5,3]", "--json", keys="ENTER\nTYPE 3.25\n")
    doc = json.loads(r.stdout)
    assert r.exit_code == 0 and doc["error"] is None
    assert doc["output"][:2] == ["MAX.CUTTING WIDTH:  12.500 MM", "MAX. CUTTING DEPTH:   3.000 MM"]
    assert doc["variables"]["WI"] == 12.5 and doc["variables"]["DP"] == 3.25
    # the manual's PRN#(0): standard REAL format ####.### (9 characters) for each value
    assert doc["editor_block"] == "Q900[  12.500,   3.250]"
    assert "Q900" not in " ".join(doc["output"])  # not in the message window


def test_name_call_block_and_the_text_summary(tmp_path):
    program = ('10 INP#(0,R,N%)\n20 DSP(1,1,"RADIUS ",R," HOLES ",N%)\n'
               '30 LJUST : PRN#(0,"N10 BOLTCIRC[",R*2,",",N%+2,"]")\nM30\n')
    r = ncvm_run(tmp_path, program, "--editor-block", "N10 BOLTCIRC[80,6]")
    assert r.exit_code == 0
    assert r.stdout.splitlines()[-1] == "RADIUS   80.000 HOLES         6"
    assert "ncvm: editor block: N10 BOLTCIRC[160.000,8]\n" in r.stderr


def test_plain_nc_block_has_no_call_parameters_and_can_be_replaced(tmp_path):
    # a block without a call goes to cpldlg05.dlg (L4509): INP#(0) finds nothing, PRN#(0) still writes
    program = ('10 INP#(0,X)\n20 IF X=NUL THEN PRN#(0,"N10 G1 X100 Y50 F",1000) ENDIF\nM30\n')
    r = ncvm_run(tmp_path, program, "--editor-block", "N10 G1 X[XVALUE] Y50", "--json")
    doc = json.loads(r.stdout)
    assert doc["error"] is None and doc["editor_block"] == "N10 G1 X100 Y50 F     1000"


def test_block_written_before_a_fault_is_kept(tmp_path):
    program = '10 PRN#(0,"N10 G81 [1,2]")\n20 DSP(47,1,"X")\nM30\n'
    r = ncvm_run(tmp_path, program, "--editor-block", "N10 G81 [5,6]", "--json")
    doc = json.loads(r.stdout)
    assert r.exit_code == 1 and doc["error"]["code"] == "CPL701"
    assert doc["editor_block"] == "N10 G81 [1,2]"


def test_without_editor_block_prn0_goes_to_the_message_window(tmp_path):
    r = ncvm_run(tmp_path, '10 INP#(0,A)\n20 PRN#(0,"A IS NUL ",A=NUL)\nM30\n', "--json")
    doc = json.loads(r.stdout)
    assert doc["output"] == ["A IS NUL TRUE"] and "editor_block" not in doc


def test_editor_block_needs_the_cpl_dialect(tmp_path):
    prog = tmp_path / "part.din"
    prog.write_text("G0 X10\nM30\n")
    r = CliRunner().invoke(cli, ["run", str(prog), "--state", str(tmp_path / "st"), "--editor-block", "N10 X1"],
                           catch_exceptions=False)
    assert r.exit_code == 0
    assert "dialect 'din' has no editor dialog; --editor-block ignored" in r.stderr
    assert "ncvm: editor block" not in r.stderr
