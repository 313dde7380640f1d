"""Intrados curves of the arch shapes in pure numpy/scipy: where the joints start, which way they
run, and the extrados they end on (docs/theory.md, "Arch shapes").

A curve runs from the left springing to the right one, parametrised by its arc length; the extrados
lies at a constant distance, the ring thickness, outward along the intrados normal. The circular
arch keeps the paper's frame (its centre at the origin); the other shapes stand on the springing
line y = 0. All are symmetric about x = 0. Lengths in metres.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Protocol

import numpy as np

ORIENTATIONS = ("normal", "vertical", "radial")
MAX_RISE_OVER_SPAN = 0.5  # elliptical and three-centred arches: the rise is at most the half-span
MIN_POINTED_RATIO = 0.5  # pointed arch: arc radius at least half the span (0.5 = semicircle)
END_TOLERANCE = 1e-12  # fraction of the length within which a station sits on an arc's end
CORNER_TOLERANCE = 1e-9  # two arcs whose normals differ by more than this meet at a corner
RAY_SAMPLES = 64  # samples of the extrados that bracket where a joint's line meets it
ROOT_XTOL = 1e-15  # parameter tolerance of the root searches (parameters of order 1)
UP = np.array([0.0, 1.0])


@dataclass(frozen=True)
class Station:
    """A point of the intrados with its unit outward normal (the bisector at a corner), the
    direction a radial joint takes there, and whether the intrados has a corner there."""

    point: np.ndarray
    normal: np.ndarray
    radial: np.ndarray
    corner: bool = False

    @property
    def tangent(self) -> np.ndarray:
        """Unit tangent, left to right."""
        return np.array([self.normal[1], -self.normal[0]])


class Intrados(Protocol):
    """A shape's intrados: clear span, rise, arc length and smallest radius of curvature (m)."""

    span: float
    rise: float
    length: float
    min_radius: float

    def station(self, s: float) -> Station:
        """The point at arc length `s` from the left springing."""

    def extrados(self, u: float, thickness: float) -> np.ndarray:
        """The extrados point at parameter `u`, 0 at the left springing, 1 at the right, continuous
        and continued a little beyond both."""


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v)


@dataclass(frozen=True)
class Arc:
    """A circular arc run clockwise from angle `start` (rad, about `centre`) through `sweep`."""

    centre: np.ndarray
    radius: float
    start: float
    sweep: float

    @property
    def end(self) -> float:
        """Angle of its right end (rad)."""
        return self.start - self.sweep

    def point(self, angle: float, offset: float = 0.0) -> np.ndarray:
        """The point at `angle` on the arc, or on its concentric offset by `offset` outward."""
        return self.centre + (self.radius + offset) * np.array([math.cos(angle), math.sin(angle)])


class Arcs:
    """An intrados of circular arcs, each beginning where the last ends; a joint on a junction
    takes the bisector of the two normals, and at a corner the offset arcs meet in a point."""

    def __init__(self, arcs: list[Arc]) -> None:
        self.arcs = arcs
        self.starts = np.concatenate([[0.0], np.cumsum([a.radius * a.sweep for a in arcs])])
        self.length = float(self.starts[-1])
        left, right = arcs[0].point(arcs[0].start), arcs[-1].point(arcs[-1].end)
        tops = [
            a.centre[1] + a.radius if a.start >= np.pi / 2 >= a.end else max(a.point(a.start)[1], a.point(a.end)[1])
            for a in arcs
        ]
        self.span, self.rise = float(right[0] - left[0]), float(max(tops) - left[1])
        self.min_radius = min(a.radius for a in arcs)

    def station(self, s: float) -> Station:
        near = END_TOLERANCE * self.length
        ends = [k for k, start in enumerate(self.starts.tolist()) if abs(start - s) <= near]
        if ends:
            return self._end_station(ends[0])
        k = min(max(int(np.searchsorted(self.starts, s)) - 1, 0), len(self.arcs) - 1)
        arc = self.arcs[k]
        angle = arc.start - (s - self.starts[k]) / arc.radius
        normal = np.array([math.cos(angle), math.sin(angle)])
        return Station(arc.point(angle), normal, normal)

    def _end_station(self, k: int) -> Station:
        """The station at the k-th arc end (0 = left springing, len(arcs) = right springing)."""
        after = self.arcs[min(k, len(self.arcs) - 1)]
        before = self.arcs[max(k - 1, 0)]
        angle_after = after.start if k < len(self.arcs) else after.end
        angle_before = before.end if k > 0 else before.start
        n_after = np.array([math.cos(angle_after), math.sin(angle_after)])
        n_before = np.array([math.cos(angle_before), math.sin(angle_before)])
        normal = _unit(n_before + n_after)
        corner = bool(np.linalg.norm(n_after - n_before) > CORNER_TOLERANCE)
        point = after.point(angle_after) if k < len(self.arcs) else before.point(angle_before)
        return Station(point, normal, normal, corner)

    def extrados(self, u: float, thickness: float) -> np.ndarray:
        ranges = self._extrados_ranges(thickness)
        k = min(int(u * len(self.arcs)), len(self.arcs) - 1)
        first, last = ranges[k]
        local = u * len(self.arcs) - k
        return self.arcs[k].point(first + (last - first) * local, thickness)

    def _extrados_ranges(self, thickness: float) -> list[tuple[float, float]]:
        """Angles at which each offset arc begins and ends: those of the intrados where arcs are
        tangent, those of the point where the offset arcs cross at a corner."""
        bounds = [[a.start, a.end] for a in self.arcs]
        for k in range(1, len(self.arcs)):
            before, after = self.arcs[k - 1], self.arcs[k]
            station = self._end_station(k)
            if station.corner:
                meet = _circles_meet(
                    before.centre,
                    before.radius + thickness,
                    after.centre,
                    after.radius + thickness,
                    station.point + thickness * station.normal,
                )
                bounds[k - 1][1] = _angle(meet - before.centre)
                bounds[k][0] = _angle(meet - after.centre)
        return [(first, last) for first, last in bounds]


