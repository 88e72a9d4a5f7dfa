"""Manual §4.3-4.5: axis zero shifts FXC/FXCR/FXDEL/FXINS, tool compensation TC, tool database TDA."""

from __future__ import annotations

import os
import time

import pytest

from ncvm.diagnostics import UsageError
from ncvm.dialects.cpl.io.files import CplFiles
from ncvm.machine.store import Store

TAB = "/usr/user/NPV1.npv"


def table_file(*rows, unit="MM", strict=0, columns=("X", "Y", "Z")) -> list[str]:
    """The records of a ZS table file (docs/decisions.md "Axis ZS table files"): rows given as
    (G address, values...) are set, all others are zero."""
    given = {r[0]: r[1:] for r in rows}
    heads = ["G", *columns]
    out = [f"ZS-TABLE {unit} STRICT={strict}", "G".ljust(5) + "".join(f" {h:>16}" for h in heads[1:])]
    for g in [f"G{b + i}" for b in (54, 154, 254) for i in range(6)]:
        values = given.get(g, [0.0] * len(columns))
        out.append(g.ljust(5) + "".join(f" {repr(float(v)):>16}" for v in values))
    return out


def records(path) -> list[str]:
    """A CPL file's records: LF-ended, then the EOF marker ETX LF."""
    raw = path.read_bytes().decode("latin-1")
    assert raw.endswith("\x03\n"), raw[-10:]
    return raw[:-2].split("\n")[:-1]


FXC_EXAMPLE = (f'0 TAB$="{TAB}"\n1 FXC(2,54,1)=80\n2 FXC(1,54,TAB$)=20\n3 FXC(-1,54,TAB$)=2\n'
               '4 FXC("Z",54,TAB$,2)=10/25.4\n5 FXC("Z",160,0)=40\n6 FXC("-Z",254,TAB$)=3\n7 FXC("-Z",254,TAB$)=3\n'
               '8 FXC("-U_CH1",54,TAB$)=20\n9 FXC("Z",255)=40\n10 X_SUM=FXC("X")\n11 Z_SUM=FXC("Z")\n'
               '20 R1=FXC(2,54,1)\n21 R2=FXC(1,54,TAB$)\n22 R3=FXC("Z",54,TAB$)\n23 R3I=FXC("Z",54,TAB$,2)\n'
               '24 R4=FXC("Z",160,0)\n25 R5=FXC(3,254,TAB$)\n26 R6=FXC("U_CH1",54,TAB$)\n27 R7=FXC("Z",255)\nM30\n')
ALL_AXES = ("X", "Y", "Z", "X2", "Y2", "Z2", "U_CH1", "A:R")


def test_fxc_example_l1767(run, tmp_path):
    """Every line of the manual's FXC example (L1767-1779), read back; the ASCII table is the file
    files/usr/user/NPV1.npv, written from the machine file's zs_tables at the start, in mm."""
    r = run(FXC_EXAMPLE, offsets={"G54": [5.0, 0.0, 1.0]}, cpl={"zs_tables": {TAB: {"G54": [0.0] * 8}}})
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert v["R1"] == 80.0 and v["R2"] == 22.0 and v["R4"] == 40.0 and v["R5"] == 6.0 and v["R6"] == 20.0
    assert v["R3"] == pytest.approx(10.0) and v["R3I"] == pytest.approx(10.0 / 25.4)
    assert v["R7"] == 40.0
    # the sum of the active shifts: G54 of the active table V1 (X 5, Z 1); the external G160 Z 40 is written
    # but not selected (G167 at power-on, group 30 of L2305), so it is not active
    assert v["X_SUM"] == 5.0 and v["Z_SUM"] == 1.0
    # the file: X = 20 + 2 (lines 2-3), Z = 10/25.4 inch = 10 mm (line 4), U_CH1 = 0 + 20 (line 8);
    # G254 Z = 3 + 3 (lines 6-7); nothing else changed
    z = 10 / 25.4 * 25.4
    assert records(tmp_path / "files/usr/user/NPV1.npv") == table_file(
        ("G54", 22.0, 0.0, z, 0.0, 0.0, 0.0, 20.0, 0.0), ("G254", 0.0, 0.0, 6.0, 0.0, 0.0, 0.0, 0.0, 0.0),
        columns=ALL_AXES)
    assert [p.name for p in (tmp_path / "files/usr/user").iterdir()] == ["NPV1.npv"]  # no temporary file left


