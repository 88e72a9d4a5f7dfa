"""A clone holds everything it refers to: no tracked file names a path outside the repository, and no file
the repository ignores (generated output, benchmark work files) is tracked."""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent

#: paths that lie outside a clone: the folder beside it, the author's machine, a home folder (the words are
#: put together here so that this file does not name them itself)
OUTSIDE = re.compile("|".join([
    r"\.\./" + "shared",
    "shared" + r"/(?:seeds|spec|bench|design)",
    r"\bspec/(?:cpl|cl800|sympas)\.md",
    r"(?<![\w.])/" + r"work/",
    r"(?<![\w.])/" + r"home/\w",
    r"(?<![\w.])/" + r"Users/\w",
    r"(?<![\w.])/" + r"root/",
    r"[A-Z]:\\" + r"Users\\",
]))


def _git(*args: str) -> list[str]:
    done = subprocess.run(["git", *args], cwd=ROOT, capture_output=True, text=True, check=True)
    return [line for line in done.stdout.split("\0" if "-z" in args else "\n") if line]


@pytest.fixture(scope="module")
def tracked() -> list[str]:
    if shutil.which("git") is None or not (ROOT / ".git").exists():
        pytest.skip("not a git checkout")
    return _git("ls-files", "-z")


def test_no_tracked_file_names_a_path_outside_the_repository(tracked):
    found = []
    for name in tracked:
        path = ROOT / name
        if not path.is_file():  # deleted in the work tree, not yet committed
            continue
        try:
            text = path.read_text(encoding="utf-8")
        except UnicodeDecodeError:  # pictures, binary test inputs
            continue
        for number, line in enumerate(text.splitlines(), 1):
            if OUTSIDE.search(line):
                found.append(f"{name}:{number}: {line.strip()[:100]}")
    assert not found, "tracked files name paths outside the repository:\n" + "\n".join(found)


def test_no_ignored_file_is_tracked(tracked):
    """Generated files (bench/.work/, out/, build/ ...) are made on demand, never committed."""
    ignored = _git("ls-files", "-z", "--cached", "--ignored", "--exclude-standard")
    assert not ignored, "tracked files that .gitignore excludes: " + ", ".join(ignored)


def test_the_pattern_finds_what_it_is_for():
    """The check itself: each kind of outside path is found, ordinary text is not."""
    outside = ["see ../" + "shared" + "/bench/peers", "`" + "shared" + "/seeds/cpl.txt`", "mapped by spec/" + "cl800.md",
               "/" + "work/wt/x", "/" + "home/user/ncvm", "C:\\" + "Users\\me"]
    inside = ["bench/peers/loop_arith.ngc", "the shared NC kernel", "/usr/bin/rs274", "docs/cpl.md",
              "machine/work/areas", "a workpiece"]
    assert all(OUTSIDE.search(s) for s in outside)
    assert not any(OUTSIDE.search(s) for s in inside)
