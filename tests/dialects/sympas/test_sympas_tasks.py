"""Four CNC tasks on one clock, task control and event procedures (manual §6.4, §6.6.2-69)."""

from __future__ import annotations

import math

import pytest

SEC = 15625

EO_MACHINE = """
[sympas]
inputs = [{axis = "A1", bit = 1, function = "EO"}, {axis = "A1", bit = 2, function = "UI"},
          {axis = "A2", bit = 1, function = "DR"}]
"""


def scenario(*events: tuple) -> str:
    out = ""
    for time, axis, bit, value in events:
        out += f'\n[[scenario]]\ntime = {time}\nkind = "input"\naxis = "{axis}"\nbit = {bit}\nvalue = {str(value).lower()}\n'
    return out


TWO_TASKS = """{$TASK 0}
program Main;
var k: integer; alive: boolean;
begin
  CI5 := 0;
  STARTCNCT(1);
  WT(15625);
  writeln('counted ', CI5);
  STOPCNCT(1);
  k := CI5;
  WT(1000);
  if CI5 = k then writeln('task 1 stopped');
  CONTCNCT(1);
  WT(100);
  alive := CI5 > k;
  writeln('continued: ', alive);
  STOPCNCT(1);
end.
{$TASK 1}
program Counter;
begin
  while TRUE do
  begin
    CI5 := CI5 + 1;
    WT(10);
  end;
end.
"""


def test_one_task_starts_stops_and_continues_another(sap):
    r = sap(TWO_TASKS)
    assert r["status"] == "ok", r["error"]
    # task 1 runs 3 statements (1 tick each) and WT(10) per turn: 13 ticks; 15625 / 13 = 1201.9
    assert r["output"] == ["counted 1202", "task 1 stopped", "continued: TRUE"]
    assert r["variables"] == {"k": 1202, "alive": True}


def test_motion_task_and_monitor_task_share_the_clock(sap):
    text = """{$TASK 0}
program Motion;
begin
  STARTCNCT(2);
  TRVL := 100.0; TRAC := 1000.0;
  MLAW(A1 := 100.0);
  CI0 := 1;
  WT(20);
end.
{$TASK 2}
program Monitor;
var seen: integer;
begin
  repeat
    if A1.dp >= 50.0 then if seen = 0 then begin seen := 1; writeln('half way at ', CLOCK); end;
  until CI0 = 1;
  writeln('motion done');
end.
"""
    r = sap(text)
    assert r["status"] == "ok", r["error"]
    half = int(r["output"][0].split()[-1])
    # 50 mm: 5 mm while accelerating (0.1 s), then 45 mm at 100 mm/s: 0.55 s
    assert half == pytest.approx(0.55 * SEC, abs=30)
    assert r["output"][1] == "motion done"


def test_event_fires_during_a_waiting_move_and_aborts(sap):
    # §6.4.1 example: EVEO writes CI0 := 999 and aborts; the move is not stopped by ABORT ([R])
    text = """program Ev;
procedure EVEO;
begin
  CI0 := 999;
  writeln('EO at ', A1.dp);
  abort;
end;
begin
  CI0 := 0;
  enev(EVEO);
  TRVL := 100.0; TRAC := 1000.0;
  MLAW(A1 := 100.0);
  writeln('not reached');
end.
"""
    r = sap(text, machine_toml=EO_MACHINE + scenario((0.5, "A1", 1, True)))
    assert r["status"] == "ok", r["error"]
    assert len(r["output"]) == 1
    # at 0.5 s: 5 mm + 0.4 s * 100 mm/s = 45 mm (the handler is polled each servo cycle of 1.28 ms)
    assert float(r["output"][0].split()[-1]) == pytest.approx(45.0, abs=0.3)
    assert r["position"]["A1"] == 100.0


def test_event_priority_and_no_nesting(sap):
    # L1598-1610: EVEO before EVUI; a handler is not interrupted; level-triggered re-firing
    text = """program P;
var order: integer;
procedure EVUI; begin order := order * 10 + 2; DISEV(EVUI); end;
procedure EVEO; begin order := order * 10 + 1; WT(100); DISEV(EVEO); end;
begin
  order := 0;
  enev(EVUI); enev(EVEO);
  WT(10);
  while order < 12 do ;
end.
"""
    r = sap(text, machine_toml=EO_MACHINE + scenario((0.01, "A1", 1, True), (0.01, "A1", 2, True)))
    assert r["variables"] == {"order": 12}