FXC_AS_PRINTED = """0 TAB$="/usr/user/NPV1.npv"
1 FXC(2,54,1)=80
2 FXC(1,54,TAB$)=20
3 FXC(-1,54,TAB$)=2
4 FXC("Z",54,TAB$,2)=10/25.4
5 FXC("Z",160,0)=40
6 FXC("-Z",254,TAB$)=3
7 FXC("-U_CH1",54,TAB$)=20
8 FXC("Z",255)=40
9 X_SUM=FXC("X")
10 Y_SUM=FXC("Y")
11 Z_SUM=FXC("Z")
20 R2=FXC(1,54,TAB$)
21 R4=FXC(3,254,TAB$)
22 R7=FXC("U_CH1",54,TAB$)
M30
"""


def test_fxc_example_l1767_as_printed(run, tmp_path):
    """The manual's lines 0-9 as printed (once a golden program; it writes a table file, so it runs in
    tmp_path). The table file does not exist before: the machine file's zs_tables creates it."""
    r = run(FXC_AS_PRINTED, cpl={"zs_tables": {TAB: {"G54": [0.0] * 8}}})
    assert r["status"] == "ok", r["error"]
    # the active shifts: G54 of the active table V1 (the kernel starts in G54) with Y = 80 (line 1); the
    # external G160 with Z = 40 (line 5) and G255 (line 8) are not selected. X: nothing.
    r["variables"].pop("TAB$")
    assert r["variables"] == {"X_SUM": 0.0, "Y_SUM": 80.0, "Z_SUM": 0.0, "R2": 22.0, "R4": 3.0, "R7": 20.0}
    assert records(tmp_path / "files/usr/user/NPV1.npv") == table_file(
        ("G54", 22.0, 0.0, 10 / 25.4 * 25.4, 0.0, 0.0, 0.0, 20.0, 0.0),
        ("G254", 0.0, 0.0, 3.0, 0.0, 0.0, 0.0, 0.0, 0.0), columns=ALL_AXES)


def test_fxc_reads_a_table_file_a_user_wrote(run, tmp_path):
    """A table typed by hand: lower case, CR LF, no EOF marker, rows in any order, a rotary column."""
    folder = tmp_path / "files/usr/user"
    folder.mkdir(parents=True)
    rows = [f"g{b + i} 0 0 0" for b in (254, 154, 54) for i in range(6)]
    rows[rows.index("g54 0 0 0")] = "g54 1.5 -2 0.25"
    (folder / "NPV1.npv").write_bytes("\r\n".join(["zs-table inch strict=1", "g  x  y  b:r", *rows, ""]).encode())
    r = run(f'1 A=FXC("Y",54,"{TAB}")\n2 B=FXC(1,54,"{TAB}",0)\n3 C=FXC("B",54,"{TAB}")\nM30\n')
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"A": -2.0, "B": pytest.approx(1.5 * 25.4), "C": 0.25}


def test_fxc_write_moves_the_active_work_offset(run):
    """A value written into the active table acts on the NC kernel's G54 at once (tool stays put)."""
    r = run("N1 G54 G0 X0\n2 FXC(1,54)=12\nN3 G0 X0\n4 WAIT\n5 M=MPOS(1)\nM30\n")
    assert r["variables"]["M"] == 12.0


def test_zs_tables_persist_in_the_store(run_text, reference):
    m = reference()
    assert run_text("1 FXC(1,54,1)=7.5\nM30\n", name="a.cpl", machine=m)["status"] == "ok"
    r = run_text("N1 G54 G0 X1\n2 WAIT\n3 V=FXC(1,54,1)\n4 M=MPOS(1)\nM30\n", name="b.cpl", machine=reference())
    assert r["variables"] == {"V": 7.5, "M": 8.5}


def test_an_active_table_named_by_a_path_stays_in_the_store(run, tmp_path):
    """The active table is the control's database (the kernel's G54..G59), even when a path names it:
    FXC on that name moves the work offset and writes no file."""
    text = f'N1 G54 G0 X0\n2 FXC(1,54,"{TAB}")=3\nN3 G0 X0\n4 WAIT\n5 M=MPOS(1)\n6 F%=FILEACCESS("{TAB}")\nM30\n'
    r = run(text, cpl={"zs_active": TAB})
    assert r["variables"] == {"M": 3.0, "F%": 6}
    assert not (tmp_path / "files/usr").exists()