def _angle(v: np.ndarray) -> float:
    return math.atan2(v[1], v[0])


def _circles_meet(c1: np.ndarray, r1: float, c2: np.ndarray, r2: float, near: np.ndarray) -> np.ndarray:
    """The intersection of two crossing circles nearer to `near`."""
    gap = c2 - c1
    d = float(np.linalg.norm(gap))
    along = (r1**2 - r2**2 + d**2) / (2.0 * d)
    across = math.sqrt(max(r1**2 - along**2, 0.0))
    base, side = c1 + along * gap / d, np.array([-gap[1], gap[0]]) / d
    candidates = (base + across * side, base - across * side)
    return min(candidates, key=lambda p: float(np.linalg.norm(p - near)))


class HalfEllipse:
    """The upper half of the ellipse of semi-axes span/2 (horizontal) and rise (vertical), rise at
    most span/2, centred on the springing line; radial joints aim at its centre."""

    def __init__(self, span: float, rise: float) -> None:
        if not 0 < rise <= MAX_RISE_OVER_SPAN * span:
            raise ValueError(f"an elliptical arch needs 0 < rise <= span/2, got rise {rise} for span {span}")
        self.a, self.b = span / 2.0, rise
        self.m = 1.0 - (self.b / self.a) ** 2  # parameter of the elliptic integrals
        self.span, self.rise = span, rise
        self.length = self._arc(np.pi)
        self.min_radius = self.b**2 / self.a  # at the springings

    def _arc(self, phi: float) -> float:
        """Arc length from the left springing to the point at eccentric angle `phi` (0..pi)."""
        from scipy.special import ellipe, ellipeinc  # elliptical arches only: scipy.special costs 40 ms to import

        return float(self.a * (ellipeinc(phi - np.pi / 2, self.m) + ellipe(self.m)))

    def _angle(self, s: float) -> float:
        if s <= END_TOLERANCE * self.length:
            return 0.0
        if s >= (1.0 - END_TOLERANCE) * self.length:
            return float(np.pi)
        from scipy.optimize import brentq  # here, not at import: scipy.optimize costs a run ~50 ms

        return float(brentq(lambda phi: self._arc(phi) - s, 0.0, np.pi, xtol=ROOT_XTOL))

    def _frame(self, phi: float) -> tuple[np.ndarray, np.ndarray]:
        c, s = math.cos(phi), math.sin(phi)
        return np.array([-self.a * c, self.b * s]), _unit(np.array([-self.b * c, self.a * s]))

    def station(self, s: float) -> Station:
        point, normal = self._frame(self._angle(s))
        return Station(point, normal, _unit(point))

    def extrados(self, u: float, thickness: float) -> np.ndarray:
        point, normal = self._frame(np.pi * u)
        return point + thickness * normal


def circular(radius: float, embrace: float) -> Arcs:
    """The segmental arch's intrados: one arc of `radius` and angle `embrace` (rad, up to pi) about
    the origin, symmetric about the y axis."""
    return Arcs([Arc(np.zeros(2), radius, np.pi / 2 + embrace / 2, embrace)])


