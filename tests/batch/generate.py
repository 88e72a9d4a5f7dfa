"""A generated archive of programs of all five dialects, as a shop's would be: the examples and the
regression programs copied, variants of them in nested folders under one machine file, CPL programs
without an extension, files that are not programs, and programs with injected errors."""

from __future__ import annotations

import re
import shutil
from dataclasses import dataclass, field
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
EXAMPLES = REPO / "examples"
REGRESSION = REPO / "tests" / "programs"

#: per dialect: a good program, how to break it (the line inserted), the error code it then stops with
INJECTIONS = {
    "din": ("din/face_and_circle.din", lambda t: _after_line(t, 1, "N1 G1 X1 ?"), "NC001"),
    "sin800": ("sin800/flange.mpf", lambda t: _after_line(t, 1, "N1 @999"), "SIN002"),
    "cl800": ("cl800/deep_hole.cl8", lambda t: t.replace("CHANNEL NC 0;", "CHANNEL NC 0;\n  R1 := ;"), "E061"),
    "sympas": ("sympas/contour.sap", lambda t: t.replace("\nbegin\n", "\nbegin\n  undeclaredvar := 1;\n"), "3"),
    "cpl": ("cpl/pocket.cpl", lambda t: "5 A% = 1 +\n" + t, "CPL001"),
}


@dataclass
class Archive:
    root: Path
    injected: dict[str, str] = field(default_factory=dict)  # relative path -> the error code expected
    limit_violations: list[str] = field(default_factory=list)
    not_programs: list[str] = field(default_factory=list)  # files without extension that are no program
    data_files: list[str] = field(default_factory=list)  # files in a machine's file root
    subprograms: list[str] = field(default_factory=list)  # sub-programs found by a call, not by main.txt
    plant_machine: str = ""
    plant_programs: list[str] = field(default_factory=list)  # programs below the plant's machine file


def _after_line(text: str, n: int, line: str) -> str:
    lines = text.split("\n")
    return "\n".join(lines[:n] + [line] + lines[n:])


def make_archive(root: Path) -> Archive:
    a = Archive(root)
    # not the files the examples write when they run (listed in the .gitignore of their file root)
    shutil.copytree(EXAMPLES, root / "examples", ignore=shutil.ignore_patterns("*.py", "machines", "PMEASLOG"))
    shutil.copytree(REGRESSION, root / "regression", ignore=shutil.ignore_patterns("*.expected.json"))
    _plant(a)
    _injected(a)
    return a


def _plant(a: Archive) -> None:
    """Variants in nested folders: one machine file for the whole plant, above the programs."""
    plant = a.root / "plant"
    plant.mkdir()
    shutil.copy(EXAMPLES / "cpl" / "machine.toml", plant / "machine.toml")
    a.plant_machine = str(plant / "machine.toml")
    din = (EXAMPLES / "din" / "face_and_circle.din").read_text()
    flange = (EXAMPLES / "cpl" / "flange.cpl").read_text()
    for k in range(6):
        line = plant / f"cell{k % 2}" / f"line{k}"
        line.mkdir(parents=True)
        # the same part at other feeds: other cycle times
        variant = re.sub(r"F(\d+)", lambda m, k=k: f"F{int(m.group(1)) * (k + 1)}", din)
        _write(a, line / f"face_{k}.din", variant)
        # a CPL program named as the control names them (no extension), its sub-program beside it
        holes = flange.replace("[0, 0, 40, 6,", f"[0, 0, {40 + k}, {4 + k},")
        header = f"1 REM FLANGE {k}, saved from the control\n2 REM holes per circle in the call\n3 K% = {k}\n"
        _write(a, line / f"FLANGE{k}", header + holes)
        shutil.copy(EXAMPLES / "cpl" / "BOLTCIRC", line / "BOLTCIRC")
        a.subprograms.append(str((line / "BOLTCIRC").relative_to(a.root)))
    sympas = (EXAMPLES / "sympas" / "contour.sap").read_text()
    for k in range(4):
        folder = plant / "robots" / f"r{k}"
        folder.mkdir(parents=True)
        _write(a, folder / f"contour_{k}.sap", sympas.replace("const r = 10.0;", f"const r = {10.0 + k};"))
    shutil.copy(EXAMPLES / "sympas" / "machine.toml", plant / "robots" / "machine.toml")


def _write(a: Archive, path: Path, text: str) -> None:
    path.write_text(text, encoding="latin-1")
    if path.is_relative_to(a.root / "plant") and "robots" not in path.parts:
        a.plant_programs.append(str(path.relative_to(a.root)))


def _injected(a: Archive) -> None:
    """Good programs broken on purpose (twice each, the second with CR LF line ends), one beyond the travel
    limits, and files without an extension that are no program."""
    for dialect, (source, inject, code) in INJECTIONS.items():
        src = EXAMPLES / source
        folder = a.root / "injected" / dialect
        folder.mkdir(parents=True)
        for side in src.parent.iterdir():  # the machine file and the sub-programs the program calls
            if side.name == "machine.toml" or side.suffix == ".spf":
                shutil.copy(side, folder / side.name)
        for k in range(2):
            name = f"{src.stem}_bad{k}{src.suffix}"
            text = inject(src.read_text(encoding="latin-1"))
            (folder / name).write_bytes((text if k == 0 else text.replace("\n", "\r\n")).encode("latin-1"))
            a.injected[f"injected/{dialect}/{name}"] = code
    folder = a.root / "injected"
    (a.root / "examples" / "cpl" / "files" / "PMEAS2").write_text("N10 G1 X10 F100\nN20 M30\n")  # data
    a.data_files.append("examples/cpl/files/PMEAS2")
    (folder / "travel.din").write_text("G0 X9000\nG0 X0\nM30\n")
    a.limit_violations.append("injected/travel.din")
    (folder / "README").write_text("Programs of the old milling cell, as saved from the control.\n")
    (folder / "DUMP").write_bytes(bytes(range(256)) * 4)
    (folder / "EMPTY").write_bytes(b"")
    # CPL as much as DIN to the detector: skipped with the reason, never run in the wrong language
    shutil.copy(EXAMPLES / "cpl" / "flange.cpl", folder / "OLDFLANGE")
    a.not_programs += ["injected/README", "injected/DUMP", "injected/EMPTY", "injected/OLDFLANGE"]
