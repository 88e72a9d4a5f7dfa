"""Output options of every command, checked before anything runs; ``--json`` usage errors as JSON."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from ncvm import cli

PROGRAM = "(MSG, roughing)\nG17 G90 G0 X10 Y0\nG1 X20 F600\nM2\n"
CL800 = Path(__file__).parents[1] / "examples" / "cl800" / "hole_pattern.cl8"  # compiles to L101.spf


def invoke(*args) -> object:
    return CliRunner().invoke(cli.cli, [str(a) for a in args], catch_exceptions=False)


@pytest.fixture
def work(tmp_path, monkeypatch) -> Path:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "part.din").write_text(PROGRAM)
    (tmp_path / "afile").write_text("a file, not a folder")
    (tmp_path / "folder").mkdir()
    return tmp_path


def assert_usage(r, *parts: str) -> None:
    assert r.exit_code == 2, r.output
    assert all(p in r.stderr for p in parts), r.stderr
    assert "internal error" not in r.stderr and "Traceback" not in r.stderr
    assert "roughing" not in r.stdout  # the program did not start


RUN_OUTPUTS = [("--trace", "t.jsonl"), ("--gcode", "g.ngc"), ("--plot", "p.png"), ("--screen", "s.png")]


@pytest.mark.parametrize("option, name", RUN_OUTPUTS)
@pytest.mark.parametrize("where, message", [
    ("missing/{name}", "folder missing does not exist"),
    ("afile/{name}", "afile is not a folder"),
    ("/proc/{name}", "cannot write: files cannot be made there"),
])
def test_run_output_that_cannot_be_written_stops_before_the_run(work, option, name, where, message):
    path = where.format(name=name)
    r = invoke("run", "part.din", option, path, "--state", "st")
    assert_usage(r, f"{option} {path}: {message}")
    assert not (work / "missing").exists()


def test_an_existing_file_that_takes_no_writes_and_a_folder_in_place_of_a_file(work):
    r = invoke("run", "part.din", "--gcode", "/proc/version")  # root may write anywhere, not into /proc
    assert_usage(r, "--gcode /proc/version: cannot write:")
    r = invoke("run", "part.din", "--trace", "folder")
    assert_usage(r, "--trace", "folder", "is a directory")


@pytest.mark.parametrize("name", ["toolpath", "toolpath.jpg", "toolpath.PNG.txt"])
def test_plot_needs_an_extension_that_names_its_format(work, name):
    r = invoke("run", "part.din", "--plot", name)
    assert_usage(r, f"--plot {name}: the file name must end in .png or .svg or .pdf")
    assert sorted(p.name for p in work.iterdir()) == ["afile", "folder", "part.din"]  # no NAME.png either


def test_screen_is_a_png(work):
    assert_usage(invoke("run", "part.din", "--screen", "screen.gif"), "--screen screen.gif: the file name must end in .png")


@pytest.mark.parametrize("option, name", RUN_OUTPUTS)
@pytest.mark.parametrize("input_option", ["program", "--machine", "--scenario", "--keys"])
def test_no_output_overwrites_an_input(work, option, name, input_option):
    inputs = {"--machine": "[[axis]]\nname = 'X'\n",
              "--scenario": "[[scenario]]\ntime = 1\nkind = 'input'\naddress = 'E1.0'\nvalue = true\n",
              "--keys": "SK1\n"}
    target = work / name
    if input_option == "program":
        target.write_text(PROGRAM)
        args = [target]
    else:
        target.write_text(inputs[input_option])
        args = ["part.din", input_option, target]
    before = target.read_bytes()
    r = invoke("run", *args, option, name, "--state", "st")
    assert_usage(r, f"{option} {name}: it would overwrite the", str(target))
    assert target.read_bytes() == before


def test_an_input_reached_through_a_link_is_still_the_input(work):
    os.symlink("part.din", work / "link.ngc")
    os.link(work / "part.din", work / "hard.ngc")
    for name in ("link.ngc", "hard.ngc"):
        assert_usage(invoke("run", "part.din", "--gcode", name), f"--gcode {name}: it would overwrite the program")
    assert (work / "part.din").read_text() == PROGRAM


def test_two_outputs_into_one_file(work):
    r = invoke("run", "part.din", "--gcode", "out.txt", "--trace", "./out.txt")
    assert_usage(r, "--gcode out.txt: is the same file as --trace ./out.txt")
    assert not (work / "out.txt").exists()  # the check leaves nothing behind
    # devices are not files to keep: any number of outputs may go there
    r = invoke("run", "part.din", "--gcode", "/dev/null", "--trace", "/dev/null", "--state", "st")
    assert r.exit_code == 0, r.stderr


def test_screen_dir_is_a_folder_in_a_folder_that_exists(work):
    assert_usage(invoke("run", "part.din", "--screen-dir", "afile"), "--screen-dir", "afile")
    assert_usage(invoke("run", "part.din", "--screen-dir", "missing/pictures"),
                 "--screen-dir missing/pictures: folder missing does not exist")
    assert_usage(invoke("run", "part.din", "--screen-dir", "/proc/pictures"),
                 "--screen-dir /proc/pictures: cannot write into folder /proc")
    r = invoke("run", "part.din", "--screen-dir", "folder", "--screen", "folder/screen_002.png")
    assert_usage(r, "--screen folder/screen_002.png: has the name of a file written by --screen-dir folder")
    (work / "folder" / "screen_001.png").write_text("SK1\n")
    r = invoke("run", "part.din", "--screen-dir", "folder", "--keys", "folder/screen_001.png")
    assert_usage(r, "--screen-dir folder: a file it writes would overwrite the input of --keys")
    # a folder that is not there yet is made at the first picture
    r = invoke("run", "part.din", "--screen-dir", "folder/new", "--state", "st")
    assert r.exit_code == 0, r.stderr


def test_state_folder_given_is_made_with_its_parents_where_folders_can_be_made(work):
    # the state directory is checked where it is locked (machine/state.py), with what to do
    assert_usage(invoke("run", "part.din", "--state", "afile/state"),
                 "state directory afile/state cannot be written (Not a directory); make it writable or give another --state")
    assert_usage(invoke("run", "part.din", "--state", "/proc/state"),
                 "state directory /proc/state cannot be written (No such file or directory); make it writable or give another --state")
    (work / "prog.cpl").write_text("10 A% = 1\nM30\n")
    r = invoke("run", "prog.cpl", "--state", "new/deeper/state")
    assert r.exit_code == 0 and (work / "new" / "deeper" / "state").is_dir()


@pytest.mark.parametrize("line", ["BOGUS 5", "KEY 300", "SK9"])
def test_a_key_script_that_does_not_read_is_a_usage_error_before_the_run(work, line):
    (work / "keys.txt").write_text(f"SK1\n# comment\n{line}\n")
    (work / "dialog.cpl").write_text("10 A% = 1\nM30\n")
    r = invoke("run", "dialog.cpl", "--keys", "keys.txt", "--state", "st")
    assert_usage(r, f"--keys keys.txt: key script line not understood: line 3: '{line}'")


def test_a_key_script_that_is_not_text(work):
    (work / "keys.bin").write_bytes(b"SK1\n\xff\xfe\n")
    assert_usage(invoke("run", "part.din", "--keys", "keys.bin"), "--keys keys.bin: not UTF-8 text (byte 5)")


@pytest.fixture
def cl8(work) -> Path:
    source = work / "holes.cl8"
    source.write_bytes(CL800.read_bytes())
    return source


def test_compile_never_overwrites_its_source_nor_writes_two_outputs_into_one_file(work, cl8):
    before = cl8.read_bytes()
    assert_usage(invoke("compile", "holes.cl8", "-o", "holes.cl8"), "-o holes.cl8: it would overwrite the program")
    assert_usage(invoke("compile", "holes.cl8", "--xref", "holes.cl8"), "--xref holes.cl8: it would overwrite")
    assert_usage(invoke("compile", "holes.cl8", "-o", "x.spf", "--xref", "x.spf"), "--xref x.spf: is the same file as -o")
    assert_usage(invoke("compile", "holes.cl8", "-o", "missing/x.spf"), "-o missing/x.spf: folder missing does not exist")
    assert_usage(invoke("compile", "holes.cl8", "--xref", "afile/x.lst"), "--xref afile/x.lst: afile is not a folder")
    assert cl8.read_bytes() == before
    # without -o the object program is named after its number: L101.spf, which here is the source
    source = work / "L101.spf"
    source.write_bytes(before)
    r = invoke("compile", source.name, "--dialect", "cl800")
    assert_usage(r, "compile L101.spf: would overwrite the source L101.spf")
    assert source.read_bytes() == before
    r = invoke("compile", "holes.cl8", "-o", "x.spf", "--xref", "x.lst")
    assert r.exit_code == 0 and (work / "x.spf").read_text().startswith("%SPF101")


@pytest.mark.parametrize("args, message", [
    (["run", "part.din", "--json", "--no-such-option"], "No such option"),
    (["run", "absent.din", "--json"], "no such program: absent.din"),
    (["run", "part.din", "--json", "--machine", "absent.toml"], "cannot read machine file absent.toml"),
    (["run", "part.din", "--json", "--machine", "afile"], "afile: not valid TOML"),
    (["run", "part.din", "--json", "--keys", "absent.txt"], "'absent.txt' does not exist"),
    (["run", "part.din", "--json", "--max-steps", "0"], "--max-steps"),
    (["run", "part.din", "--json", "--gcode", "missing/g.ngc"], "--gcode missing/g.ngc: folder missing does not exist"),
    (["run", "--json"], "Missing argument 'PROGRAMS...'"),
    (["check", "--json", "part.din", "absent.din"], "no such program: absent.din"),
    (["check", "part.din", "--json", "--dialect", "pascal"], "--dialect"),
])
def test_json_usage_errors_are_a_json_document(work, args, message):
    r = invoke(*args)
    assert r.exit_code == 2
    doc = json.loads(r.stdout)
    assert doc["status"] == "usage_error" and message in doc["error"]["message"]
    assert set(doc["error"]) == {"code", "message", "file", "line", "column"}  # as the error of a run
    assert message in r.stderr  # and the people at a terminal read it as before


def test_json_usage_error_from_the_installed_command(work):
    r = subprocess.run([sys.executable, "-m", "ncvm", "run", "part.din", "--json", "--plot", "plot"],
                       capture_output=True, text=True)
    assert r.returncode == 2
    assert json.loads(r.stdout)["status"] == "usage_error"
    # "--json" after "--" is a program name, not the option
    r = subprocess.run([sys.executable, "-m", "ncvm", "run", "--", "--json"], capture_output=True, text=True)
    assert r.returncode == 2 and r.stdout == "" and "no such program: --json" in r.stderr