def test_events_are_not_processed_during_wt(sap):
    text = """program P;
var at: timer;
procedure EVUI; begin at := CLOCK; DISEV(EVUI); end;
begin
  enev(EVUI);
  WT(15625);
  WT(1);
end.
"""
    r = sap(text, machine_toml=EO_MACHINE + scenario((0.1, "A1", 2, True)))
    assert r["variables"]["at"] >= SEC


def test_drive_not_ready_fires_when_the_input_drops(sap):
    text = """program P;
var hit: integer;
procedure EVDNR; begin hit := CLOCK; DISEV(EVDNR); end;
begin
  enev(EVDNR);
  while hit = 0 do ;
end.
"""
    r = sap(text, machine_toml=EO_MACHINE + scenario((0.0, "A2", 1, True), (0.2, "A2", 1, False)))
    assert r["variables"]["hit"] == pytest.approx(0.2 * SEC, abs=5)


def test_software_limit_event(sap):
    text = """program P;
var where: double;
procedure EVLSS; begin where := A1.dp; JSW(A1); DISEV(EVLSS); end;
begin
  A1.slr := 20.0;
  TRVL := 100.0; TRAC := 1000.0;
  enev(EVLSS);
  MLAW(A1 := 100.0);
end.
"""
    r = sap(text)
    assert r["variables"]["where"] == pytest.approx(20.0, abs=0.2)
    assert r["position"]["A1"] < 30.0


def test_stop_and_contcnct_from_another_task(sap):
    text = """{$TASK 0}
program Main;
begin
  STARTCNCT(1);
  WT(100);
  CI1 := 1;
  CONTCNCT(1);
  WT(100);
end.
{$TASK 1}
program Worker;
begin
  writeln('before stop');
  STOP;
  writeln('after continue, CI1=', CI1);
end.
"""
    r = sap(text)
    assert r["output"] == ["before stop", "after continue, CI1=1"]


def test_stoptoss_and_stepcnct(sap):
    text = """{$TASK 0}
program Main;
begin
  STARTCNCT(3);
  WT(5);
  STOPCNCT(3);
  a := CI7;
  STOPTOSS(3);
  WT(50);
  b := CI7;
  STEPCNCT(3);
  WT(50);
  c := CI7;
end.
{$TASK 3}
program Stepper;
begin
  while TRUE do CI7 := CI7 + 1;
end.
"""
    r = sap(text.replace("program Main;", "program Main;\nvar a, b, c: integer;"))
    v = r["variables"]
    assert v["a"] > 0
    assert v["b"] == v["a"]             # STOPTOSS executes nothing
    assert v["c"] == v["b"] + 1         # one loop turn in step mode


def test_abort_ends_and_startcnct_restarts(sap):
    text = """{$TASK 0}
program Main;
begin
  STARTCNCT(1);
  WT(100);
  STARTCNCT(1);
  WT(100);
end.
{$TASK 1}
program Once;
begin
  CI2 := CI2 + 1;
  abort;
  CI3 := 1;
end.
"""
    r = sap(text.replace("WT(100);\nend.\n{$TASK 1}", "WT(100);\n  n := CI2; m := CI3;\nend.\n{$TASK 1}")
            .replace("program Main;", "program Main;\nvar n, m: integer;"))
    assert r["variables"] == {"n": 2, "m": 0}


def test_writeln_stops_the_task_with_moderegbit_26(sap):
    r = sap("program P;\nbegin\n  MODEREG := $4000000;\n  writeln('one');\n  writeln('two');\nend.\n")
    assert r["output"] == ["one"]


def test_runtime_error_in_a_second_task_names_it(sap):
    text = """{$TASK 0}
program Main;
begin STARTCNCT(1); WT(100); end.
{$TASK 1}
program Bad;
var i: integer;
begin i := 1 mod 0; end.
"""
    r = sap(text)
    assert r["error"]["code"] == "32768"
    assert r["error"]["line"] == 7
    assert "task 1" in r["error"]["message"]


def test_task_directive_with_constant(sap):
    # §6.7.2 L2251: {$TASK Task1}; with a trailing ';'
    r = sap("program P;\nconst Task1 = 1;\n{$TASK Task1};\nvar i: integer;\nbegin i := 3; end.\n")
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"i": 3}


def test_rs_halts_every_task_and_opens_the_loops(sap):
    # §6.6.56: RS resets the axis system; the CNC tasks lose control
    text = """{$TASK 0}
program Main;
begin
  STARTCNCT(1);
  MLA(A1 := 500.0);
  WT(100);
  RS;
  CI3 := 1;
end.
{$TASK 1}
program Other;
begin
  while TRUE do CI4 := CI4 + 1;
end.
"""
    r = sap(text.replace("program Main;", "program Main;\nvar after: integer;").replace("CI3 := 1;", "after := 1;"))
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"after": 0}  # the main task itself was halted by RS
    assert r["position"]["A1"] < 10.0  # the move was cut off at once


