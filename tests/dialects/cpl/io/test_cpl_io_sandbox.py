"""CPL programs that try to leave the file root (issue "the file root is the only door"): every one ends with
the manual's file error (INVALID FILE NAME, CPL609) at its statement, or with a result code, and nothing outside
the root -- above all the permanent store -- is read, written or removed. Real links, FIFOs and processes."""

from __future__ import annotations

import os
import shutil
import sqlite3
import struct
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest
from PIL import Image

from ncvm.api import run
from ncvm.machine.config import machine_from_dict
from ncvm.runtime.session import RunOptions

#: channel 1 drives X Y Z; channel 2 (X2) exists for MCOPS program selection
MACHINE = {"axis": [{"name": "X"}, {"name": "Y"}, {"name": "Z"}],
           "cpl": {"channel": 1, "axes": [{"name": "X", "channel": 1}, {"name": "Y", "channel": 1},
                                          {"name": "Z", "channel": 1}, {"name": "X2", "channel": 2}]}}
STORE_HEADER = b"SQLite format 3\x00"


def machine(folder: Path, file_root: str = "files", program_path: str = "."):
    return machine_from_dict({**MACHINE, "paths": {"program_path": [program_path], "file_root": file_root}},
                             "<test>", folder)


@pytest.fixture
def cpl(tmp_path):
    """cpl(text, machine=None, **options) -> (result, session); the state directory is <tmp>/.ncvm, the
    built-in machine's file root <tmp>/.ncvm/files."""

    def _run(text: str, machine=None, **opts):
        path = tmp_path / "prog.cpl"
        path.write_text(text, encoding="latin-1")
        return run(path, machine=machine, options=RunOptions(state_dir=tmp_path / ".ncvm", **opts))

    return _run


def store_is_intact(state: Path) -> bool:
    """The store still opens as a database and holds what the first run stored."""
    if not (state / "store.sqlite").read_bytes().startswith(STORE_HEADER):
        return False
    with sqlite3.connect(state / "store.sqlite") as db:
        db.execute("select count(*) from sqlite_master").fetchone()
    return True


def refused(result, line: int, *words: str) -> bool:
    err = result["error"]
    return (result["status"] != "ok" and err["code"] == "CPL609" and err["line"] == line
            and all(w in err["message"] for w in words))


# -- SERCOS lists (SCSL) ------------------------------------------------------------------------------
def test_scsl_cannot_overwrite_the_store_of_the_built_in_machine(cpl, tmp_path):
    """The built-in machine keeps its files in <state>/files, beside store.sqlite: SCSL(...,"../store.sqlite")
    used to replace the permanent store by the list file."""
    first, _ = cpl("10 @1=4711\nM30\n")
    assert first["status"] == "ok"
    r, _ = cpl('10 SCSL(1,"S",51,"../store.sqlite")\nM30\n')
    assert refused(r, 1, "outside the file root")
    r, _ = cpl('10 SCSL(1,"S",51,"../store.sqlite",E%)\n20 A%=@1\nM30\n')
    assert r["status"] == "ok" and r["variables"]["E%"] == 2 and r["variables"]["A%"] == 4711
    assert store_is_intact(tmp_path / ".ncvm")


def test_scsl_through_a_link_or_a_new_folder_stays_in_the_root(cpl, tmp_path):
    files, outside = tmp_path / ".ncvm" / "files", tmp_path / "outside"
    files.mkdir(parents=True)
    outside.mkdir()
    (files / "out").symlink_to(outside)
    r, _ = cpl('10 SCSL(1,"S",51,"out/LIST",E%)\n20 SCSL(1,"S",51,"/new/folder/LIST")\n'
               '30 SCSL(1,"S",51,"' + str(outside / "ABS") + '")\nM30\n')
    assert r["status"] == "ok" and r["variables"]["E%"] == 2
    assert list(outside.iterdir()) == []
    assert (files / "new/folder/LIST").read_text() == "0\n\x03\n"
    assert (files / str(outside / "ABS").lstrip("/")).read_text() == "0\n\x03\n"  # a control path, in the root


