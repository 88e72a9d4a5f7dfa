"""Random but valid rw_SymPas programs (sympas_gen.py) run to their end without a traceback, end only
with the faults they may cause, and leave the axes where their waiting moves sent them; plus the
minimal programs of the bugs the generator found."""

from __future__ import annotations

import json

import pytest
from sympas_gen import generate

from ncvm.api import check, run
from ncvm.runtime.session import RunOptions

SEEDS = [*range(12), 42889]  # 42889: two tasks in W-waits with events enabled through 38 minutes of motion


def _run(tmp_path, text: str, machine: str | None = None, **opts):
    path = tmp_path / "prog.sap"
    path.write_text(text, encoding="latin-1")
    mach = None
    if machine is not None:
        mach = tmp_path / "machine.toml"
        mach.write_text(machine, encoding="utf-8")
    errors = [d for d in check(path, machine=mach) if d.severity == "error"]
    result, _ = run(path, machine=mach, options=RunOptions(state_dir=tmp_path / ".ncvm", **opts))
    return errors, result


@pytest.mark.parametrize("seed", SEEDS)
def test_generated_program_runs_to_its_end(tmp_path, seed):
    p = generate(seed)
    errors, r = _run(tmp_path, p.text, p.machine, max_steps=50_000)
    assert errors == [], p.text
    if p.fault:  # the probe at the end of task 0 ends the run with its error number
        assert r["error"] is not None and r["error"]["code"] in {p.fault, *p.allowed}, (p.text, r["error"])
    elif r["status"] != "ok":
        assert r["error"]["code"] in p.allowed, (p.text, r["error"])
    for axis, target in p.expected.items():
        assert r["position"][axis] == pytest.approx(target, abs=1.5e-3), p.text


def test_generator_is_deterministic():
    assert generate(7).text == generate(7).text
    assert generate(7).text != generate(8).text


def test_spooled_moves_of_another_task_started_by_ssmsw(tmp_path):
    # the spoolers belong to the axes (§6.6.63): task 0's SSMSW starts what task 1 spooled; the moves
    # keep their own source lines (was an IndexError: task 1's statement looked up in task 0's program)
    text = """{$TASK 0}
program Main;
begin
  STARTCNCT(1);
  WT(100);
  SSMSW(A1, A2);
end.
{$TASK 1}
program Spooler;
var i: integer;
begin
  i := 1;
  i := 2;
  i := 3;
  i := 4;
  SMLR(A1 := 10.0);
  SMCR(A1 := 5.0, A2 := 0.0, PHI := 360.0);
end.
"""
    trace = tmp_path / "trace.jsonl"
    errors, r = _run(tmp_path, text, trace=trace)
    assert errors == []
    assert r["status"] == "ok", r["error"]
    assert r["position"] == {"A1": 10.0, "A2": 0.0, "A3": 0.0}  # 10 mm, then a full circle back to A1 10
    calls = [json.loads(line) for line in trace.read_text().splitlines()]
    assert [(c["call"], c["line"]) for c in calls if c["call"] in ("feed", "arc")] == [("feed", 16), ("arc", 17)]


def test_refused_w_move_still_waits_for_its_axes(tmp_path):
    # §6.5 (L1614-1618): a W command waits until the profile-end flag of all its axes is set. A move on
    # a moving axis is refused (A-59, axst bit 14); its W form still waits for the running profile (it
    # returned at once, so A1.dp read 0 while the MLA to 20 was still under way)
    text = """program P;
var p, q: double; refused: boolean;
begin
  TRVL := 100.0; TRAC := 1000.0;
  MLA(A1 := 20.0);
  MLAW(A1 := 30.0);
  p := A1.dp; refused := A1.axstb.15;
  MLA(A1 := 0.0);
  MCRW(A1 := 5.0, A2 := 0.0, PHI := 90.0);
  q := A1.dp;
end.
"""
    errors, r = _run(tmp_path, text)
    assert errors == []
    assert r["status"] == "ok", r["error"]
    assert r["variables"] == {"p": 20.0, "q": 0.0, "refused": True}


@pytest.mark.parametrize("statement, line_text", [
    ("MCR(A1 := 1.0, A2 := 0.0, PHI := n)", "PHI"),      # was ValueError: cannot convert float NaN to integer
    ("MLAW(A1 := n)", "axis value"),                      # the same in the target rounding
    ("SMLR(A3 := n); SSMSW(A3)", "axis value"),
    ("TRVL := n; MLAW(A1 := 1.0)", "TRVL"),
    ("A1.jvl := n; JRW(A1 := 1.0)", "A1.jvl"),            # ran for ever without counting steps
])
def test_nan_as_a_move_parameter_is_error_32768(tmp_path, statement, line_text):
    # SQRT(-1) has "no valid return value" (NaN, rw_SymPas manual §6.6, L1643-2172); used as a position, angle, velocity or
    # qualifier it is an invalid parameter in an arithmetic operation (Table 40, $8000), not a traceback
    text = f"program P;\nvar n: double;\nbegin\n  n := SQRT(-1.0);\n  {statement};\nend.\n"
    errors, r = _run(tmp_path, text, max_steps=20_000)
    assert errors == []
    assert r["error"]["code"] == "32768", r["error"]
    assert line_text in r["error"]["message"]
    assert r["error"]["line"] == 5
    assert r["position"] == {"A1": 0.0, "A2": 0.0, "A3": 0.0}
