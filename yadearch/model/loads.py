"""Live loads on the arch (pure numpy, SI): what grows until the arch collapses, the self-weight held.

A vertical load of 1 N stands on the extrados, centred at a horizontal position measured from the
left springing's intrados point, spread uniformly over a width (0: concentrated; a width covering
the span: a uniform load); each voussoir takes the part of it above its own extrados, at that part's
centre. A horizontal acceleration of 1 g pushes each voussoir by its weight at its centroid (the
quasi-static seismic check, the tilting table), and the fill each voussoir carries by that fill's weight
at its centroid (`model.backfill.fill_inertia`). Each is a set of point forces on the blocks, and the
generalised forces it puts on every block (force x, force y, moment about the origin) are the form the
limit analysis balances, so its multiplier at collapse is the collapse load in N or the collapse
acceleration in g.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from yadearch.model.dispersal import STRIP_POINTS, Dispersal, dispersed_share
from yadearch.model.geometry import QUADRILATERAL_PRISM, ArchGeometry, front_face

NONE, VERTICAL, ACCELERATION = "none", "vertical", "horizontal_acceleration"
LIVE_LOADS = (NONE, VERTICAL, ACCELERATION)
UNITS = {VERTICAL: "N", ACCELERATION: "g"}  # the multiplier's unit: the load is 1 N, or 1 g
UNIFORM, RISING, FALLING = "uniform", "rising", "falling"
LOAD_SHAPES = (UNIFORM, RISING, FALLING)  # a spread load's intensity across its width


@dataclass(frozen=True)
class LiveLoad:
    """The live load of a case: its kind, and for a load on the extrados its position from the left
    springing, the width it spreads over (m), its inclination and the loads that go with it (an axle's
    others); an acceleration pushes toward +x or -x."""

    kind: str
    position: float = 0.0
    width: float = 0.0
    toward_right: bool = True
    shape: str = UNIFORM
    inclination: float = 0.0  # a load on the extrados: its angle from the downward vertical (rad, + toward +x)
    further: tuple[tuple[float, float], ...] = ()  # more such loads: (offset of its centre (m), magnitude ratio)
    dispersal: Dispersal | None = None  # a load on the fill's surface, spread through it (None: on the extrados)
    # an acceleration: the fill's columns the voussoirs carry, pushed by their weight at their centroids,
    # as (block, x, y, weight N) (`model.backfill.fill_inertia`; none without fill)
    fill_inertia: tuple[tuple[int, float, float, float], ...] = ()


@dataclass(frozen=True)
class LoadPoints:
    """A live load as point forces: the block each acts on, its point (k, 2) and force (k, 2) in SI,
    in the undeformed arch (a load moves with the block it stands on)."""

    block: np.ndarray
    point: np.ndarray
    force: np.ndarray


def live_load_points(geometry: ArchGeometry, centroids: np.ndarray, weight: np.ndarray, load: LiveLoad) -> LoadPoints:
    """The unit live `load` as point forces on the voussoirs (none for `none`)."""
    if load.kind == ACCELERATION:
        fill = np.array(load.fill_inertia, float).reshape(-1, 4)
        blocks = np.concatenate([np.arange(1, len(weight) - 1), fill[:, 0].astype(int)])
        points = np.vstack([centroids[1:-1, :2], fill[:, 1:3]])
        push = np.concatenate([weight[1:-1], fill[:, 3]]) * (1.0 if load.toward_right else -1.0)
        return LoadPoints(blocks, points, np.column_stack([push, np.zeros_like(push)]))
    if load.kind == VERTICAL:
        shares = [
            (block, ratio * newtons, point)
            for offset, ratio in ((0.0, 1.0), *load.further)
            for block, newtons, point in _shares(geometry, load, load.position + offset)
        ]
        if shares:
            blocks, newtons, points = zip(*shares)
            along = np.array([np.sin(load.inclination), -np.cos(load.inclination)])  # 1 N down, leaning
            force = np.outer(newtons, along)
            return LoadPoints(np.array(blocks), np.array(points), force)
    return LoadPoints(np.zeros(0, int), np.zeros((0, 2)), np.zeros((0, 2)))


def generalised(points: LoadPoints, n_blocks: int, placed: np.ndarray | None = None) -> np.ndarray:
    """(n_blocks, 3) force x, force y and moment about the origin of the point forces on each block,
    at the points `placed` (k, 2; default: where the undeformed arch has them)."""
    where = points.point if placed is None else placed
    forces = np.zeros((n_blocks, 3))
    np.add.at(forces[:, 0], points.block, points.force[:, 0])
    np.add.at(forces[:, 1], points.block, points.force[:, 1])
    np.add.at(forces[:, 2], points.block, where[:, 0] * points.force[:, 1] - where[:, 1] * points.force[:, 0])
    return forces


def block_loads(points: LoadPoints, centroids: np.ndarray, n_blocks: int) -> np.ndarray:
    """(n_blocks, 4) the point forces on each block as the static engine takes them: force x, force y,
    and the moment m0 and dot product d0 of each force with its arm from the block's centroid in the
    undeformed arch (the arm turns with the block: moment = cos(t) m0 - sin(t) d0)."""
    loads = np.zeros((n_blocks, 4))
    arm = points.point - centroids[points.block, :2]
    np.add.at(loads[:, 0], points.block, points.force[:, 0])
    np.add.at(loads[:, 1], points.block, points.force[:, 1])
    np.add.at(loads[:, 2], points.block, arm[:, 0] * points.force[:, 1] - arm[:, 1] * points.force[:, 0])
    np.add.at(loads[:, 3], points.block, arm[:, 0] * points.force[:, 0] + arm[:, 1] * points.force[:, 1])
    return loads


def turned_moments(loads: np.ndarray, turn: np.ndarray) -> np.ndarray:
    """Each block's moment about its centroid of its `loads` (`block_loads`) with the arms turned by the
    block's rotation `turn` (rad): cos(t) m0 - sin(t) d0."""
    return np.cos(turn) * loads[:, 2] - np.sin(turn) * loads[:, 3]