# -- OPENW / OPENR / ERASE through links -----------------------------------------------------------------
@pytest.mark.parametrize("statement", ['OPENW(1,"out/SECRET")', 'OPENR(1,"out/SECRET")', 'OPENW(1,"out/NEW")',
                                       'E%=ERASE("out/SECRET")', 'OPENR(1,"secret")', 'E%=ERASE("secret")'])
def test_a_link_out_of_the_root_is_refused(cpl, tmp_path, statement):
    files, outside = tmp_path / ".ncvm" / "files", tmp_path / "outside"
    files.mkdir(parents=True)
    outside.mkdir()
    (outside / "SECRET").write_text("secret\n")
    (files / "out").symlink_to(outside)
    (files / "secret").symlink_to(outside / "SECRET")
    r, _ = cpl(f"10 {statement}\n20 PRN#(1,\"X\")\nM30\n")
    assert refused(r, 1, "out of the file root")
    assert sorted(p.name for p in outside.iterdir()) == ["SECRET"] and (outside / "SECRET").read_text() == "secret\n"


def test_a_link_inside_the_root_still_works(cpl, tmp_path):
    files = tmp_path / ".ncvm" / "files"
    (files / "data").mkdir(parents=True)
    (files / "data" / "IN").write_text("42\n\x03\n")
    (files / "here").symlink_to("data")
    r, _ = cpl('10 OPENR(1,"here/IN")\n20 INP#(1,A%)\n30 CLOSE(1)\nM30\n')
    assert r["status"] == "ok" and r["variables"]["A%"] == 42


def test_a_folder_swapped_for_a_link_after_openw_does_not_redirect_prn(cpl, tmp_path):
    """Between two PRN# (here while the program waits in MMC) the folder of the open file is moved away and
    a link to a folder outside takes its name, where a file of that name waits: PRN# keeps writing to the
    file OPENW opened."""
    files, outside = tmp_path / ".ncvm" / "files", tmp_path / "outside"
    (files / "log").mkdir(parents=True)
    outside.mkdir()
    (outside / "LOG").write_text("untouched\n")

    def swap(names, values):
        os.rename(files / "log", files / "moved")
        (files / "log").symlink_to(outside)
        return 0, {}

    r, _ = cpl('10 OPENW(1,"log/LOG")\n20 PRN#(1,"FIRST")\n30 I%=MMC(I%)\n40 PRN#(1,"SECOND")\n'
               '50 CLOSE(1)\nM30\n', mmc_client=swap)
    assert r["status"] == "ok", r["error"]
    assert (files / "moved" / "LOG").read_text() == "FIRST\nSECOND\n\x03\n"
    assert (outside / "LOG").read_text() == "untouched\n"


# -- FIFOs, sockets, devices -------------------------------------------------------------------------------
def ncvm_run(tmp_path: Path, text: str, *args: str) -> subprocess.CompletedProcess:
    """``ncvm run`` as a process: a statement that blocks on a FIFO would hang it, the timeout fails the test."""
    (tmp_path / "prog.cpl").write_text(text)
    return subprocess.run([sys.executable, "-m", "ncvm", "run", "prog.cpl", "--state", ".ncvm", *args],
                          cwd=tmp_path, capture_output=True, text=True, timeout=60,
                          env=dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path)))


@pytest.mark.parametrize("statement", ['OPENW(1,"PIPE")', 'OPENR(1,"PIPE")', 'SCSL(1,"S",51,"PIPE")',
                                       'E%=ERASE("PIPE")', 'BMP(0,0,"PIPE")'])
def test_a_fifo_in_the_root_is_refused_not_opened(tmp_path, statement):
    files = tmp_path / ".ncvm" / "files"
    (files / "cplbmp").mkdir(parents=True)
    os.mkfifo(files / "PIPE")
    os.mkfifo(files / "cplbmp" / "PIPE.bmp")
    done = ncvm_run(tmp_path, f"10 {statement}\nM30\n")
    assert done.returncode == 1, done.stderr
    assert "error CPL609: INVALID FILE NAME: " in done.stderr and "is a FIFO, not a file" in done.stderr
    assert os.path.exists(files / "PIPE")


