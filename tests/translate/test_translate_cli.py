"""``ncvm translate`` as a user runs it (real processes, real files): complete files only, a failed run
writes nothing, the header, the machine frame, source comments, rw_SymPas' program end, the trace's
``work`` field."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).parents[2]
EX = ROOT / "examples"


def ncvm(*args, cwd) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "ncvm", *map(str, args)], cwd=cwd, capture_output=True, text=True,
                          timeout=120)


def test_a_failed_run_writes_nothing_and_keeps_the_old_file(tmp_path):
    """flangedlg.cpl waits for the operator: without --keys the run stops, the translation is refused with
    the run's error and the cure, and the file already there stays as it was; no temporary file is left."""
    out = tmp_path / "dlg.ngc"
    out.write_text("old\n")
    r = ncvm("translate", EX / "cpl" / "flangedlg.cpl", "-o", out, "--state", tmp_path / "st", cwd=tmp_path)
    assert r.returncode == 1
    assert "error TRN002: translation refused: the run did not end normally: CPL705" in r.stderr
    assert "give the operator's key presses with --keys" in r.stderr and "flangedlg.cpl:11:4" in r.stderr
    # no temporary file, and no state directory either: a translation creates none (it reads one that is there)
    assert out.read_text() == "old\n" and sorted(p.name for p in tmp_path.iterdir()) == ["dlg.ngc"]
    r = ncvm("translate", EX / "cpl" / "flangedlg.cpl", "-o", out, "--keys", EX / "cpl" / "flangedlg.keys",
             "--state", tmp_path / "st", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    text = out.read_text()
    # marked with the line that asked the operator (90 INP(DA) ... is line 11 of the file)
    assert "(FROZEN: operator input INP[DA] = 140.0 at flangedlg.cpl:11;" in text and text.endswith("M2\n")


def test_sympas_translation_ends_with_a_program_end(tmp_path):
    """An rw_SymPas program has no M2/M30: the translation ends with the target's program end anyway."""
    for target, end in (("linuxcnc", "M2\n"), ("sinumerik840d", "M30\n"), ("iso", "M30\n%\n")):
        out = tmp_path / f"contour.{target}"
        r = ncvm("translate", EX / "sympas" / "contour.sap", "-o", out, "--target", target, "--state",
                 tmp_path / "st", cwd=tmp_path)
        assert r.returncode == 0, r.stderr
        assert out.read_text().endswith(end) and "G10" not in out.read_text()


def test_machine_frame_and_source_comments(tmp_path):
    """--frame machine: the simulated machine's coordinates (X150.02 ... for the SINUMERIK flange's X0 Y0
    Z50) under a loud header, no G43 and no G10; --source-comments ends each block with (file:line)."""
    out = tmp_path / "m.ngc"
    r = ncvm("translate", EX / "sin800" / "flange.mpf", "-o", out, "--frame", "machine", "--source-comments",
             "--state", tmp_path / "st", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    text = out.read_text()
    assert "(!!! MACHINE COORDINATES OF THE SIMULATED MACHINE" in text
    assert "G0 X150.02 Y99.99 Z135.1 (flange.mpf:" in text
    assert "G43" not in text and "G10" not in text


def test_840d_words(tmp_path):
    """The 840D target: D for the tool length, G4 F for a dwell, ; comments, M30."""
    out = tmp_path / "f.mpf"
    r = ncvm("translate", EX / "sin800" / "flange.mpf", "-o", out, "--target", "sinumerik840d", "--state",
             tmp_path / "st", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    lines = out.read_text().splitlines()
    assert lines[0].startswith("; written by ncvm from flange.mpf for SINUMERIK 840D")
    assert "D1" in lines and "G4 F0.5" in lines and lines[-1] == "M30" and "G54" in lines


def test_trace_gives_work_coordinates_beside_machine_ones(tmp_path):
    """The SINUMERIK flange's first move: program X0 Y0 Z50 is machine X150.02 Y99.99 Z135.1 (G54 and the
    85.1 mm tool length of D1)."""
    trace = tmp_path / "t.jsonl"
    r = ncvm("run", EX / "sin800" / "flange.mpf", "--trace", trace, "--state", tmp_path / "st", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    first = next(rec for rec in map(json.loads, trace.read_text().splitlines()) if rec["call"] == "rapid")
    assert first["end"] == {"X": 150.02, "Y": 99.99, "Z": 135.1}
    assert first["work"] == {"X": 0.0, "Y": 0.0, "Z": 50.0}


def test_translate_refuses_to_overwrite_a_sub_program_but_writes_its_own_file_again(tmp_path):
    """-o onto a program the run may call is a usage error before the run; a translation ncvm wrote (its
    first comment says so) is written again."""
    for name in ("flange.cpl", "BOLTCIRC", "machine.toml"):
        (tmp_path / name).write_bytes((EX / "cpl" / name).read_bytes())
    r = ncvm("translate", "flange.cpl", "-o", "BOLTCIRC", "--state", "st", cwd=tmp_path)
    assert r.returncode == 2 and "-o BOLTCIRC: would overwrite a program the run may call" in r.stderr
    for target in ("linuxcnc", "iso", "sinumerik840d"):
        for _ in range(2):
            r = ncvm("translate", "flange.cpl", "-o", "FLANGE.ngc", "--target", target, "--state", "st", cwd=tmp_path)
            assert r.returncode == 0, r.stderr


def test_run_gcode_is_the_linuxcnc_translation(tmp_path):
    """``run --gcode``: the same file as ``translate`` (LinuxCNC, work coordinates, no G10); a failed run
    writes no file, and on a stream it ends with a marker that the output is incomplete."""
    a, b = tmp_path / "a.ngc", tmp_path / "b.ngc"
    r = ncvm("run", EX / "sin800" / "flange.mpf", "--gcode", a, "--state", tmp_path / "st", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    r = ncvm("translate", EX / "sin800" / "flange.mpf", "-o", b, "--state", tmp_path / "fresh", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert a.read_text() == b.read_text() and "G10" not in a.read_text()
    # the dialog program without its flangedlg.keys beside it (which a run takes): the run waits for keys
    alone = tmp_path / "alone"
    alone.mkdir()
    for name in ("flangedlg.cpl", "machine.toml"):
        (alone / name).write_bytes((EX / "cpl" / name).read_bytes())
    r = ncvm("run", alone / "flangedlg.cpl", "--json", "--gcode", tmp_path / "dlg.ngc", "--state",
             tmp_path / "st", cwd=tmp_path)
    assert r.returncode == 1 and not (tmp_path / "dlg.ngc").exists() and not list(tmp_path.glob(".dlg.ngc*"))
    assert json.loads(r.stdout)["error"]["code"] == "CPL705"
    r = ncvm("run", alone / "flangedlg.cpl", "--gcode", "/dev/stdout", "--state", tmp_path / "st",
             cwd=tmp_path)
    assert r.returncode == 1
    assert "(!!! INCOMPLETE: TRN002: translation refused: the run did not end normally: CPL705" in r.stdout
    assert "\nM2\n" not in r.stdout


def test_outputs_through_links_and_stdout_are_never_replaced(tmp_path):
    """A symbolic link to the output stays a link (its file is replaced), with the permissions a new file
    gets; a name that reaches this process's own stdout (here a link to /proc/self/fd/1 with stdout in a
    file) is written as a stream into that file, never replaced by another file."""
    real = tmp_path / "real.ngc"
    real.write_text("old\n")
    real.chmod(0o644)
    (tmp_path / "link.ngc").symlink_to("real.ngc")
    r = ncvm("translate", EX / "din" / "face_and_circle.din", "-o", "link.ngc", "--state", "st", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert (tmp_path / "link.ngc").is_symlink() and real.read_text().endswith("M2\n")
    assert real.stat().st_mode & 0o777 == 0o644
    (tmp_path / "out").symlink_to("/proc/self/fd/1")
    with open(tmp_path / "stdout.txt", "w") as f:
        inode = os.fstat(f.fileno()).st_ino
        p = subprocess.run([sys.executable, "-m", "ncvm", "run", str(EX / "din" / "face_and_circle.din"), "--gcode",
                            "out", "--state", "st"], cwd=tmp_path, stdout=f, stderr=subprocess.PIPE, text=True,
                           timeout=120)
    assert p.returncode == 0, p.stderr
    text = (tmp_path / "stdout.txt").read_text()
    assert "(written by ncvm from face_and_circle.din" in text and text.endswith("M2\n")
    assert (tmp_path / "out").is_symlink() and not list(tmp_path.glob(".*"))
    assert (tmp_path / "stdout.txt").stat().st_ino == inode  # the file stdout goes to, not a new one


def test_a_file_in_dev_shm_is_a_file_and_dev_stdout_a_stream():
    """/dev/shm holds ordinary files (a tmpfs): a translation there is written beside and moved into place,
    so a failed one leaves nothing; /dev/stdout, /dev/fd/1 and /proc/self/fd/1 are streams."""
    from ncvm.translate.output import _is_stream

    assert not _is_stream(Path("/dev/shm/ncvm-no-such-dir/out.ngc"))
    assert all(_is_stream(Path(p)) for p in ("/dev/stdout", "/dev/fd/1", "/proc/self/fd/1", "/dev/null"))
