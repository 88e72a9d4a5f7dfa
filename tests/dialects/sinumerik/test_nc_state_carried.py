"""Offsets the NC keeps from one program to the next are never applied silently (issue 15; the NC keeps
its zero offset memory, ZOA/ZOPR L3184-3214, and its rotation angles, ZOADW/ZOPRDW L3260-3302; ncvm
keeps them in the state directory, docs/sin800.md "The NC state")."""

from __future__ import annotations

from sin800_helpers import machine, run_mpf


def _notes(result: dict) -> list[str]:
    return [line for line in result["output"] if line.startswith("NC state:")]


def test_offsets_and_angles_written_by_one_program_are_named_in_the_next(tmp_path):
    # ZOA(1,2,0) = 5: G54 coarse in Y; ZOPRDW(0,2,1) = 15: the G59 rotation angle of its own channel
    run_mpf(tmp_path, "%MPF1\n@430 K1 K2 K0 K5 @439 K0 K2 K1 K15 @432 K2 K1 K-2.5\nM30\n", ok=True)
    later = run_mpf(tmp_path, "%MPF2\nG0 X1\nM30\n", ok=True)
    notes = _notes(later)
    assert any(n.startswith("NC state: G54 coarse Y5 kept from an earlier run") for n in notes), notes
    assert any(n.startswith("NC state: G59 X-2.5 kept") for n in notes), notes
    assert any(n.startswith("NC state: programmable rotation 2 15 deg kept") for n in notes), notes


def test_offsets_of_the_machine_file_are_no_news(tmp_path):
    extra = "[sin800.zero_offsets]\nG58 = [10.0, 0.0, 0.0]\n"
    run_mpf(tmp_path, "%MPF1\nG0 X1\nM30\n", machine_text=machine(extra=extra), ok=True)
    again = run_mpf(tmp_path, "%MPF2\nG0 X1\nM30\n", machine_text=machine(extra=extra), ok=True)
    assert _notes(again) == []