def test_fileaccess_and_filedate_see_no_file_in_a_fifo(cpl, tmp_path):
    files = tmp_path / ".ncvm" / "files"
    files.mkdir(parents=True)
    os.mkfifo(files / "PIPE")
    r, _ = cpl('10 A%=FILEACCESS("PIPE")\n20 DIM D$(8)\n30 D$=FILEDATE("PIPE")\nM30\n')
    assert r["status"] == "ok" and r["variables"]["A%"] == -1 and r["variables"].get("D$", "") == ""


# -- the state directory inside the file root ----------------------------------------------------------------
@pytest.mark.parametrize("statement", ['E%=ERASE(".ncvm/store.sqlite")', 'OPENW(1,".ncvm/store.sqlite")',
                                       'OPENW(1,"/.ncvm/store.sqlite")\n20 REWRITE(1)',
                                       'OPENR(1,".ncvm/store.sqlite")', 'SCSL(1,"S",51,".ncvm/store.sqlite")',
                                       'OPENW(1,"state/link/prog.cpl.I")', 'E%=ERASE("state/store.sqlite")'])
def test_the_state_directory_is_out_of_reach_with_file_root_dot(cpl, tmp_path, statement):
    """A machine file with file_root = "." and the state directory .ncvm inside it (also through a link)."""
    m = machine(tmp_path, file_root=".")
    first, _ = cpl("10 @1=4711\nM30\n", machine=m)
    assert first["status"] == "ok"
    (tmp_path / "state").symlink_to(".ncvm")
    before = sorted(p.name for p in (tmp_path / ".ncvm").rglob("*"))
    r, _ = cpl(f"10 {statement}\nM30\n", machine=m)
    assert refused(r, 1, "state directory")
    assert store_is_intact(tmp_path / ".ncvm")
    after = sorted(p.name for p in (tmp_path / ".ncvm").rglob("*"))
    assert set(before) <= set(after) and set(after) - set(before) <= {"store.sqlite-wal", "store.sqlite-shm"}
    again, _ = cpl("10 A%=@1\nM30\n", machine=m)
    assert again["variables"]["A%"] == 4711


def test_the_state_directory_itself_is_no_folder_of_the_file_root(cpl, tmp_path):
    """FILEACCESS and FILEDATE do not tell the state directory's folder (or a link to it) from a missing
    name, and OPENW of it is refused as out of reach, like every name below it."""
    m = machine(tmp_path, file_root=".")
    assert cpl("10 @1=4711\nM30\n", machine=m)[0]["status"] == "ok"
    (tmp_path / "state").symlink_to(".ncvm")
    (tmp_path / "folder").mkdir()
    r, _ = cpl('1 DIM D$(8),E$(8)\n10 A%=FILEACCESS(".ncvm")\n20 B%=FILEACCESS("state")\n30 C%=FILEACCESS("folder")\n'
               '40 D$=FILEDATE(".ncvm")\n50 E$=FILEDATE("folder")\nM30\n', machine=m)
    got = r["variables"]
    assert (got["A%"], got["B%"], got.get("D$", "")) == (-1, -1, "") and got["C%"] & 8 and got["E$"]
    r, _ = cpl('10 OPENW(1,".ncvm")\nM30\n', machine=m)
    assert refused(r, 1, "state directory")


def test_the_state_directory_run_from_the_command_line(tmp_path):
    """The same with a real machine file and ``ncvm run``: ERASE of the store is refused."""
    (tmp_path / "machine.toml").write_text('[[axis]]\nname = "X"\n\n[paths]\nfile_root = "."\n')
    assert ncvm_run(tmp_path, "10 @1=7\nM30\n", "-m", "machine.toml").returncode == 0
    done = ncvm_run(tmp_path, '10 E%=ERASE(".ncvm/store.sqlite")\nM30\n', "-m", "machine.toml")
    assert done.returncode == 1 and "error CPL609" in done.stderr and "state directory" in done.stderr
    assert store_is_intact(tmp_path / ".ncvm")


