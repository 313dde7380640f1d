"""Labels that stay readable: a label is moved round its point until it clears the drawing's blocks,
the other labels, the legends and the axes' edge, and `label_clashes` lists what still overlaps (the figure tests
assert none does). Both work on the figure as drawn, in display coordinates."""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.backend_bases import RendererBase
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.legend import Legend
from matplotlib.patches import Polygon
from matplotlib.path import Path
from matplotlib.text import Annotation, Text
from matplotlib.transforms import Bbox

from yadearch.plotting.blocks import BLOCKS_GID

TURNS_DEG = (0.0, 45.0, -45.0, 90.0, -90.0, 135.0, -135.0, 180.0)  # tried in turn from the preferred side
OBSTACLE_GID = "yadearch-obstacle"  # a line that labels keep clear of, as of the blocks
PAD_PX = 1.0  # a label this close to something touches it
FARTHER = 2.5  # where no direction is clear at the label's distance, they are tried this much farther
CORNERS = (  # axes positions and alignments of a corner text, in the order tried
    ((0.01, 0.02), ("left", "bottom")),
    ((0.01, 0.98), ("left", "top")),
    ((0.99, 0.02), ("right", "bottom")),
    ((0.99, 0.98), ("right", "top")),
)


def place_label(ax: Axes, label: Annotation, preferred: np.ndarray, offset_pt: float) -> None:
    """Move `label` (offset from its point in points) to the first direction, turning away from
    `preferred` (a unit vector), where it clears the blocks, the labels already placed and the edge."""
    renderer = _renderer(ax.figure)
    for distance in (offset_pt, FARTHER * offset_pt):
        for turn in np.radians(TURNS_DEG):
            c, s = np.cos(turn), np.sin(turn)
            direction = np.array([c * preferred[0] - s * preferred[1], s * preferred[0] + c * preferred[1]])
            _aim(label, direction, distance)
            if not _clashes(ax, label, renderer):
                return
    _aim(label, preferred, offset_pt)  # nowhere clear: the preferred side, and the tests will say so


def place_corner(ax: Axes, text: Text) -> None:
    """Put `text` (in axes coordinates) in the first corner, lower left first, where it clears the blocks."""
    renderer = _renderer(ax.figure)
    for (x, y), (ha, va) in CORNERS:
        text.set_position((x, y))
        text.set_ha(ha)
        text.set_va(va)
        if not _clashes(ax, text, renderer):
            return
    text.set_position(CORNERS[0][0])
    text.set_ha(CORNERS[0][1][0])
    text.set_va(CORNERS[0][1][1])


def label_clashes(fig: Figure) -> list[str]:
    """Every text of the figure's axes that overlaps a block, another text or its axes' edge, and
    every legend that covers a block or a text."""
    renderer = _renderer(fig)
    fig.canvas.draw()
    texts = [
        f"{text.get_text()!r} in axes {k}"
        for k, ax in enumerate(fig.axes)
        for text in ax.texts
        if text.get_text().strip() and _clashes(ax, text, renderer)
    ]
    return texts + [
        f"the legend {[t.get_text() for t in legend.get_texts()]}"
        for legend in _legends(fig)
        if _covers(fig, legend.get_window_extent(renderer), renderer)
    ]


def layout(fig: Figure) -> None:
    """Lay the figure out as it will be saved, so that texts can be measured where they will be."""
    _renderer(fig)
    fig.canvas.draw()


def _renderer(fig: Figure) -> RendererBase:
    """The renderer that measures text as the figure will be saved (Agg, at the figure's dpi)."""
    if not isinstance(fig.canvas, FigureCanvasAgg):
        FigureCanvasAgg(fig)
    return fig.canvas.get_renderer()


def _aim(label: Annotation, direction: np.ndarray, offset_pt: float) -> None:
    label.xyann = (offset_pt * direction[0], offset_pt * direction[1])
    label.set_ha(_anchor(direction[0], ("right", "center", "left")))
    label.set_va(_anchor(direction[1], ("top", "center", "bottom")))


def _anchor(component: float, names: tuple[str, str, str]) -> str:
    """The alignment that puts a text on the side `component` (of a unit vector) points to."""
    return names[0] if component < -0.4 else names[2] if component > 0.4 else names[1]


def _clashes(ax: Axes, text: Text, renderer: RendererBase) -> bool:
    box = text.get_window_extent(renderer).padded(PAD_PX)
    if not _inside(box, ax.get_window_extent(renderer)):
        return True
    others = (t for t in ax.texts if t is not text and t.get_text().strip() and t.get_visible())
    if any(box.overlaps(t.get_window_extent(renderer)) for t in others):
        return True
    if any(box.overlaps(legend.get_window_extent(renderer)) for legend in _legends(ax.figure)):
        return True
    return any(path.intersects_bbox(box, filled=True) for path in _block_paths(ax))


def _legends(fig: Figure) -> list[Legend]:
    """The figure's legends and its axes'."""
    return [*fig.legends, *(ax.get_legend() for ax in fig.axes if ax.get_legend() is not None)]


def _covers(fig: Figure, box: Bbox, renderer: RendererBase) -> bool:
    """Whether `box` overlaps a text or a block of any of the figure's axes."""
    for ax in fig.axes:
        others = (t for t in ax.texts if t.get_text().strip() and t.get_visible())
        if any(box.overlaps(t.get_window_extent(renderer)) for t in others):
            return True
        if any(path.intersects_bbox(box, filled=True) for path in _block_paths(ax)):
            return True
    return False


def _block_paths(ax: Axes) -> list[Path]:
    """The outlines of the axes' filled blocks in display coordinates: filled polygon patches and the
    blocks' collection (`plotting.blocks`)."""
    paths = [
        p.get_transform().transform_path(p.get_path())
        for p in ax.patches
        if isinstance(p, Polygon) and p.get_fill() and p.get_path().get_extents().width > 0.0  # not a legend's proxy
    ]
    for collection in ax.collections:
        if collection.get_gid() == BLOCKS_GID:
            transform = collection.get_transform()
            paths.extend(transform.transform_path(path) for path in collection.get_paths())
    for line in ax.lines:  # lines a label must not cross (a load's dispersal through the fill)
        if line.get_gid() == OBSTACLE_GID:
            paths.append(line.get_transform().transform_path(line.get_path()))
    return paths


def _inside(box: Bbox, frame: Bbox) -> bool:
    return box.x0 >= frame.x0 and box.x1 <= frame.x1 and box.y0 >= frame.y0 and box.y1 <= frame.y1
