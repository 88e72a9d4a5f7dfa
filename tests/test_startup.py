"""Start-up (issue 18): the commands import the heavy libraries and the dialects only when they use them.

Each command runs in a fresh interpreter, as a user starts it; the test reads which modules it loaded.
"""

from __future__ import annotations

import ast
import json
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

HEAVY = ("numpy", "matplotlib", "PIL", "sqlite3", "rich")
DIALECTS = ("ncvm.dialects.din", "ncvm.dialects.cpl", "ncvm.dialects.sinumerik", "ncvm.dialects.sympas")

#: imports nothing a run might not (no json): the arguments come as they are, the modules go out as a repr
PROBE = """\
import runpy, sys
sys.argv = ["ncvm"] + sys.argv[1:]
try:
    runpy.run_module("ncvm", run_name="__main__")
except SystemExit as e:
    code = e.code
else:
    code = 0
sys.stdout.flush()
sys.stderr.write("\\nMODULES " + repr([code, sorted(sys.modules)]) + "\\n")
"""


def loaded(args: list[str], cwd) -> tuple[int, set[str]]:
    """(exit code, modules loaded) of ``ncvm <args>`` in a new interpreter."""
    out = subprocess.run([sys.executable, "-c", PROBE, *args], capture_output=True, text=True,
                         cwd=cwd, timeout=120)
    line = [ln for ln in out.stderr.splitlines() if ln.startswith("MODULES ")][-1]
    code, modules = ast.literal_eval(line[len("MODULES "):])
    return code, set(modules)


def top(modules: set[str], names) -> set[str]:
    return {n for n in names if n in modules}


def test_version_imports_no_heavy_library_and_no_dialect(tmp_path):
    code, modules = loaded(["--version"], tmp_path)
    assert code == 0
    assert top(modules, HEAVY) == set()
    assert top(modules, DIALECTS) == set()
    assert "ncvm.api" not in modules


@pytest.mark.parametrize(("name", "text", "dialect"), [
    ("p.cpl", "10 A% = 1\n20 WHILE A% < 3 DO\n30 A% = A% + 1\n40 END\nM30\n", "ncvm.dialects.cpl"),
    ("p.ngc", "G1 X10 Y5 F1000\nM2\n", "ncvm.dialects.din"),
    ("p.sap", "program P;\nvar i: integer;\nbegin\n  i := 1;\nend.\n", "ncvm.dialects.sympas"),
])
def test_check_of_a_small_program_imports_no_numpy_and_only_its_dialect(tmp_path, name, text, dialect):
    (tmp_path / name).write_text(text)
    code, modules = loaded(["check", name], tmp_path)
    assert code == 0
    assert top(modules, HEAVY) == set()
    assert top(modules, DIALECTS) == {dialect}


def test_a_one_block_run_imports_neither_plot_nor_screen_libraries_nor_numpy(tmp_path):
    (tmp_path / "p.ngc").write_text("M2\n")
    code, modules = loaded(["run", "--state", str(tmp_path / ".ncvm"), "p.ngc"], tmp_path)
    assert code == 0
    assert top(modules, HEAVY) - {"sqlite3"} == set()  # the permanent store is opened when a program uses it
    assert top(modules, DIALECTS) == {"ncvm.dialects.din"}
    assert "tomllib" not in modules  # the built-in machine file's precomputed form (machine/default_form.py)
    assert {"json", "string"} & modules == set()  # json for --json and the store's values only
    # the built-in machine's precomputed form and a machine without a [din] section need no schema check
    assert {"ncvm.machine.schema", "ncvm.machine.sections", "ncvm.machine.spec"} & modules == set()
    # Machine, RunOptions and the run's records are no dataclasses: the module is not imported at all
    assert "dataclasses" not in modules