def turning_stiffness(loads: np.ndarray, turn: np.ndarray) -> np.ndarray:
    """Each block's rotational stiffness from its `loads` (N m/rad): minus the change of
    `turned_moments` with the rotation, sin(t) m0 + cos(t) d0 (a load above the centroid softens it)."""
    return np.sin(turn) * loads[:, 2] + np.cos(turn) * loads[:, 3]


def load_displacement(
    loads: np.ndarray, pos0: np.ndarray, turn0: np.ndarray, pos: np.ndarray, turn: np.ndarray
) -> float:
    """The work of `loads` (multiplier 1) from the poses `pos0`, `turn0` to `pos`, `turn` over the sum of
    its forces' magnitudes: the mean displacement of the load's points along their forces (m)."""
    magnitude = float(np.hypot(loads[:, 0], loads[:, 1]).sum())
    if magnitude == 0.0:
        return 0.0
    work = (pos - pos0) * loads[:, 0:2]
    # the turned moment integrated over the turn: m0 (sin t - sin t0) + d0 (cos t - cos t0)
    turning = loads[:, 2] * (np.sin(turn) - np.sin(turn0)) + loads[:, 3] * (np.cos(turn) - np.cos(turn0))
    return float((work.sum() + turning.sum()) / magnitude)


def _shares(geometry: ArchGeometry, load: LiveLoad, position: float) -> list[tuple[int, float, np.ndarray]]:
    """(block, newtons, point) of a unit vertical `load` centred `position` m from the left springing: on
    the extrados, or from the fill's surface through the fill (`model.dispersal`)."""
    if load.dispersal is None:
        return _extrados_shares(geometry, position, load.width, load.shape)
    return _dispersed_shares(geometry, load.dispersal, position, load.width, load.shape)


def _dispersed_shares(
    geometry: ArchGeometry, dispersal: Dispersal, position: float, width: float, shape: str
) -> list[tuple[int, float, np.ndarray]]:
    """(block, newtons, point) of a unit load on the fill's surface centred `position` m from the left
    springing, spread over `width` m with the intensity `shape` (as STRIP_POINTS point loads), each
    dispersed through the fill above the extrados under it: each voussoir's part at its resultant on the
    extrados (parallel forces: their weighted mean point). The parts beyond the springings stand on the
    supports."""
    centre = geometry.joints[0].intrados[0] + position
    low = centre - width / 2.0
    step = width / STRIP_POINTS
    surface = (
        [(1.0, centre)]
        if width == 0.0
        else [_part(low, width, low + k * step, low + (k + 1) * step, shape) for k in range(STRIP_POINTS)]
    )
    segments = extrados_segments(geometry)
    parts: dict[int, tuple[float, np.ndarray]] = {}
    for newtons, x in surface:
        depth = dispersal.level - extrados_height(segments, x)
        for block, left, right in segments:
            share, at = dispersed_share(dispersal, x, depth, float(left[0]), float(right[0]))
            if share > 0.0:
                total, moment = parts.get(block, (0.0, np.zeros(2)))
                parts[block] = (total + newtons * share, moment + newtons * share * on_segment(left, right, at))
    return [(block, total, moment / total) for block, (total, moment) in sorted(parts.items())]


