"""A hinge drawn on an arch figure: its pivot as a dot and its label, pointing out of the arch for an
extrados hinge and into it for an intrados one, then moved round its dot until it clears the blocks,
the other labels and the axes' edge (the collapse figure and the thrust-line figure)."""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.text import Annotation

from yadearch.plotting.house import MIN_TEXT_PT
from yadearch.plotting.labels import layout, place_label

HINGE_LABEL_OFFSET_PT = 5  # a hinge's label from its dot (points)


def mark_hinge(ax: Axes, point: np.ndarray, text: str, side: str, colour: str) -> tuple[Annotation, np.ndarray]:
    """A hinge's pivot (mm) as a dot with its label, and the side the label prefers: away from the
    arch's centre (the origin) for an extrados hinge, toward it for an intrados one."""
    outward = point / np.linalg.norm(point)
    direction = outward if side == "E" else -outward
    ax.plot(*point, "o", ms=4, mfc=colour, mec="white", mew=0.5, zorder=4)
    label = ax.annotate(
        text,
        point,
        xytext=direction * HINGE_LABEL_OFFSET_PT,
        textcoords="offset points",
        color=colour,
        fontsize=MIN_TEXT_PT,
        fontweight="bold",
        zorder=5,
    )
    label.set_in_layout(False)  # kept inside the axes by its placement: it must not move them as it moves
    return label, direction


def place_hinge_labels(ax: Axes, marks: list[tuple[Annotation, np.ndarray]]) -> None:
    """Each hinge label of `marks` moved round its dot, from its preferred side, to where it clears the
    blocks, the labels placed before it and the axes' edge (call once the axes' limits are set)."""
    layout(ax.figure)
    for label, direction in marks:
        place_label(ax, label, direction, HINGE_LABEL_OFFSET_PT)
