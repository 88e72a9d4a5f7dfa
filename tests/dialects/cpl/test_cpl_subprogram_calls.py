"""CPL sub-programs (manual §3): drilling cycles called by G address (§3.1 L1071-1074), programs excluded
from linking (§3.3), program names along the program path, CALL statements.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from ncvm.api import check

CYCLE = '10 #HOLES% = #HOLES% + 1 : #DEPTH = P1\nN1 G1 Z[P1] F100\nN2 G0 Z10\n'


def test_g81_calls_program_99999081_without_a_table_entry_l1073(run, reference):
    """§3.1 L1071-1074: "the programs for the drilling cycles (99999081 through 99999086) are permanently
    assigned to the functions G81 through G86". The machine file maps nothing; G81 calls 99999081 and, being a
    drilling cycle, again after every traversing block until G80: at X0, X10 and X20, not at X30."""
    m = reference()
    (m.program_path[0] / "99999081").write_text(CYCLE)
    r = run("1 #HOLES% = 0\nN1 G0 X0 Y0 Z10\nN2 G81 [-5]\nN3 X10\nN4 X20\nN5 G80\nN6 X30\nM30\n")
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["#HOLES%"] == 3 and r["variables"]["#DEPTH"] == -5.0
    assert r["position"]["X"] == 30.0 and r["motion"]["feed_moves"] == 3


@pytest.mark.parametrize("code", [82, 83, 84, 85, 86])
def test_g82_to_g86_call_their_programs_l1073(run, reference, code):
    m = reference()
    (m.program_path[0] / f"999990{code}").write_text(CYCLE)
    r = run(f"1 #HOLES% = 0\nN1 G0 X0 Y0 Z10\nN2 G{code} [-2]\nN5 G80\nM30\n")
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["#HOLES%"] == 1 and r["variables"]["#DEPTH"] == -2.0


def test_missing_drilling_cycle_program_is_a_link_error(run):
    """Linking checks sub-program calls (§2.3 L413): G81 without program 99999081 stops before anything runs."""
    r = run('10 PRN#(0,"started")\nN2 G81 [-5]\nM30\n')
    assert r["error"]["code"] == "CPL005" and "99999081" in r["error"]["message"]
    assert r["output"] == [] and r["error"]["line"] == 2


def test_machine_file_entry_replaces_a_drilling_cycle(run, reference):
    m = reference(cpl={"calls": {"G81": {"program": "MYDRILL", "modal": True}}})
    (m.program_path[0] / "MYDRILL").write_text(CYCLE)
    r = run("1 #HOLES% = 0\nN2 G81 [-1]\nN3 X5\nN4 G80\nM30\n", cpl={"calls": {"G81": {"program": "MYDRILL",
                                                                                   "modal": True}}})
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["#HOLES%"] == 2


def test_cpl_expression_in_a_din_excluded_program_is_an_error_l1101(run, reference):
    """§3.3 L1101-1104: a sub-program with CPL elements excluded by DIN gives an error at run time. `X[5]` is
    the CPL syntax of §2.1.1 (L357); the block used to be dropped without a word."""
    (reference().program_path[0] / "DINEXPR").write_text("N10 G1 X[5] F100\n")
    r = run("10 CALL DINEXPR DIN\n20 A=1\nM30\n")
    assert r["error"]["code"] == "CPL030" and "DINEXPR" in r["error"]["message"]


def test_variable_parameter_in_a_din_excluded_program_is_an_error(run, reference):
    m = reference(cpl={"calls": {"M66": "TOOLMSG"}})
    (m.program_path[0] / "TOOLMSG").write_text("5 PDIM P1$(20)\n10 #MSG$ = P1$\n")
    (m.program_path[0] / "DINCALL").write_text("N10 M66 [T$]\n")
    r = run("10 CALL DINCALL DIN\nM30\n", cpl={"calls": {"M66": "TOOLMSG"}})
    assert r["error"]["code"] == "CPL030"


@pytest.mark.parametrize("pdim, expected", [(True, "ok"), (False, "CPL026")])
def test_din_excluded_program_calls_by_m_address_with_pdim_l1161(run, reference, pdim, expected):
    """§3.4 L1149-1175: a string constant passed by a program selected without linking reaches the sub-program
    only through PDIM ("invalid variable" without it). The excluded program's M66 call runs (it used to be
    executed as a bare M66, the sub-program never called); the sub-program, which no linked program reaches,
    is linked when it is called."""
    calls = {"calls": {"M66": "TOOLMSG"}}
    m = reference(cpl=calls)
    (m.program_path[0] / "TOOLMSG").write_text(("5 PDIM P1$(20)\n" if pdim else "") + "10 #MSG$ = P1$\n")
    (m.program_path[0] / "DINCALL").write_text('N10 G0 X5\nN20 M66 ["T1 READY"]\nN30 G0 X7\n')
    r = run("10 CALL DINCALL DIN\n20 WAIT\n30 X = MPOS(1)\nM30\n", cpl=calls)
    if expected == "ok":
        assert r["status"] == "ok", r["error"]
        assert r["variables"]["#MSG$"] == "T1 READY" and r["variables"]["X"] == 7.0
    else:
        assert r["error"]["code"] == expected and r["error"]["file"].endswith("TOOLMSG")


def test_din_header_program_runs_a_drilling_cycle(run, reference):
    """"(DIN)" in the first line (L1115-1120): G81 in it calls 99999081 at N20 and again after N30 (§3.1, §3.2)."""
    m = reference()
    (m.program_path[0] / "99999081").write_text("10 #HOLES% = #HOLES% + 1\n")
    (m.program_path[0] / "DRILL").write_text("N10 (DIN)\nN20 G81 [-5]\nN30 X10\nN40 G80\nN50 X20\n")
    r = run("10 #HOLES% = 0\n20 CALL DRILL\nM30\n")
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["#HOLES%"] == 2 and r["position"]["X"] == 20.0


def test_din_header_program_drills_only_after_traversing_blocks_l1083(run, reference):
    """§3.2 L1083: the modal cycle runs "after each traversing movement": not after G4 X1 (a dwell) nor
    G92 X0 (set actual value, L2813); a new G81 with other parameters runs once, with its own."""
    m = reference()
    (m.program_path[0] / "99999081").write_text("10 #HOLES% = #HOLES% + 1\n20 #LAST = P1\n")
    (m.program_path[0] / "DRILL").write_text("N10 (DIN)\nN20 G81 [-5] X10\nN30 G4 X1\nN35 G92 X0\n"
                                             "N40 G81 [-8] X10\nN50 G80\n")
    r = run("10 #HOLES% = 0\n20 CALL DRILL\nM30\n")
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["#HOLES%"] == 2 and r["variables"]["#LAST"] == -8.0


def test_link_error_of_a_program_reached_through_an_excluded_one(run, reference):
    calls = {"calls": {"M67": "BADSUB"}}
    m = reference(cpl=calls)
    (m.program_path[0] / "BADSUB").write_text("10 X=(1\n")
    (m.program_path[0] / "DINCALL").write_text("N10 M67\n")
    r = run("10 CALL DINCALL DIN\nM30\n", cpl=calls)
    assert r["error"]["code"] == "CPL001" and r["error"]["file"].endswith("BADSUB")


def test_main_program_with_din_header_runs_unlinked_l1115(run, reference):
    """L1115-1120: "(DIN)" as a remark in the first line excludes the program from linking; the PDIM example
    (L1161-1175) starts such a main program. Its P call runs with the string constant for PDIM."""
    (reference().program_path[0] / "SP").write_text("10 PDIM P1$(4)\n20 #P$ = P1$\nM30\n")
    r = run('N10 (DIN)\nN50 P SP["TEST"]\nN60 G0 X5\nM30\n')
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["#P$"] == "TEST" and r["position"]["X"] == 5.0


def test_main_program_with_din_header_and_cpl_is_an_error_l1101(run):
    r = run("N10 (DIN)\nN20 G0 X5\n30 X=1\nM30\n")
    assert r["error"]["code"] == "CPL030" and (r["error"]["line"], r["error"]["column"]) == (3, 4)


def test_program_names_tell_upper_from_lower_case_l3853(run, reference):
    """§6.1.1 L3853-3857: "A distinction is made between upper- and lower-case letters" (P12_Data_Dial and
    P12_DATA_DIAL are two files). CALL finds a program as written or with ".cpl", in that case only."""
    folder = reference().program_path[0]
    (folder / "Sub1.cpl").write_text("10 #HIT% = 1\n")
    assert run("10 CALL Sub1\nM30\n")["variables"] == {"#HIT%": 1}
    assert run("10 CALL Sub1.cpl\nM30\n")["variables"] == {"#HIT%": 1}
    r = run("10 CALL SUB1\nM30\n")
    assert r["error"]["code"] == "CPL005" and "SUB1" in r["error"]["message"]
    (folder / "P999.CPL").write_text("10 #HIT% = 2\n")  # an archive copied from a PC: the extension in capitals
    assert run("10 CALL P999\nM30\n")["variables"] == {"#HIT%": 2}


@pytest.mark.parametrize("name", ["/etc/hostname", "../p.cpl", "sub/P999", ".."])
def test_call_takes_a_program_name_not_a_host_path(run, name):
    """§6.1.1 L3851: a file name has alphanumeric characters, "." and "_". CALL used to open any file of the
    host (an absolute path, or ../ out of the program path) and print its lines in the link errors."""
    r = run(f"10 CALL {name}\nM30\n")
    assert r["error"]["code"] == "CPL001" and "program name" in r["error"]["message"]


@pytest.mark.parametrize("block, ok", [
    ("10 CALL P999 : REM the remark is no instruction", True),
    ("10 .AGAIN: CALL P999", True),
    ("10 CALL P999 : CALL P999", False),
    ("10 X=1 : CALL P999", False),
    ("10 IF TRUE THEN CALL P999 ENDIF", False),
])
def test_call_in_a_block_of_its_own_l1068(run, reference, block, ok):
    (reference().program_path[0] / "P999").write_text("10 #N% = #N% + 1\n")
    r = run("5 #N% = 0\n" + block + "\nM30\n")
    assert (r["status"] == "ok") is ok and (ok or r["error"]["code"] == "CPL014")


def test_drilling_cycle_runs_after_the_moves_of_a_called_program(run, reference):
    """A built-in drilling cycle behaves as a modal entry of the machine file: after every traversing block,
    also one of a sub-program called while it is active (§3.2 L1079-1081)."""
    m = reference()
    (m.program_path[0] / "99999081").write_text(CYCLE)
    (m.program_path[0] / "ROW").write_text("N1 X10\nN2 X20\n")
    r = run("1 #HOLES% = 0\nN1 G0 X0 Y0 Z10\nN2 G81 [-5]\n10 CALL ROW\nN5 G80\nM30\n")
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["#HOLES%"] == 3


def _chain(folder, levels: int, deepest: str = "10 #DEEP% = 1\n") -> None:
    """L1 calls L2 ... calls L<levels>, the last one runs ``deepest``."""
    for k in range(1, levels):
        (folder / f"L{k}").write_text(f"10 CALL L{k + 1}\n")
    (folder / f"L{levels}").write_text(deepest)


def test_eight_sub_program_levels_are_a_link_error_l325(run, reference, tmp_path):
    """§2.1 L325: "CPL permits a maximum 7-fold nesting depth". A chain of 8 fixed in the source is reported by
    check, at the call that opens level 8, and the run stops before anything ran (it used to find it at run
    time, after the main program had written its file)."""
    m = reference()
    _chain(m.program_path[0], 8)
    main = tmp_path / "p.cpl"
    main.write_text('10 OPENW(1,"PLOG",1024,"log") : PRN#(1,"started") : CLOSE(1)\n20 IF #GO% = 1 THEN\n'
                    "30 CALL L1\n40 ENDIF\nM30\n")
    diags = check(main, machine=m)
    assert [(d.code, Path(d.span.file).name, d.span.line) for d in diags] == [("CPL007", "L7", 1)]
    assert "L8 would be level 8" in diags[0].message
    r = run(main.read_text())
    assert r["error"]["code"] == "CPL007" and r["error"]["file"].endswith("L7")
    assert not (m.file_root / "PLOG").exists()


def test_seven_sub_program_levels_run_l325(run, reference):
    m = reference()
    _chain(m.program_path[0], 7)
    r = run("10 CALL L1\nM30\n")
    assert r["error"] is None, r["error"]
    assert r["variables"] == {"#DEEP%": 1}


def test_the_deepest_chain_counts_not_the_first_one_found_l325(run, reference):
    """A sub-program reached first on a short chain and again on a long one: the long one is level 8."""
    m = reference()
    _chain(m.program_path[0], 7, "10 CALL SHARED\n")
    (m.program_path[0] / "SHARED").write_text("10 #DEEP% = 1\n")
    r = run("10 CALL SHARED\n20 CALL L1\nM30\n")
    assert r["error"]["code"] == "CPL007" and r["variables"] == {}
