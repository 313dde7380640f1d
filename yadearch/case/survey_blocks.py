"""A surveyed arch given block by block (pure): each voussoir a convex polygon of its corners (two on each
joint, any more on its faces) and the two supports marked, as a survey or a drawing gives them, turned
into the joints' intrados and extrados corners that geometry.joint_points_mm holds and the faces' other
corners (geometry.intrados_points_mm, extrados_points_mm; docs/movements.md, "A surveyed arch").
Corners of neighbouring blocks within a tolerance are one joint corner (a survey never closes a dry
joint to the micron); the intrados is the shorter of the ring's two chains of joint corners."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from yadearch.errors import CaseError

SUPPORTS = ("left", "right")  # a block's "support" mark: the fixed or moving abutment on that side
VOUSSOIR_CORNERS = 4  # at least: two on each of its joints
DEFAULT_JOINT_TOLERANCE_MM = 0.5  # corners of two neighbours closer than this are one joint corner


@dataclass(frozen=True)
class SurveyedRing:
    """A survey of blocks as the measured arch's parameters (mm): the joints (joints, 4) [x_i, y_i, x_e,
    y_e] left to right, and each face's other corners as rows [voussoir, x, y], left to right."""

    joints: np.ndarray
    intrados_points: list[list[float]]
    extrados_points: list[list[float]]


def ring_from_blocks(data: dict[str, Any]) -> SurveyedRing:
    """The ring of a survey's blocks: `data["blocks"]` a list of {"corners": [[x, y], ...] (mm), in
    order round the block, "support": "left" | "right" (the two abutments only), "name" (optional: what
    the messages call it)}, in any order; `data["joint_tolerance_mm"]` optional. CaseError in one line
    for a survey that makes no ring."""
    blocks = data.get("blocks")
    if not isinstance(blocks, list) or not blocks:
        raise CaseError("survey: 'blocks' must be a list of blocks, each {'corners': [[x, y], ...]}")
    tolerance = float(data.get("joint_tolerance_mm", DEFAULT_JOINT_TOLERANCE_MM))
    if not tolerance > 0.0:
        raise CaseError(f"survey: joint_tolerance_mm must be > 0 mm, got {tolerance:g}")
    names = [str(b.get("name", k)) if isinstance(b, dict) else str(k) for k, b in enumerate(blocks)]
    corners = [_corners(block, name) for block, name in zip(blocks, names)]
    marks = [block.get("support") for block in blocks]
    ends = {side: [k for k, mark in enumerate(marks) if mark == side] for side in SUPPORTS}
    unknown = sorted({str(m) for m in marks if m is not None and m not in SUPPORTS})
    if unknown or any(len(found) != 1 for found in ends.values()):
        raise CaseError(
            "survey: mark exactly one block 'support': 'left' and one 'support': 'right'"
            + (f" (got {', '.join(unknown)})" if unknown else "")
        )
    order = _chain(corners, ends["left"][0], ends["right"][0], tolerance, names)
    joints = [_shared(corners[a], corners[b], tolerance) for a, b in zip(order, order[1:])]
    for k, index in enumerate(order[1:-1]):
        if len(corners[index]) < VOUSSOIR_CORNERS:
            raise CaseError(
                f"survey: voussoir {k + 1} (block {names[index]}) has {len(corners[index])} corners; a voussoir has "
                f"{VOUSSOIR_CORNERS} at least, two on each joint"
            )
    first, second = _chains(joints)
    intrados_first = (
        np.linalg.norm(np.diff(first, axis=0), axis=1).sum() <= np.linalg.norm(np.diff(second, axis=0), axis=1).sum()
    )
    intrados, extrados = (first, second) if intrados_first else (second, first)
    inner, outer = [], []
    for k, index in enumerate(order[1:-1], start=1):
        ring = corners[index]
        inner += [[k, *p] for p in _between(ring, intrados[k - 1], intrados[k], (extrados[k - 1], extrados[k]), k)]
        outer += [[k, *p] for p in _between(ring, extrados[k - 1], extrados[k], (intrados[k - 1], intrados[k]), k)]
    return SurveyedRing(np.hstack([intrados, extrados]), inner, outer)


