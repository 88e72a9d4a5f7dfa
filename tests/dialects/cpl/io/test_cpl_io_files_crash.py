"""What a CPL program wrote to a file survives ncvm being killed (docs/decisions.md, "CPL files")."""

from __future__ import annotations

from ncvm.dialects.cpl.io.files import CplFiles

WRITER = """
import sys
from ncvm.dialects.cpl.io.files import CplFiles
fs = CplFiles(root=sys.argv[1])
i = 0
if fs.FILEACCESS("LOG") > 0:          # count what earlier runs wrote
    fs.OPENR(3, "LOG")
    while not fs.EOF(3):
        fs.INP(3, "S")
        i += 1
    fs.CLOSE(3)
fs.OPENW(1, "LOG", 130, "measurements")
fs.OPENW(2, "RND", 130, "random", 12)
while True:
    i += 1
    fs.PRN(1, "REC ", i)
    fs.PRN(2, "R", i)
    print(i, flush=True)   # printed only after both PRN# have returned
"""


def records(path):
    data = path.read_bytes().decode("latin-1")
    assert data.endswith("\x03\n"), "the EOF marker is always there"
    return data[:-2].split("\n")[:-1]


def test_writer_killed_at_any_moment_keeps_every_completed_record(tmp_path, killed_writer):
    last = 0
    for delay in (0.05, 0.13, 0.21, 0.29):
        printed = killed_writer(WRITER, delay)
        seq = records(tmp_path / "LOG")
        rnd = records(tmp_path / "RND")
        assert len(seq) >= max(printed), "a record reported as written was lost"
        assert seq == [f"REC {n:9d}" for n in range(1, len(seq) + 1)], "records are whole and in order"
        numbers = [int(r[1:]) for r in rnd]
        assert all(len(r) == 12 and r[0] == "R" for r in rnd) and numbers == sorted(set(numbers))
        assert len(seq) - len(rnd) in range(0, 5), "the random file lags by at most one record per kill"
        assert len(seq) > last, "the writer made progress"
        last = len(seq)
    # the files are still valid CPL files: they can be opened and read with their record length
    fs = CplFiles(root=tmp_path)
    fs.OPENR(1, "RND", 12)
    assert fs.FILESIZE(1, 4) == len(records(tmp_path / "RND"))
