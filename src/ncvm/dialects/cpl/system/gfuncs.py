"""Typ3 osa G functions that the shared NC kernel does not know, kept by the CPL controller so that
SD/SDR groups 68, 168, 268, 131, 328 and 581 (manual §4.9 L2259-2297, L2328-2347), SD(1,28), NCF and
MCODS 51, 54, 64-67 read them.

The CPL manual names these functions but their block syntax is in the DIN manual, which is not among
the manuals this project follows; the forms below are recorded in docs/decisions.md:

* ``G168 <axis words>``: program coordinate shift of the named axes (the others keep theirs); ``G168``
  alone clears it. ``G268 <axis words>``: the additive coordinate shift, the same way. The axis words of
  these blocks are shift values, not a motion. PCS = WCS - G168 - G268 (CPL manual §4.2, L1256-1337): the shifts act
  on the kernel like the external shifts G160-G360, as additive offsets.
* ``G131 <axis><offset angle> [I<adaptation angle>]``: tangential tool guidance with that axis as axis of
  rotation symmetry; ``G130`` deselects it.
* ``G328 [I<precision barrier>] [K<distance between corners>]``: a missing word keeps its last value.
* ``G581 <slave axis><slave shift> I<master> [J<factor>] [K<master shift>]``: axis coupling (master as
  a logical axis number of the channel); ``G580 [<slave axes>]`` removes the couplings of the named
  slaves, or all.
* ``G145``..``G845`` select an external, ``G147``..``G847`` a general tool compensation (values: TC with
  table 0); ``G146`` deselects both. MCODS 51/54 read them. Their lengths on the tool axis (external L(1)3,
  general L(2)3) add to the H length from the block that selects them on, as a tool compensation (PPOS
  removes them with H, L1572-1574); a general compensation with L(2)1, L(2)2, an orientation or Euler
  angles stops the run with NC005 (not supported by ncvm), see :func:`compensation_length`.
* ``M40``..``M44``, ``M48``: the spindle gear range (MCODS 64-67); the M function also goes to the PLC.
* ``G160``, ``G260``, ``G360`` select the external zero shift of that number (FXC with table 0 writes its
  values, L1759-1773), ``G167`` deselects it (G group 30 of the SD(1) table, L2305): one is active at a
  time, as one external tool compensation G145..G845 is; at power-on G167. Only the selected shift moves
  the axes.
* ``G154``..``G159`` (G group 16) and ``G254``..``G259`` (group 17) add the values of that row of the
  active ZS table (FXC rows 154..159, 254..259, L1759) to the axis zero shift G54..G59 of group 15;
  ``G153`` and ``G253`` switch their group off, as G53 does group 15 (MCODS 15, L2856: "the axis zero
  shift values of the 3 groups G53..G59, G153..G159 and G253..G259"); at power-on G153 and G253.

A block carrying one of them is split at preparation: the programmed state changes at once (SD index
1, "last programmed"); the rest of the block is queued as a :class:`Typ3Block` that carries the state,
which becomes active when the block is executed (SD index 2).
"""

from __future__ import annotations

from ....nc.block import Block
from ....nc.profiles.blockrules import g_conflict
from ....nc.profiles.typ3osa import EXTERNAL_LENGTH, TYP3OSA
from ....nc.spindle import CPL_GEARS
from ....records import FrozenRecord, replace
from ..errors import CplError
from .context import SystemContext

WORD_CODES = frozenset((130, 131, 168, 268, 328, 580, 581))  # their block's words are their values
COMPENSATIONS = frozenset([146] + [g + 45 for g in range(100, 900, 100)] + [g + 47 for g in range(100, 900, 100)])
#: G group 30: the external zero shifts G160/G260/G360 and G167, no external shift
EXTERNAL_ZS = frozenset((160, 260, 360, 167))
NO_EXTERNAL_ZS = 167
#: G groups 16 and 17: the additive axis zero shifts (first number: the group's "off")
ADDITIVE_ZS = {16: tuple(range(153, 160)), 17: tuple(range(253, 260))}
ADDITIVE_G = frozenset(ADDITIVE_ZS[16] + ADDITIVE_ZS[17])
TYP3_G = WORD_CODES | COMPENSATIONS | EXTERNAL_ZS | ADDITIVE_G
GEARS = CPL_GEARS.codes  # M40 automatic gear range, M41-M44 gear 1-4, M48 neutral (nc/spindle.py)
INCH = 25.4
N_LOGICAL = 8  # the shifts are kept for logical axes 1..8 (SD index range 1..8)


