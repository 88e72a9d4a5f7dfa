"""``ncvm compile`` without -o names the object after its program number (``L101.spf`` beside the source); a
file of that name that ncvm did not write -- a hand-written or hand-edited program -- is kept unless --force
(issue 19). Files ncvm writes end with the mark line ``(CRC32 <checksum>) (COMPILED BY NCVM)``, after M17, a "(Text)" note of
the NC program (L6401)."""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

EXAMPLE = Path(__file__).parents[4] / "examples" / "cl800" / "hole_pattern.cl8"  # PROGRAM 101
HAND_WRITTEN = "%SPF101\n(HOLE PATTERN, CORRECTED BY HAND AT THE MACHINE)\nG90 G00 X10 Y10\nG01 F200 L=R20 P1\nM17\n"


def ncvm(cwd: Path, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", "from ncvm.cli import main; main()", *args], cwd=cwd, capture_output=True, text=True,
                          timeout=120)


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    shutil.copy(EXAMPLE, tmp_path / "hole_pattern.cl8")
    return tmp_path


def test_a_hand_written_object_file_is_kept(folder: Path):
    (folder / "L101.spf").write_text(HAND_WRITTEN, encoding="latin-1")
    r = ncvm(folder, "compile", "hole_pattern.cl8")
    assert r.returncode == 2, r.stderr
    assert ("ncvm: error: compile L101.spf: the file exists and ncvm did not write it (no (COMPILED BY NCVM) line at its end, "
            "or the file was changed since ncvm wrote it); "
            "give another name with -o, or --force to overwrite it") in r.stderr
    assert (folder / "L101.spf").read_text(encoding="latin-1") == HAND_WRITTEN
    assert "Traceback" not in r.stderr


def test_force_overwrites_it_and_the_file_written_carries_the_mark(folder: Path):
    (folder / "L101.spf").write_text(HAND_WRITTEN, encoding="latin-1")
    r = ncvm(folder, "compile", "hole_pattern.cl8", "--force")
    assert r.returncode == 0, r.stderr
    lines = (folder / "L101.spf").read_text(encoding="latin-1").splitlines()
    assert lines[0] == "%SPF101" and lines[-2].endswith("M17")
    assert re.fullmatch(r"\(CRC32 [0-9A-F]{8}\) \(COMPILED BY NCVM\)", lines[-1])


def test_a_file_ncvm_wrote_is_replaced_by_the_next_compile(folder: Path):
    assert ncvm(folder, "compile", "hole_pattern.cl8").returncode == 0
    first = (folder / "L101.spf").read_text(encoding="latin-1")
    src = (folder / "hole_pattern.cl8").read_text(encoding="latin-1")
    (folder / "hole_pattern.cl8").write_text(src.replace("F200", "F250"), encoding="latin-1")
    r = ncvm(folder, "compile", "hole_pattern.cl8")
    assert r.returncode == 0, r.stderr
    second = (folder / "L101.spf").read_text(encoding="latin-1")
    assert "F250" in second and second != first


def test_a_hand_edited_compiled_file_whose_mark_was_removed_is_kept(folder: Path):
    assert ncvm(folder, "compile", "hole_pattern.cl8").returncode == 0
    edited = (folder / "L101.spf").read_text(encoding="latin-1").replace(" (COMPILED BY NCVM)\n", "\n")
    (folder / "L101.spf").write_text(edited, encoding="latin-1")
    assert ncvm(folder, "compile", "hole_pattern.cl8").returncode == 2
    assert (folder / "L101.spf").read_text(encoding="latin-1") == edited


def test_an_explicit_o_names_the_file_to_write(folder: Path):
    """-o is the user's own choice of file: written as asked."""
    (folder / "mine.spf").write_text(HAND_WRITTEN, encoding="latin-1")
    assert ncvm(folder, "compile", "hole_pattern.cl8", "-o", "mine.spf").returncode == 0
    text = (folder / "mine.spf").read_text(encoding="latin-1")
    assert text.startswith("%SPF101\n") and re.search(r"M17\n\(CRC32 [0-9A-F]{8}\) \(COMPILED BY NCVM\)\n\Z", text)


def test_the_marked_object_file_runs_as_the_source_does(folder: Path):
    """The note is an ordinary NC note: the written object runs on the sin800 NC."""
    assert ncvm(folder, "compile", "hole_pattern.cl8").returncode == 0
    r = ncvm(folder, "check", "L101.spf")
    assert r.returncode == 0, r.stdout + r.stderr


def test_a_listing_ncvm_wrote_is_replaced_and_a_hand_written_one_only_with_force(folder: Path):
    """`--xref` alone names the listing itself (the source's name, .lst): it carries the mark line as well."""
    assert ncvm(folder, "compile", "hole_pattern.cl8", "--xref").returncode == 0
    assert ncvm(folder, "compile", "hole_pattern.cl8", "--xref").returncode == 0  # ncvm's own: replaced
    listing = folder / "hole_pattern.lst"
    listing.write_text(listing.read_text(encoding="latin-1").replace("%SPF101", "%SPF101 (NOTE)"), encoding="latin-1")
    kept = ncvm(folder, "compile", "hole_pattern.cl8", "--xref")
    assert kept.returncode == 2 and "hole_pattern.lst" in kept.stderr and "(NOTE)" in listing.read_text()
    assert ncvm(folder, "compile", "hole_pattern.cl8", "--xref", "--force").returncode == 0
    assert "(NOTE)" not in listing.read_text()


def test_a_hand_written_listing_is_kept_and_the_refusal_names_the_listing_option(folder: Path):
    """The listing's name comes from ``--xref LISTING``, not from -o: the refusal says which option names it."""
    (folder / "hole_pattern.lst").write_text("MY NOTES\n", encoding="latin-1")
    r = ncvm(folder, "compile", "hole_pattern.cl8", "--xref")
    assert r.returncode == 2, r.stderr
    assert "compile hole_pattern.lst: the file exists and ncvm did not write it" in r.stderr
    assert "give another name with --xref LISTING, or --force" in r.stderr
    assert (folder / "hole_pattern.lst").read_text(encoding="latin-1") == "MY NOTES\n"
