"""A hinge drawn on an arch figure: its pivot as a dot and its label, pointing out of the arch for an
extrados hinge and into it for an intrados one (the collapse figure and the thrust-line figure)."""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes

HINGE_LABEL_OFFSET_PT = 5  # a hinge's label from its dot (points)


def mark_hinge(ax: Axes, point: np.ndarray, text: str, side: str, colour: str) -> None:
    """A hinge's pivot (mm) as a dot with its label, pointing away from the arch's centre (the
    origin) for an extrados hinge and toward it for an intrados one."""
    outward = point / np.linalg.norm(point)
    direction = outward if side == "E" else -outward
    ax.plot(*point, "o", ms=4, mfc=colour, mec="white", mew=0.5, zorder=4)
    ax.annotate(
        text,
        point,
        xytext=direction * HINGE_LABEL_OFFSET_PT,
        textcoords="offset points",
        ha="left" if direction[0] > 0 else "right",
        va="bottom" if direction[1] > 0 else "top",
        color=colour,
        fontweight="bold",
        zorder=5,
    )
