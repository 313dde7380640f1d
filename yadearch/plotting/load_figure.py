"""The figure of a live load's collapse (`yadearch loads`): the arch at rest, the line of the contact
resultants at the collapse load through every joint, the mechanism's hinges, and the load (an arrow at
its position, or the acceleration's direction)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from matplotlib.patches import FancyArrow

from yadearch.case.config import ArchCase
from yadearch.case.mechanics import backfill, load_position
from yadearch.model.backfill import fill_surface
from yadearch.model.dispersal import NONE as NOT_DISPERSED
from yadearch.model.geometry import ArchGeometry, front_face
from yadearch.model.loads import VERTICAL, extrados_height, extrados_segments
from yadearch.plotting.blocks import draw_blocks
from yadearch.plotting.house import (
    AXIS_MARGINS_CM,
    CM,
    COLUMN_CM,
    THRUST_COLOUR,
    house_style,
    mechanism_colour,
    new_figure,
    save_figure,
)
from yadearch.plotting.labels import OBSTACLE_GID, layout, place_label
from yadearch.solve.load_lp import LoadCapacity

MM = 1e3
LABEL_PT, OFFSET_PT = 7, 5
HEIGHT_CM = 6.5  # before the figure is fitted to its drawing
LEGEND_ROW_PT = 15  # a legend row between the title and the axes
TITLE_CM = 0.5
GAP = 0.01  # of the span: between the load's arrow and the extrados


def thrust_points(geometry: ArchGeometry, result: LoadCapacity) -> np.ndarray:
    """(joints, 2) where the resultant of each joint's corner forces crosses it (mm; NaN where none)."""
    intrados = np.array([j.intrados[:2] for j in geometry.joints])
    extrados = np.array([j.extrados[:2] for j in geometry.joints])
    total = result.normal.sum(axis=1)
    share = np.divide(result.normal[:, 1], total, out=np.full(len(total), np.nan), where=total > 0)
    return (intrados + share[:, None] * (extrados - intrados)) * MM


@house_style
def plot_load_collapse(case: ArchCase, geometry: ArchGeometry, result: LoadCapacity, stem: Path) -> tuple[Path, Path]:
    """STEM.pdf and .png: the arch, the thrust line at collapse, the hinges and the load."""
    fig = new_figure(height_cm=HEIGHT_CM, width_cm=COLUMN_CM)
    ax = fig.add_subplot()
    draw_blocks(ax, [front_face(vertices) * MM for vertices in geometry.blocks], edge="0.2")
    points = thrust_points(geometry, result)
    ax.plot(points[:, 0], points[:, 1], "-", color=THRUST_COLOUR, lw=0.9, label="thrust line at collapse")
    labels = []
    for k, pivot in enumerate(result.pivots):
        joint = geometry.joints[pivot.joint]
        corner = (joint.intrados if pivot.side == 0 else joint.extrados)[:2] * MM
        across = (joint.extrados - joint.intrados)[:2]
        across = across / np.linalg.norm(across)
        ax.plot(*corner, "o", ms=4, mfc=mechanism_colour(k), mec="white", mew=0.5, zorder=4)
        label = ax.annotate(pivot.label, corner, xytext=(0, 0), textcoords="offset points", color=mechanism_colour(k))
        label.set_fontsize(LABEL_PT)
        labels.append((label, across if pivot.side == 1 else -across))
    _draw_load(ax, case, geometry)
    ax.set_aspect("equal")
    ax.margins(0.12)
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    ax.plot([], [], "o", ms=4, mfc="0.5", mec="white", mew=0.5, label="hinge (I, E: at the intrados, extrados)")
    rows = len(ax.get_legend_handles_labels()[1])
    ax.set_title(
        f"{case.name}, rigid blocks: collapse at {result.multiplier:.4g} {result.unit}",
        fontsize=LABEL_PT + 1,
        pad=LEGEND_ROW_PT * rows,
    )
    # rows between the title and the axes: inside, any corner may hold the load's arrow or a hinge
    ax.legend(loc="lower center", bbox_to_anchor=(0.5, 1.0), frameon=False, fontsize=LABEL_PT, handlelength=1.2)
    ax.autoscale_view()  # the figure as tall as the drawing at the column's width: no empty band
    xlim, ylim = ax.get_xlim(), ax.get_ylim()
    drawing_cm = (COLUMN_CM - AXIS_MARGINS_CM[0]) * (ylim[1] - ylim[0]) / (xlim[1] - xlim[0])
    fig.set_size_inches(COLUMN_CM * CM, (drawing_cm + AXIS_MARGINS_CM[1] + TITLE_CM) * CM + rows * LEGEND_ROW_PT / 72)
    layout(fig)
    for label, away in labels:
        place_label(ax, label, away, OFFSET_PT)
    return save_figure(fig, stem)


