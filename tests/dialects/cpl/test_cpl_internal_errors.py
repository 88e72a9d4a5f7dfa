"""A Python error inside ncvm's own output (the translation writer, the sinks) is ncvm's fault: it must never be
reported as the program's RUNTIME ERROR (a TypeError there used to read "CPL020: VARIABLE NOT ASSIGNED")."""

from __future__ import annotations

import pytest

from ncvm.translate import translate
from ncvm.translate.output import TranslationRefused
from ncvm.translate.writer import Translation

PROGRAM = "N10 G1 X10 Y0 F1000\nN20 G1 X20\nN30 M30\n"


def test_a_type_error_in_the_translation_writer_is_not_cpl020(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # the state folder of the run
    monkeypatch.setattr(Translation, "_straight", None)  # the writer's own code then fails with a TypeError
    (tmp_path / "p.cpl").write_text(PROGRAM)
    with pytest.raises(TypeError, match="not callable"):
        translate(tmp_path / "p.cpl", tmp_path / "p.ngc")


def test_a_nul_in_the_program_is_still_cpl020(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "p.cpl").write_text("10 A%=Q%+1\nM30\n")
    with pytest.raises(TranslationRefused, match="CPL020: VARIABLE NOT ASSIGNED"):
        translate(tmp_path / "p.cpl", tmp_path / "p.ngc")