#: the commands in modules of their own (cli.py, _Guarded.LAZY) and the start of their one-line help
LAZY_COMMANDS = {"check": ("ncvm.checkcmd", "Check programs for every error"),
                 "compile": ("ncvm.compilecmd", "Compile SOURCE (CL 800 to @ code)."),
                 "machine-schema": ("ncvm.schemacmd", "Print the JSON Schema of machine files"),
                 "state": ("ncvm.statecmd", "The permanent memory of the simulated"),
                 "translate": ("ncvm.translatecmd", "Translate PROGRAM for a modern control")}


def test_a_run_builds_no_other_command_and_each_command_is_built_when_named(tmp_path):
    """Every command but ``run`` is a lazily loaded subcommand (cli.py, _Guarded.LAZY): a run imports none of
    their modules; naming one builds it (and only it)."""
    (tmp_path / "p.ngc").write_text("M2\n")
    code, modules = loaded(["run", "--state", str(tmp_path / ".ncvm"), "p.ngc"], tmp_path)
    assert code == 0 and {m for m, _help in LAZY_COMMANDS.values()} & modules == set()
    code, modules = loaded(["state", "show", "--state", str(tmp_path / ".ncvm")], tmp_path)
    assert code == 0 and {m for m, _help in LAZY_COMMANDS.values()} & modules == {"ncvm.statecmd"}
    code, modules = loaded(["check", "p.ngc"], tmp_path)
    assert code == 0 and {m for m, _help in LAZY_COMMANDS.values()} & modules == {"ncvm.checkcmd"}
    for name, (module, _help) in LAZY_COMMANDS.items():
        code, modules = loaded([name, "--help"], tmp_path)
        assert code == 0 and module in modules


def test_ncvm_help_lists_every_command_with_its_one_line_help(tmp_path):
    listed = subprocess.run([sys.executable, "-m", "ncvm", "--help"], capture_output=True, text=True, cwd=tmp_path,
                            timeout=120)
    assert listed.returncode == 0
    commands = listed.stdout.split("\nCommands:\n", 1)[1].split("\n\n", 1)[0].splitlines()
    assert [line.split()[0] for line in commands] == sorted([*LAZY_COMMANDS, "run"])
    helps = {line.split()[0]: " ".join(line.split()[1:]) for line in commands}
    for name, (_module, help_start) in LAZY_COMMANDS.items():
        assert helps[name].startswith(help_start), helps[name]
    assert helps["run"].startswith("Run PROGRAMS on the simulated controller")


def test_a_mistyped_command_is_matched_against_the_lazily_built_ones_too(tmp_path):
    out = subprocess.run([sys.executable, "-m", "ncvm", "translat", "p.ngc"], capture_output=True, text=True,
                         cwd=tmp_path, timeout=120)
    assert out.returncode == 2 and "No such command 'translat'" in out.stderr
    import click

    if hasattr(click.exceptions, "NoSuchCommand"):  # click 8.4 and later suggest the names that are close
        assert "Did you mean 'translate'?" in out.stderr


def test_a_run_with_moves_and_a_plot_loads_what_it_uses(tmp_path):
    (tmp_path / "p.ngc").write_text("G1 X10 Y5 F1000\nM2\n")
    code, modules = loaded(["run", "--state", str(tmp_path / ".ncvm"), "--plot", "p.png", "p.ngc"], tmp_path)
    assert code == 0
    assert {"numpy", "matplotlib"} <= modules
    assert (tmp_path / "p.png").stat().st_size > 0


def test_a_cpl_run_that_draws_and_shows_nothing_imports_no_numpy(tmp_path):
    """The CPL screen's pixels and text cells are made when the program first draws or shows something."""
    (tmp_path / "p.cpl").write_text("10 A = 0.5 : I% = 0\n20 WHILE I% < 3 DO\n30 A = A * 2 : I% = I% + 1\n"
                                    "40 END\nM30\n")
    code, modules = loaded(["run", "--state", str(tmp_path / ".ncvm"), "p.cpl"], tmp_path)
    assert code == 0
    assert top(modules, HEAVY) - {"sqlite3"} == set()
    assert top(modules, DIALECTS) == {"ncvm.dialects.cpl"}
    assert "ctypes" not in modules  # a REAL store rounds through a memoryview's C float


