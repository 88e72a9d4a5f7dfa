"""Manual §4.3-4.5: axis zero shifts FXC/FXCR/FXDEL/FXINS, tool compensation TC, tool database TDA."""

from __future__ import annotations

import pytest

TAB = "/usr/user/NPV1.npv"


@pytest.fixture
def run(run_text, reference):
    return lambda text, channel=1, **kw: run_text(text, name="p.cpl", machine=reference(channel, **kw))


def test_fxc_example_l1767(run):
    """Every line of the manual's FXC example, read back; the ASCII table holds mm."""
    text = (f'0 TAB$="{TAB}"\n1 FXC(2,54,1)=80\n2 FXC(1,54,TAB$)=20\n3 FXC(-1,54,TAB$)=2\n'
            '4 FXC("Z",54,TAB$,2)=10/25.4\n5 FXC("Z",160,0)=40\n6 FXC("-Z",254,TAB$)=3\n7 FXC("-Z",254,TAB$)=3\n'
            '8 FXC("-U_CH1",54,TAB$)=20\n9 FXC("Z",255)=40\n10 X_SUM=FXC("X")\n11 Z_SUM=FXC("Z")\n'
            '20 R1=FXC(2,54,1)\n21 R2=FXC(1,54,TAB$)\n22 R3=FXC("Z",54,TAB$)\n23 R3I=FXC("Z",54,TAB$,2)\n'
            '24 R4=FXC("Z",160,0)\n25 R5=FXC(3,254,TAB$)\n26 R6=FXC("U_CH1",54,TAB$)\n27 R7=FXC("Z",255)\nM30\n')
    r = run(text, offsets={"G54": [5.0, 0.0, 1.0]}, cpl={"zs_tables": {TAB: {"G54": [0.0] * 8}}})
    assert r["status"] == "ok", r["error"]
    v = r["variables"]
    assert v["R1"] == 80.0 and v["R2"] == 22.0 and v["R4"] == 40.0 and v["R5"] == 6.0 and v["R6"] == 20.0
    assert v["R3"] == pytest.approx(10.0) and v["R3I"] == pytest.approx(10.0 / 25.4)
    assert v["R7"] == 40.0
    # the sum of the active shifts: G54 of the active table V1 (X 5, Z 1) plus the external G160 Z 40
    assert v["X_SUM"] == 5.0 and v["Z_SUM"] == 41.0


def test_fxc_write_moves_the_active_work_offset(run):
    """A value written into the active table acts on the NC kernel's G54 at once (tool stays put)."""
    r = run("N1 G54 G0 X0\n2 FXC(1,54)=12\nN3 G0 X0\n4 WAIT\n5 M=MPOS(1)\nM30\n")
    assert r["variables"]["M"] == 12.0


def test_zs_tables_persist_in_the_store(run_text, reference):
    m = reference()
    assert run_text("1 FXC(1,54,1)=7.5\nM30\n", name="a.cpl", machine=m)["status"] == "ok"
    r = run_text("N1 G54 G0 X1\n2 WAIT\n3 V=FXC(1,54,1)\n4 M=MPOS(1)\nM30\n", name="b.cpl", machine=reference())
    assert r["variables"] == {"V": 7.5, "M": 8.5}


def test_external_shift_of_a_foreign_axis_is_an_error(run):
    assert run('1 FXC("X2",160,0)=1\nM30\n')["error"]["code"] == "1970"


def test_fxcr_fxdel_fxins_example_l1809(run_text, reference):
    text = ('10 NPV_BASIS$="/usr/user/NPV_TAB_K2.npv"\n12 FXCR(2,NPV_BASIS$)\n'
            '13 FXDEL("NPV_TAB_K2.npv",2)\n14 FXINS("NPV_TAB_K2.npv",3,"U",0)\n'
            '17 FXCR(NPV_BASIS$,"NPV2_TAB_K2.npv")\n18 FXC("U",54,"NPV2_TAB_K2.npv")=4\n'
            '19 A=FXC(3,54,"NPV2_TAB_K2.npv")\n20 B=FXC("Z2",54,"NPV2_TAB_K2.npv")\nM30\n')
    r = run_text(text, name="p.cpl", machine=reference())
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["A"] == 4.0 and r["variables"]["B"] == 0.0
    # columns X2 Y2 Z2 -> delete Y2 -> insert U in front of column 3: X2 Z2 U
    r = run_text('1 A=FXC("Y2",54,"NPV2_TAB_K2.npv")\nM30\n', name="q.cpl", machine=reference())
    assert r["error"]["code"] == "1938"
    r = run_text('1 FXCR(2,"/usr/user/NPV_TAB_K2.npv")\nM30\n', name="r.cpl", machine=reference())
    assert r["error"]["code"] == "CPL040"  # the table exists (kept in the store)


def test_tc_example_l1879(run):
    text = ("1 A=2.5\n2 B=0.5\n10 TC(1,10,5)=A\n20 TC(2,10,5)=B\n25 TC(1,10,5,0)=25.4\n26 TC(1,11,5,2)=1\n"
            "30 TC(-1,10,4)=A\n40 TC(-2,10,4)=B\n50 A8=TC(1,8,4)\n60 B8=TC(2,8,4)\n70 TC(1,17)=A\n"
            "N75 T8 M6\nN76 G43 H8\n80 BR=TC(2)\n81 HL=TC(1)\nN85 G71\n90 TC(1,745,0)=A\nN90 G70\nN91 WAIT\n"
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
    """A length written into K4 is the one G43 applies, also in the next run (store)."""
    m = reference(tool=[{"number": 3, "length": 10.0}])
    assert run_text("1 TC(1,3,4)=25\nM30\n", name="a.cpl", machine=m)["status"] == "ok"
    r = run_text("N1 T3 M6\nN2 G43 H3 G0 Z0\n3 WAIT\n4 Z=MPOS(3)\nM30\n", name="b.cpl",
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
