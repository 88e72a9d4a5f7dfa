"""Affine maps over the kernel's axis vector: the building blocks of coordinate transformations.

A dialect that shifts, scales or rotates the programmed contour (Bosch G60, G37/G38, G138, ...)
composes these and hands the kernel an object with ``forward``, ``inverse`` and ``plane_similarity``
(see :meth:`ncvm.nc.kernel.NcKernel.set_transform`). Vectors have one float per kernel axis, in mm
(degrees for rotary axes). Plain lists: a controller has a handful of axes, numpy would cost more
than it saves on vectors this short.
"""

from __future__ import annotations

import math


class SingularTransform(ValueError):
    """The map has no inverse (a scaling factor of 0)."""


class Affine:
    """``x -> M x + t``; immutable."""

    __slots__ = ("m", "t")

    def __init__(self, m, t):
        self.m = tuple(tuple(float(v) for v in row) for row in m)
        self.t = tuple(float(v) for v in t)

    @classmethod
    def identity(cls, n: int) -> Affine:
        return cls([[1.0 if i == j else 0.0 for j in range(n)] for i in range(n)], [0.0] * n)

    @classmethod
    def shift(cls, vec) -> Affine:
        """``x -> x + vec``."""
        n = len(vec)
        return cls(cls.identity(n).m, vec)

    @classmethod
    def scaling(cls, pole, factors) -> Affine:
        """Each axis i scaled by ``factors[i]`` about ``pole[i]``: ``x -> pole + f (x - pole)``."""
        n = len(pole)
        m = [[factors[i] if i == j else 0.0 for j in range(n)] for i in range(n)]
        return cls(m, [p - f * p for p, f in zip(pole, factors)])

    @classmethod
    def rotation(cls, n: int, a: int, b: int, degrees: float, centre=(0.0, 0.0)) -> Affine:
        """Turn the plane of axes ``a`` (first) and ``b`` (second) by ``degrees`` about ``centre``,
        counter-clockwise, i.e. from the first axis towards the second."""
        c, s = _cos_sin(degrees)
        m = [list(row) for row in cls.identity(n).m]
        m[a][a], m[a][b], m[b][a], m[b][b] = c, -s, s, c
        t = [0.0] * n
        ca, cb = centre
        t[a] = ca - (c * ca - s * cb)
        t[b] = cb - (s * ca + c * cb)
        return cls(m, t)

    def apply(self, vec) -> list[float]:
        return [sum(mij * vj for mij, vj in zip(row, vec)) + ti for row, ti in zip(self.m, self.t)]

    def then(self, other: Affine) -> Affine:
        """This map followed by ``other``: ``x -> other(self(x))``."""
        cols = list(zip(*self.m))
        m = [[sum(r * c for r, c in zip(row, col)) for col in cols] for row in other.m]
        return Affine(m, other.apply(self.t))

    def inverse(self) -> Affine:
        """Gauss-Jordan with partial pivoting; :class:`SingularTransform` when there is none."""
        n = len(self.t)
        a = [list(row) + [1.0 if i == j else 0.0 for j in range(n)] for i, row in enumerate(self.m)]
        for col in range(n):
            pivot = max(range(col, n), key=lambda r: abs(a[r][col]))
            if abs(a[pivot][col]) < 1e-12:
                raise SingularTransform("the transformation cannot be inverted (a factor of 0?)")
            a[col], a[pivot] = a[pivot], a[col]
            p = a[col][col]
            a[col] = [v / p for v in a[col]]
            for r in range(n):
                if r != col and a[r][col] != 0.0:
                    f = a[r][col]
                    a[r] = [v - f * w for v, w in zip(a[r], a[col])]
        inv = [row[n:] for row in a]
        t = [-sum(mij * tj for mij, tj in zip(row, self.t)) for row in inv]
        return Affine(inv, t)

    def plane_similarity(self, a: int, b: int) -> tuple[float, bool] | None:
        """(factor, mirrored) when the map keeps circles in the plane of axes a and b: the plane maps
        onto itself, turned and scaled alike in both directions; None otherwise (an ellipse)."""
        m = self.m
        for i in range(len(m)):
            if i not in (a, b) and (m[i][a] or m[i][b] or m[a][i] or m[b][i]):
                return None
        c1 = (m[a][a], m[b][a])
        c2 = (m[a][b], m[b][b])
        k1, k2 = math.hypot(*c1), math.hypot(*c2)
        if k1 == 0.0 or abs(k1 - k2) > 1e-12 * max(k1, k2) or abs(c1[0] * c2[0] + c1[1] * c2[1]) > 1e-12 * k1 * k2:
            return None
        return k1, c1[0] * c2[1] - c1[1] * c2[0] < 0.0


class AffineTransform:
    """One :class:`Affine` as the kernel's transformation object (see :meth:`NcKernel.set_transform`), its
    inverse computed once. ``shown``: the control shows positions with the transform applied (SINUMERIK's
    coordinate rotation), not as programmed (CPL's G37/G38/G138)."""

    __slots__ = ("map", "_inv", "shown")

    def __init__(self, affine: Affine, shown: bool = False):
        self.map = affine
        self._inv = affine.inverse()  # SingularTransform when there is none
        self.shown = shown

    def forward(self, vec) -> list[float]:
        return self.map.apply(vec)

    def inverse(self, vec) -> list[float]:
        return self._inv.apply(vec)

    def plane_similarity(self, a: int, b: int) -> tuple[float, bool] | None:
        return self.map.plane_similarity(a, b)


def _cos_sin(degrees: float) -> tuple[float, float]:
    """cos and sin of an angle in degrees, exact at multiples of 90 degrees (no 6e-17 residues)."""
    q, r = divmod(degrees, 90.0)
    if r == 0.0:
        return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[int(q) % 4]
    rad = math.radians(degrees)
    return math.cos(rad), math.sin(rad)
