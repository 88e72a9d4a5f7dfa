"""Nothing a program does can exhaust memory: bounded moves, bounded output, the memory guard (RUN006)."""

from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

import pytest

from ncvm.diagnostics import UsageError
from ncvm.nc.canon import CanonSink
from ncvm.runtime.memory import parse_size
from ncvm.runtime.session import MAX_OUTPUT_LINES

NCVM = [sys.executable, "-m", "ncvm"]

PRINTS = """\
10 I% = 1
20 WHILE I% <= {n} DO
30 PRN#(0, "LINE ", I%)
40 I% = I% + 1
50 END
M30
"""

MOVES = """\
N1 G90 F3000
10 FOR I% = 1 TO {n}
G1 X[(I% - INT(I% / 2) * 2) * 10] Y[I% * 0.001]
20 NEXT I%
M30
"""


def test_output_keeps_its_first_and_last_lines_and_says_how_many_were_dropped(run_text):
    r = run_text(PRINTS.format(n=25), name="p.cpl", max_output_lines=10)
    assert [" ".join(line.split()) for line in r["output"]] == [f"LINE {i}" for i in (1, 2, 3, 4, 5, 21, 22, 23, 24, 25)]
    assert r["output_dropped"] == 15
    r = run_text(PRINTS.format(n=10), name="p.cpl", max_output_lines=10)
    assert len(r["output"]) == 10 and r["output_dropped"] == 0


def test_cli_streams_every_line_but_json_keeps_a_bounded_number(tmp_path):
    n = MAX_OUTPUT_LINES + 500
    prog = tmp_path / "p.cpl"
    prog.write_text(PRINTS.format(n=n))
    plain = subprocess.run([*NCVM, "run", str(prog), "--state", str(tmp_path / "s")], capture_output=True,
                           text=True, check=True)
    assert [" ".join(line.split()) for line in plain.stdout.splitlines()] == [f"LINE {i}" for i in range(1, n + 1)]
    doc = json.loads(subprocess.run([*NCVM, "run", str(prog), "--json", "--state", str(tmp_path / "s")],
                                    capture_output=True, text=True, check=True).stdout)
    assert len(doc["output"]) == MAX_OUTPUT_LINES and doc["output_dropped"] == 500
    assert doc["output"][0].split() == ["LINE", "1"] and doc["output"][-1].split() == ["LINE", str(n)]


@pytest.mark.parametrize(("name", "text"), [("p.cpl", PRINTS.format(n=1_000_000)),
                                            ("p.sap", "program P; var i: integer;\nbegin for i := 1 to 1000000 do "
                                                      "writeln('LINE ', i); end.\n")],
                         ids=["cpl", "sympas"])
