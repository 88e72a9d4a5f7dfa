"""``ncvm run prog.cl8`` and running the written object file with ``--dialect sin800`` give the same result.

Every golden and manual example: compile it to its object file, then run the source (compile + hand-over
to the NC) and the object file (the NC alone) on the same machine and compare the whole result document.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from ncvm.api import compile_program, run
from ncvm.runtime.session import RunOptions

HERE = Path(__file__).parent
SOURCES = sorted([*HERE.glob("golden/*.cl8"), *HERE.glob("manual/*.cl8")])
SAME = ("status", "output", "variables", "position", "motion", "cycle_time_s", "steps", "limit_violations")


@pytest.mark.parametrize("source", SOURCES, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_object_file_runs_like_its_source(source: Path, tmp_path: Path):
    obj = compile_program(source, tmp_path / "object.spf")
    # the object file under the name the compiler gives it (L<n>.spf), so reports name the same file
    obj = obj.rename(tmp_path / f"L{obj.read_text(encoding='latin-1').split()[0].removeprefix('%SPF')}.spf")
    by_source, _ = run(source, options=RunOptions(state_dir=tmp_path / "a", max_steps=100_000))
    by_object, _ = run(obj, dialect="sin800", options=RunOptions(state_dir=tmp_path / "b", max_steps=100_000))
    assert by_source["dialect"] == "cl800" and by_object["dialect"] == "sin800"
    # the source run names the .cl8 statement where the object run names its block (issue 15)
    assert all(f"(first at {source}:" in v for v in by_source["limit_violations"]), by_source["limit_violations"]
    for doc in (by_source, by_object):
        doc["limit_violations"] = [re.sub(r"\(first at [^)]*\)", "(first at ...)", v) for v in doc["limit_violations"]]
        doc["output"] = [re.sub(r"^M0 at line \d+:", "M0 at line ...:", v) for v in doc["output"]]
    for key in SAME:
        assert by_source[key] == by_object[key], key
    if by_source["error"]:
        for key in ("code", "message"):
            assert by_source["error"][key] == by_object["error"][key], key
        if by_object["error"]["file"] == str(obj):
            # the source run names the CL 800 statement, with the object block it stopped in (issue 15)
            assert by_source["error"]["file"] == str(source)
            assert f"object program {obj.name} line {by_object['error']['line']}: " in by_source["error"]["stack"][0]
        else:  # a sub-program's fault
            assert by_source["error"]["line"] == by_object["error"]["line"]
