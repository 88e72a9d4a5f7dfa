"""``ncvm check`` of a DIN program a stretch at a time (issue 18): the same diagnostics as a check of the
program in one stretch, the file never read whole, and at most MAX_KEPT diagnostics kept, the others counted."""

from __future__ import annotations

import subprocess
import sys
import tracemalloc

import pytest

from ncvm import api
from ncvm.diagnostics import MAX_KEPT, Diagnostic, Diagnostics, Span
from ncvm.nc import block

#: a program with one of every kind of diagnostic a DIN check gives, spread over many lines
PARTS = (
    "G1 X1 Y\n",  # NC001 syntax
    "#1 = 5\n",  # NC001 of a LinuxCNC extension: folded into one NC013
    "G1 B5 F100\n",  # NC011: an axis the machine lacks
    "G10 L1 P1 X0\n",  # NC004 warning: G10 other than L2, counted over the program
    "G0 G1 X1\n",  # NC015: two motion functions in one block
    "E5\n",  # NC007 warning: an address no function reads
)


def program(filler: int = 40) -> str:
    plain = "".join(f"G1 X{i % 50} Y{i % 7} F1000\n" for i in range(filler))
    tool = "T9\n" + plain + "M6\n"  # NC008 warning: the T word in one stretch, the change in a later one
    return "".join(part + plain for part in PARTS) + tool + "".join(PARTS) + "M2\n"


def checked(path, monkeypatch, chunk: int) -> list[dict]:
    with monkeypatch.context() as m:
        m.setattr(block, "CHUNK_CHARS", chunk)
        return [d.to_json() for d in api.check(path)]


def test_a_check_in_small_stretches_is_the_check_in_one(tmp_path, monkeypatch):
    path = tmp_path / "p.ngc"
    path.write_text(program())
    whole = checked(path, monkeypatch, 1 << 24)
    streamed = checked(path, monkeypatch, 64)
    assert streamed == whole
    assert [d["code"] for d in whole] == ["NC001", "NC013", "NC011", "NC004", "NC015", "NC007", "NC008", "NC001",
                                          "NC011", "NC015"]
    g10 = next(d for d in whole if d["code"] == "NC004")
    assert g10["message"].endswith("2 blocks use it") and g10["line"] == 1 + 3 * 41
    assert next(d for d in whole if d["code"] == "NC013")["message"].count("2 lines") == 1


def test_a_small_program_is_checked_line_by_line_with_the_same_result(tmp_path, monkeypatch):
    """Under COLUMNS_FROM lines a stretch is read the general way (no numpy for a small check)."""
    path = tmp_path / "p.ngc"
    path.write_text(program(filler=2))
    lines = path.read_text().count("\n")
    assert lines < block.COLUMNS_FROM
    with monkeypatch.context() as m:
        m.setattr(block, "COLUMNS_FROM", 0)
        import ncvm.dialects.din as din

        m.setattr(din, "COLUMNS_FROM", 0)
        by_columns = [d.to_json() for d in api.check(path)]
    assert [d.to_json() for d in api.check(path)] == by_columns


def _no_whole_read(*_args):
    raise AssertionError("the program file was read whole")


@pytest.mark.parametrize("name", ["p.ngc", "p"])
def test_the_check_of_a_din_file_never_reads_it_whole(tmp_path, refuse_whole_reads, name):
    """A named .ngc file is read a stretch at a time; one without an extension is told by its head."""
    path = tmp_path / name
    path.write_text("".join(f"G1 X{i % 9} F100\n" for i in range(3000)) + "G1 X1 Y\nM2\n")
    refuse_whole_reads(_no_whole_read)
    diags = api.check(path)
    assert [(d.code, d.span.line) for d in diags] == [("NC001", 3001)]


def test_a_file_told_by_its_content_is_read_whole_once_only_for_a_dialect_that_needs_the_text(tmp_path,
                                                                                                monkeypatch):
    path = tmp_path / "prog"
    path.write_text("10 A% = 1\n20 WHILE A% < 3 DO\n30 A% = A% + 1\n40 END\nM30\n")
    reads = []
    real = api.read_text
    monkeypatch.setattr(api, "read_text", lambda p: reads.append(p) or real(p))
    assert api.check(path) == [] and len(reads) == 1