def test_check_reports_lenient_readings_as_warnings(tmp_path):
    from ncvm.api import check
    p = tmp_path / "w.sap"
    p.write_text("program P;\nconst s := 5;\nvar i: integer;\nbegin\n if i > 0 then i := 0; else i := s;\nend.\n")
    diags = check(p)
    assert [(d.severity, d.code) for d in diags] == [("warning", "W009"), ("warning", "W017")]


def test_stepcnct_executes_exactly_one_line(sap):
    # L2125: STEPCNCT executes one program line; two statements on one line are one step
    text = """{$TASK 0}
program Main;
var a, b, c, d: integer;
begin
  STARTCNCT(3);
  STOPCNCT(3);
  a := CI7;
  STEPCNCT(3);
  WT(50);
  b := CI7;
  STEPCNCT(3);
  WT(50);
  c := CI7;
  STEPCNCT(3);
  WT(50);
  d := CI7;
end.
{$TASK 3}
program S;
begin
  CI7 := 1;
  CI7 := 2; CI7 := 3;
  CI7 := 4;
  while TRUE do CI8 := CI8 + 1;
end.
"""
    v = sap(text)["variables"]
    assert (v["a"], v["b"], v["c"], v["d"]) == (0, 1, 3, 4)


def test_runtime_error_halts_only_its_task(sap):
    # §8 (L2259): the failing task is halted with its error number and line; the others go on
    text = """{$TASK 0}
program Main;
var i: integer;
begin
  STARTCNCT(1);
  WT(100);
  for i := 1 to 3 do CI5 := CI5 + 1;
  writeln('main goes on ', CI5);
end.
{$TASK 1}
program Bad;
var z: integer;
begin
  writeln('bad starts');
  z := 0;
  CI6 := 7 / z;
  writeln('never');
end.
"""
    r = sap(text)
    assert r["status"] == "error"
    assert r["error"]["code"] == "32768"
    assert r["error"]["line"] == 16
    assert "task 1" in r["error"]["message"]
    assert r["output"] == ["bad starts", "main goes on 3"]


def test_runtime_error_is_reported_when_the_others_run_away(sap):
    text = """{$TASK 0}
program Main;
begin
  STARTCNCT(1);
  while TRUE do CI5 := CI5 + 1;
end.
{$TASK 1}
program Bad;
begin
  WRCBD(3, 1.0);
end.
"""
    r = sap(text, max_steps=20000)
    assert r["status"] == "error"
    assert r["error"]["code"] == "2048"
    assert r["error"]["line"] == 10


def test_stepcnct_through_a_procedure(sap):
    # the call line steps into the routine's first line; then line by line, back in the caller
    text = """{$TASK 0}
program Main;
var a, b, c, d, e: integer;
begin
  STARTCNCT(3);
  STOPCNCT(3);
  a := CI7;
  STEPCNCT(3); WT(50); b := CI7;
  STEPCNCT(3); WT(50); c := CI7;
  STEPCNCT(3); WT(50); d := CI7;
  STEPCNCT(3); WT(50); e := CI7;
end.
{$TASK 3}
program S;
procedure P;
begin
  CI7 := CI7 + 10;
  CI7 := CI7 + 100;
end;
begin
  CI7 := 1;
  P;
  CI7 := CI7 + 1000;
  while TRUE do CI8 := CI8 + 1;
end.
"""
    v = sap(text)["variables"]
    assert (v["a"], v["b"], v["c"], v["d"], v["e"]) == (0, 1, 11, 111, 1111)


def _two_long_moves(main_handler: str, other_handler: str) -> str:
    """Task 0 moves A1 1000 mm and task 1 A2 500 mm, both at 10 mm/s in W-waits, each with the EVUI handler
    body given ("" for none); each writes CLOCK when its move is done."""
    def task(n: int, name: str, handler: str, axis: str, target: float, start: str) -> str:
        ev = f"procedure EVUI; begin {handler} DISEV(EVUI); end;\n" if handler else ""
        enable = "  enev(EVUI);\n" if handler else ""
        return (f"{{$TASK {n}}}\nprogram {name};\n{ev}begin\n{enable}{start}  TRVL := 10.0; TRAC := 1000.0;\n"
                f"  MLAW({axis} := {target});\n  writeln('{n}: {axis} done at ', CLOCK);\nend.\n")
    return (task(0, "Main", main_handler, "A1", 1000.0, "  STARTCNCT(1);\n")
            + task(1, "Other", other_handler, "A2", 500.0, ""))