def test_cli_stops_quietly_when_its_output_is_closed(tmp_path, name, text):
    """``ncvm run PROG | head -1``: the run stops at the next line it prints, without a traceback."""
    prog = tmp_path / name
    prog.write_text(text)
    proc = subprocess.Popen([*NCVM, "run", str(prog), "--state", str(tmp_path / "s")], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    assert proc.stdout.readline().split() == ["LINE", "1"]
    proc.stdout.close()
    stderr = proc.stderr.read()
    assert proc.wait(timeout=60) == 1
    assert "internal error" not in stderr and "Traceback" not in stderr and "Broken pipe" not in stderr, stderr


class Hog(CanonSink):
    """A sink that holds on to memory at every move (as a toolpath held in full would)."""

    def __init__(self):
        self.held = []

    def feed(self, start, end, feed, src):
        self.held.append(bytearray(1 << 20))


def test_a_run_past_the_memory_limit_stops_with_run006_and_the_limit_is_lifted_after(run_text):
    hog = Hog()
    r = run_text("G1 X1 F100\n" * 200, max_memory=50 << 20, extra_sinks=[hog])
    assert r["status"] == "error" and r["error"]["code"] == "RUN006"
    assert "50 MiB" in r["error"]["message"] and "--max-memory" in r["error"]["message"]
    hog.held.clear()
    assert len(bytearray(200 << 20)) == 200 << 20  # the process may grow again
    r = run_text("G1 X1 F100\n" * 20, max_memory=50 << 20, extra_sinks=[Hog()])
    assert r["status"] == "ok"


def test_cli_memory_limit_is_a_diagnostic_not_an_internal_error(tmp_path):
    prog = tmp_path / "fields.cpl"  # 60 fields of 65537 elements: 30 MB
    prog.write_text("".join(f"{10 * i} DIM F{i}%(65536)\n" for i in range(1, 61)) + "M30\n")
    run = subprocess.run([*NCVM, "run", str(prog), "--state", str(tmp_path / "s"), "--max-memory", "25M"],
                         capture_output=True, text=True)
    assert run.returncode == 1, run.stderr
    assert "error RUN006: memory limit reached" in run.stderr and "Traceback" not in run.stderr
    assert re.search(r"fields\.cpl:(\d+):5: error RUN006: .*\n +\1\d DIM F\1%\(65536\)", run.stderr), run.stderr
    assert subprocess.run([*NCVM, "run", str(prog), "--state", str(tmp_path / "s")],
                          capture_output=True).returncode == 0


@pytest.mark.parametrize(("text", "size"), [("8G", 8 << 30), ("512M", 512 << 20), ("1.5g", 3 << 29), ("0", 0),
                                            ("2048KiB", 2 << 20), ("100", 100)])
def test_memory_sizes(text, size):
    assert parse_size(text) == size


def test_bad_memory_size_is_a_usage_error():
    with pytest.raises(UsageError):
        parse_size("lots")


def _peak_rss_kb(tmp_path: Path, moves: int) -> int:
    prog = tmp_path / f"m{moves}.cpl"
    prog.write_text(MOVES.format(n=moves))
    code = ("import resource\nfrom pathlib import Path\nfrom ncvm.api import run\n"
            "from ncvm.runtime.session import RunOptions\n"
            f"r, _ = run({str(prog)!r}, options=RunOptions(state_dir=Path({str(tmp_path / 's')!r})))\n"
            f"assert r['status'] == 'ok' and r['motion']['feed_moves'] == {moves}, r['error']\n"
            "print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return int(out.stdout.split()[-1])


def test_memory_of_a_cpl_run_does_not_grow_with_its_moves(tmp_path):
    # 200,000 G1 blocks without a WAIT: the motion queue and the toolpath used to take ~0.6 kB per move
    # (110 MB more than 20,000 moves); the block buffer and the toolpath window hold a bounded number
    small, large = _peak_rss_kb(tmp_path, 20_000), _peak_rss_kb(tmp_path, 200_000)
    assert large - small < 40_000, (small, large)


@pytest.mark.parametrize("name, said", [
    ("big.mpf", "error RUN006: out of memory"),  # read whole before the run: too large to read within 5 MB
    ("big.ngc", "error RUN006: memory limit reached"),  # din reads a stretch at a time: the run reaches it
])
def test_cli_program_too_large_to_read_within_the_limit_is_run006(tmp_path, name, said):
    prog = tmp_path / name
    prog.write_text("G21 G90 F1000\n" + "G1 X1.123 Y2.456 (a comment that makes the line long)\n" * 200_000 + "M30\n")
    run = subprocess.run([*NCVM, "run", str(prog), "--state", str(tmp_path / "s"), "--max-memory", "5M"],
                         capture_output=True, text=True)
    assert run.returncode == 1
    assert said in run.stderr and "internal error" not in run.stderr


WRITES = """\
10 OPENW(1, "LOG", 130)
20 FOR I% = 1 TO 1000
30 PRN#(1, "RECORD ", I%)
40 NEXT I%
50 CLOSE(1)
M30
"""


@pytest.mark.parametrize(("space", "code"), [(2000, "CPL614"), (0, None)], ids=["bounded", "no-limit"])
def test_a_cpl_run_writes_at_most_its_file_space(tmp_path, run_text, space, code):
    from ncvm.machine.config import machine_from_dict

    machine = machine_from_dict({"axis": [{"name": "X"}, {"name": "Y"}, {"name": "Z"}],
                                 "paths": {"program_path": ["."], "file_root": "files"},
                                 "cpl": {"file_space": space}}, "<test>", tmp_path)
    r = run_text(WRITES, name="w.cpl", machine=machine)
    log = (tmp_path / "files" / "LOG").read_text(encoding="latin-1")
    if code is None:
        assert r["status"] == "ok" and log.count("\n") == 1001
    else:
        assert r["error"]["code"] == code and r["error"]["line"] == 3, r["error"]
        assert len(log) <= space and log.endswith("\x03\n")  # the records before it and the EOF marker