def test_a_cpl_run_on_a_machine_without_scenario_events_imports_no_event_type(tmp_path):
    """The CPL controller, measuring blocks and SERCOS functions take the event types only from a scenario."""
    (tmp_path / "p.cpl").write_text("10 I% = 0\n20 WHILE I% < 3 DO\n30 I% = I% + 1\n40 END\nM30\n")
    code, modules = loaded(["run", "--state", str(tmp_path / ".ncvm"), "p.cpl"], tmp_path)
    assert code == 0
    assert "ncvm.machine.scenario" not in modules


def test_a_cpl_run_that_draws_makes_its_canvas(tmp_path):
    (tmp_path / "p.cpl").write_text("10 GWD(0, 100, 0, 100)\n20 LIN(10, 10, 50, 50)\nM30\n")
    code, modules = loaded(["run", "--state", str(tmp_path / ".ncvm"), "--screen", "s.png", "p.cpl"], tmp_path)
    assert code == 0
    assert "numpy" in modules
    assert (tmp_path / "s.png").stat().st_size > 0


def test_a_one_block_run_imports_no_sink_it_was_not_asked_for_and_no_scenario_events(tmp_path):
    (tmp_path / "p.ngc").write_text("M2\n")
    code, modules = loaded(["run", "--state", str(tmp_path / ".ncvm"), "p.ngc"], tmp_path)
    assert code == 0
    unused = {"ncvm.sinks.trace", "ncvm.sinks.plot", "ncvm.sinks.plotview", "ncvm.translate",
              "ncvm.machine.scenario", "tempfile", "secrets"}
    assert unused & modules == set()
    # the moves table only for a run asked for its moves (the API), the DIN check only for ncvm check
    assert {"ncvm.sinks.moves", "ncvm.dialects.din.check"} & modules == set()


def test_a_run_with_a_trace_and_gcode_loads_and_writes_them(tmp_path):
    (tmp_path / "p.ngc").write_text("G1 X10 Y5 F1000\nM2\n")
    code, modules = loaded(["run", "--state", str(tmp_path / ".ncvm"), "--trace", "t.jsonl", "--gcode", "g.ngc",
                            "p.ngc"], tmp_path)
    assert code == 0
    assert {"ncvm.sinks.trace", "ncvm.translate"} <= modules
    assert '"feed"' in (tmp_path / "t.jsonl").read_text()
    assert "G1" in (tmp_path / "g.ngc").read_text()


def test_a_run_on_a_machine_file_parses_it(tmp_path):
    (tmp_path / "p.ngc").write_text("M2\n")
    (tmp_path / "m.toml").write_text('[machine]\nname = "m"\n[[axis]]\nname = "X"\n')
    code, modules = loaded(["run", "--state", str(tmp_path / ".ncvm"), "--machine", "m.toml", "p.ngc"], tmp_path)
    assert code == 0
    assert {"tomllib", "ncvm.machine.schema", "ncvm.machine.spec"} <= modules  # and checks it


def test_a_machine_file_with_a_bad_din_section_is_refused_by_a_run(tmp_path):
    (tmp_path / "p.ngc").write_text("M2\n")
    (tmp_path / "m.toml").write_text('[machine]\nname = "m"\n[[axis]]\nname = "X"\n[din]\nprofile = "nope"\n')
    out = subprocess.run([sys.executable, "-m", "ncvm", "run", "--state", str(tmp_path / ".ncvm"), "--machine",
                          "m.toml", "p.ngc"], capture_output=True, text=True, cwd=tmp_path, timeout=120)
    assert out.returncode == 2 and "din.profile" in out.stderr


