"""Review of issue 19 (a newcomer's project) from a fresh clone: the defects found, one failing test each.

Each test names the issue item it holds the project to; it fails on main as reviewed.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"


def ncvm(*args: str, cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "ncvm", *args], cwd=cwd, capture_output=True, text=True, timeout=120)


def tracked_files() -> list[Path]:
    out = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True, check=True).stdout
    return [ROOT / line for line in out.splitlines() if line and not line.startswith("tests/")]


# --- item 1: self-contained ---------------------------------------------------------------------------------

# "digest §5.3" cites the project's private digests of the manuals (not in the repository); "the seeds" /
# "the seed manual" is the project's private name for its copy of the manuals. A newcomer has neither.
PRIVATE_CITATION = re.compile(r"\bdigests?\s*§|\bdigest \d|\bthe seeds\b|\bseed manual", re.IGNORECASE)
TEXT_SUFFIXES = {".py", ".md", ".toml", ".txt", ".cpl", ".cl8", ".sap", ".dat"}


def test_item1_docs_and_code_cite_no_private_digest_or_seeds():
    """Issue 19 item 1: "cite the manuals by title, edition and section/line ... let no file name a path
    outside the repository". About 200 places cited "digest §N" and some "the seeds", which are documents
    outside the repository. Comments in tests and test programs count too; only this file names them."""
    out = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True, check=True).stdout
    hits = []
    for rel in out.splitlines():
        path = ROOT / rel
        if path.suffix not in TEXT_SUFFIXES or path == Path(__file__).resolve() or not path.is_file():
            continue
        for number, line in enumerate(path.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
            if PRIVATE_CITATION.search(line):
                hits.append(f"{rel}:{number}: {line.strip()[:90]}")
    assert not hits, f"{len(hits)} citations of documents outside the repository, e.g.:\n" + "\n".join(hits[:15])


@pytest.mark.parametrize(
    ("name", "dialect", "text"),
    [("g5.cpl", "cpl", "N10 G5 X10\nN20 M30\n"), ("g5.din", "sin800", "N10 G5 X10 Y5\nN20 M30\n")],
)
def test_item1_user_messages_do_not_speak_of_seeds(tmp_path, name, dialect, text):
    """Issue 19 item 1: a user's `ncvm check` warning says "not among the seeds" / "the seed manual does
    not describe": the user does not know what the seeds are; name the manual by its title."""
    (tmp_path / name).write_text(text)
    result = ncvm("check", "--dialect", dialect, name, cwd=tmp_path)
    assert "NC004" in result.stdout + result.stderr
    assert not re.search(r"\bthe seeds\b|\bseed manual", result.stdout + result.stderr, re.IGNORECASE), (
        result.stdout + result.stderr
    )


# --- item 2: plots / summary line ---------------------------------------------------------------------------


@pytest.mark.parametrize("program", ["sympas/pick_place.sap", "cpl/pocket.cpl"])
def test_item2_summary_line_is_short(tmp_path, program):
    """Issue 19 item 2: "the summary line is 200 characters". It still is (rw_SymPas pick_place: 271)."""
    shutil.copytree(EXAMPLES, tmp_path / "examples")
    result = ncvm("run", f"examples/{program}", "--state", str(tmp_path / "state"), cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    summary = [line for line in result.stderr.splitlines() if line.startswith("ncvm: ended")]
    assert summary, result.stderr
    assert all(len(line) <= 160 for line in summary), [len(line) for line in summary]


# --- item 4: commands that protect the user's files ---------------------------------------------------------


def test_item4_compile_xref_keeps_a_hand_written_listing(tmp_path):
    """Issue 19 item 4: "refuse to overwrite a file that ncvm did not write ... unless --force". The
    listing that `compile --xref` writes beside the source by default overwrites a hand-written
    `hole_pattern.lst` silently (exit 0), although the object program of that name is protected."""
    shutil.copy(EXAMPLES / "cl800" / "hole_pattern.cl8", tmp_path)
    listing = tmp_path / "hole_pattern.lst"
    listing.write_text("my own notes on the hole pattern\n")
    result = ncvm("compile", "hole_pattern.cl8", "--xref", "-o", "out.spf", cwd=tmp_path)
    assert listing.read_text() == "my own notes on the hole pattern\n", "hand-written listing overwritten"
    assert result.returncode == 2, (result.returncode, result.stderr)


def test_item4_compile_keeps_a_hand_written_object_program_without_force(tmp_path):
    """Issue 19 item 4 (checked right): a hand-written L101.spf is kept without --force, replaced with it."""
    shutil.copy(EXAMPLES / "cl800" / "hole_pattern.cl8", tmp_path)
    target = tmp_path / "L101.spf"
    target.write_text("%SPF101\nN10 G0 X1 (hand)\nM17\n")
    refused = ncvm("compile", "hole_pattern.cl8", cwd=tmp_path)
    assert refused.returncode == 2 and "L101.spf" in refused.stderr
    assert "(hand)" in target.read_text()
    forced = ncvm("compile", "hole_pattern.cl8", "--force", cwd=tmp_path)
    assert forced.returncode == 0, forced.stderr
    assert target.read_text().rstrip().endswith("(COMPILED BY NCVM)")


# --- item 3: README -------------------------------------------------------------------------------------------


def test_item3_readme_usage_output_is_what_ncvm_prints(tmp_path):
    """Issue 19 item 3 (README for a newcomer): the README's first example shows the summary line a user
    will compare with their own; it says `cycle time 0:50.024, bounds` but ncvm prints
    `cycle time 0:49.896 (look-ahead), bounds` (the README was not updated with the look-ahead planner)."""
    readme = (ROOT / "README.md").read_text()
    quoted = re.search(
        r"\$ \.venv/bin/ncvm run examples/din/face_and_circle\.din.*?\n(.*?)\n(ncvm: ended[^\n]*)", readme
    )
    assert quoted, "README no longer shows the face_and_circle run"
    shutil.copytree(EXAMPLES, tmp_path / "examples")
    result = ncvm("run", "examples/din/face_and_circle.din", "--state", str(tmp_path / "state"), cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert quoted.group(1) in result.stdout
    assert quoted.group(2) in result.stderr.splitlines(), (quoted.group(2), result.stderr)


def test_item4_compile_keeps_an_object_program_edited_by_hand_after_ncvm_wrote_it(tmp_path):
    """Issue 19 item 4: "`ncvm compile L101.cl8` without `-o` silently overwrites a hand-edited `L101.spf`".
    The common case is an object program ncvm wrote and the user then edited at the machine (a feed, a
    dwell): its `(COMPILED BY NCVM)` line is still there, so the next compile replaces the edit silently.
    The mark must show that the file is as ncvm wrote it (e.g. a checksum of the text in the mark)."""
    shutil.copy(EXAMPLES / "cl800" / "hole_pattern.cl8", tmp_path)
    first = ncvm("compile", "hole_pattern.cl8", cwd=tmp_path)
    assert first.returncode == 0, first.stderr
    target = tmp_path / "L101.spf"
    lines = target.read_text().splitlines()
    lines.insert(1, "N1 G4 X2 (dwell added by hand at the machine)")
    target.write_text("\n".join(lines) + "\n")
    again = ncvm("compile", "hole_pattern.cl8", cwd=tmp_path)
    assert "added by hand" in target.read_text(), "the hand edit was overwritten silently"
    assert again.returncode == 2, (again.returncode, again.stderr)