class NcFuncs(FrozenRecord):
    """The state of the Typ3 G functions; lengths in mm, angles in degrees."""

    __slots__ = ("g168", "g268", "rotation_axis", "offset_angle", "adaptation_angle", "barrier", "corners", "coupling",
                 "external", "general", "gear", "external_zs", "zs16", "zs17")

    def __init__(self, g168: tuple = (0.0,) * N_LOGICAL, g268: tuple = (0.0,) * N_LOGICAL, rotation_axis: int = 0,
                 offset_angle: float = 0.0, adaptation_angle: float = 0.0, barrier: float = 0.0,
                 corners: float = 0.0, coupling: tuple = (), external: int = 0, general: int = 0, gear: int = 40,
                 external_zs: int = NO_EXTERNAL_ZS, zs16: int = 153, zs17: int = 253):
        self.g168 = g168
        self.g268 = g268
        self.rotation_axis = rotation_axis  # G131: logical axis number, 0 = not selected
        self.offset_angle = offset_angle
        self.adaptation_angle = adaptation_angle
        self.barrier = barrier  # G328 precision barrier
        self.corners = corners  # G328 distance between corners
        self.coupling = coupling  # ((slave, master, slave shift, factor, master shift), ...) by slave
        self.external = external  # selected external tool compensation G145..G845, 0 = none
        self.general = general  # selected general tool compensation G147..G847, 0 = none
        self.gear = gear  # spindle gear range (M40 automatic at power-on)
        self.external_zs = external_zs  # selected external zero shift G160/G260/G360, G167 = none
        self.zs16 = zs16  # additive axis zero shift G154..G159, G153 = none
        self.zs17 = zs17  # second additive axis zero shift G254..G259, G253 = none


class Typ3Block(Block):
    """A queued block that also activates the Typ3 G-function state prepared with it."""

    __slots__ = ("state",)

    def __init__(self, state: NcFuncs, g, m, words, n, msg, src):
        super().__init__(g, m, words, n, msg, src)
        self.state = state

    def has_nc(self) -> bool:
        return bool(self.g or self.m or self.words or self.msg is not None)


def prepare(rt: SystemContext, blk: Block) -> Block:
    """Take the Typ3 G functions (and the gear M functions) out of a block at preparation; two functions of one
    G group are CPL040 (the block compiler sends every block that has them here)."""
    both = g_conflict(TYP3OSA, blk.g)
    if both is not None:  # the SD(1) group table, L2302-2306: one function of each group is active
        raise CplError("CPL040", both[0])
    if not (TYP3_G.intersection(blk.g) or GEARS.intersection(blk.m)):
        return blk
    c = rt.ctl
    st = c.g_programmed
    for mc in blk.m:
        if mc in GEARS:
            st = replace(st, gear=mc)
    shifts = [g for g in blk.g if g in EXTERNAL_ZS]
    if shifts:
        st = replace(st, external_zs=shifts[0])
    for group, numbers in ADDITIVE_ZS.items():
        chosen = [g for g in blk.g if g in numbers]
        if chosen:
            st = replace(st, **{f"zs{group}": chosen[0]})
    for g in blk.g:
        if g in COMPENSATIONS:
            st = _compensation(st, g)
    codes = [g for g in blk.g if g in WORD_CODES]
    if len(codes) > 1:
        raise CplError("CPL040", f"G{codes[0]} and G{codes[1]} cannot stand in one block")
    words = dict(blk.words)
    if codes:
        st = _with_words(rt, blk, codes[0], st, words)
    c.g_programmed = st
    return Typ3Block(st, tuple(g for g in blk.g if g not in TYP3_G), blk.m, words, blk.n, blk.msg, blk.src)


def _compensation(st: NcFuncs, g: int) -> NcFuncs:
    """G145..G845 select an external, G147..G847 a general tool compensation; G146 deselects both."""
    if g == 146:
        return replace(st, external=0, general=0)
    return replace(st, external=g) if g % 100 == 45 else replace(st, general=g)


def _with_words(rt: SystemContext, blk: Block, code: int, st: NcFuncs, words: dict) -> NcFuncs:
    """G168/G268, G130/G131, G328, G580/G581: the values of the block's words (taken out of ``words``)."""
    c = rt.ctl
    logical = c.channel_axes(c.channel)[:N_LOGICAL]
    scale = INCH if 70 in blk.g else 1.0 if 71 in blk.g else rt.prepared_kernel().scale  # G70/G71 first
    axes = []  # (logical number, value in mm or degrees)
    for n, ax in enumerate(logical, 1):
        if ax.name in words:
            v = words.pop(ax.name)
            axes.append((n, v if ax.rotary else v * scale))
    if code in (168, 268):
        vals = list(st.g168 if code == 168 else st.g268) if axes else [0.0] * N_LOGICAL
        for n, v in axes:
            vals[n - 1] = v
        return replace(st, **{f"g{code}": tuple(vals)})
    if code == 130:
        return replace(st, rotation_axis=0, offset_angle=0.0, adaptation_angle=0.0)
    if code == 131:
        if len(axes) != 1:
            raise CplError("CPL040", "G131 names one axis of rotation symmetry with its offset angle")
        (n, v), = axes
        if not logical[n - 1].rotary:
            raise CplError("CPL040", f"G131: {logical[n - 1].name} is not a rotary axis")
        return replace(st, rotation_axis=n, offset_angle=v, adaptation_angle=float(words.pop("I", 0.0)))
    if code == 328:
        return replace(st, barrier=words.pop("I") * scale if "I" in words else st.barrier,
                       corners=words.pop("K") * scale if "K" in words else st.corners)
    if code == 580:
        slaves = {n for n, _ in axes}
        return replace(st, coupling=tuple(cp for cp in st.coupling if axes and cp[0] not in slaves))
    return replace(st, coupling=_couple(st, axes, words, len(logical), scale))


