"""Coordinate rotation and the angle address (PANG, @447), applied when a block executes.

Both act in the active plane, in the program's units, when a block executes
(rotation angles written by @437-@43a act at once even on blocks already
decoded, manual L4325-4334). The rotation turns the programmed plane
coordinates about the workpiece zero by the settable angle of the selected
zero offset (G54-G57 = group 1-4) plus the programmable angles of G58 and G59,
counter-clockwise from the plane's first axis; arc centres turn with them. It is
the kernel's coordinate transform (:func:`rotation_transform`, set before each
block), shown applied: positions a program reads are in the turned frame.
The angle address completes a straight line: with one plane axis programmed,
the other follows from the start point and the angle (docs/decisions.md, sin800).
MEAS M and INTA work on the block's words turned by hand (:func:`machine_frame`).
"""

from __future__ import annotations

import math

from ...nc.block import Block
from ...nc.kernel import PLANES
from ...nc.transform import Affine, AffineTransform
from .errors import Cl800Error

_CENTRE = {"X": "I", "Y": "J", "Z": "K"}
#: MD byte 5001 names the angle address; the manual gives only 11 = A (L2325-2326, L3060)
ANGLE_ADDRESSES = {0: "A", 11: "A"}


def angle_address(channel) -> str:
    """The address letter of the programmed angle, from NC MD byte 5001."""
    code = channel.data.areas["nc_md"].get("5001", 0.0)
    name = ANGLE_ADDRESSES.get(int(code)) if code == int(code) else None
    if name is None:
        raise Cl800Error(f"NC MD byte 5001 = {code:g} names no known angle address (11 = A)")
    return name


def rotation_active(channel) -> bool:
    """A settable or programmable coordinate rotation is selected (some angle is not 0)."""
    return any(a != 0.0 for a in channel.data.rot.values())


def block_frame(channel, block: Block) -> tuple[str, str, bool, float]:
    """(first plane axis, second plane axis, absolute?, rotation angle in degrees) for this block."""
    k = channel.kernel
    g = block.g
    plane = next((x for x in g if x in (17, 18, 19)), None)
    if plane is not None:
        h, v = PLANES[plane][:2]
    else:
        h, v = channel.positions.plane_axes()
    absolute = k.absolute
    if 90 in g:
        absolute = True
    elif 91 in g:
        absolute = False
    if 53 in g:
        return h, v, absolute, 0.0
    rot = channel.data.rot
    group = next((int(x) - 53 for x in g if x in (54, 55, 56, 57)), None)
    if group is None and k.work_offset in ("G54", "G55", "G56", "G57"):
        group = int(k.work_offset[1:]) - 53
    angle = rot.get(f"settable:{group}", 0.0) if group else 0.0
    angle += rot.get("programmable:1", 0.0) + rot.get("programmable:2", 0.0)
    return h, v, absolute, angle


def _turn(a: float, b: float, deg: float) -> tuple[float, float]:
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return a * c - b * s, a * s + b * c


def rotate_for(channel, block: Block) -> None:
    """Set the kernel's transform to the coordinate rotation ``block`` executes under (none at 0 degrees)."""
    k = channel.kernel
    h, v, _absolute, theta = block_frame(channel, block)
    key = (h, v, theta) if theta != 0.0 else None
    if key != channel.rotation_key:
        if key is not None and (h not in k.axis_of or v not in k.axis_of):
            raise Cl800Error(f"the plane needs the axes {h} and {v}")
        k.set_transform(None if key is None else rotation_transform(k, *key))
        channel.rotation_key = key


def rotation_transform(k, h: str, v: str, theta: float) -> AffineTransform:
    """The kernel transform turning plane (h, v) by ``theta`` degrees about the workpiece zero, shown applied."""
    return AffineTransform(Affine.rotation(k.n_axes, k.axis_of[h], k.axis_of[v], theta), shown=True)


