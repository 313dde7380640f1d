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
WIDENINGS = 2  # times the axes are widened for a label reaching past their side
LABEL_PAD_PX = 4.0  # room left beside such a label


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
    blocks, the labels placed before it and the axes' edge (call once the axes' limits are set); where
    one still reaches past a side of the axes (a wide arch's labels at its springings), the axes widened
    by that much each side and the labels placed again."""
    for widened in range(WIDENINGS + 1):
        layout(ax.figure)
        for label, direction in marks:
            place_label(ax, label, direction, HINGE_LABEL_OFFSET_PT)
        layout(ax.figure)
        box = ax.get_window_extent()
        over_px = max([0.0] + [max(box.x0 - b.x0, b.x1 - box.x1) for b in (m.get_window_extent() for m, _ in marks)])
        if over_px <= 0.0 or widened == WIDENINGS:
            return
        low, high = ax.get_xlim()
        more = (over_px + LABEL_PAD_PX) * (high - low) / box.width
        ax.set_xlim(low - more, high + more)