def _draw_dispersal(ax, case: ArchCase, geometry: ArchGeometry, x: float, half: float, surface: float) -> None:
    """The load's spread through the fill (mm): from its edges on the surface to the extrados as far as
    the dispersal reaches, the fill's depth under the load x the tangent of its angle either side."""
    segments = extrados_segments(geometry)
    depth = surface - extrados_height(segments, x / MM) * MM
    reach = half + depth * math.tan(math.radians(case.loads.load_dispersal_deg))
    for side in (-1.0, 1.0):
        end = x + side * reach
        ends = ([x + side * half, end], [surface, extrados_height(segments, end / MM) * MM])
        ax.plot(*ends, "-", color="0.3", lw=0.6, gid=OBSTACLE_GID)  # a hinge's label keeps clear of it


def _draw_load(ax, case: ArchCase, geometry: ArchGeometry) -> None:
    """An arrow onto the extrados (or the fill dispersing it) at the vertical load's centre and at each
    further load's, leaning as the load does (its spread as a bar), or one sideways above the crown for
    an acceleration."""
    span = geometry.span * MM
    top = max(float(b[:, 1].max()) for b in geometry.blocks) * MM
    length = 0.15 * span
    fill = backfill(case)
    if fill.present:  # the fill's level surface, where a dispersed load stands
        top = fill_surface(geometry, fill) * MM
        ends = [geometry.joints[0].extrados[0] * MM, geometry.joints[-1].extrados[0] * MM]
        ax.plot(
            ends, [top, top], "--", color="0.45", lw=0.8, label=f"fill surface ({case.loads.fill_depth_mm:g} mm deep)"
        )
    if case.loads.live_load == VERTICAL:
        centre = (geometry.joints[0].intrados[0] + load_position(case, geometry)) * MM
        half = case.loads.load_width_mm / 2.0
        lean = math.radians(case.loads.load_inclination_deg)
        dispersed = case.loads.load_dispersal != NOT_DISPERSED
        segments = extrados_segments(geometry)
        for offset_mm, ratio in [(0.0, 1.0), *case.loads.further_loads]:
            x, arrow = centre + offset_mm, 0.9 * length * min(ratio, 1.0)  # a lighter load, a shorter arrow
            # on the fill it disperses through, or where it acts: on the extrados under its centre
            tip = top if dispersed else (extrados_height(segments, x / MM) * MM + GAP * span)
            if half > 0.0:
                ax.plot([x - half, x + half], [tip + 0.02 * span] * 2, "-", color="k", lw=1.5)
            dx, dy = arrow * math.sin(lean), -arrow * math.cos(lean)
            ax.add_patch(FancyArrow(x - dx, tip - dy, dx, dy, width=0.004 * span, color="k", length_includes_head=True))
            if dispersed:
                _draw_dispersal(ax, case, geometry, x, half, top)
    else:
        sign = 1.0 if case.loads.acceleration_toward == "right" else -1.0
        ax.add_patch(
            FancyArrow(
                -sign * length / 2,
                top + 0.1 * span,
                sign * length,
                0.0,
                width=0.004 * span,
                color="k",
                length_includes_head=True,
            )
        )
        ax.annotate(
            "a", (0.0, top + 0.1 * span), xytext=(0, 4), textcoords="offset points", ha="center", fontsize=LABEL_PT
        )
