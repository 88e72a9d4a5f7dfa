"""Manual §7.2 (L4503-4532): which part of the editor's selected NC block INP#(0) reads."""

from __future__ import annotations

import pytest

from ncvm.dialects.cpl.io.editor import call_parameters
from ncvm.dialects.cpl.io.files import CplFiles
from ncvm.dialects.cpl.io.strings import CharacterField


@pytest.mark.parametrize("block,params", [
    ("Q900[12.5,3]", ["12.5", "3"]),  # the block the manual's PRN#(0) example writes (L4786)
    ("N10 BOLTCIRC[80,6]", ["80", "6"]),  # a program called by name
    ('N50 P SP["TEST"]', ['"TEST"']),  # P address with a program name (L1163-1169)
    ("N20 G81 [ 2 , 5.5 ]", ["2", "5.5"]),  # a calling G address, blanks around the list
    ("51 CALL P999 [2.75, X%, 0]", ["2.75", "X%", "0"]),  # §3.4's call (L1138)
    ("N10 P999 [R(1,2),\"A,B\",[1,2]]", ["R(1,2)", '"A,B"', "[1,2]"]),  # commas inside do not split
    ("N10 G1 X[XVALUE]F[ FEED*2+1000]M[M3]", []),  # variable syntax in words (L359-369): no call
    ("N10 X2=[A] Y [B] BOLTCIRC[1]", ["1"]),  # word values first, then the call's list
    ("N10 G1 X100 Y50", []),  # a plain NC block
    ("N10 G0 X0 (SUB[1,2])", []),  # brackets in a remark
    ("N10 CYC[]", []),
])
def test_call_parameters(block, params):
    assert call_parameters(block) == params


def test_inp0_reads_whole_parameters_by_type():
    fs = CplFiles(root=".", editor_block='N50 P SP["TEST",2.5,FALSE,-0012,1.25,2*A,,7]')
    name = CharacterField(3)
    got = fs.INP(0, "S", "I", "B", "I", "D", "R", "R", name, "R")
    # "TEST" without quotes; 2.5 is no INTEGER; -0012 reads as -12 (INP# skips leading zeros);
    # 2*A is no constant and the empty parameter is missing: NUL; "7" fills the field
    assert got == ["TEST", None, False, -12, 1.25, None, None, "7", None]
    assert name.text == "7"


def test_prn0_overwrites_the_whole_block_and_tells_it():
    seen = []
    fs = CplFiles(root=".", editor_block="N10 G1 X100 Y50", on_editor_block=seen.append)
    assert fs.INP(0, "R", "R") == [None, None]  # a plain block has no call parameters
    fs.PRN(0, "N10 G1 X", 120, semicolon=True)
    assert seen == [] and fs.editor_block == "N10 G1 X100 Y50"  # the record is still open
    fs.PRN(0, " Y50", "\r")
    assert fs.editor_block == "N10 G1 X      120 Y50"
    assert seen == ["N10 G1 X      120 Y50"] and fs.messages == []