def test_a_clean_din_run_compiles_neither_the_dialect_guess_nor_the_linuxcnc_patterns(tmp_path):
    """The content guess (dialects/din _DIN_LINE) and the LinuxCNC extensions' patterns (din/ngc.py) are
    compiled into re's cache when first used: a run of a named .ngc program without errors uses neither."""
    (tmp_path / "p.ngc").write_text("G1 X1 F100\nM2\n")
    probe = ("import re, runpy, sys\nsys.argv = ['ncvm', 'run', '--state', '.ncvm', 'p.ngc']\n"
             "try:\n    runpy.run_module('ncvm', run_name='__main__')\nexcept SystemExit:\n    pass\n"
             "from ncvm.dialects import din\nfrom ncvm.dialects.din import ngc\n"
             "lazy = {din._DIN_LINE, *(p for _what, p in ngc.FEATURES)}\n"
             "print('COMPILED', sorted(k[1] for k in re._cache if k[1] in lazy))\n")
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, cwd=tmp_path, timeout=120)
    assert "COMPILED []" in out.stdout, out.stdout + out.stderr


def test_a_run_of_a_short_program_reads_it_line_by_line_without_the_plain_line_pattern(tmp_path):
    """A program of fewer than COLUMNS_FROM lines is read line by line by a run too, as by a check
    (nc/block.py): the plain-line pattern (about 1.5 ms to compile, into re's cache at first use) is not
    compiled, and the run's result is the one of the same program read in columns."""
    (tmp_path / "p.ngc").write_text("G1 X10 Y5 F1000\nG1 X20\nG2 X30 Y15 I5 J5\nG0 Z5\nM2\n")
    runs = {}
    for how, columns_from in (("lines", None), ("columns", 0)):
        out = subprocess.run([sys.executable, "-c", READ_AS, how, "" if columns_from is None else str(columns_from)],
                             capture_output=True, text=True, cwd=tmp_path, timeout=120)
        doc, compiled = out.stdout.rsplit("PLAIN_LINE ", 1)
        runs[how] = json.loads(doc), compiled.strip()
    assert runs["lines"][1] == "False" and runs["columns"][1] == "True"
    doc = runs["lines"][0]
    assert doc["status"] == "ok" and doc["motion"]["feed_moves"] == 2 and doc["motion"]["arc_moves"] == 1
    assert doc["motion"] == runs["columns"][0]["motion"] and doc["position"] == runs["columns"][0]["position"]
    assert doc["cycle_time_s"] == runs["columns"][0]["cycle_time_s"]


#: a run of p.ngc with --json (state .ncvm-<argv 1>), every stretch read in columns when argv 2 says 0; then
#: whether the plain-line pattern was compiled
READ_AS = """\
import re, runpy, sys
how, columns_from = sys.argv[1:3]
if columns_from:
    from ncvm.dialects import din
    din.COLUMNS_FROM = int(columns_from)
sys.argv = ["ncvm", "run", "--json", "--state", ".ncvm-" + how, "p.ngc"]
try:
    runpy.run_module("ncvm", run_name="__main__")
except SystemExit:
    pass
from ncvm.nc import block
print("PLAIN_LINE", any(k[1] == block._PLAIN_LINE for k in re._cache))
"""