def _couple(st: NcFuncs, axes, words: dict, n_logical: int, scale: float) -> tuple:
    if len(axes) != 1 or "I" not in words:
        raise CplError("CPL040", "G581 names one slave axis (its shift) and its master with I")
    (slave, shift), = axes
    master = words.pop("I")
    if master != int(master) or not 1 <= master <= n_logical:
        raise CplError("1938", f"G581 master axis {master:g} is not a logical axis of the channel")
    if int(master) == slave:
        raise CplError("CPL040", "G581: an axis cannot be its own master")
    entry = (slave, int(master), shift, float(words.pop("J", 1.0)), words.pop("K", 0.0) * scale)
    return tuple(sorted([cp for cp in st.coupling if cp[0] != slave] + [entry]))


def activate(rt: SystemContext, kernel, blk: Typ3Block) -> None:
    """Execution of a Typ3Block: its state becomes active (on the NC kernel, or on the prepared copy)."""
    if kernel is rt.kernel:
        rt.ctl.g_active = blk.state
    kernel.set_additive_offset(additive(rt, kernel, blk.state))
    length = compensation_length(rt.ctl, blk.state, kernel, blk.src)
    held = kernel.modal.get(EXTERNAL_LENGTH, 0.0)
    if length != held:
        kernel.modal[EXTERNAL_LENGTH] = length
        kernel.set_tool_length(kernel.tool_length - held + length, blk.src, kernel.modal.get("H", 0))
    if blk.has_nc():
        kernel.execute(blk)


#: the fields of a general compensation (TC selection 3..8 but 6, the type) ncvm cannot apply
GENERAL_UNSUPPORTED = {2: "L(2)1", 3: "L(2)2", 4: "the orientation TO", 6: "Euler angle 1", 7: "Euler angle 2"}


def compensation_length(c, state: NcFuncs, kernel, src) -> float:
    """The length (mm) the selected external (L(1)3, TC selection 1) and general (L(2)3) tool compensations
    add on the tool axis. The radii wait for G41/G42 (refused in CPL); a general compensation that also
    holds lengths across the tool axis, an orientation or Euler angles is refused (NC005): ncvm's tool
    length acts on the tool axis alone (docs/decisions.md, "Typ3 external and general tool compensation")."""
    length = c.tc_external.get(state.external, (0.0, 0.0))[0] if state.external else 0.0
    if state.general:
        values = c.tc_general.get(state.general, (0.0,) * 8)
        held = [name for i, name in GENERAL_UNSUPPORTED.items() if values[i]]
        if held:
            kernel.fault("NC005", f"G{state.general} (general tool compensation) with {', '.join(held)} is not "
                         "supported by ncvm: it applies a compensation's length L(2)3 on the tool axis only", src)
        length += values[0]
    return length


def additive(rt: SystemContext, kernel, state: NcFuncs) -> list[float]:
    """The kernel's additive offsets: the rows G154..G159 and G254..G259 selected, the selected external
    shift (G160/G260/G360), G168 and G268."""
    c = rt.ctl
    logical = [a.name for a in c.channel_axes(c.channel)]
    external = external_shift(c, state)
    add = [0.0] * kernel.n_axes
    for i, name in enumerate(kernel.axis_names):
        if name in logical and (n := logical.index(name)) < N_LOGICAL:
            add[i] = external[n] + state.g168[n] + state.g268[n]
        add[i] += additive_zs(c, state.zs16, name) + additive_zs(c, state.zs17, name)
    return add


def additive_zs(c, g: int, name: str) -> float:
    """The value (mm) of axis ``name`` in row G<g> (54..59, 154..159, 254..259) of the active ZS table; 0 for
    G153/G253 (off)."""
    if g in (153, 253):
        return 0.0
    table = c.zs_tables[c.zs_active]
    if name not in table["columns"]:
        return 0.0
    v = table["rows"][f"G{g}"][table["columns"].index(name)]
    return v * INCH if table["unit"] == "inch" else v


def external_shift(c, state: NcFuncs) -> list[float]:
    """The external zero shift ``state`` selects, logical axes 1..8 in mm (all 0 under G167)."""
    if state.external_zs == NO_EXTERNAL_ZS:
        return [0.0] * N_LOGICAL
    return list(c.external[f"G{state.external_zs}"])


def program_shift(rt: SystemContext, kernel, i: int) -> float:
    """G168 + G268 (mm) of kernel axis i: part of the kernel's additive offset that is no axis zero shift."""
    c = rt.ctl
    st = c.g_active if kernel is rt.kernel else c.g_programmed
    logical = [a.name for a in c.channel_axes(c.channel)]
    name = kernel.axis_names[i]
    if name not in logical or (n := logical.index(name)) >= N_LOGICAL:
        return 0.0
    return st.g168[n] + st.g268[n]