def test_a_hard_link_to_the_store_is_refused_but_not_the_roots_own_hard_links(cpl, tmp_path):
    """The built-in machine keeps its file root in the state directory (.ncvm/files): a hard link planted
    there to the store is refused, while two names of one file of the root itself are an ordinary file
    (they were refused as "a hard link to a file of the state directory")."""
    assert cpl("10 @1=4711\nM30\n")[0]["status"] == "ok"
    files = tmp_path / ".ncvm" / "files"
    files.mkdir()
    os.link(tmp_path / ".ncvm" / "store.sqlite", files / "planted")
    (files / "A").write_text("DATA\n")
    os.link(files / "A", files / "B")
    r, _ = cpl('10 OPENW(1,"planted")\n20 REWRITE(1)\nM30\n')
    assert refused(r, 1, "hard link")
    assert store_is_intact(tmp_path / ".ncvm")
    r, _ = cpl('1 DIM S$(8)\n10 OPENR(1,"A")\n20 INP#(1,S$)\nM30\n')
    assert r["status"] == "ok" and r["variables"]["S$"].rstrip() == "DATA", r["error"]


@pytest.mark.parametrize("statement", ['E%=ERASE("machine.toml")', 'OPENW(1,"machine.toml")\n20 REWRITE(1)',
                                       'SCSL(1,"S",51,"machine.toml")', 'OPENR(1,"machine.toml")',
                                       'OPENW(1,"linked.toml")\n20 REWRITE(1)', 'FXCR(0,"machine.toml")'])
def test_the_machine_file_in_the_file_root_is_out_of_reach(tmp_path, statement):
    """file_root = "." is the machine file's own folder: a program that erased or rewrote the machine file
    would stop every later run (or, were the file still TOML, choose the next run's file root). It is
    refused like the state directory, under any name (a hard link too)."""
    text = '[[axis]]\nname = "X"\n\n[paths]\nfile_root = "."\n'
    (tmp_path / "machine.toml").write_text(text)
    os.link(tmp_path / "machine.toml", tmp_path / "linked.toml")
    done = ncvm_run(tmp_path, f"10 {statement}\nM30\n", "-m", "machine.toml")
    assert done.returncode == 1 and "error CPL609" in done.stderr and "machine file" in done.stderr, done.stderr
    assert (tmp_path / "machine.toml").read_text() == text
    ok = ncvm_run(tmp_path, '1 DIM D$(8)\n10 A%=FILEACCESS("machine.toml")\n20 D$=FILEDATE("machine.toml")\n'
                            '30 PRN#(0,"A",A%,D$)\nM30\n', "-m", "machine.toml")
    assert ok.returncode == 0 and ok.stdout.split() == ["A", "-1"], ok.stdout + ok.stderr


# -- bitmaps (BMP) -------------------------------------------------------------------------------------------
def red_image(path: Path) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    Image.new("RGB", (8, 8), (255, 0, 0)).save(path, format="BMP")


def test_bmp_does_not_read_an_image_outside_the_bitmap_folder(cpl, tmp_path):
    red_image(tmp_path / "outside" / "host.bmp")
    (tmp_path / ".ncvm" / "files" / "cplbmp").mkdir(parents=True)
    r, session = cpl('10 BMP(10,100,"../../../outside/host")\nM30\n')
    assert refused(r, 1, "outside the file root")
    host = Path(tempfile.mkdtemp(prefix="bmp"))  # BMP takes at most 70 characters: a short absolute name
    try:
        red_image(host / "host.bmp")
        r, session = cpl(f'10 BMP(10,100,"{host}/host")\nM30\n')
    finally:
        shutil.rmtree(host)
    assert r["status"] == "ok", r["error"]
    assert f"warning CPL803: cplbmp\\{host}/host.bmp is not existing" in r["output"]
    assert not (session.screen.canvas == (255, 0, 0)).all(axis=2).any(), "no pixel of the host's image"


def test_bmp_refuses_a_link_out_and_reads_its_own_folder(cpl, tmp_path):
    bitmaps = tmp_path / ".ncvm" / "files" / "cplbmp"
    red_image(bitmaps / "logo.bmp")
    red_image(tmp_path / "outside" / "host.bmp")
    (bitmaps / "planted.bmp").symlink_to(tmp_path / "outside" / "host.bmp")
    r, session = cpl('10 BMP(10,100,"logo")\nM30\n')
    assert r["status"] == "ok" and (session.screen.canvas == (255, 0, 0)).all(axis=2).sum() == 64
    r, _ = cpl('10 BMP(10,100,"planted")\nM30\n')
    assert refused(r, 1, "out of the file root")


