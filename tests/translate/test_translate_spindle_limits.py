"""G96 constant cutting speed in a translation (issue 16, rule 4: "feed and spindle words as programmed";
docs/translate.md): the S words are the speeds the spindle turned in the run. Where no spindle speed limit
bounded them (DIN G96 without D, rs274's maximum spindle speed) the translation is refused at the block: the
old machine's maximum held the spindle, and no machine file says what it was. Where a limit held the spindle
(DIN G96 D, SINUMERIK G92 S or the gear stage's maximum in ``[sin800] gears``), the S word is the limit, with
a comment that says so and what the cutting speed asked for."""

from __future__ import annotations

import re

import pytest

from tests.review16c.helpers import code_lines, translate

LATHE = '[machine]\nname = "lathe"\n[[axis]]\nname = "X"\n[[axis]]\nname = "Z"\n[[tool]]\nnumber = 1\n'
# facing from X50 to X10 at 200 m/min: 636.6 rev/min at the start, 3183.1 at X10 (radius, DIN 66025)
DIN = "G21 G90 G94 G54 G18\nT1 M6\nG0 X50 Z5\n{g96} S200 M3\nG1 X10 Z0 F100\nG0 X50\nM30\n"
SIN = ("%MPF8\nN10 G18 G71 G90 G54 G94\nN20 G0 X50 Z5\nN30 {limit}\nN40 G96 S200 M3\nN50 G1 Z0 F0.2\n"
       "N60 G1 X10\nN70 G0 X50\nN80 M30\n")


def _speeds(text):
    return [float(s) for line in code_lines(text) for s in re.findall(r"\bS(\d+(?:\.\d*)?)", line)]


def _machine(tmp_path, extra=""):
    (tmp_path / "lathe.toml").write_text(LATHE + extra)
    return ("-m", "lathe.toml")


@pytest.mark.parametrize("target", ["linuxcnc", "sinumerik840d", "iso"])
def test_din_g96_without_d_is_refused_at_its_block(tmp_path, target):
    rc, out, err = translate(tmp_path, DIN.format(g96="G96"), "css.din", "--target", target, *_machine(tmp_path))
    assert rc == 1 and out == "", err
    assert "css.din:4: error TRN001" in err and "G96 constant cutting speed with no spindle speed limit" in err
    assert "G96 D<max>" in err and "G96 S200 M3" in err, err


@pytest.mark.parametrize("target", ["linuxcnc", "sinumerik840d", "iso"])
def test_din_g96_d_limit_is_written_and_marked(tmp_path, target):
    rc, out, err = translate(tmp_path, DIN.format(g96="G96 D2000"), "css.din", "--target", target,
                             *_machine(tmp_path), out_name=f"out.{target}")
    assert rc == 0, err
    assert max(_speeds(out)) == 2000.0, out
    assert re.search(r"S2000: the spindle speed limit of the simulated control .* asked for S3183\.0989", out), out


@pytest.mark.parametrize(("limit", "extra"), [("M41", "[sin800]\ngears = [1000.0, 3000.0]\n"),
                                              ("G92 S1000", "")])
def test_sinumerik_gear_or_g92_cap_is_the_written_speed_and_marked(tmp_path, limit, extra):
    rc, out, err = translate(tmp_path, SIN.format(limit=limit), "gear.mpf", *_machine(tmp_path, extra))
    assert rc == 0, err
    lines = code_lines(out)
    assert max(_speeds(out)) == 1000.0 and "M3 S1000" in lines, out
    marked = [line for line in out.splitlines() if line.startswith("(S1000: the spindle speed limit")]
    assert len(marked) == 1 and "asked for S3183.0989" in marked[0], out


def test_sinumerik_g96_with_no_limit_is_refused(tmp_path):
    rc, out, err = translate(tmp_path, SIN.format(limit="G94"), "gear.mpf", *_machine(tmp_path))
    assert rc == 1 and "TRN001" in err and "no spindle speed limit" in err and "G92 S<max>" in err, err
