"""The live load a run holds while its support moves, on its collapse figure: an arrow onto the load's
resultant, carried by the blocks it stands on, or sideways above the arch for an acceleration."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from matplotlib.axes import Axes
from matplotlib.patches import FancyArrow

from yadearch.analysis.blocks import block_centroids, placed_points
from yadearch.case.config import case_from_dict
from yadearch.case.held import held_multiplier
from yadearch.case.mechanics import live_load
from yadearch.model.geometry import ArchGeometry
from yadearch.model.loads import UNITS, VERTICAL, live_load_points
from yadearch.plotting.house import MIN_TEXT_PT

MM = 1e3
ARROW_SPAN = 0.12  # the arrow's length, of the span
WIDTH_SPAN = 0.004  # its shaft's width, of the span
GAP_SPAN = 0.01  # between its head and the extrados, of the span
ABOVE_SPAN = 0.08  # an acceleration's arrow above the arch's highest point, of the span


@dataclass(frozen=True)
class HeldArrow:
    """Where the held load's arrow starts and ends (mm) and what it says."""

    tail: np.ndarray
    head: np.ndarray
    text: str


def held_arrow(
    stored: dict[str, Any], geometry: ArchGeometry, snapshot: dict[str, Any], outlines_mm: np.ndarray
) -> HeldArrow | None:
    """The arrow of the live load a run's case (`stored`: its case.toml) holds (None: none held), in the
    snapshot's state whose blocks' corners are `outlines_mm`: onto its resultant's point on the extrados
    along the load, or, for an acceleration, sideways over the highest corner."""
    case = case_from_dict({key: stored[key] for key in ("geometry", "imperfections", "loads") if key in stored})
    held = held_multiplier(case)
    if held <= 0.0:
        return None
    span = geometry.span * MM
    text = (
        f"held {'load' if case.loads.live_load == VERTICAL else 'acceleration'} {held:g} {UNITS[case.loads.live_load]}"
    )
    if case.loads.live_load != VERTICAL:
        sign = 1.0 if case.loads.acceleration_toward == "right" else -1.0
        y = float(outlines_mm[:, 1].max()) + ABOVE_SPAN * span
        x = float(outlines_mm[:, 0].mean())
        return HeldArrow(
            np.array([x - sign * ARROW_SPAN * span / 2, y]), np.array([x + sign * ARROW_SPAN * span / 2, y]), text
        )
    weights = np.zeros(len(geometry.blocks))  # a vertical load does not read them
    points = live_load_points(geometry, block_centroids(geometry), weights, live_load(case, geometry))
    placed = placed_points(geometry, snapshot, points.block, points.point) * MM
    size = np.linalg.norm(points.force, axis=1)
    at = (placed * size[:, None]).sum(axis=0) / size.sum()
    along = points.force.sum(axis=0) / np.linalg.norm(points.force.sum(axis=0))
    head = at - GAP_SPAN * span * along
    return HeldArrow(head - ARROW_SPAN * span * along, head, text)


def draw_held_arrow(ax: Axes, arrow: HeldArrow, span_mm: float) -> None:
    """The arrow and its words at its tail."""
    dx, dy = arrow.head - arrow.tail
    ax.add_patch(
        FancyArrow(*arrow.tail, dx, dy, width=WIDTH_SPAN * span_mm, color="k", length_includes_head=True, zorder=4)
    )
    ax.annotate(arrow.text, arrow.tail, xytext=(3, 2), textcoords="offset points", fontsize=MIN_TEXT_PT)