def test_a_value_that_is_no_finite_number_is_not_written(run, tmp_path):
    power = "*".join(["A"] * 40)  # (10^9)^40 overflows a double
    r = run(f'1 FXCR(1,"/T.npv")\n2 A=1000000000.0\n3 FXC(1,54,"/T.npv")={power}\nM30\n')
    assert r["error"]["code"] == "CPL023"
    assert records(tmp_path / "files/T.npv") == table_file()


def test_external_shift_of_a_foreign_axis_is_an_error(run):
    assert run('1 FXC("X2",160,0)=1\nM30\n')["error"]["code"] == "1970"


def run_in(run_text, tmp_path, folder: str, text: str, machine):
    """Run ``text`` as a program lying in ``folder`` of the file root (its current directory)."""
    (tmp_path / "files" / folder).mkdir(parents=True, exist_ok=True)
    return run_text(text, name=f"files/{folder}/p.cpl", machine=machine)


def test_fxcr_fxdel_fxins_example_l1809(run_text, reference, tmp_path):
    """The manual's example runs in /usr/user, so the table's file name alone finds it (L1809-1827)."""
    text = ('10 NPV_BASIS$="/usr/user/NPV_TAB_K2.npv"\n12 FXCR(2,NPV_BASIS$)\n'
            '13 FXDEL("NPV_TAB_K2.npv",2)\n14 FXINS("NPV_TAB_K2.npv",3,"U",0)\n'
            '17 FXCR(NPV_BASIS$,"NPV2_TAB_K2.npv")\n18 FXC("U",54,"NPV2_TAB_K2.npv")=4\n'
            '19 A=FXC(3,54,"NPV2_TAB_K2.npv")\n20 B=FXC("Z2",54,"NPV2_TAB_K2.npv")\nM30\n')
    r = run_in(run_text, tmp_path, "usr/user", text, reference())
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["A"] == 4.0 and r["variables"]["B"] == 0.0
    # channel 2 has X2 Y2 Z2 -> delete column 2 (Y2) -> insert the rotary axis U in front of column 3: X2 Z2 U
    folder = tmp_path / "files/usr/user"
    assert records(folder / "NPV_TAB_K2.npv") == table_file(columns=("X2", "Z2", "U:R"))
    assert records(folder / "NPV2_TAB_K2.npv") == table_file(("G54", 0.0, 0.0, 4.0), columns=("X2", "Z2", "U:R"))
    r = run_in(run_text, tmp_path, "usr/user", '1 A=FXC("Y2",54,"NPV2_TAB_K2.npv")\nM30\n', reference())
    assert r["error"]["code"] == "1938"
    r = run_in(run_text, tmp_path, "usr/user", '1 FXCR(2,"/usr/user/NPV_TAB_K2.npv")\nM30\n', reference())
    assert r["error"]["code"] == "CPL040"  # the table file exists


def test_a_table_name_without_path_is_in_the_current_directory(run_text, reference, tmp_path):
    """From a program outside the file root the current directory is the root: "NPV_TAB_K2.npv" is not
    /usr/user's table."""
    r = run_text('1 FXCR(2,"/usr/user/NPV_TAB_K2.npv")\n2 FXDEL("NPV_TAB_K2.npv",2)\nM30\n', name="p.cpl",
                 machine=reference())
    assert r["error"]["code"] == "CPL040" and "does not exist" in r["error"]["message"]
    assert (tmp_path / "files/usr/user/NPV_TAB_K2.npv").is_file()


def test_a_table_file_is_an_ordinary_cpl_file(run_text, reference, tmp_path):
    """FILEACCESS, FILEDATE, OPENR/INP#, FILESIZE and ERASE see a table file like any other (§6)."""
    text = ('1 DIM H$(40)\n2 DIM C$(60)\n3 DIM R$(60)\n10 FXCR(1,"/T1.npv")\n11 FXC("Y",54,"/T1.npv")=12.5\n'
            '20 F%=FILEACCESS("/T1.npv")\n21 D$=FILEDATE("/T1.npv")\n'
            '30 OPENR(1,"/T1.npv")\n31 INP#(1,H$)\n32 INP#(1,C$)\n33 INP#(1,R$)\n34 S%=FILESIZE(1,1)\n'
            '35 N%=0\n36 WHILE NOT EOF(1) DO\n37 INP#(1,C$) : N%=N%+1\n38 END\n39 CLOSE(1)\nM30\n')
    r = run_text(text, name="p.cpl", machine=reference())
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    path = tmp_path / "files/T1.npv"
    expected = table_file(("G54", 0.0, 12.5, 0.0))
    assert records(path) == expected
    assert v["F%"] == 6 and v["S%"] == path.stat().st_size
    assert v["H$"].rstrip() == "ZS-TABLE MM STRICT=0" and v["R$"].rstrip() == expected[2]
    assert v["N%"] == 17  # rows G55..G259 after G54
    assert v["D$"] == time.strftime("%d.%m.%y", time.gmtime(path.stat().st_mtime))
    r = run_text('1 E%=ERASE("/T1.npv")\n2 F%=FILEACCESS("/T1.npv")\n3 A=FXC(1,54,"/T1.npv")\nM30\n',
                 name="q.cpl", machine=reference())
    assert r["variables"] == {"E%": 0, "F%": -1}
    assert r["error"]["code"] == "CPL040" and not path.exists()


