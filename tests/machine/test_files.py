"""The file root resolver: names stay below the root, links out of it and the state directory are refused,
only regular files are opened, and a descriptor once opened is not redirected (real links, FIFOs, sockets)."""

from __future__ import annotations

import os
import socket
import stat

import pytest

from ncvm.machine import files as files_module
from ncvm.machine.files import FileRoot, FileRootError
from ncvm.machine.model import Machine


@pytest.fixture
def tree(tmp_path):
    """<tmp>/root (the file root) beside <tmp>/outside, which holds a secret the root must not reach."""
    root, outside = tmp_path / "root", tmp_path / "outside"
    root.mkdir()
    outside.mkdir()
    (outside / "SECRET").write_text("secret\n")
    (root / "sub").mkdir()
    (root / "sub" / "A").write_text("a\n")
    return FileRoot(root), root, outside


def read(fr: FileRoot, name: str, cwd: str = "") -> bytes:
    return fr.read_bytes(fr.place(name, cwd))


@pytest.mark.parametrize("name, parts", [
    ("sub/A", ("sub", "A")), ("/sub/A", ("sub", "A")), ("\\sub\\A", ("sub", "A")), ("C:\\sub\\A", ("sub", "A")),
    ("c:/sub/./A", ("sub", "A")), ("sub/x/../A", ("sub", "A")), ("  sub//A ", ("sub", "A")),
])
def test_a_control_name_is_placed_below_the_root(name, parts):
    """A leading / or a drive letter is the control's root -- the file root, never the host's."""
    assert FileRoot.place(name).parts == parts


def test_relative_names_start_in_the_current_directory():
    assert FileRoot.place("A", cwd="usr/user").parts == ("usr", "user", "A")
    assert FileRoot.place("../../B", cwd="usr/user").parts == ("B",)
    assert FileRoot.place("/B", cwd="usr/user").parts == ("B",)


@pytest.mark.parametrize("name", ["..", "../x", "/../x", "sub/../../x", "C:..\\x", "a\x00b", "", "  ", "/", "."])
def test_names_that_climb_out_hold_nul_or_name_nothing_are_refused(name):
    with pytest.raises(FileRootError):
        FileRoot.place(name)


def test_absolute_names_never_reach_the_host(tree):
    fr, root, outside = tree
    assert fr.stat(fr.place(str(outside / "SECRET"))) is None  # <root>/<tmp>/outside/SECRET: not there
    assert read(fr, "/sub/A") == b"a\n"


def test_a_link_inside_the_root_is_followed(tree):
    fr, root, _ = tree
    (root / "rel").symlink_to("sub/A")
    (root / "dir").symlink_to("sub")
    (root / "abs").symlink_to(root / "sub" / "A")  # an absolute target inside the root
    (root / "sub" / "up").symlink_to("../sub/A")
    for name in ("rel", "dir/A", "abs", "sub/up"):
        assert read(fr, name) == b"a\n", name


@pytest.mark.parametrize("target", ["../outside/SECRET", "{outside}/SECRET", "sub/../../outside/SECRET", "/etc/hostname"])
def test_a_link_that_leads_out_is_refused(tree, target):
    fr, root, outside = tree
    (root / "link").symlink_to(target.format(outside=outside))
    with pytest.raises(FileRootError, match="outside the file root|out of the file root"):
        read(fr, "link")


def test_a_folder_link_out_is_refused_for_writing_and_nothing_is_made_outside(tree):
    fr, root, outside = tree
    (root / "out").symlink_to(outside)
    for place in (fr.place("out/NEW"), fr.place("out/deeper/NEW"), fr.place("out/SECRET")):
        with pytest.raises(FileRootError):
            fr.open(place, write=True, create=True)
        with pytest.raises(FileRootError):
            fr.replace(place, b"x")
    with pytest.raises(FileRootError):
        fr.unlink(fr.place("out/SECRET"))
    assert sorted(p.name for p in outside.iterdir()) == ["SECRET"] and (outside / "SECRET").read_text() == "secret\n"


def test_a_link_loop_is_refused(tree):
    fr, root, _ = tree
    (root / "a").symlink_to("b")
    (root / "b").symlink_to("a")
    with pytest.raises(FileRootError, match="too many symbolic links"):
        read(fr, "a")