def _peak_of_check(path, lines: int) -> tuple[int, Diagnostics]:
    with path.open("w") as f:
        for i in range(lines):
            f.write("G1 X1 Y\n" if i % 100 == 99 else f"G1 X{i % 97}.125 Y{i % 89}.5 F1000\n")
    tracemalloc.start()
    try:
        diags = api.check(path)
        return tracemalloc.get_traced_memory()[1], diags
    finally:
        tracemalloc.stop()


def test_a_check_of_a_din_file_holds_a_stretch_not_the_file(tmp_path, monkeypatch):
    """Peak Python memory of checking a file with an error every 100 lines does not grow with the file: four
    times the lines, the same peak (read whole, the text, its lines and blocks grew with it). Stretches of
    16 KB keep the files small."""
    monkeypatch.setattr(block, "CHUNK_CHARS", 1 << 14)
    _peak_of_check(tmp_path / "warm.ngc", 1_000)  # the imports of a first check are not the program's
    small, _ = _peak_of_check(tmp_path / "small.ngc", 10_000)
    large, diags = _peak_of_check(tmp_path / "large.ngc", 40_000)
    assert [d.span.line for d in diags][:2] == [100, 200] and len(diags) == 400
    assert (tmp_path / "large.ngc").stat().st_size > 800_000
    assert large < 1.5 * small, (small, large)


def test_diagnostics_keep_the_first_and_count_the_rest_by_severity():
    many = [Diagnostic("NC001", f"bad {i}", Span("p", i)) for i in range(1, 1006)]
    many += [Diagnostic("NC004", "w", Span("p", 2000), severity="warning")] * 3
    capped = Diagnostics.capped(many)
    assert capped == many[:MAX_KEPT] and capped.left_out == {"error": 5, "warning": 3}
    assert capped.errors() == 1005
    assert capped.not_shown() == f"5 more errors and 3 more warnings not shown (a check lists the first {MAX_KEPT} " \
                                 "diagnostics of a program)"
    assert Diagnostics.capped(capped).left_out == capped.left_out and Diagnostics(many[:3]).not_shown() is None


def test_the_command_shows_the_first_diagnostics_and_says_how_many_more(tmp_path):
    (tmp_path / "p.ngc").write_text("G1 X1 Y\n" * (MAX_KEPT + 234) + "M2\n")
    out = subprocess.run([sys.executable, "-m", "ncvm", "check", "p.ngc"], capture_output=True, text=True,
                         cwd=tmp_path, timeout=300)
    assert out.returncode == 1
    assert out.stderr.count("error NC001") == MAX_KEPT
    assert "p.ngc: 234 more errors not shown" in out.stderr
    assert f"{MAX_KEPT + 234} diagnostic(s)" in out.stderr
    js = subprocess.run([sys.executable, "-m", "ncvm", "check", "--json", "p.ngc"], capture_output=True, text=True,
                        cwd=tmp_path, timeout=300)
    import json

    doc = json.loads(js.stdout)["files"][0]
    assert js.returncode == 1 and not doc["ok"]
    assert len(doc["diagnostics"]) == MAX_KEPT and doc["not_shown"] == {"error": 234}


def test_a_report_record_whose_errors_were_all_left_out_is_an_error():
    """The first diagnostics kept may all be warnings: the record's status counts the errors left out too."""
    from ncvm.archive.report import check_record

    warning = Diagnostic("NC004", "w", Span("p.ngc", 1), severity="warning").to_json()
    capped = Diagnostics([Diagnostic("NC004", "w", Span("p.ngc", 1), severity="warning")], {"error": 2})
    record = check_record("p.ngc", "din", "built-in", [warning], capped.not_shown(), capped.left_out["error"])
    assert record["status"] == "error" and record["error"]["message"].startswith("2 more errors not shown")
    assert check_record("p.ngc", "din", "built-in", [warning])["status"] == "ok"