def rle_bomb(width: int, height: int) -> bytes:
    """An 8-bit run-length BMP of ``width`` x ``height`` pixels in a few hundred bytes: "delta" escapes
    (0, 2, 0, 255) skip 255 rows each. It holds no byte 13, so a CPL program can write it with PRN#."""
    rle = b"".join(bytes([0, 2, 0, min(255, height - row)]) for row in range(0, height, 255)) + b"\x00\x01"
    palette = b"\x00\x00\x00\x00\xff\xff\xff\x00"
    start = 14 + 40 + len(palette)
    info = struct.pack("<IiiHHIIiiII", 40, width, height, 1, 8, 1, len(rle), 2835, 2835, 2, 2)
    return b"BM" + struct.pack("<IHHI", start + len(rle), 0, 0, start) + info + palette + rle


def test_bmp_does_not_decode_a_bitmap_far_larger_than_the_screen(cpl, tmp_path):
    """A program writes a 3000 x 3000 run-length bitmap of 300 bytes and shows it: decoding it would take
    memory and time out of all proportion to the 633 x 415 window (9000 x 9000 took 900 MB and 3 s
    per BMP). It warns like a file that holds no image, and the program goes on."""
    data = rle_bomb(3000, 3000)
    assert b"\r" not in data and len(data) < 400
    writes = "".join(f"{20 + i}PRN#(1,{','.join(f'CHR$({b})' for b in data[i * 16:(i + 1) * 16])};)\n"
                     for i in range((len(data) + 15) // 16))
    r, session = cpl('10 OPENW(1,"cplbmp/big.bmp",130)\n' + writes + '90 CLOSE(1)\n91 BMP(0,0,"big")\nM30\n')
    assert (tmp_path / ".ncvm" / "files" / "cplbmp" / "big.bmp").read_bytes().startswith(data)
    assert r["status"] == "ok", r["error"]
    assert "warning CPL803: cplbmp\\big.bmp is not existing: 3000 x 3000 pixels, more than 4194304 (2048 x 2048)" in r["output"]


def test_bmp_shows_bmp_files_only(cpl, tmp_path):
    """BMP shows "*.bmp" picture files (L5128): a file of another image format (for which an image library
    may start helper programs) is not decoded."""
    bitmaps = tmp_path / ".ncvm" / "files" / "cplbmp"
    bitmaps.mkdir(parents=True)
    Image.new("RGB", (8, 8), (255, 0, 0)).save(bitmaps / "png.bmp", format="PNG")
    r, session = cpl('10 BMP(0,0,"png")\nM30\n')
    assert r["status"] == "ok" and "warning CPL803: cplbmp\\png.bmp is not existing" in r["output"]
    assert not (session.screen.canvas == (255, 0, 0)).all(axis=2).any()


# -- MCOPS program selection ---------------------------------------------------------------------------------
def test_mcops_does_not_tell_whether_a_host_file_exists(cpl, tmp_path):
    """MCOPS(4) answers 0 for a program it finds and 6 (no program) otherwise: host paths and names out of
    the program path must all be 6, whether the file exists or not."""
    progs = tmp_path / "progs"
    progs.mkdir()
    (progs / "P1.cpl").write_text("M30\n")
    (tmp_path / "HOST.cpl").write_text("M30\n")
    (progs / "LINK.cpl").symlink_to(tmp_path / "HOST.cpl")
    m = machine(tmp_path, program_path="progs")
    names = ["P1", str(tmp_path / "HOST.cpl"), str(tmp_path / "NONE.cpl"), "../HOST", "../NONE", "LINK"]
    text = "".join(f'{10 * i} R{i}%=MCOPS(4,2,"{n}")\n' for i, n in enumerate(names, 1)) + "M30\n"
    r, _ = cpl(text, machine=m)
    assert r["status"] == "ok", r["error"]
    assert [r["variables"][f"R{i}%"] for i in range(1, len(names) + 1)] == [0, 6, 6, 6, 6, 6]


def test_mcops_does_not_tell_whether_a_file_of_the_state_directory_exists(cpl, tmp_path):
    """The state directory inside a program folder (``ncvm run prog.cpl`` in the program's own folder keeps
    .ncvm there): MCOPS(4) finds no program in it, so the store is neither selected nor told apart from a
    missing name."""
    m = machine(tmp_path)  # program path ".": the folder of prog.cpl, which holds .ncvm
    (tmp_path / "P1.cpl").write_text("M30\n")
    assert cpl("10 @1=1\nM30\n", machine=m)[0]["status"] == "ok"
    names = ["P1", ".ncvm/store.sqlite", ".ncvm/lock", ".ncvm/NONE", ".ncvm"]
    text = "".join(f'{10 * i} R{i}%=MCOPS(4,2,"{n}")\n' for i, n in enumerate(names, 1)) + "M30\n"
    r, _ = cpl(text, machine=m)
    assert r["status"] == "ok", r["error"]
    assert [r["variables"][f"R{i}%"] for i in range(1, len(names) + 1)] == [0, 6, 6, 6, 6]


# -- the permanent-variable declarations -----------------------------------------------------------------------
@pytest.mark.parametrize("decl", ["anwperm.dat", "wmhperm.dat", "ANWPERM.DAT"])
def test_a_planted_link_for_the_declarations_is_not_followed(cpl, tmp_path, decl):
    """The declaration file is read at start-up; a link planted in its place (here to a file outside that
    would even declare @SECRET) is a declaration file error, and no line of its target is shown."""
    files = tmp_path / ".ncvm" / "files"
    files.mkdir(parents=True)
    (tmp_path / "host.txt").write_text("DEF INT @SECRET\nroot:x:0:0:host line\n")
    (files / decl).symlink_to(tmp_path / "host.txt")
    r, _ = cpl("10 @SECRET=1\nM30\n")
    assert r["status"] != "ok" and r["error"]["code"] == "CPL038"
    assert "symbolic link" in r["error"]["message"] and "host line" not in r["error"]["message"]


def test_a_link_inside_the_root_for_the_declarations_is_refused_too(cpl, tmp_path):
    files = tmp_path / ".ncvm" / "files"
    files.mkdir(parents=True)
    (files / "mine.dat").write_text("DEF INT @MINE\n")
    (files / "anwperm.dat").symlink_to("mine.dat")
    r, _ = cpl("10 @MINE=1\nM30\n")
    assert r["error"]["code"] == "CPL038" and "symbolic link" in r["error"]["message"]


# -- folders the file system itself refuses ------------------------------------------------------------------
def test_a_folder_that_cannot_be_searched_is_a_file_error_not_a_crash(tmp_path, monkeypatch):
    """Permissions do not stop root (the tests may run as root), so the file system's answer is simulated."""
    from ncvm.dialects.cpl.io.errors import CplRuntimeError
    from ncvm.dialects.cpl.io.files import CplFiles

    fs = CplFiles(root=tmp_path, durable=False)
    (tmp_path / "A").write_text("x\n")

    def denied(*args, **kw):
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr(fs.fileroot, "unlink", denied)
    assert fs.ERASE("A") == 2 and (tmp_path / "A").exists()
    monkeypatch.setattr(fs.fileroot, "stat", denied)
    with pytest.raises(CplRuntimeError) as err:
        fs.ERASE("A")
    assert err.value.code == "CPL609" and "Permission denied" in err.value.message
    assert fs.FILEACCESS("A") == -1 and fs.FILEDATE("A") == ""


def test_openw_below_a_file_is_an_invalid_name(tmp_path):
    from ncvm.dialects.cpl.io.errors import CplRuntimeError
    from ncvm.dialects.cpl.io.files import CplFiles

    fs = CplFiles(root=tmp_path, durable=False)
    (tmp_path / "A").write_text("x\n")
    with pytest.raises(CplRuntimeError) as err:
        fs.OPENW(1, "A/B")
    assert err.value.code == "CPL609" and "Not a directory" in err.value.message
    with pytest.raises(CplRuntimeError) as err:
        fs.OPENR(1, "A/B")
    assert err.value.code == "CPL612"