@pytest.mark.parametrize("stmt", ['FXCR(1,"../../OUT.npv")', 'A=FXC(1,54,"/../OUT.npv")',
                                  'FXC(1,54,"/usr/../../OUT.npv")=1', 'FXDEL("../OUT.npv",1)'])
def test_a_table_outside_the_file_root_is_refused(run_text, reference, tmp_path, stmt):
    (tmp_path / "OUT.npv").write_text("\n".join(table_file()) + "\n")
    before = (tmp_path / "OUT.npv").read_bytes()
    r = run_text(f"1 {stmt}\nM30\n", name="p.cpl", machine=reference())
    assert r["error"]["code"] == "CPL609"  # INVALID FILE NAME, as for OPENW/OPENR
    assert (tmp_path / "OUT.npv").read_bytes() == before and not (tmp_path.parent / "OUT.npv").exists()


DAMAGE = ['10 OPENW(1,"/T.npv")\n11 PRN#(1,"G54 1 2")\n12 CLOSE(1)',  # a row twice, and too short
          '10 OPENW(1,"/T.npv")\n11 REWRITE(1)\n12 PRN#(1,"ZS-TABLE MM STRICT=0")\n13 CLOSE(1)',  # rows lost
          '10 OPENW(1,"/T.npv")\n11 REWRITE(1)\n12 CLOSE(1)']  # empty
DAMAGED_TEXT = [["ZS-TABLE CM STRICT=0"] + table_file()[1:], table_file()[:1] + ["X Y Z"] + table_file()[2:],
                table_file()[:2] + ["G54 1 2 x"] + table_file()[3:], table_file()[:2] + ["G53 0 0 0"] + table_file()[3:],
                table_file()[:2] + ["G54 0 0 inf"] + table_file()[3:], table_file(columns=("X", "X", "Z")),
                table_file()[:2] + ["G54 1_0 0 0"] + table_file()[3:]]  # Python's float() reads "1_0" as 10


@pytest.mark.parametrize("damage", DAMAGE)
def test_fxc_on_a_table_a_program_damaged_is_cpl040(run_text, reference, tmp_path, damage):
    r = run_text(f'1 FXCR(1,"/T.npv")\n{damage}\n20 A=FXC(1,54,"/T.npv")\nM30\n', name="p.cpl", machine=reference())
    assert r["error"]["code"] == "CPL040" and "damaged" in r["error"]["message"], r["error"]
    assert r["error"]["line"] == 1 + (damage.count("\n") + 1) + 1  # the FXC line, after FXCR and the damage


@pytest.mark.parametrize("lines", DAMAGED_TEXT)
@pytest.mark.parametrize("stmt", ['A=FXC(1,54,"/T.npv")', 'FXC(1,54,"/T.npv")=1', 'FXINS("/T.npv",1,"B")',
                                  'FXCR("/T.npv","/T2.npv")'])
def test_a_damaged_table_file_is_cpl040_and_stays_as_it_was(run_text, reference, tmp_path, lines, stmt):
    path = tmp_path / "files/T.npv"
    path.parent.mkdir(parents=True)
    path.write_text("\n".join(lines) + "\n")
    r = run_text(f"1 {stmt}\nM30\n", name="p.cpl", machine=reference())
    assert r["error"]["code"] == "CPL040" and "damaged" in r["error"]["message"], r["error"]
    assert path.read_text() == "\n".join(lines) + "\n" and not (tmp_path / "files/T2.npv").exists()