def test_follow_false_refuses_a_link_even_inside_the_root(tree):
    fr, root, _ = tree
    (root / "rel").symlink_to("sub/A")
    with pytest.raises(FileRootError, match="symbolic link"):
        fr.read_bytes(fr.place("rel"), follow=False)


def test_a_fifo_is_refused_without_being_opened(tree):
    """Opening a FIFO for writing blocks until a reader comes: the lstat refuses it first."""
    fr, root, _ = tree
    os.mkfifo(root / "PIPE")
    for call in (lambda p: fr.open(p, write=True, create=True), lambda p: fr.open(p), fr.read_bytes, fr.unlink,
                 lambda p: fr.replace(p, b"x")):
        with pytest.raises(FileRootError, match="is a FIFO, not a file"):
            call(fr.place("PIPE"))
    assert stat.S_ISFIFO(os.lstat(root / "PIPE").st_mode)


def test_a_socket_and_a_device_are_refused(tree):
    fr, root, _ = tree
    sock = socket.socket(socket.AF_UNIX)
    try:
        sock.bind(str(root / "SOCK"))
        with pytest.raises(FileRootError, match="is a socket"):
            fr.open(fr.place("SOCK"), write=True, create=True)
    finally:
        sock.close()
    try:
        os.mknod(root / "NULL", stat.S_IFCHR | 0o666, os.makedev(1, 3))
    except PermissionError:
        return  # only root makes device nodes; the socket above covers the rule
    with pytest.raises(FileRootError, match="is a device"):
        fr.open(fr.place("NULL"), write=True)


def test_a_directory_is_no_file(tree):
    fr, _, _ = tree
    with pytest.raises(FileRootError, match="is a directory"):
        fr.open(fr.place("sub"), write=True, create=True)
    assert stat.S_ISDIR(fr.stat(fr.place("sub")).st_mode)


def test_the_state_directory_inside_the_root_is_never_reached(tmp_path):
    """file_root = "." with the state directory .ncvm inside it: the store is out of reach, also by a link."""
    state = tmp_path / ".ncvm"
    state.mkdir()
    (state / "store.sqlite").write_bytes(b"SQLite format 3\x00")
    (tmp_path / "alias").symlink_to(".ncvm")
    fr = FileRoot(tmp_path, private=[state])
    for name in (".ncvm/store.sqlite", "alias/store.sqlite", "/.ncvm/NEW", "x/../.ncvm/store.sqlite"):
        with pytest.raises(FileRootError, match="state directory"):
            fr.open(fr.place(name), write=True, create=True)
        with pytest.raises(FileRootError, match="state directory"):
            fr.stat(fr.place(name))
    with pytest.raises(FileRootError, match="state directory"):
        fr.unlink(fr.place(".ncvm/store.sqlite"))
    assert (state / "store.sqlite").read_bytes() == b"SQLite format 3\x00"
    assert sorted(p.name for p in state.iterdir()) == ["store.sqlite"]


def test_a_hard_link_to_the_store_planted_in_the_root_is_not_opened(tmp_path):
    state, root = tmp_path / "state", tmp_path / "root"
    (state / "link").mkdir(parents=True)
    root.mkdir()
    (state / "store.sqlite").write_bytes(b"SQLite format 3\x00")
    (state / "link" / "P.I").write_bytes(b"table")
    os.link(state / "store.sqlite", root / "STORE")
    os.link(state / "link" / "P.I", root / "TABLE")
    fr = FileRoot(root, private=[state])
    for name in ("STORE", "TABLE"):
        with pytest.raises(FileRootError, match="hard link"):
            fr.open(fr.place(name), write=True)
    (root / "OWN").write_text("x")
    os.link(root / "OWN", root / "OWN2")  # two names inside the root are fine
    assert fr.read_bytes(fr.place("OWN2")) == b"x"


def test_a_root_that_is_the_state_directory_is_refused(tmp_path):
    fr = FileRoot(tmp_path, private=[tmp_path])
    with pytest.raises(FileRootError, match="state directory"):
        fr.stat(fr.place("store.sqlite"))


