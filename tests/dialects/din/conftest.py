"""Fixtures of the DIN dialect's tests."""

from __future__ import annotations

import sys

import pytest

from ncvm import dialects, source
from ncvm.nc import block


@pytest.fixture
def refuse_whole_reads(monkeypatch):
    """refuse(replacement): every ncvm module's ``read_text`` (ncvm.source's read of a whole program file)
    replaced by ``replacement`` for this test.

    Every dialect is imported first: a module first imported while the patch is in place binds the
    replacement through ``from ...source import read_text`` and keeps it after the test (cpl.unlinked did,
    so a later "(DIN)" CPL run in the same process ended in an internal error)."""

    def refuse(replacement) -> None:
        dialects.available()
        real = source.read_text
        for name, module in list(sys.modules.items()):
            if name.split(".")[0] == "ncvm" and getattr(module, "read_text", None) is real:
                monkeypatch.setattr(module, "read_text", replacement)

    return refuse



@pytest.fixture
def reads(monkeypatch):
    """The text pieces runs and checks read from their program files (``nc.block.stretches``), in order: a file
    read twice gives its text twice."""
    pieces = []
    real = block.stretches

    def spy(file, chars, at=None):
        for piece in real(file, chars, at):
            pieces.append(piece)
            yield piece

    monkeypatch.setattr(block, "stretches", spy)
    return pieces
