"""The arch's blocks as every figure and movie draws them: one collection for the filled blocks (the
two supports grey) and one for the dashed undeformed outlines, not a patch a block (a strip of four
states of 57 blocks draws in a fraction of the time), tagged so that labels keep clear of them."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from matplotlib.axes import Axes
from matplotlib.collections import PolyCollection
from matplotlib.patches import Polygon

BLOCK_COLOUR, SUPPORT_COLOUR = "#EADDCA", "0.45"
EDGE_COLOUR = "0.15"
UNDEFORMED_COLOUR = "0.65"
BLOCKS_GID = "yadearch-blocks"  # the filled blocks' collection: `labels` places texts clear of it


def draw_blocks(
    ax: Axes,
    outlines: Sequence[np.ndarray],
    undeformed: Sequence[np.ndarray] | None = None,
    edge: str = EDGE_COLOUR,
    undeformed_colour: str = UNDEFORMED_COLOUR,
) -> PolyCollection:
    """Draw the blocks' outlines (mm, the first and last the supports) filled, over the `undeformed`
    ones dashed; returns the filled collection."""
    if undeformed is not None:
        ax.add_collection(
            PolyCollection(
                list(undeformed),
                closed=True,
                facecolors="none",
                edgecolors=undeformed_colour,
                linewidths=0.4,
                linestyles="--",
                zorder=1,
            )
        )
    last = len(outlines) - 1
    faces = [SUPPORT_COLOUR if b in (0, last) else BLOCK_COLOUR for b in range(len(outlines))]
    blocks = PolyCollection(list(outlines), closed=True, facecolors=faces, edgecolors=edge, linewidths=0.3, zorder=2)
    blocks.set_gid(BLOCKS_GID)
    ax.add_collection(blocks)
    return blocks


def block_legend_entries(ax: Axes, label: str) -> None:
    """Legend entries for the drawing: the undeformed outline (dashed) and the blocks as `label`."""
    ax.plot([], [], color=UNDEFORMED_COLOUR, lw=0.6, ls="--", label="undeformed")
    ax.add_patch(Polygon(np.zeros((3, 2)), fc=BLOCK_COLOUR, ec=EDGE_COLOUR, lw=0.3, label=label))
