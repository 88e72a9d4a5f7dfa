"""Mutated programs: whatever a user's file holds, ncvm answers with diagnostics or a fault, never a traceback.

Each program of tests/programs and examples is changed at random (characters deleted,
inserted or replaced by tokens of the languages, lines swapped) with a fixed
seed, then checked and run with a small step limit. Any exception other than
the compile-error signal fails the test and names the mutated text.
"""

from __future__ import annotations

import random
import shutil
from pathlib import Path

import pytest

from ncvm.api import check, run
from ncvm.diagnostics import CompileFailed
from ncvm.runtime.session import RunOptions

TESTS = Path(__file__).parent.parent
ROOTS = [TESTS / "programs", TESTS.parent / "examples"]
SUFFIXES = {".din", ".ngc", ".cpl", ".cl8", ".mpf", ".spf", ".sap"}
TOKENS = ["(", ")", "[", "]", ":", ";", "=", "'", '"', "@", "#", "%", "$", "!", "?", ".", ",", "-", "+", "*", "/",
          "0", "9", "1e99", "X", "G", "M", "N", "R", "END", "IF", "THEN", "BEGIN", "\n", " ", "999999999999", "P1",
          "CALL", "GOTO", "WHILE", "DO", "FOR", "TO", "NEXT", "_",
          # issue 12: Latin-1 letters and superscript digits, a byte-order mark, numbers beyond every range
          # (400 and 4400 digits), deep nesting
          "é", "ß", "¹", "²", "\xa0", "\x00", "\xef\xbb\xbf", "1" * 400, "9" * 4400, "(" * 300, "-" * 300,
          "IF R1=1 THEN\n" * 100, "begin\n" * 100, "WHILE A<1 DO\n" * 30]
PER_DIALECT = 60


def _mutate(rnd: random.Random, text: str) -> str:
    chars = list(text)
    for _ in range(rnd.randint(1, 4)):
        if not chars:
            break
        i = rnd.randrange(len(chars))
        op = rnd.random()
        if op < 0.3:
            del chars[i:i + rnd.randint(1, 5)]
        elif op < 0.7:
            chars[i:i] = list(rnd.choice(TOKENS))
        elif op < 0.85:
            chars[i] = rnd.choice(TOKENS)
        else:
            lines = "".join(chars).split("\n")
            a, b = rnd.randrange(len(lines)), rnd.randrange(len(lines))
            lines[a], lines[b] = lines[b], lines[a]
            chars = list("\n".join(lines))
    return "".join(chars)


def _sources(folder: str) -> list[Path]:
    return sorted(p for root in ROOTS for p in (root / folder).rglob("*") if p.suffix.lower() in SUFFIXES)


@pytest.mark.parametrize("folder", ["din", "cpl", "cl800", "sin800", "sympas"])
def test_mutated_programs_never_raise(tmp_path, folder):
    rnd = random.Random(f"ncvm-{folder}")
    sources = _sources(folder)
    assert sources
    copies: dict[Path, Path] = {}
    for n in range(PER_DIALECT):
        src = rnd.choice(sources)
        text = _mutate(rnd, src.read_text(encoding="latin-1"))
        if src.parent not in copies:  # the program's folder: its sub-programs, machine file, files
            copies[src.parent] = tmp_path / f"w{len(copies)}"
            shutil.copytree(src.parent, copies[src.parent], ignore=shutil.ignore_patterns("*.expected.json"))
        path = copies[src.parent] / src.name
        path.write_text(text, encoding="latin-1")
        try:
            check(path)
            run(path, options=RunOptions(state_dir=tmp_path / f".n{n}", max_steps=20_000))
        except CompileFailed:
            pass
        except Exception as e:  # noqa: BLE001 - the point of the test
            pytest.fail(f"{src.name} mutated to:\n{text}\nraised {type(e).__name__}: {e}")
        finally:
            shutil.copy(src, path)
