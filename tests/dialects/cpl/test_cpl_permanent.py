"""Permanent variables: @1..@100, @_R, definable permanents from wmhperm.dat/anwperm.dat, kept in the store."""

from __future__ import annotations

from pathlib import Path

from ncvm.machine.config import machine_from_dict
from ncvm.machine.store import Store

COUNT_PARTS = "10 IF @1 = NUL THEN @1 = 0 ENDIF\n20 @1 = @1 + 1\n30 @_R(2) = @_R(2) + 0.5\nM30\n"


def mill(tmp_path: Path):
    data = {"axis": [{"name": "X"}, {"name": "Y"}, {"name": "Z"}],
            "paths": {"program_path": ["."], "file_root": "files"}}
    (tmp_path / "files").mkdir(exist_ok=True)
    return machine_from_dict(data, "<test>", tmp_path)


def test_numbered_permanents_survive_the_end_of_program(tmp_path, run_text):
    m = mill(tmp_path)
    first = run_text("5 @_R(2) = 1.0\n" + COUNT_PARTS, name="p.cpl", machine=m)
    second = run_text(COUNT_PARTS, name="p.cpl", machine=m)
    assert first["variables"]["@1"] == 1 and first["variables"]["@_R(2)"] == 1.5
    assert second["variables"]["@1"] == 2 and second["variables"]["@_R(2)"] == 2.0
    store = Store(tmp_path / ".ncvm")
    try:
        assert store.get("cpl.perm", "@1") == 2
        assert store.get("cpl.perm", "@_R(2)") == 2.0
    finally:
        store.close()


def test_locals_and_globals_end_with_the_program(tmp_path, run_text):
    m = mill(tmp_path)
    run_text("10 #G% = 5 : L% = 6\nM30\n", name="p.cpl", machine=m)
    r = run_text("10 GONE? = #G% = NUL\nM30\n", name="p.cpl", machine=m)
    assert r["variables"]["GONE?"] is True


def test_definable_permanents_created_kept_and_deleted(tmp_path, run_text):
    m = mill(tmp_path)
    decl = tmp_path / "files" / "anwperm.dat"
    decl.write_text("DEF INT @COUNTER ;parts made\nDEF CHAR @LASTPART(8)\nDEF REAL @OFFS(3,2)\n")
    r = run_text('10 @COUNTER% = 5 : @LASTPART$ = "FLANGE-12" : @OFFS(1,2) = 0.25\nM30\n', name="p.cpl", machine=m)
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["@LASTPART$"] == "FLANGE-1"  # cut to the declared length
    r = run_text("10 C% = @COUNTER% : O = @OFFS(1,2)\nM30\n", name="p.cpl", machine=m)
    assert (r["variables"]["C%"], r["variables"]["O"]) == (5, 0.25)  # kept across start-ups
    decl.write_text("DEF CHAR @LASTPART(8)\n")
    r = run_text("10 C% = @COUNTER%\nM30\n", name="p.cpl", machine=m)
    assert r["error"]["code"] == "CPL034"  # no longer declared: deleted at start-up
    decl.write_text("DEF INT @COUNTER\nDEF CHAR @LASTPART(8)\n")
    r = run_text("10 NEW? = @COUNTER% = NUL : L$ = @LASTPART$\nM30\n", name="p.cpl", machine=m)
    assert r["variables"]["NEW?"] is True and r["variables"]["L$"] == "FLANGE-1"


def test_a_declaration_file_a_program_wrote_is_read_at_the_next_start(tmp_path, run_text):
    """anwperm.dat written with OPENW/PRN# is in the control's file form (records, then the EOF marker
    ETX LF); the marker ends the declarations, it is no declaration line (CPL038 before)."""
    m = mill(tmp_path)
    r = run_text('10 OPENW(1,"anwperm.dat")\n20 PRN#(1,"DEF INT @COUNTER")\n30 CLOSE(1)\nM30\n', name="w.cpl", machine=m)
    assert r["status"] == "ok" and (tmp_path / "files" / "anwperm.dat").read_bytes().endswith(b"\x03\n")
    r = run_text("10 @COUNTER% = 5\nM30\n", name="p.cpl", machine=m)
    assert r["status"] == "ok", r["error"]
    assert run_text("10 C% = @COUNTER%\nM30\n", name="p.cpl", machine=m)["variables"]["C%"] == 5


def test_declarations_beyond_the_memory_budget_are_error_1869(tmp_path, run_text):
    m = mill(tmp_path)
    # 3 + 20 + 12583 * 8 = 100,687 bytes > 100,678 (manual L580-613)
    (tmp_path / "files" / "wmhperm.dat").write_text("DEF DOUBLE @BIG(12583)\n")
    r = run_text("10 @BIG!(1) = 1.0\nM30\n", name="p.cpl", machine=m)
    assert r["error"]["code"] == "1869"
    (tmp_path / "files" / "wmhperm.dat").write_text("DEF DOUBLE @BIG(12575)\n")
    r = run_text("10 @BIG!(1) = 1.0\nM30\n", name="p.cpl", machine=m)
    assert r["status"] == "ok", r["error"]


def test_bad_declaration_line(tmp_path, run_text):
    m = mill(tmp_path)
    (tmp_path / "files" / "wmhperm.dat").write_text("DEF INTEGER @X\n")
    r = run_text("10 @1 = 1\nM30\n", name="p.cpl", machine=m)
    assert r["error"]["code"] == "CPL038"
    assert r["error"]["file"].endswith("wmhperm.dat")


def test_permanent_character_fields_as_inp_and_mid_targets(tmp_path, run_text):
    """INP# fills a permanent character field (as many characters as declared) and MID$(...)= writes into
    one; both go to the store at once, like an assignment (manual §2.4.3, §5.3, §6.6)."""
    m = mill(tmp_path)
    (tmp_path / "files" / "anwperm.dat").write_text("DEF CHAR @PART(6)\nDEF CHAR @NAMES(3,4)\n")
    (tmp_path / "files" / "P2").write_text("FLANGE12ABCDEFGH\n\x03\n", encoding="latin-1")
    r = run_text('10 OPENR(2,"P2")\n20 INP#(2,@PART$,MID$(@NAMES$(2),1,2),@NAMES$(3))\n30 CLOSE(2)\n'
                 '40 MID$(@PART$,2,3) = "***"\n50 @NAMES$(1) = "WXYZ"\n60 MID$(@NAMES$(1),4) = "!"\nM30\n',
                 name="p.cpl", machine=m)
    assert r["status"] == "ok", r["error"]
    # "FLANGE" (6 characters), then "12" into the first 2 of row 2, then "ABCD" (4) into row 3
    r = run_text("10 A$ = @PART$ : B$ = @NAMES$(1) : C$ = @NAMES$(2) : D$ = @NAMES$(3)\nM30\n",
                 name="p.cpl", machine=m)
    v = r["variables"]
    assert (v["A$"], v["B$"], v["C$"], v["D$"]) == ("F***GE", "WXY!", "12", "ABCD")


def test_mid_write_beyond_an_unassigned_permanent_field(tmp_path, run_text):
    m = mill(tmp_path)
    (tmp_path / "files" / "anwperm.dat").write_text("DEF CHAR @TEXT(5)\n")
    r = run_text('10 MID$(@TEXT$,3) = "AB"\nM30\n', name="p.cpl", machine=m)
    assert r["error"]["code"] == "CPL024"  # CHARACTER FIELD NOT ASSIGNED, as for a DIMensioned field
