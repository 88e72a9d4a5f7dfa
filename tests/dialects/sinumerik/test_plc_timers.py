"""PLC timers and counters (PLCT @3a4, PLCC @3a5; manual L2849-2866) running in simulated time.

An S5 timer holds up to 999 units of its time base (0.01, 0.1, 1 or 10 s) and loses one unit per
elapsed base; PLCT reads the rest in seconds with 2 decimals. A counter holds 0-999 and counts rising
edges. Expected values are worked by hand in each test.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from sin800_helpers import R, machine, run_mpf

from ncvm.diagnostics import UsageError

MACHINE = machine("X")


def _run(tmp_path: Path, text: str, extra: str = ""):
    return run_mpf(tmp_path, text, extra, machine_text=MACHINE)


def _ok(tmp_path: Path, text: str, extra: str = ""):
    return run_mpf(tmp_path, text, extra, machine_text=MACHINE, ok=True)


def _event(time: float, kind: str, **fields) -> str:
    body = "".join(f"{k} = {v!r}\n".replace("'", '"') for k, v in fields.items())
    return f'[[scenario]]\ntime = {time}\nkind = "{kind}"\n{body}'


def test_timer_started_by_the_scenario_runs_down_during_a_dwell(tmp_path):
    # the PLC starts timer 7 with 4 s at 0 s (base 0.01 s: 400 units); after G4 X2.5 250 units are gone:
    # 150 units = 1.50 s. After G4 X2 more (4.5 s in all) it has run out: 0.
    r = _ok(tmp_path, "%MPF1\n@3a4 R1 K1 K7\nG4 X2.5\n@3a4 R2 K1 K7\nG4 X2\n@3a4 R3 K1 K7\nM30\n",
            _event(0.0, "timer", number=7, value=4.0))
    assert (R(r, 1), R(r, 2), R(r, 3)) == (4.0, 1.5, 0.0)


def test_timer_started_by_an_m_function_counts_in_its_time_base(tmp_path):
    # M71 starts timer 3 with 25 s at 1 s: 25 s needs the base 0.1 s (250 units; 2500 units of 0.01 s do not
    # fit 3 decades). 2.46 s later 24 whole units have gone: 226 units = 22.6 s
    wiring = '[sin800.plc.1]\ntimers = { "3" = { start = "M71", value = 25 } }\n'
    r = _ok(tmp_path, "%MPF1\nG4 X1\nM71\nG4 X2.46\n@3a4 R1 K1 K3\nM30\n", wiring)
    assert R(r, 1) == 22.6


def test_timer_time_base_from_the_machine_file_and_reset(tmp_path):
    # 100 s: base 1 s (100 units). After 0.5 s no unit has gone (100); M72 resets it to 0; M71 restarts it
    wiring = '[sin800.plc.1]\ntimers = { "0" = { start = "M71", reset = "M72", value = 100 } }\n'
    r = _ok(tmp_path, "%MPF1\nM71\nG4 X0.5\n@3a4 R1 K1 K0\nM72\n@3a4 R2 K1 K0\nM71\nG4 X1\n@3a4 R3 K1 K0\nM30\n",
            wiring)
    assert (R(r, 1), R(r, 2), R(r, 3)) == (100.0, 0.0, 99.0)


def test_timer_value_at_power_on_stands_until_started(tmp_path):
    wiring = '[sin800.plc.2]\nT = { "5" = 1.5 }\n'
    r = _ok(tmp_path, "%MPF1\nG4 X1\n@3a4 R1 K2 K5\nM30\n", wiring)
    assert R(r, 1) == 1.5


def test_counter_counts_rising_edges_of_a_plc_input(tmp_path):
    # I1.0 rises at 1 s and 3 s (the event at 3.5 s finds it 1 already: no edge); I1.1 sets the preset 5 at
    # 5 s, a later rising edge of I1.0 at 6 s counts on from there: 6. The program reads at 4 s and 7 s.
    wiring = '[sin800.plc.1]\nC = { "2" = 10 }\ncounters = { "2" = { up = "I1.0", set = "I1.1", value = 5 } }\n'
    events = "".join(_event(t, "plc", area="I", byte=1, bit=b, value=v) for t, b, v in
                     ((1.0, 0, 1), (2.0, 0, 0), (3.0, 0, 1), (3.5, 0, 1), (5.0, 1, 1), (5.5, 0, 0), (6.0, 0, 1)))
    r = _ok(tmp_path, "%MPF1\n@3a5 R1 K1 K2\nG4 X4\n@3a5 R2 K1 K2\nG4 X3\n@3a5 R3 K1 K2\nM30\n", wiring + events)
    assert (R(r, 1), R(r, 2), R(r, 3)) == (10.0, 12.0, 6.0)


def test_counter_counts_down_on_flags_the_nc_program_writes(tmp_path):
    # PLCF(1,10,3) = 1 (@482) is a rising edge: 3 -> 2; writing 1 again is none; 0 then 1 is: 2 -> 1
    wiring = '[sin800.plc.1]\nC = { "4" = 3 }\ncounters = { "4" = { down = "F10.3" } }\n'
    r = _ok(tmp_path, "%MPF1\n@482 K1 K10 K3 K1\n@3a5 R1 K1 K4\n@482 K1 K10 K3 K1\n@3a5 R2 K1 K4\n"
                      "@482 K1 K10 K3 K0\n@493 K1 K10 K1000\n@3a5 R3 K1 K4\nM30\n", wiring)
    assert (R(r, 1), R(r, 2), R(r, 3)) == (2.0, 2.0, 1.0)


def test_counter_scenario_actions_and_limits(tmp_path):
    # set 998 at 0 s, up twice (999 is the top), down once at 2 s; reset at 4 s
    events = (_event(0.0, "counter", number=9, action="set", value=998) + _event(0.5, "counter", number=9)
              + _event(1.0, "counter", number=9, action="up") + _event(2.0, "counter", number=9, action="down")
              + _event(4.0, "counter", number=9, action="reset"))
    r = _ok(tmp_path, "%MPF1\nG4 X1.5\n@3a5 R1 K1 K9\nG4 X1\n@3a5 R2 K1 K9\nG4 X2\n@3a5 R3 K1 K9\nM30\n", events)
    assert (R(r, 1), R(r, 2), R(r, 3)) == (999.0, 998.0, 0.0)


def test_plc_input_read_sees_the_scripted_change(tmp_path):
    # a PLC read applies the scenario up to now (the input byte changes at 1 s, read at 2 s)
    r = _ok(tmp_path, "%MPF1\n@380 R1 K1 K3 K2\nG4 X2\n@380 R2 K1 K3 K2\nM30\n",
            _event(1.0, "plc", area="I", byte=3, bit=2, value=1))
    assert (R(r, 1), R(r, 2)) == (0.0, 1.0)


@pytest.mark.parametrize("extra, match", [
    ('[sin800.plc.1]\ntimers = { "3" = { start = "M71", value = 12.345 } }\n', "whole number of 0.1 s units"),
    ('[sin800.plc.1]\ntimers = { "3" = { start = "M71", value = 20000 } }\n', "exceeds 999 units"),
    ('[sin800.plc.1]\ntimers = { "3" = { start = "M71" } }\n', "needs the time 'value'"),
    ('[sin800.plc.1]\ncounters = { "3" = { up = "X1.0" } }\n', "not an M function"),
    ('[sin800.plc.1]\ncounters = { "3" = { up = "I200.0" } }\n', "byte 200"),
    ('[sin800.plc.1]\nC = { "3" = 1000 }\n', "sin800.plc.1.C.3 = 1000: must be 0 to 999"),
    ('[sin800.plc.1]\ntimers = { "3" = { value = 1, done = "I1.0" } }\n', "not an output or flag bit"),
    ('[sin800.plc.1]\ncounters = { "3" = { up = "M5", base = 1 } }\n', r"counters\.3\.base = 1: unknown key \(known: up, down, set, reset, value\)"),
    (_event(1.0, "timer", number=7), "needs the time 'value'"),
    (_event(1.0, "counter", number=7, action="start"), 'scenario\\[0\\].action = "start": must be one of "up"'),
])
def test_timer_and_counter_configuration_errors(tmp_path, extra, match):
    with pytest.raises(UsageError, match=match):
        _run(tmp_path, "%MPF1\nM30\n", extra)


def test_timer_done_bit_is_set_when_the_time_has_run_out_and_counts(tmp_path):
    # M71 starts timer 3 (2.5 s) at 0 s; its done bit F20.0 is 0 at 2 s and 1 at 2.5 s, a rising edge that
    # counter 1 counts. M71 again at 2.5 s restarts it: the bit is 0, and 1 again at 5 s (read at 5.5 s):
    # counter 1 = 2.
    wiring = ('[sin800.plc.1]\ntimers = { "3" = { start = "M71", value = 2.5, done = "F20.0" } }\n'
              'counters = { "1" = { up = "F20.0" } }\n')
    r = _ok(tmp_path, "%MPF1\nM71\nG4 X2\n@382 R1 K1 K20 K0\nG4 X0.5\n@382 R2 K1 K20 K0 @3a5 R3 K1 K1\n"
                      "M71\n@382 R4 K1 K20 K0\nG4 X3\n@382 R5 K1 K20 K0 @3a5 R6 K1 K1\n@3a4 R7 K1 K3\nM30\n", wiring)
    assert [R(r, n) for n in range(1, 8)] == [0.0, 1.0, 1.0, 0.0, 1.0, 2.0, 0.0]


def test_done_bit_of_a_scenario_timer_comes_before_later_scenario_events(tmp_path):
    # the scenario starts timer 0 (1 s) at 0 s; its done bit Q4.1 counts counter 5 up at 1 s (0 -> 1), before
    # the scenario sets the counter to 10 at 1.5 s. Read at 2 s: 10 (11 if the bit came after the set).
    wiring = ('[sin800.plc.1]\ntimers = { "0" = { value = 1, done = "Q4.1" } }\n'
              'counters = { "5" = { up = "Q4.1" } }\n')
    events = _event(0.0, "timer", number=0) + _event(1.5, "counter", number=5, action="set", value=10)
    r = _ok(tmp_path, "%MPF1\nG4 X2\n@3a5 R1 K1 K5 @381 R2 K1 K4 K1\nM30\n", wiring + events)
    assert (R(r, 1), R(r, 2)) == (10.0, 1.0)