def pointed(span: float, radius_over_span: float) -> Arcs:
    """A two-centred (pointed) arch: two arcs of radius ratio x span, centred on the springing line,
    each rising from one springing with a vertical tangent to meet at the apex (1 = equilateral)."""
    if radius_over_span < MIN_POINTED_RATIO:
        raise ValueError(f"a pointed arch needs radius_over_span >= 0.5, got {radius_over_span}")
    r = radius_over_span * span
    offset = r - span / 2.0  # distance of each centre from the axis, on the far side
    apex = math.acos(offset / r)  # angle of the apex about the right arc's centre
    return Arcs([Arc(np.array([offset, 0.0]), r, np.pi, apex), Arc(np.array([-offset, 0.0]), r, apex, apex)])


def three_centred(span: float, rise: float) -> Arcs:
    """A three-centred (basket-handle) arch by the classical construction: join a springing A to the
    crown B, mark the half-span minus the rise off BA from B at F; the perpendicular bisector of AF
    meets the springing line at the side arcs' centre and the axis at the crown arc's centre."""
    a, b = span / 2.0, rise
    if not 0 < b < a:
        raise ValueError(f"a three-centred arch needs 0 < rise < span/2, got rise {rise} for span {span}")
    c = math.hypot(a, b)
    r_side = c * (c - a + b) / (2.0 * a)
    y_crown = (c * (c - a + b) / 2.0 - a * a) / b  # height of the crown arc's centre (below 0)
    left, centre, right = np.array([r_side - a, 0.0]), np.array([0.0, y_crown]), np.array([a - r_side, 0.0])
    joint = _angle(left - centre)  # direction of the left junction from both centres
    return Arcs(
        [
            Arc(left, r_side, np.pi, np.pi - joint),
            Arc(centre, b - y_crown, joint, 2.0 * joint - np.pi),
            Arc(right, r_side, np.pi - joint, np.pi - joint),
        ]
    )


def stations(intrados: Intrados, n_voussoirs: int) -> list[Station]:
    """The n + 1 joints' intrados points, at equal arc lengths from springing to springing."""
    return [intrados.station(intrados.length * k / n_voussoirs) for k in range(n_voussoirs + 1)]


def joint_direction(station: Station, orientation: str) -> np.ndarray:
    """Unit direction of a joint from its intrados point: along the normal, up, or radial."""
    if orientation not in ORIENTATIONS:
        raise ValueError(f"joint orientation must be one of {', '.join(ORIENTATIONS)}, got {orientation!r}")
    return {"normal": station.normal, "vertical": UP, "radial": station.radial}[orientation]


def extrados_end(intrados: Intrados, station: Station, direction: np.ndarray, thickness: float) -> np.ndarray:
    """Where a joint leaving `station` along `direction` meets the extrados: `thickness` along a
    smooth normal, else where the joint's line crosses the extrados ahead of the intrados point."""
    if np.array_equal(direction, station.normal) and not station.corner:
        return station.point + thickness * direction

    def across(u: float) -> float:
        d = intrados.extrados(u, thickness) - station.point
        return float(direction[0] * d[1] - direction[1] * d[0])

    from scipy.optimize import brentq  # here, not at import: scipy.optimize costs a run ~50 ms

    margin = 1.0 / RAY_SAMPLES  # the curves continue past the springings, where round-off may put a root
    u = np.linspace(-margin, 1.0 + margin, RAY_SAMPLES + 3)
    side = np.array([across(x) for x in u])
    for k in np.flatnonzero(side[:-1] * side[1:] <= 0):  # the line crosses; ahead, or behind the point?
        root = float(brentq(across, u[k], u[k + 1], xtol=ROOT_XTOL))
        reach = float((intrados.extrados(root, thickness) - station.point) @ direction)
        if reach > 0:
            return station.point + reach * direction
    raise ValueError(f"a joint from {station.point} along {direction} does not reach the extrados")


def joint_obliquity_deg(intrados: Intrados, n_voussoirs: int, orientation: str) -> np.ndarray:
    """Angle between each joint and the intrados tangent where it starts (deg; 90 = normal)."""
    angles = []
    for st in stations(intrados, n_voussoirs):
        t, d = st.tangent, joint_direction(st, orientation)
        angles.append(math.degrees(math.asin(min(abs(float(t[0] * d[1] - t[1] * d[0])), 1.0))))
    return np.array(angles)