def test_the_command_freezes_what_loading_made_and_runs_under_the_collector(tmp_path):
    """ncvm.startup.main (the console script and ``python -m ncvm``) loads the CLI with the collector's first
    threshold raised, freezes what loading made and puts the thresholds back before the command runs."""
    (tmp_path / "p.ngc").write_text("M2\n")
    probe = ("import gc, sys\ndefaults = gc.get_threshold()\nimport ncvm.cli\n"
             "print('IMPORT', gc.get_freeze_count(), gc.get_threshold() == defaults)\n"
             "seen = []\nimport ncvm.runtime.session as s\n_init = s.Session.__init__\n"
             "def init(self, *a, **k):\n    seen.append((gc.get_threshold() == defaults, gc.get_freeze_count()))\n"
             "    _init(self, *a, **k)\ns.Session.__init__ = init\n"
             "from ncvm import startup\nsys.argv = ['ncvm', 'run', '--state', '.ncvm', 'p.ngc']\n"
             "try:\n    startup.main()\nexcept SystemExit as e:\n    print('EXIT', e.code)\n"
             "print('RUN', seen)\n")
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, cwd=tmp_path, timeout=120)
    lines = dict(ln.split(" ", 1) for ln in out.stdout.splitlines() if ln.startswith(("IMPORT", "EXIT", "RUN")))
    assert lines["IMPORT"] == "0 True", out.stdout + out.stderr  # importing the CLI (tests, the API) changes nothing
    assert lines["EXIT"] == "0"
    (restored, frozen), = ast.literal_eval(lines["RUN"])
    assert restored and frozen > 1000  # the run's collector: default thresholds; start-up's objects frozen


def test_python_m_ncvm_and_the_console_script_start_through_ncvm_startup():
    root = Path(__file__).resolve().parents[1]
    scripts = tomllib.loads((root / "pyproject.toml").read_text())["project"]["scripts"]
    assert scripts == {"ncvm": "ncvm.startup:main"}
    main_module = ast.parse((root / "src" / "ncvm" / "__main__.py").read_text())
    assert any(isinstance(n, ast.ImportFrom) and n.module == "startup" for n in main_module.body)


@pytest.mark.parametrize(("name", "text", "options"), [
    ("p.ngc", "G1 X10 F100\nM2\n", []),
    ("p.ngc", "G1 X10 F100\nM2\n", ["--json"]),
    ("p.ngc", "G90 G64 F2000\nG0 X5 Y5\nG1 X10\nG2 X20 Y5 I5 J0\nG1 Z-2\nM3 S500\nG1 X0\nM2\n", []),
    ("p.mpf", "%MPF1\nN10 G64 G1 G90 X10 F3000\nN20 X20 Y5\nN30 G2 X30 Y5 I5 J0\nM30\n", []),
    ("p.cpl", "N1 G71 G90 G17 F1000\nN10 G1 X10 Y5\nN20 G1 X20\nN30 G0 Z5\nM30\n", []),
    ("p.cpl", "10 A% = 0\n20 WHILE A% < 5 DO\nN30 G1 X[A%] Y[A% * 2] F1000\n40 A% = A% + 1\n50 END\nM30\n", []),
])
def test_a_run_with_a_few_moves_imports_no_numpy(tmp_path, name, text, options):
    """A few moves are planned (nc.planner) and settled (sinks.toolpath: totals, soft limits, work bounds) in
    plain Python: numpy's import would be most of such a run's start-up. A CPL program's block buffer runs a
    short run of plain blocks block by block (nc.block.columnar), so its few moves need no numpy either."""
    (tmp_path / name).write_text(text)
    code, modules = loaded(["run", "--state", str(tmp_path / ".ncvm"), *options, name], tmp_path)
    assert code == 0
    assert top(modules, HEAVY) - {"sqlite3"} == set()


def test_a_cpl_run_whose_waits_drain_a_few_blocks_imports_no_numpy(tmp_path):
    """A CPL drain of fewer than RUN_COLUMNS_FROM blocks (nc.block.columnar) (a WAIT after a few moves, the program end) runs them one by
    one through the kernel, not as numpy columns (dialects.cpl.runtime.execute_blocks)."""
    (tmp_path / "p.cpl").write_text("N1 G90 G1 X10 F1000\nN2 G2 X20 Y10 I10 J0\n10 WAIT\n20 P = MPOS(1)\n"
                                    "N3 G0 Z5\nM30\n")
    code, modules = loaded(["run", "--state", str(tmp_path / ".ncvm"), "p.cpl"], tmp_path)
    assert code == 0
    assert top(modules, HEAVY) - {"sqlite3"} == set()
