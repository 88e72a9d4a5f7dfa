"""Scenario events (machine/scenario.py): one typed event per addressing, checked when the file is read,
handed out in time order by one queue, and refused by a control that cannot use them."""

from __future__ import annotations

import pytest

from ncvm.api import run
from ncvm.diagnostics import UsageError
from ncvm.machine.config import load_machine
from ncvm.machine.scenario import (
    AxisInput,
    EventQueue,
    ExternalInput,
    FixedStop,
    InterfaceBit,
    ProbeSwitch,
    SercosLock,
)
from ncvm.runtime.session import RunOptions

AXES = '[[axis]]\nname = "X"\n[[axis]]\nname = "Y"\n'


def events(tmp_path, *tables: str):
    p = tmp_path / "m.toml"
    p.write_text(AXES + "".join(f"[[scenario]]\n{t}\n" for t in tables))
    return load_machine(p).scenario


def test_each_addressing_is_its_own_event_type(tmp_path):
    got = events(tmp_path,
                 'time = 1\nkind = "input"\naddress = "IC(3,0,1)"',
                 'time = 2\nkind = "input"\nbyte = 2\nbit = 7\nvalue = 0',
                 'time = 3\nkind = "input"\naxis = "A1"\nbit = 32',
                 'time = 4\nkind = "probe"\nx = 1.5',
                 'time = 5\nkind = "probe"\ninput = 2\nposition = { Y = -2 }',
                 'time = 6\nkind = "fixed_stop"\nX = 3',
                 'time = 7\nkind = "sercos"')
    assert got == [InterfaceBit(1.0, "IC(3,0,1)", True), ExternalInput(2.0, 2, 7, False),
                   AxisInput(3.0, "A1", 32, True), ProbeSwitch(4.0, {"X": 1.5}, 1),
                   ProbeSwitch(5.0, {"Y": -2.0}, 2), FixedStop(6.0, {"X": 3.0}), SercosLock(7.0, True)]


@pytest.mark.parametrize("table, expected", [
    ('kind = "input"\naddress = "E1.0"\nbyte = 1', r"scenario\[0\] = .*: names its input more than one way"),
    ('kind = "input"\naddress = "E1.0"\nbit = 3', r"scenario\[0\] = .*: names its input more than one way"),
    ('kind = "input"\naxis = "A1"\nbyte = 1\nbit = 1', r"scenario\[0\] = .*: names its input more than one way: give address \(CPL\)"),
    ('kind = "input"\naxis = "A1"', r"scenario\[0\]\.bit: is missing: an axis input names its digital input"),
    ('kind = "input"\naxis = "A1"\nbit = 0', r"scenario\[0\]\.bit = 0: must be 1 to 32 for an axis' digital"),
    ('kind = "input"\nbyte = 1\nbit = 8', r"scenario\[0\]\.bit = 8: must be 0 to 7 for a bit of an input byte"),
    ('kind = "probe"\nX = 1\nposition = { X = 2 }', r"scenario\[0\]\.X = 1: the position is given twice"),
])
def test_a_bad_addressing_is_a_machine_file_error(tmp_path, table, expected):
    with pytest.raises(UsageError, match=r"m\.toml: machine file error: " + expected):
        events(tmp_path, "time = 1\n" + table)


def test_the_queue_hands_out_events_when_their_time_comes():
    a, b, c = InterfaceBit(2.0, "a"), InterfaceBit(1.0, "b"), InterfaceBit(2.0, "c")
    q = EventQueue([a, b, c])
    assert q.next_time() == 1.0 and list(q.due(0.5)) == []
    assert list(q.due(2.0)) == [b, a, c]  # in time order, the same time as written
    assert not q and q.next_time() is None
    q = EventQueue([ProbeSwitch(5.0), FixedStop(1.0), ProbeSwitch(6.0)])
    assert q.take(lambda e: isinstance(e, ProbeSwitch)) == ProbeSwitch(5.0)  # ahead of its time
    assert q.take(lambda e: isinstance(e, SercosLock)) is None
    q.push(InterfaceBit(3.0, "d"))
    assert [e.time for e in q] == [1.0, 3.0, 6.0]


def _run(tmp_path, program: str, name: str, scenario: str, dialect=None):
    (tmp_path / "m.toml").write_text(AXES + '[[axis]]\nname = "Z"\n' + "[[scenario]]\ntime = 0.5\n" + scenario)
    (tmp_path / name).write_text(program)
    result, _session = run(tmp_path / name, dialect=dialect, machine=tmp_path / "m.toml",
                           options=RunOptions(state_dir=tmp_path / ".ncvm"))
    return result


@pytest.mark.parametrize("name, program, scenario, expected", [
    ("p.cpl", "10 A%=1\nM30\n", 'kind = "input"\nbyte = 1\nbit = 3',
     r"an input by byte and bit \(SINUMERIK\), which the CPL control cannot use .*an input by address \(CPL\)"),
    ("p.cpl", "10 A%=1\nM30\n", 'kind = "alarm"\nnumber = 3000', r"an alarm event \(SINUMERIK\), which the CPL"),
    ("p.cpl", "10 A%=1\nM30\n", 'kind = "probe"\ninput = 2\nX = 1',
     r"probe event at 0.5 s: input = 2: the CPL control has one probe input"),
    ("p.mpf", "%MPF1\nR1=1\nM30\n", 'kind = "input"\naddress = "E1.0"',
     r"an input by address \(CPL\), which the SINUMERIK control cannot use"),
    ("p.mpf", "%MPF1\nR1=1\nM30\n", 'kind = "fixed_stop"\nX = 1', r"a fixed_stop event \(CPL\), which the SINUMERIK"),
])
def test_a_control_refuses_an_event_it_cannot_use(tmp_path, name, program, scenario, expected):
    with pytest.raises(UsageError, match=r"scenario event at 0.5 s: " + expected if "probe event at" not in expected
                       else expected):
        _run(tmp_path, program, name, scenario)


def test_sympas_refuses_a_sinumerik_timer(tmp_path):
    with pytest.raises(UsageError, match=r"a timer event \(SINUMERIK\), which the sympas card cannot use"):
        _run(tmp_path, "program P;\nbegin\nend.\n", "p.sap", 'kind = "timer"\nnumber = 1\nvalue = 1')


def test_a_cpl_input_without_value_switches_on_as_documented(tmp_path):
    """``value`` defaults to true (docs/machine-file.md); CPL once stored no value, which reads as false."""
    r = _run(tmp_path, "10 WAIT(IC(5,1,1),2000,R%)\nM30\n", "p.cpl", 'kind = "input"\naddress = "IC(5,1,1)"')
    assert r["status"] == "ok", r["error"]
    assert r["variables"]["R%"] == 2  # the input came on while waiting (1: the 2 s ran out)
