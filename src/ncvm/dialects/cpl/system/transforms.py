"""Contour shift G60/G67, scaling G37/G38/G39, workpiece-position compensation G138, and the functions
that read them: COF, SCL, DPC (manual §4.6-4.8 L1967-2051; transformation chain §4.2 L1305-1323).

The G functions are registered with the NC kernel (``kernel.g_handlers``); their data form one
immutable :class:`Programmed` record that is also the kernel's transformation (``kernel.set_transform``),
so blocks after them move to transformed positions and the prepared kernel (what COF, SCL and DPC read,
"last programmed") and the executed kernel (WPOS) each have their own. The CPL manual names the
functions but not their NC syntax; the forms below are ncvm's reading (docs/decisions.md):

* ``G60 X.. Y..`` contour shift of the named coordinates (the others keep theirs); ``G67`` ends it
  (G60/G67 are one modal group in the G group table of SD(1), L2302).
* ``G37 X.. Y.. I.. J.. K..`` scaling about the pole X.., Y.. (0 where not named) with the factors
  I, J, K of X, Y, Z (1 where not named); ``G38`` the same plus ``R..``, the rotation angle of the main
  plane in degrees, counter-clockwise from its first axis; ``G39`` ends both (group 37-39, L2302).
* ``G138 X.. Y.. R..`` workpiece-position compensation: shift of the named coordinates and rotation
  angle R in the main plane about the program zero; a G138 with no values (or all 0) ends it.

Order, after the manual's chain (PCS -> contour shift -> scaling -> WCS -> coordinate transformation
G138 -> ... -> axis zero shifts -> MCS): a programmed point p goes to G138(scale(p + shift)); the
kernel's offsets (G92, zero shifts, tool length) are added after that.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

from ....nc.kernel import PLANES
from ....nc.transform import Affine, SingularTransform
from ..errors import CplError
from .axes import kernel_index, nul, resolve, to_unit
from .context import SystemContext

#: the addresses of the scaling factors of X, Y and Z (the interpolation parameters of those axes)
FACTOR_WORDS = {"X": "I", "Y": "J", "Z": "K"}


@dataclass(frozen=True)
class Programmed:
    """The channel's programmed G60/G67, G37/G38/G39 and G138 data, per kernel axis (mm, degrees)."""

    contour: tuple = ()
    contour_on: bool = False  # G60 (True) or G67
    scaling: int = 39  # 37 scaling, 38 scaling and rotation, 39 off
    pole: tuple = ()
    factors: tuple = ()
    angle: float = 0.0  # G38 rotation of the main plane
    scl_plane: tuple | None = None
    dpc_shift: tuple = ()
    dpc_angle: float = 0.0
    dpc_plane: tuple | None = None
    _full: Affine = field(init=False, repr=False, compare=False)
    _full_inv: Affine = field(init=False, repr=False, compare=False)
    _coord_inv: Affine = field(init=False, repr=False, compare=False)

    @classmethod
    def neutral(cls, n: int) -> Programmed:
        return cls((0.0,) * n, False, 39, (0.0,) * n, (1.0,) * n, 0.0, None, (0.0,) * n, 0.0, None)

    def __post_init__(self):
        n = len(self.contour)
        prep = Affine.shift(self.contour).then(Affine.scaling(self.pole, self.factors))
        if self.angle and self.scl_plane is not None:
            prep = prep.then(Affine.rotation(n, *self.scl_plane, self.angle, self._plane_pole()))
        coord = Affine.identity(n)
        if self.dpc_angle and self.dpc_plane is not None:
            coord = Affine.rotation(n, *self.dpc_plane, self.dpc_angle)
        coord = coord.then(Affine.shift(self.dpc_shift))
        full = prep.then(coord)
        object.__setattr__(self, "_full", full)
        object.__setattr__(self, "_full_inv", full.inverse())  # SingularTransform for a factor 0
        object.__setattr__(self, "_coord_inv", coord.inverse())

    def _plane_pole(self) -> tuple[float, float]:
        a, b = self.scl_plane
        return self.pole[a], self.pole[b]

    @property
    def is_neutral(self) -> bool:
        return (not self.contour_on and self.scaling == 39 and not self.dpc_angle
                and not any(self.dpc_shift) and not any(self.contour))

    # -- the kernel's transformation interface -------------------------------------------------------
    def forward(self, vec) -> list[float]:
        return self._full.apply(vec)

    def inverse(self, vec) -> list[float]:
        return self._full_inv.apply(vec)

    def plane_similarity(self, a: int, b: int):
        return self._full.plane_similarity(a, b)

    def to_wcs(self, vec) -> list[float]:
        """Undo the coordinate transformation (G138): from the position before the offsets to the WCS."""
        return self._coord_inv.apply(vec)


def programmed(k) -> Programmed:
    """The record of a kernel (the neutral one when nothing is programmed)."""
    t = k.transform
    return t if isinstance(t, Programmed) else Programmed.neutral(k.n_axes)


# -- the G functions ----------------------------------------------------------------------------------
def _axis_values(k, words) -> dict[int, float]:
    """The block's axis words by kernel axis: linear axes in mm (G70/G71), rotary axes in degrees."""
    out = {}
    axes = k.machine.axes
    for name, v in words.items():
        i = k.axis_of.get(name)
        if i is not None:
            out[i] = v if axes[i].rotary else v * k.scale
    return out


def _plane(k, g, src) -> tuple[int, int]:
    an, bn = PLANES[k.plane][:2]
    if an not in k.axis_of or bn not in k.axis_of:
        k.fault("NC009", f"G{g}: the rotation needs the axes {an} and {bn} of plane G{k.plane}", src)
    return k.axis_of[an], k.axis_of[bn]


