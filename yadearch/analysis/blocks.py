"""The arch's blocks from a run's case.toml, undeformed and as placed by a snapshot (pure numpy)."""

from __future__ import annotations

from typing import Any

import numpy as np

from yadearch.case.config import case_from_dict
from yadearch.case.mechanics import arch_geometry
from yadearch.model.geometry import ArchGeometry, front_face, polygon_centroid
from yadearch.model.joints import block_outlines

MM = 1e-3


def case_geometry(case: dict[str, Any]) -> ArchGeometry:
    """The SI geometry of the [geometry] and [imperfections] sections of a run's case.toml, built as the
    run built it (a case.toml older than a parameter takes its default: the segmental arch)."""
    return arch_geometry(case_from_dict({key: case[key] for key in ("geometry", "imperfections") if key in case}))


def block_centroids(geometry: ArchGeometry) -> np.ndarray:
    """(n_blocks, 2) centroids of the prisms: YADE's body positions before anything moves."""
    return np.array([polygon_centroid(front_face(b)) for b in geometry.blocks])


def snapshot_outlines(geometry: ArchGeometry, snapshot: dict[str, Any]) -> list[np.ndarray]:
    """Front-face outline (m) of every block as placed in a snapshots.json entry."""
    pos = np.asarray(snapshot["pos_m"], float)
    rot = np.asarray(snapshot["rot_rad"], float)
    return block_outlines(geometry, block_centroids(geometry), pos, rot)


def _placed(point: np.ndarray, block: int, pos0: np.ndarray, pos: np.ndarray, rot: np.ndarray) -> np.ndarray:
    c, s = np.cos(rot[block]), np.sin(rot[block])
    d = point - pos0[block]
    return pos[block] + np.array([c * d[0] - s * d[1], s * d[0] + c * d[1]])


def placed_points(
    geometry: ArchGeometry, snapshot: dict[str, Any], blocks: np.ndarray, points: np.ndarray
) -> np.ndarray:
    """(k, 2) points (m) given on the undeformed blocks `blocks`, carried by them to the snapshot's poses."""
    pos0 = block_centroids(geometry)
    pos, rot = np.asarray(snapshot["pos_m"], float), np.asarray(snapshot["rot_rad"], float)
    return np.array([_placed(p, int(b), pos0, pos, rot) for b, p in zip(blocks, points)]).reshape(-1, 2)


def joint_points(geometry: ArchGeometry, snapshot: dict[str, Any], side: str) -> np.ndarray:
    """(n_joints, 2) intrados (side "I") or extrados ("E") end of every joint, carried by the block on
    its left, as placed in the snapshot (m): where a hinge's pivot is drawn."""
    corners = np.array([j.intrados if side == "I" else j.extrados for j in geometry.joints])
    return placed_points(geometry, snapshot, np.array([j.left for j in geometry.joints]), corners)


def tangential_slip_mm(geometry: ArchGeometry, snapshot: dict[str, Any]) -> np.ndarray:
    """Slip of every joint (mm): displacement of the right block relative to the left at the joint's
    mid-point, along the joint. A hinge rotation about either edge gives almost none."""
    pos0 = block_centroids(geometry)
    pos, rot = np.asarray(snapshot["pos_m"], float), np.asarray(snapshot["rot_rad"], float)
    slips = []
    for j in geometry.joints:
        mid = (j.intrados + j.extrados) / 2.0
        relative = _placed(mid, j.right, pos0, pos, rot) - _placed(mid, j.left, pos0, pos, rot)
        along = j.extrados - j.intrados
        c, s = np.cos(rot[j.left]), np.sin(rot[j.left])
        along_now = np.array([c * along[0] - s * along[1], s * along[0] + c * along[1]])
        slips.append(float(relative @ along_now / np.linalg.norm(along_now)) / MM)
    return np.array(slips)
