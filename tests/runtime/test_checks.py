"""Checks of the motion register through the session's Checks (runtime/checks.py), not through the sinks."""

from __future__ import annotations

from dataclasses import dataclass

import pytest

from ncvm.api import RunResult, run, run_program
from ncvm.machine.config import load_machine
from ncvm.runtime.checks import DEAD, Area
from ncvm.runtime.session import RunOptions, RunSinks, Session


@dataclass
class Said:
    line: int
    text: str

    def message(self) -> str:
        return self.text


class EveryMove:
    """A check a front end builds itself: it watches the recorder and reports the number of moves it saw."""

    def __init__(self, recorder):
        self.seen = 0
        self.recorder = recorder
        recorder.watch(self)

    def observe(self, rec, lo: int, hi: int) -> None:
        self.seen += hi - lo

    def first(self):
        self.recorder.settle()
        return [Said(1, f"{self.seen} moves seen")]


def test_a_registered_check_is_reported_after_the_soft_limits(tmp_path):
    prog = tmp_path / "p.din"
    prog.write_text("G1 X2000 F1000\nG0 X0\n")  # leaves the built-in machine's X range

    def register(session: Session) -> None:
        session.checks.add(EveryMove(session.recorder))

    doc, _ = run(prog, options=RunOptions(state_dir=tmp_path / ".s", on_session=register))
    assert len(doc["limit_violations"]) == 2
    assert doc["limit_violations"][0].startswith("axis X reaches 2000.0000")
    assert doc["limit_violations"][1] == "2 moves seen"


def test_areas_go_to_the_check_the_api_supplied(tmp_path):
    prog = tmp_path / "p.din"
    prog.write_text("G0 X0 Y0\nG1 X100 F1000\n")

    def register(session: Session) -> None:
        session.checks.add_areas([Area(1, DEAD, ("X", "Y"), (50.0, 0.0), (10.0, 10.0))], ("X", "Y", "Z"))

    result = run_program(prog, options=RunOptions(state_dir=tmp_path / ".s", on_session=register))
    assert isinstance(result, RunResult) and result.status == "ok"
    assert result.limit_violations == ["the path enters dead range 1 (X 45.0000..55.0000, Y -5.0000..5.0000) "
                                       f"(first at {prog}:2)"]
    assert result.to_json()["limit_violations"] == result.limit_violations


def test_a_session_without_sinks_refuses_areas_instead_of_passing_them(tmp_path):
    session = Session(load_machine(None), RunOptions(state_dir=tmp_path / ".s"), sinks=RunSinks())
    with pytest.raises(RuntimeError, match="records no moves"):
        session.checks.add_areas([Area(1, DEAD, ("X", "Y"), (0.0, 0.0), (1.0, 1.0))], ("X", "Y", "Z"))
    session.checks.add_areas([], ("X", "Y", "Z"))  # nothing to watch: nothing refused
    assert session.checks.violations() == []


def test_the_typed_result_is_the_document(tmp_path):
    prog = tmp_path / "p.din"
    prog.write_text("G1 X10 F600\nG1 X5 Y0 Z0 Q1\n")
    result = run_program(prog, options=RunOptions(state_dir=tmp_path / ".s"))
    doc, _ = run(prog, options=RunOptions(state_dir=tmp_path / ".t"))
    assert result.to_json() == doc
    assert list(doc)[:11] == ["status", "dialect", "error", "output", "output_dropped", "variables", "position",
                              "motion", "cycle_time_s", "steps", "limit_violations"]


def test_a_session_built_directly_gets_the_sinks_of_a_run(tmp_path):
    session = Session(load_machine(None), RunOptions(state_dir=tmp_path / ".s", keep_toolpath=True, plot=True))
    assert session.recorder is not None and session.recorder in session.sinks and session.plot is not None
    assert len(session.checks.violations()) == 0


@dataclass
class AxisSaid:
    """A front end's own violation as a dataclass that names its place and an axis."""

    file: str
    line: int
    axis: str
    frame: str = "work"

    def message(self) -> str:
        return f"{self.axis} at {self.file}:{self.line}"


class Reports:
    def __init__(self, *found):
        self.found = found

    def first(self):
        return list(self.found)


def test_a_dataclass_violation_is_placed_and_named_as_a_record_is():
    """Checks.violations maps a dataclass violation's place and axis (dataclasses.replace), as a record's."""
    from ncvm.nc.canon import Src
    from ncvm.runtime.checks import Checks

    checks = Checks()
    checks.add(Reports(AxisSaid("gen.py", 7, "X"), Said(3, "no place")))
    got = checks.violations(place=lambda src: Src("p.cpl", src.line + 100), labels={"X": "X1"})
    assert got == [AxisSaid("p.cpl", 107, "X1", "machine"), Said(3, "no place")]
    assert checks.violations() == [AxisSaid("gen.py", 7, "X"), Said(3, "no place")]