def _install(k, g, src, **changes) -> None:
    try:
        new = replace(programmed(k), **changes)
    except SingularTransform:
        k.fault("NC009", f"G{g}: a scaling factor of 0 cannot be inverted", src)
    k.set_transform(None if new.is_neutral else new)


def g60(k, g, words, src) -> bool:
    """G60: contour shift of the named coordinates; the axis words are the shift, not a target."""
    contour = list(programmed(k).contour)
    for i, v in _axis_values(k, words).items():
        contour[i] = v
    _install(k, g, src, contour=tuple(contour), contour_on=True)
    return True


def g67(k, g, words, src) -> bool:
    """G67: contour shift off; axis words in the block are a target as usual."""
    _install(k, g, src, contour=(0.0,) * k.n_axes, contour_on=False)
    return False


def g37_38(k, g, words, src) -> bool:
    """G37 scaling / G38 scaling and rotation: pole from the axis words, factors from I/J/K, angle R."""
    n = k.n_axes
    pole = [0.0] * n
    for i, v in _axis_values(k, words).items():
        pole[i] = v
    factors = [1.0] * n
    for name, word in FACTOR_WORDS.items():
        i = k.axis_of.get(name)
        if i is not None and word in words:
            factors[i] = words[word]
    angle = float(words.get("R", 0.0)) if g == 38 else 0.0
    plane = _plane(k, g, src) if angle else None
    _install(k, g, src, scaling=g, pole=tuple(pole), factors=tuple(factors), angle=angle, scl_plane=plane)
    return True


def g39(k, g, words, src) -> bool:
    """G39: scaling and rotation off; axis words in the block are a target as usual."""
    n = k.n_axes
    _install(k, g, src, scaling=39, pole=(0.0,) * n, factors=(1.0,) * n, angle=0.0, scl_plane=None)
    return False


def g138(k, g, words, src) -> bool:
    """G138: workpiece-position compensation, shift from the axis words and rotation angle R."""
    shift = [0.0] * k.n_axes
    for i, v in _axis_values(k, words).items():
        shift[i] = v
    angle = float(words.get("R", 0.0))
    plane = _plane(k, g, src) if angle else None
    _install(k, g, src, dpc_shift=tuple(shift), dpc_angle=angle, dpc_plane=plane)
    return True


G_HANDLERS = {60: g60, 67: g67, 37: g37_38, 38: g37_38, 39: g39, 138: g138}
#: the G functions whose axis words are parameters, not a target: such a block does not travel
PARAMETER_G = frozenset((60, 37, 38, 138))
#: G functions whose axis words are data, not a traversing movement: a dwell's time (G4), set actual value
#: (G92) and the parameter G functions; the modal drilling cycle does not run after them (§3.2 L1083)
NO_TRAVEL_G = PARAMETER_G | {4, 92}


def setup(rt: SystemContext) -> None:
    """At program start: the NC kernel runs the Bosch transformation G functions with these handlers (their
    rows in the typ3osa profile name this module)."""
    rt.kernel.g_handlers.update(G_HANDLERS)


def active_group(k, group: int) -> int | None:
    """SD(1)/NCF groups 18 (G60/G67) and 19 (G37-G39) from a kernel's record; None for other groups."""
    if group == 18:
        return 60 if programmed(k).contour_on else 67
    if group == 19:
        return programmed(k).scaling
    return None


# -- COF, DPC, SCL --------------------------------------------------------------------------------------
def _coordinate(rt: SystemContext, sel, seltype):
    """(prepared kernel, axis, kernel index) of a coordinate of the own channel."""
    ax = resolve(rt, sel, seltype)
    k = rt.prepared_kernel()
    return k, ax, kernel_index(rt, ax)


def f_cof(rt: SystemContext, sel, seltype=1):
    """COF: the last programmed G60 contour shift of a coordinate (L1969-1988); COF(0) is an error."""
    k, ax, i = _coordinate(rt, sel, seltype)
    return 0.0 if i is None else to_unit(k, ax, programmed(k).contour[i])


def f_dpc(rt: SystemContext, sel, seltype=1):
    """DPC: the last programmed G138 shift of a coordinate; DPC(0) the rotation angle (L1992-2018)."""
    if nul(sel) == 0 and sel.__class__ is int and seltype in (None, 1):
        return programmed(rt.prepared_kernel()).dpc_angle
    k, ax, i = _coordinate(rt, sel, seltype)
    return 0.0 if i is None else to_unit(k, ax, programmed(k).dpc_shift[i])


def f_scl(rt: SystemContext, what, sel=None, seltype=1):
    """SCL: 0 the last programmed G38 angle, 1 the pole, 2 the scaling factor of a coordinate (L2022-2050)."""
    what = nul(what)
    if what == 0 and what.__class__ is int:
        if sel is not None:
            raise CplError("CPL023", "SCL(0) takes no axis selection")
        return programmed(rt.prepared_kernel()).angle
    if what.__class__ is not int or what not in (1, 2):
        raise CplError("CPL023", f"SCL selection {what!r}: 0 angle, 1 pole, 2 scaling factor")
    if sel is None:
        raise CplError("CPL023", f"SCL({what}) needs an axis selection")
    k, ax, i = _coordinate(rt, sel, seltype)
    rec = programmed(k)
    if what == 1:
        return 0.0 if i is None else to_unit(k, ax, rec.pole[i])
    return 1.0 if i is None else rec.factors[i]
