"""The profiles by name (nc/profiles/named.py): each imported when first named (issue 18)."""

from __future__ import annotations

import subprocess
import sys

import pytest

from ncvm.machine.sections import SECTIONS
from ncvm.nc.profiles.named import WHERE, every_profile, profile


def test_each_name_gives_the_profile_of_that_name_and_the_machine_file_offers_them_all():
    assert [p.name for p in every_profile()] == list(WHERE)
    choices = next(f.type.choices for f in SECTIONS["din"].fields if f.name == "profile")
    assert set(choices) == set(WHERE)


def test_a_name_not_known_is_a_key_error():
    with pytest.raises(KeyError):
        profile("fanuc")


def test_a_din_run_imports_only_the_profile_it_reads_its_blocks_with(tmp_path):
    (tmp_path / "p.ngc").write_text("G1 X1 F100\nM2\n")
    probe = ("import runpy, sys\nsys.argv = ['ncvm', 'run', '--state', '.ncvm', 'p.ngc']\n"
             "try:\n    runpy.run_module('ncvm', run_name='__main__')\nexcept SystemExit:\n    pass\n"
             "print(sorted(m for m in sys.modules if m.startswith('ncvm.nc.profiles.')))\n")
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, cwd=tmp_path, timeout=120)
    loaded = out.stdout.splitlines()[-1]
    assert "ncvm.nc.profiles.iso" in loaded
    assert "typ3osa" not in loaded and "sinumerik8xx" not in loaded