def test_a_descriptor_keeps_writing_to_its_file_when_the_folder_becomes_a_link(tree):
    fr, root, outside = tree
    fd = fr.open(fr.place("sub/LOG"), write=True, create=True)
    try:
        os.rename(root / "sub", root / "moved")
        (root / "sub").symlink_to(outside)
        os.write(fd, b"after the swap\n")
    finally:
        os.close(fd)
    assert (root / "moved" / "LOG").read_bytes() == b"after the swap\n"
    assert not (outside / "LOG").exists()


def test_a_folder_swapped_for_a_link_during_the_walk_is_not_followed(tree, monkeypatch):
    """Between the lstat of a folder and its opening, the folder becomes a link out: the opening
    (O_NOFOLLOW) refuses it instead of writing outside."""
    fr, root, outside = tree
    real_stat = os.stat

    def stat_then_swap(path, *args, **kw):
        st = real_stat(path, *args, **kw)
        if path == "sub":
            os.rename(root / "sub", root / "moved")
            (root / "sub").symlink_to(outside)
        return st

    monkeypatch.setattr(files_module.os, "stat", stat_then_swap)
    with pytest.raises(FileRootError, match="became a symbolic link"):
        fr.open(fr.place("sub/SECRET"), write=True, create=True)
    monkeypatch.undo()
    assert (outside / "SECRET").read_text() == "secret\n"


def test_replace_writes_whole_files_and_keeps_their_rights(tree):
    fr, root, _ = tree
    (root / "sub" / "A").chmod(0o640)
    fr.replace(fr.place("sub/A"), b"new\n", durable=False)
    fr.replace(fr.place("made/on/the/way"), b"x\n", durable=False)
    assert (root / "sub" / "A").read_bytes() == b"new\n" and stat.S_IMODE((root / "sub" / "A").stat().st_mode) == 0o640
    assert (root / "made/on/the/way").read_bytes() == b"x\n"
    assert sorted(p.name for p in (root / "sub").iterdir()) == ["A"]  # no temporary file left


def test_find_answers_any_case_and_sees_a_link_without_following_it(tree):
    fr, root, _ = tree
    (root / "ANWPERM.DAT").write_text("x")
    (root / "wmhperm.dat").symlink_to("/etc/hostname")
    assert fr.find("anwperm.dat", ignore_case=True).parts == ("ANWPERM.DAT",)
    assert fr.find("anwperm.dat") is None
    assert fr.find("wmhperm.dat").parts == ("wmhperm.dat",)
    assert fr.find("../outside/SECRET") is None


def test_the_program_path_answers_for_programs_only(tmp_path):
    """MCOPS and CALL look names up here: a host path or a name outside the program folder finds nothing, so
    the answer never tells whether a host file exists; a FIFO is no program."""
    progs = tmp_path / "progs"
    progs.mkdir()
    (progs / "P1.cpl").write_text("M30\n")
    (tmp_path / "OUT.cpl").write_text("M30\n")
    os.mkfifo(progs / "PIPE.cpl")
    (progs / "LINK.cpl").symlink_to(tmp_path / "OUT.cpl")
    m = Machine(program_path=[progs])
    assert m.find_program("P1", (".cpl",)) == progs / "P1.cpl"
    assert m.find_program("p1.CPL") == progs / "P1.cpl"
    for name in (str(tmp_path / "OUT.cpl"), "../OUT", "/etc/hostname", "PIPE", "LINK"):
        assert m.find_program(name, (".cpl",)) is None, name


def test_program_heads_are_read_as_programs_are_read(tmp_path):
    """A header behind a UTF-8 byte-order mark is found by its number, as the program itself is read."""
    (tmp_path / "a.spf").write_bytes(b"\xef\xbb\xbf%SPF 77\nM17\n")
    (tmp_path / "b.spf").write_bytes(b"%SPF 78\nM17\n")
    (tmp_path / "c.txt").write_bytes(b"%SPF 79\n")
    found = dict(files_module.heads([tmp_path], (".spf",)))
    assert {p.name: h[:7] for p, h in found.items()} == {"a.spf": "%SPF 77", "b.spf": "%SPF 78"}
