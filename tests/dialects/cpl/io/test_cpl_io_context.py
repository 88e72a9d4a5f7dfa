"""CplIO wires the I/O of one run to an ncvm Session: file root, clock, key script, output."""

from __future__ import annotations

from ncvm.dialects.cpl.io.context import CplIO
from ncvm.machine.model import Machine
from ncvm.runtime.session import RunOptions, Session


def test_cplio_for_session(tmp_path):
    keys = tmp_path / "keys.txt"
    keys.write_text("# operator\nSK2\n")
    machine = Machine(file_root=tmp_path / "files")
    machine.clock.now = 60.0
    session = Session(machine, RunOptions(state_dir=tmp_path / ".ncvm", keys=keys), dialect="cpl")
    io = CplIO.for_session(session)
    io.mode.LJUST()
    io.files.OPENW(1, "LOG")
    io.files.PRN(1, "X", 1.5, semicolon=True)
    io.files.PRN(0, "MSG ", 7)
    io.screen.DSP(1, 1, "N=###", 123)
    assert io.screen.SFK(0, "A", "B") == 2
    io.files.PRN(0, "#", 123)  # overflow: a warning in the output
    io.screen.BMP(0, 0, "nothing")
    io.end_program(png=tmp_path / "end.png")
    assert (tmp_path / "files" / "LOG").read_text(encoding="latin-1") == "X1.5\n\x03\n"
    assert session.output.lines() == ["MSG 7", "N=123", "SFK [1:A] [2:B]", "warning CPL620: PRN FORMAT INCORRECT: *", "*",
                              "warning CPL803: cplbmp\\nothing.bmp is not existing"]
    assert (tmp_path / "end.png").stat().st_size > 1000
    assert not io.mode.ljust and io.files.handles == {}


def test_screen_of_a_run_does_not_keep_what_the_session_keeps(tmp_path):
    """Millions of PRN#(0) lines and warnings: the session keeps a bounded number of lines; the files and the
    screen used to keep every line and warning as well."""
    import tracemalloc

    session = Session(Machine(file_root=tmp_path / "files"), RunOptions(state_dir=tmp_path / ".ncvm",
                                                                        max_output_lines=10), dialect="cpl")
    io = CplIO.for_session(session)
    tracemalloc.start()
    try:
        before = tracemalloc.get_traced_memory()[0]
        for i in range(25_000):
            io.files.PRN(0, "LINE ", i)
            io.files.PRN(0, "#", 123)  # a line and a warning (format overflow)
        io.screen.BMP(0, 0, "nothing")  # a warning of the graphics
        grown = tracemalloc.get_traced_memory()[0] - before
    finally:
        tracemalloc.stop()
    assert session.output.dropped == 75_001 - 10
    assert session.output.lines()[-1] == "warning CPL803: cplbmp\\nothing.bmp is not existing"
    assert grown < 200_000, grown  # was ~6 MB: each line and warning kept by the files and the screen
