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


def test_mid_write_on_a_permanent_character_field_is_not_in_this_version(tmp_path, run_text):
    m = mill(tmp_path)
    (tmp_path / "files" / "anwperm.dat").write_text("DEF CHAR @LASTPART(8)\n")
    r = run_text('10 MID$(@LASTPART$,1,2)="AB"\nM30\n', name="p.cpl", machine=m)
    assert r["status"] == "error" and r["error"]["code"] == "CPL037"