def test_a_write_protected_table_file_is_not_changed(run_text, reference, tmp_path):
    path = tmp_path / "files/T.npv"
    path.parent.mkdir(parents=True)
    path.write_text("\n".join(table_file()) + "\n")
    path.chmod(0o444)
    r = run_text('1 A=FXC(1,54,"/T.npv")\n2 FXC(1,54,"/T.npv")=1\nM30\n', name="p.cpl", machine=reference())
    assert r["variables"] == {"A": 0.0}
    assert r["error"]["code"] == "CPL040" and "write-protected" in r["error"]["message"]
    assert path.read_text() == "\n".join(table_file()) + "\n"


def test_a_table_is_replaced_whole_or_not_at_all(tmp_path, monkeypatch):
    """The new table goes into a temporary file that is renamed over the old one: when the rename
    fails (a crash at that moment), the old table is intact and no temporary file is left."""
    path = tmp_path / "T.npv"
    files = CplFiles(root=tmp_path, durable=False)
    files.replace_records(files.place_of("T.npv"), table_file())
    assert records(path) == table_file()

    def crash(src, dst, **dir_fds):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "replace", crash)
    with pytest.raises(OSError):
        files.replace_records(files.place_of("T.npv"), table_file(("G54", 1.0, 2.0, 3.0)))
    assert records(path) == table_file() and [p.name for p in tmp_path.iterdir()] == ["T.npv"]


def test_fxins_refuses_a_column_twice(run, tmp_path):
    r = run('1 FXCR(1,"/T.npv")\n2 FXINS("/T.npv",1,"y")\nM30\n')
    assert r["error"]["code"] == "CPL040" and records(tmp_path / "files/T.npv") == table_file()


def test_a_machine_file_table_outside_the_file_root_is_a_usage_error(run):
    with pytest.raises(UsageError, match="outside the file root"):
        run("1 A=1\nM30\n", cpl={"zs_tables": {"../T.npv": {"G54": [1.0]}}})


def test_a_store_table_of_an_older_run_becomes_a_file(run_text, reference, tmp_path):
    """Tables named by a path that an older ncvm kept in the store are written to their files once."""
    old = {"columns": ["X", "Y", "Z"], "unit": "inch", "strict": 1,
           "rows": {g: [0.0, 0.0, 0.0] for g in (f"G{b + i}" for b in (54, 154, 254) for i in range(6))}}
    old["rows"]["G55"] = [1.0, 2.0, 3.0]
    store = Store(tmp_path / ".ncvm")
    store.put("cpl.zs", "/usr/user/OLD.npv", old)
    store.close()
    r = run_text('1 A=FXC(2,55,"/usr/user/OLD.npv")\nM30\n', name="p.cpl", machine=reference())
    assert r["variables"] == {"A": 2.0}
    assert records(tmp_path / "files/usr/user/OLD.npv") == table_file(("G55", 1.0, 2.0, 3.0), unit="INCH", strict=1)
    store = Store(tmp_path / ".ncvm")
    assert "/usr/user/OLD.npv" not in store.items("cpl.zs")
    store.close()


def test_tc_example_l1879(run):
    text = ("1 A=2.5\n2 B=0.5\n10 TC(1,10,5)=A\n20 TC(2,10,5)=B\n25 TC(1,10,5,0)=25.4\n26 TC(1,11,5,2)=1\n"
            "30 TC(-1,10,4)=A\n40 TC(-2,10,4)=B\n50 A8=TC(1,8,4)\n60 B8=TC(2,8,4)\n70 TC(1,17)=A\n"
            "N75 T8 M6\nN76 H8\n80 BR=TC(2)\n81 HL=TC(1)\nN85 G71\n90 TC(1,745,0)=A\nN90 G70\nN91 WAIT\n"
            "95 TC(3,347,0)=A\n100 B345=TC(2,345,0)\n101 L347=TC(3,347,0)\n110 G33=TC(2,39,\"/usr/user/GK33\")\n"
            "120 K5H10=TC(1,10,5)\n121 K5H11=TC(1,11,5)\n122 K4H10=TC(1,10,4)\n123 K4D10=TC(2,10,4)\n"
            "124 L17=TC(1,17)\n125 L745=TC(1,745,0)\nM30\n")
    tools = [{"number": 8, "length": 100.0, "radius": 4.0}, {"number": 10, "length": 50.0, "radius": 3.0}]
    r = run(text, tool=tools, cpl={"tc_tables": {"/usr/user/GK33": {"39": [0.0, 6.0]}}})
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert (v["A8"], v["B8"]) == (100.0, 4.0)
    assert v["K5H10"] == v["K5H11"] == pytest.approx(25.4)  # 25.4 mm and 1 inch are the same value
    assert (v["K4H10"], v["K4D10"]) == (52.5, 3.5)  # added to the K4 values of group 10
    assert v["L17"] == 2.5  # the last selected table (K4)
    assert (v["HL"], v["BR"]) == (100.0, 4.0)  # the active compensation of tool 8
    assert v["L745"] == pytest.approx(2.5 / 25.4)  # written under G71 in mm, read under G70 in inch
    assert v["L347"] == pytest.approx(2.5) and v["B345"] == 0.0 and v["G33"] == 6.0


