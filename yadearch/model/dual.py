"""Forward-mode derivatives for the compiled joint law: a dual number is a 7-tuple (value, and its
partial derivatives with respect to the six degrees of freedom of a joint's two blocks).

Tuples stay in registers inside numba, so the joint law written with these helpers gives the exact
tangent of its own arithmetic (`model.joint_tangent`), branch by branch, at about the cost of the
forces themselves. Finite differences serve only to test it.
"""

from __future__ import annotations

import math

from numba import njit

WIDTH = 6  # derivatives carried: x, y, rotation of the left block, then of the right block


@njit(cache=True)
def const(v):
    """A number that depends on no degree of freedom."""
    return (v, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)


@njit(cache=True)
def var(v, k):
    """Degree of freedom `k` (0..5) at value `v`."""
    return (
        v,
        1.0 if k == 0 else 0.0,
        1.0 if k == 1 else 0.0,
        1.0 if k == 2 else 0.0,
        1.0 if k == 3 else 0.0,
        1.0 if k == 4 else 0.0,
        1.0 if k == 5 else 0.0,
    )


@njit(cache=True)
def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3], a[4] + b[4], a[5] + b[5], a[6] + b[6])


@njit(cache=True)
def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2], a[3] - b[3], a[4] - b[4], a[5] - b[5], a[6] - b[6])


@njit(cache=True)
def scale(a, c):
    """a x c for a plain number c."""
    return (a[0] * c, a[1] * c, a[2] * c, a[3] * c, a[4] * c, a[5] * c, a[6] * c)


@njit(cache=True)
def shift(a, c):
    """a + c for a plain number c."""
    return (a[0] + c, a[1], a[2], a[3], a[4], a[5], a[6])


@njit(cache=True)
def mul(a, b):
    v, w = a[0], b[0]
    return (
        v * w,
        a[1] * w + v * b[1],
        a[2] * w + v * b[2],
        a[3] * w + v * b[3],
        a[4] * w + v * b[4],
        a[5] * w + v * b[5],
        a[6] * w + v * b[6],
    )


@njit(cache=True)
def chain(a, value, slope):
    """f(a) given f(a[0]) = `value` and f'(a[0]) = `slope`."""
    return (value, a[1] * slope, a[2] * slope, a[3] * slope, a[4] * slope, a[5] * slope, a[6] * slope)


@njit(cache=True)
def div(a, b):
    inverse = 1.0 / b[0]
    return mul(a, chain(b, inverse, -inverse * inverse))


@njit(cache=True)
def dcos(a):
    return chain(a, math.cos(a[0]), -math.sin(a[0]))


@njit(cache=True)
def dsin(a):
    return chain(a, math.sin(a[0]), math.cos(a[0]))


@njit(cache=True)
def dtan(a):
    t = math.tan(a[0])
    return chain(a, t, 1.0 + t * t)


@njit(cache=True)
def dabs(a):
    return scale(a, -1.0) if a[0] < 0.0 else a


@njit(cache=True)
def dmax(a, b):
    """The larger of two duals, with its derivatives (the first on a tie)."""
    return a if a[0] >= b[0] else b


@njit(cache=True)
def dmin(a, b):
    return a if a[0] <= b[0] else b