def shape_block(channel, block: Block, angle_key: str | None, turn: bool = True) -> Block:
    """The block with the angle word resolved, and the rotation applied to its words when ``turn`` (MEAS M and
    INTA; blocks the kernel executes are turned by its transform, see :func:`rotate_for`)."""
    words = block.words
    k = channel.kernel
    h, v, absolute, theta = block_frame(channel, block)
    turned = theta if turn else 0.0
    if turned == 0.0 and angle_key not in words:
        return block
    words = dict(words)
    if h not in k.axis_of or v not in k.axis_of:
        raise Cl800Error(f"the plane needs the axes {h} and {v}")
    ch, cv = program_point(channel, h, v, theta)
    if angle_key in words:
        _resolve_angle(words, words.pop(angle_key), h, v, absolute, ch, cv)
    if not turn:
        return Block(block.g, block.m, words, block.n, block.msg, block.src)
    if theta != 0.0 and (h in words or v in words):
        if absolute:
            words[h], words[v] = _turn(words.get(h, ch), words.get(v, cv), theta)
        else:
            words[h], words[v] = _turn(words.get(h, 0.0), words.get(v, 0.0), theta)
    ih, iv = _CENTRE.get(h), _CENTRE.get(v)
    if theta != 0.0 and ih and iv and (ih in words or iv in words):
        words[ih], words[iv] = _turn(words.get(ih, 0.0), words.get(iv, 0.0), theta)
    return Block(block.g, block.m, words, block.n, block.msg, block.src)


def machine_frame(channel, g, words: dict) -> tuple[dict, tuple[str, str, float]]:
    """The block's words as the kernel will get them (angle resolved, turned into the frame of the
    machine axes), and the frame (first, second plane axis, angle) that turns results back.

    MEAS M and INTA cut a block's path where something happens on the machine; they work on these
    words and hand the cut point back in the program's frame with :func:`program_frame`."""
    blk = Block(tuple(g), (), words, None, None, None)
    h, v, _absolute, theta = block_frame(channel, blk)
    key = angle_address(channel) if channel.angle_used else None
    return shape_block(channel, blk, key).words, (h, v, theta)


def program_frame(words: dict, frame: tuple[str, str, float]) -> dict:
    """Plane coordinates (or G91 increments) and arc centre vectors of the machine-axis frame turned
    back into the program's frame; both plane axes must be in ``words`` when one is (shape_block
    always writes both)."""
    h, v, theta = frame
    if theta == 0.0:
        return words
    out = dict(words)
    if h in words or v in words:
        out[h], out[v] = _turn(words[h], words[v], -theta)
    ih, iv = _CENTRE.get(h), _CENTRE.get(v)
    if ih and iv and (ih in words or iv in words):
        out[ih], out[iv] = _turn(words.get(ih, 0.0), words.get(iv, 0.0), -theta)
    return out


def program_point(channel, h: str, v: str, theta: float) -> tuple[float, float]:
    """The current point of the plane (h, v) in the program's frame, in program units."""
    pos = channel.kernel.workpiece_position()
    return _turn(pos[h], pos[v], -theta)


def _resolve_angle(words: dict, alpha: float, h: str, v: str, absolute: bool, ch: float, cv: float) -> None:
    """A straight line at angle alpha (degrees from the first plane axis) through the start point."""
    if (h in words) == (v in words):
        raise Cl800Error(f"the angle address needs exactly one of the axes {h}, {v} in its block")
    c, s = math.cos(math.radians(alpha)), math.sin(math.radians(alpha))
    if h in words:
        if abs(c) < 1e-12:
            raise Cl800Error(f"angle {alpha:g} is parallel to {v}: program {v}, not {h}")
        d = words[h] - ch if absolute else words[h]
        words[v] = (cv if absolute else 0.0) + d * s / c
    else:
        if abs(s) < 1e-12:
            raise Cl800Error(f"angle {alpha:g} is parallel to {h}: program {h}, not {v}")
        d = words[v] - cv if absolute else words[v]
        words[h] = (ch if absolute else 0.0) + d * c / s