def test_two_tasks_waiting_on_long_moves_see_an_event_in_its_servo_cycle(sap):
    # Both tasks wait on minutes-long W moves with EVUI enabled. Nothing can happen between the scenario
    # input at 30 s and the ends of the moves, so the card looks only then (a run of 150,000 servo cycles
    # took a minute when every cycle was stepped); what the tasks see is what they saw stepping every cycle.
    text = _two_long_moves("writeln('0: UI at ', CLOCK, ' A1 ', A1.dp);", "writeln('1: UI at ', CLOCK);")
    r = sap(text, machine_toml=EO_MACHINE + scenario((30.0, "A1", 2, True)))
    assert r["status"] == "ok", r["error"]
    out = sorted(r["output"])
    servo = 20  # ticks of 64 us: 1.28 ms
    ui = 30.0 / 64e-6  # the input changes at 30 s: 468,750 ticks, a whole servo cycle (23,437.5 cycles: no)
    first_cycle = math.ceil(ui / servo) * servo  # the first servo cycle at or after it: 468,760
    assert [line.split()[:3] for line in out] == [["0:", "A1", "done"], ["0:", "UI", "at"], ["1:", "A2", "done"],
                                                   ["1:", "UI", "at"]]
    t0_ui = int(out[1].split()[3])
    t1_ui = int(out[3].split()[3])
    # both handlers run in that cycle (CLOCK read a statement tick later), as when every cycle was stepped
    assert t0_ui == t1_ui and first_cycle <= t0_ui <= first_cycle + 2
    # A1 at 10 mm/s after 0.01 s of acceleration: 0.05 mm + (t - 0.01 s) * 10 mm/s, less the few statement
    # ticks (64 us, 0.64 um of travel each) before the move starts
    t = first_cycle * 64e-6
    assert float(out[1].split()[-1]) == pytest.approx(0.05 + (t - 0.01) * 10.0, abs=0.01)
    # the moves end 100.01 s and 50.01 s after they start (a few statement ticks in); the W-waits see it then
    assert int(out[0].split()[-1]) == pytest.approx(100.01 / 64e-6, abs=10)
    assert int(out[2].split()[-1]) == pytest.approx(50.01 / 64e-6, abs=10)
    assert r["position"]["A1"] == 1000.0 and r["position"]["A2"] == 500.0


def test_a_sleeping_task_sees_the_stop_another_tasks_event_handler_makes(sap):
    # Task 0 waits on A1's 100 s move; task 1, itself waiting on A2, gets EVUI at 30 s and stops A1 with MS.
    # Task 0 must see A1 stand still in the servo cycle after the stop, not when its own move would have ended.
    text = _two_long_moves("", "writeln('1: UI at ', CLOCK); MS(A1);")
    r = sap(text, machine_toml=EO_MACHINE + scenario((30.0, "A1", 2, True)))
    assert r["status"] == "ok", r["error"]
    ui, done, a2 = (int(line.split()[-1]) for line in r["output"])
    assert r["output"][0].startswith("1: UI") and r["output"][1].startswith("0: A1 done")
    assert ui == math.ceil(30.0 / 64e-6 / 20) * 20 + 1  # the first servo cycle at or after 30 s, a statement on
    # 10 mm/s braked at the stop deceleration: the axis stands within a few servo cycles, near 300 mm
    assert 0 < done - ui < 10 * 20
    assert r["position"]["A1"] == pytest.approx(300.0, abs=0.1)
    assert a2 == pytest.approx(50.01 / 64e-6, abs=10)


def test_a_scenario_input_without_an_axis_says_so(sap):
    """An input event written for CPL (an address, no axis) in a rw_SymPas run."""
    from ncvm.diagnostics import UsageError

    event = '\n[[scenario]]\ntime = 0.1\nkind = "input"\naddress = "E1.0"\n'
    with pytest.raises(UsageError, match=r"scenario input: no axis given: rw_SymPas events name one with axis"):
        sap("program P;\nbegin\nend.\n", machine_toml=EO_MACHINE + event)


def test_a_ref_position_of_no_axis_is_refused(sap):
    from ncvm.diagnostics import UsageError

    with pytest.raises(UsageError, match=r"key 'sympas\.ref_positions\.Q9' names no axis of the card \(axes: A1"):
        sap("program P;\nbegin\nend.\n", machine_toml="[sympas]\nref_positions = { A1 = 5.0, Q9 = 1.0 }\n")