def test_tc_k4_is_the_kernels_tool_table(run_text, reference):
    """A length written into K4 is the one the H word applies (L1573), also in the next run (store)."""
    m = reference(tool=[{"number": 3, "length": 10.0}])
    assert run_text("1 TC(1,3,4)=25\nM30\n", name="a.cpl", machine=m)["status"] == "ok"
    r = run_text("N1 T3 M6\nN2 H3 G0 Z0\n3 WAIT\n4 Z=MPOS(3)\nM30\n", name="b.cpl",
                 machine=reference(tool=[{"number": 3, "length": 10.0}]))
    assert r["variables"]["Z"] == 25.0


def test_tda_example_l1961(run_text, reference):
    db = [{"sector": 1, "place": 1, "fields": {"9": 0}}, {"sector": 2, "place": 3, "fields": {"8": ""}},
          {"sector": 2, "place": 1, "fields": {"3": 312000}}]
    m = reference(cpl={"tool_database": db})
    r = run_text('1 NAME$="DRILL 12"\n70 TDA(1,1,9,1)=20000\n71 TDA(2,3,8,1)=NAME$\n72 A%=TDA(2,1,3)\nM30\n',
                 name="a.cpl", machine=m)
    assert r["variables"]["A%"] == 312000
    r = run_text("1 B%=TDA(1,1,9)\n2 N$=TDA(2,3,8)\nM30\n", name="b.cpl", machine=reference(cpl={"tool_database": db}))
    assert r["variables"] == {"B%": 20000, "N$": "DRILL 12"}  # kept in the store


@pytest.mark.parametrize("stmt,code", [("TDA(1,1,1)=5", "CPL040"), ("TDA(1,1,9,2)=5", "CPL023"),
                                       ('TDA(1,1,9)="X"', "CPL021"), ("TDA(1,1,8)=5", "CPL021")])
def test_tda_errors(run, stmt, code):
    r = run(f"1 {stmt}\nM30\n", cpl={"tool_database": [{"sector": 1, "place": 1}]})
    assert r["error"]["code"] == code


@pytest.mark.parametrize("stmt", ['FXDEL(-1,1)', 'FXINS(0,1,"U")', 'A=FXC(1,54,TRUE)'])
def test_a_table_name_that_is_no_string_is_a_type_error(run, stmt):
    assert run(f"10 {stmt}\nM30\n")["error"]["code"] == "CPL032"


def test_external_zero_shift_acts_only_when_selected_l1773_l2305(run):
    """L1773: FXC("Z",160,0)=40 assigns the external shift G160; G160/G167 are G group 30 of the SD(1) table
    (L2305). Written, it does not move the axes (it did, with no G160 anywhere); G160 selects it, G260 the
    second one instead, G167 none. MPOS is the machine position, WPOS the workpiece position (it stays)."""
    text = ('10 FXC("X",160,0)=40 : FXC("X",260,0)=5\nN20 G0 X10\n30 WAIT\n40 A=MPOS(1) : A%=SD(1,30,1)\n'
            'N50 G160 X10\n60 WAIT\n70 B=MPOS(1) : B%=SD(1,30,1) : BW=WPOS(1) : BS=FXC("X")\n'
            'N80 G260 X10\n90 WAIT\n100 C=MPOS(1)\nN110 G167 X10\n120 WAIT\n130 D=MPOS(1) : D%=SD(1,30,1)\nM30\n')
    r = run(text)
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert (v["A"], v["A%"]) == (10.0, 167)
    assert (v["B"], v["B%"], v["BW"], v["BS"]) == (50.0, 160, 10.0, 40.0)
    assert v["C"] == 15.0
    assert (v["D"], v["D%"]) == (10.0, 167)


def test_two_external_zero_shifts_in_one_block_are_refused(run):
    r = run("N10 G160 G260 X10\nM30\n")
    assert r["error"]["code"] == "CPL040" and "G group 30" in r["error"]["message"]