def extrados_height(segments: list[tuple[int, np.ndarray, np.ndarray]], x: float) -> float:
    """The extrados's height (m) at abscissa `x` (`extrados_segments`); beyond its ends, the nearer end's."""
    for _, left, right in segments:
        if left[0] <= x <= right[0] and right[0] > left[0]:
            return float(on_segment(left, right, x)[1])
    ends = [point for _, left, right in segments for point in (left, right)]
    return float(min(ends, key=lambda point: abs(point[0] - x))[1])


def _extrados_shares(
    geometry: ArchGeometry, position: float, width: float, shape: str = UNIFORM
) -> list[tuple[int, float, np.ndarray]]:
    """(block, newtons, point) of a 1 N vertical load centred `position` m from the left springing and
    spread over `width` m with the intensity `shape`: each voussoir's part, at that part's centre of
    load on the block's extrados."""
    origin = geometry.joints[0].intrados[0]
    low, high = origin + position - width / 2.0, origin + position + width / 2.0
    shares = []
    for block, left, right in extrados_segments(geometry):
        if width == 0.0:
            if left[0] <= low <= right[0]:
                return [(block, 1.0, on_segment(left, right, low))]
            continue
        start, end = max(low, left[0]), min(high, right[0])
        if end > start:
            share, centre = _part(low, width, start, end, shape)
            shares.append((block, share, on_segment(left, right, centre)))
    return shares


def _part(low: float, width: float, start: float, end: float, shape: str) -> tuple[float, float]:
    """The share of a unit load spread over [low, low + width] with intensity `shape` that lies in
    [start, end], and the abscissa of that part's resultant."""
    if shape == UNIFORM:
        return (end - start) / width, 0.5 * (start + end)
    s, e = (start - low) / width, (end - low) / width  # on the load's own width, 0 to 1
    if shape == FALLING:  # the mirror image of a rising load
        s, e = 1.0 - e, 1.0 - s
    share = e * e - s * s  # a rising intensity 2 t: its integral from s to e
    centre = (2.0 / 3.0) * (e**3 - s**3) / share
    if shape == FALLING:
        centre = 1.0 - centre
    return share, low + centre * width


def extrados_segments(geometry: ArchGeometry) -> list[tuple[int, np.ndarray, np.ndarray]]:
    """Each voussoir's extrados face as segments, left to right: (block, a segment's left end, its right
    end), in m; one segment between its joints' extrados corners, or one between each two of a measured
    voussoir's extrados corners (`geometry.extrados_points_mm`)."""
    segments = []
    for block in range(1, len(geometry.blocks) - 1):
        chain = extrados_chain(geometry, block)
        for a, b in zip(chain[:-1], chain[1:]):
            segments.append((block, *((a, b) if a[0] <= b[0] else (b, a))))
    return segments


def extrados_chain(geometry: ArchGeometry, block: int) -> np.ndarray:
    """(k, 2) voussoir `block`'s extrados corners from its left joint's to its right joint's (m): the
    joints' corners, and between them a polygon voussoir's own (its front face counter-clockwise runs
    from the right joint's extrados corner to the left one's)."""
    left, right = geometry.joints[block - 1].extrados[:2], geometry.joints[block].extrados[:2]
    polygon = geometry.blocks[block]
    if len(polygon) == QUADRILATERAL_PRISM:
        return np.array([left, right])
    face = front_face(polygon)
    start = int(np.argmin(np.linalg.norm(face - right, axis=1)))
    end = int(np.argmin(np.linalg.norm(face - left, axis=1)))
    between = np.roll(face, -start, axis=0)[1 : (end - start) % len(face)]
    return np.vstack([left, between[::-1], right])


def on_segment(left: np.ndarray, right: np.ndarray, x: float) -> np.ndarray:
    """The point of the segment left-right at abscissa `x`."""
    run = right[0] - left[0]
    t = (x - left[0]) / run if run > 0.0 else 0.5
    return left + t * (right - left)
