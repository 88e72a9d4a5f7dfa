"""Reading arcs back from a translation: the full circles of its text, the sweep rs274 makes of it."""

from __future__ import annotations

import math
import re

from tests.review16c.helpers import code_lines, translate


def full_circles(text: str) -> list[str]:
    """The `G2`/`G3` lines (plane G17) whose X Y end point is the point they start from: full circles."""
    x = y = None
    full = []
    for line in code_lines(text):
        words = dict(re.findall(r"\b([XY])(-?[\d.]+)", line))
        nx, ny = float(words.get("X", x or 0)), float(words.get("Y", y or 0))
        if re.match(r"G[23]\b", line) and (nx, ny) == (x, y):
            full.append(line)
        if re.match(r"G[0-3]\b", line):
            x, y = nx, ny
    return full


def rs274_sweep(canon: str) -> float:
    """Degrees of arc that rs274's ARC_FEED calls (plane XY) turn in all."""
    position = None
    sweep = 0.0
    for line in canon.splitlines():
        m = re.search(r"(STRAIGHT_FEED|STRAIGHT_TRAVERSE|ARC_FEED)\(([^)]*)\)", line)
        if not m:
            continue
        v = [float(a) for a in m.group(2).split(",")]
        if m.group(1) == "ARC_FEED":
            ex, ey, cx, cy, rotation = v[:5]
            a0 = math.atan2(position[1] - cy, position[0] - cx)
            a1 = math.atan2(ey - cy, ex - cx)
            turn = (a1 - a0) % (2 * math.pi) if rotation > 0 else (a0 - a1) % (2 * math.pi)
            sweep += math.degrees(turn or 2 * math.pi) + 360 * (abs(rotation) - 1)
            position = (ex, ey)
        else:
            position = (v[0], v[1])
    return sweep


def machine(name: str, extra: str = "") -> str:
    """A machine file: three linear axes X Y Z from -500 to 500 mm, then ``extra`` (tools, offsets, sections)."""
    axes = "".join(f'[[axis]]\nname = "{a}"\nmin = -500.0\nmax = 500.0\n' for a in "XYZ")
    return f'[machine]\nname = "{name}"\n{axes}{extra}'


def translation(tmp_path, machine_text: str, program: str, name: str, target: str = "linuxcnc",
                *args: str) -> tuple[int, str, str]:
    """``ncvm translate`` of ``program`` (file ``name``) on ``machine_text`` to ``target`` (and ``args``):
    (exit code, the text written or "", stderr)."""
    (tmp_path / "machine.toml").write_text(machine_text)
    return translate(tmp_path, program, name, "--target", target, "-m", "machine.toml", *args,
                     out_name=f"out.{target}")


def translated(tmp_path, machine_text: str, program: str, name: str, target: str = "linuxcnc", *args: str) -> str:
    """The text ``ncvm translate`` writes for ``program`` (file ``name``) on ``machine_text`` to ``target``."""
    rc, out, err = translation(tmp_path, machine_text, program, name, target, *args)
    assert rc == 0, err
    return out