def _between(ring: np.ndarray, start: np.ndarray, end: np.ndarray, other: tuple[np.ndarray, ...], k: int) -> list:
    """A voussoir's corners on one face: those met going round its polygon `ring` from the corner at
    its left joint `start` to the one at its right joint `end` the way that passes neither corner of the
    `other` face, in that order (left to right)."""
    at = [int(np.argmin(np.linalg.norm(ring - p, axis=1))) for p in (start, end, *other)]
    for step in (1, -1):
        walk = [(at[0] + step * i) % len(ring) for i in range(1, len(ring))]
        inside = walk[: walk.index(at[1])]
        if not set(inside) & set(at[2:]):
            return [ring[i].tolist() for i in inside]
    raise CaseError(f"survey: voussoir {k}'s corners are not in order round the block")


def _corners(block: Any, name: str) -> np.ndarray:
    """A block's corners as an (n, 2) array; CaseError naming the block otherwise."""
    points = block.get("corners") if isinstance(block, dict) else None
    try:
        array = np.asarray(points, dtype=float)
    except (TypeError, ValueError):
        array = np.empty((0,))
    if array.ndim != 2 or array.shape[1] != 2 or len(array) < 3 or not np.isfinite(array).all():
        raise CaseError(f"survey: block {name} needs 'corners', at least 3 finite [x, y] points (mm)")
    return array


def _touching(a: np.ndarray, b: np.ndarray, tolerance: float) -> list[tuple[int, int]]:
    """Pairs (corner of a, corner of b) closer than `tolerance`."""
    distance = np.linalg.norm(a[:, None, :] - b[None, :, :], axis=2)
    return [(int(i), int(j)) for i, j in zip(*np.nonzero(distance < tolerance))]


def _chain(corners: list[np.ndarray], left: int, right: int, tolerance: float, names: list[str]) -> list[int]:
    """The blocks from the left support to the right one, each sharing two corners with the next
    (`names`: what the messages call them)."""
    order, remaining = [left], set(range(len(corners))) - {left}
    while order[-1] != right:
        after = [k for k in remaining if len(_touching(corners[order[-1]], corners[k], tolerance)) == 2]
        if not after:
            gap, nearest = min((_joint_gap(corners[order[-1]], corners[k]), k) for k in remaining)
            raise CaseError(
                f"survey: block {names[order[-1]]} shares a joint (two corners within {tolerance:g} mm) with no "
                f"block; the nearest, {names[nearest]}, is {gap:.3g} mm off (its second-closest corners): move "
                'their corners together, or give a JSON survey a "joint_tolerance_mm" above that gap'
            )
        if len(after) != 1:
            raise CaseError(
                f"survey: block {names[order[-1]]} shares a joint (two corners within {tolerance:g} mm) with "
                f"blocks {', '.join(names[k] for k in sorted(after))}; each block must share one with the next only"
            )
        order.append(after[0])
        remaining.discard(after[0])
    if remaining:
        raise CaseError(
            f"survey: blocks {', '.join(names[k] for k in sorted(remaining))} are not on the ring between the supports"
        )
    return order


def _joint_gap(a: np.ndarray, b: np.ndarray) -> float:
    """How far blocks a and b are from sharing a joint (mm): the second-smallest distance between a
    corner of a and one of b (a joint needs two pairs of corners)."""
    return float(np.sort(np.linalg.norm(a[:, None, :] - b[None, :, :], axis=2), axis=None)[1])


def _shared(a: np.ndarray, b: np.ndarray, tolerance: float) -> np.ndarray:
    """The joint between blocks a and b: its two corners, each the mean of the two blocks' corners."""
    return np.array([(a[i] + b[j]) / 2.0 for i, j in _touching(a, b, tolerance)])


def _chains(joints: list[np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    """The ring's two chains of joint corners: each joint's ends ordered so that a joint's first end
    is nearer the previous joint's first end (a voussoir's side joins the same chain)."""
    first, second = [joints[0][0]], [joints[0][1]]
    for joint in joints[1:]:
        keep = np.linalg.norm(joint[0] - first[-1]) + np.linalg.norm(joint[1] - second[-1])
        swap = np.linalg.norm(joint[1] - first[-1]) + np.linalg.norm(joint[0] - second[-1])
        a, b = (joint[0], joint[1]) if keep <= swap else (joint[1], joint[0])
        first.append(a)
        second.append(b)
    return np.array(first), np.array(second)
