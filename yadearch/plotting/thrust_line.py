"""The thrust-line figure of a rigid-block limit analysis: the blocks placed at du_rigid over the
undeformed arch, the line of the contact resultants through every interface, the hinges labelled.

House style of `yadearch.figures` (8 pt, journal column, constrained layout, matplotlib's Figure
without pyplot, so no backend is chosen at import).
"""

from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.text import Annotation

from yadearch.case.config import ArchCase
from yadearch.case.held import held_load_text
from yadearch.case.mechanics import arch_geometry
from yadearch.model.geometry import ArchGeometry, front_face
from yadearch.model.hinges import paper_labels
from yadearch.model.joints import rotate
from yadearch.plotting.blocks import block_legend_entries, draw_blocks
from yadearch.plotting.hinge_marks import mark_hinge, place_hinge_labels
from yadearch.plotting.house import (
    AXIS_MARGINS_CM,
    COLUMN_CM,
    LABEL_ROOM,
    STYLE,
    THRUST_COLOUR,
    hinge_colour,
    new_figure,
    save_figure,
)
from yadearch.solve.limit_result import LimitResult

M_TO_MM = 1e3
TITLE_CM = 0.4  # the title's row above the axes
LEGEND_ROW_CM = 0.45  # the legend's row below the x label
LEGEND_BELOW_AXES = -0.26  # the legend's top, in axes heights below the axes (under the x label), in a given axes
X_LABEL_CM = 0.95  # the tick labels' and the x label's height under the axes


def placed_outlines(result: LimitResult, geometry: ArchGeometry) -> list[np.ndarray]:
    """Front-face outline (mm) of every block as the result places it at du_rigid."""
    outlines = []
    for vertices, rot, shift in zip(geometry.blocks, result.rotation_rad, result.shift_mm):
        front = front_face(vertices) * M_TO_MM
        outlines.append(rotate(front, rot) + np.asarray(shift))
    return outlines


def hinge_points(result: LimitResult) -> dict[str, np.ndarray]:
    """Pivot corner (mm) of each hinge to mark: the collapse mechanism's, else those still active."""
    labels = result.collapse_hinges or tuple(h.label for h in result.hinge_history if h.to_mm is None)
    points = {}
    for label in labels:
        force = result.forces[int(label[:-1]) - 1]
        points[label] = np.asarray(force.intrados_mm if label[-1] == "I" else force.extrados_mm)
    return points


def plot_thrust_line(result: LimitResult, geometry_or_case: ArchGeometry | ArchCase, ax: Axes | None = None) -> Figure:
    """Draw the arch at du_rigid with its thrust line and hinges into `ax` (a new column-wide figure
    if None); returns the figure."""
    geometry = geometry_or_case
    if not isinstance(geometry, ArchGeometry):
        geometry = arch_geometry(geometry)
    held = held_load_text(geometry_or_case) if isinstance(geometry_or_case, ArchCase) else ""  # a run's load
    with matplotlib.rc_context(STYLE):
        outlines = placed_outlines(result, geometry)
        undeformed = [front_face(b) * M_TO_MM for b in geometry.blocks]
        all_xy = np.vstack(undeformed + outlines)
        width = np.ptp(all_xy[:, 0])
        xlim = (all_xy[:, 0].min() - LABEL_ROOM * width, all_xy[:, 0].max() + LABEL_ROOM * width)
        ylim = (all_xy[:, 1].min() - 0.03 * width, all_xy[:, 1].max() + 0.10 * width)
        if ax is None:
            axes_width = COLUMN_CM - AXIS_MARGINS_CM[0]
            titles = TITLE_CM * (2 if held else 1)  # a held load's line under the title
            drawing_cm = axes_width * np.ptp(ylim) / np.ptp(xlim)
            fig = new_figure(height_cm=drawing_cm + AXIS_MARGINS_CM[1] + titles + LEGEND_ROW_CM)
            ax = fig.add_subplot()
            below = -X_LABEL_CM / drawing_cm  # the legend's top under the x label, whatever the arch's height
        else:
            below = LEGEND_BELOW_AXES
        marks = _draw(ax, result, undeformed, outlines)
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, below), ncols=3, handlelength=1.5, frameon=False)
        ax.set_aspect("equal")
        ax.set_xlim(*xlim)
        ax.set_ylim(*ylim)
        ax.set_xlabel("x (mm)")
        ax.set_ylabel("y (mm)")
        du = result.du_rigid_mm
        state = rf"$d_{{u,\mathrm{{rigid}}}}$ = {du:.2f} mm" if du is not None else "no collapse"
        ax.set_title(f"{result.name}: rigid blocks, {state}" + (f"\n{held} held" if held else ""))
        place_hinge_labels(ax, marks)
    return ax.figure


def _draw(
    ax: Axes, result: LimitResult, undeformed: list[np.ndarray], outlines: list[np.ndarray]
) -> list[tuple[Annotation, np.ndarray]]:
    """Blocks, thrust line, hinges and the legend's entries; the hinges' labels with their preferred sides."""
    draw_blocks(ax, outlines, undeformed)
    thrust = np.array([f.thrust_mm for f in result.forces])
    ax.plot(thrust[:, 0], thrust[:, 1], color=THRUST_COLOUR, lw=0.9, marker="o", ms=1.2, zorder=3, label="thrust line")
    points = hinge_points(result)
    letters = paper_labels([(int(h[:-1]), h[-1], 0.0) for h in points], len(result.forces))
    marks = [
        mark_hinge(
            ax,
            point,
            f"{label} (new)" if label in result.new_at_collapse else label,
            label[-1],
            hinge_colour(letters.get((int(label[:-1]), label[-1]), ""), k),
        )
        for k, (label, point) in enumerate(points.items())
    ]
    block_legend_entries(ax, "at the limit")
    return marks


def save_thrust_line(result: LimitResult, geometry_or_case: ArchGeometry | ArchCase, stem: Path) -> tuple[Path, Path]:
    """The thrust-line figure as `stem`.pdf (vector) and `stem`.png (300 dpi), each written atomically."""
    fig = plot_thrust_line(result, geometry_or_case)
    with matplotlib.rc_context(STYLE):  # font embedding and dpi are read when saving
        return save_figure(fig, stem)
