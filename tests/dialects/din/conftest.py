"""Fixtures of the DIN reader's tests."""

from __future__ import annotations

import pytest

from ncvm.nc import block


@pytest.fixture
def reads(monkeypatch):
    """The text pieces runs and checks read from their program files (``nc.block.stretches``), in order: a file
    read twice gives its text twice."""
    pieces = []
    real = block.stretches

    def spy(file, chars):
        for piece in real(file, chars):
            pieces.append(piece)
            yield piece

    monkeypatch.setattr(block, "stretches", spy)
    return pieces
