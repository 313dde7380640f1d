"""Figures of a run for a paper: the arch at collapse with its hinges, support reactions, hinge
openings and crown displacement against the support displacement delta ("settlement" when it moves
straight down).
(in the house style, `plotting.house`)."""

from __future__ import annotations

from functools import partial
from pathlib import Path
from typing import cast

import numpy as np
import pandas as pd
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.ticker import MaxNLocator

from yadearch.analysis.blocks import case_geometry, joint_points, snapshot_outlines
from yadearch.analysis.run import RunAnalysis
from yadearch.errors import RunFolderError
from yadearch.model.geometry import front_face
from yadearch.plotting.blocks import block_legend_entries, draw_blocks
from yadearch.plotting.held_load import draw_held_arrow, held_arrow
from yadearch.plotting.hinge_marks import mark_hinge, place_hinge_labels
from yadearch.plotting.house import (
    AXIS_MARGINS_CM,
    COLUMN_CM,
    LABEL_ROOM,
    hinge_colour,
    house_style,
    new_figure,
    save_figure,
)
from yadearch.plotting.parallel import Drawing, draw_all
from yadearch.plotting.states import plot_strip
from yadearch.results.rundir import STIFFNESS_COLUMN, RunFolder
from yadearch.solve.stages import Stage

LEFT_COLOUR, RIGHT_COLOUR = "#0072B2", "#D55E00"
PAST_DU_ALPHA = 0.35
LEGEND_ROWS_CM = 0.9  # the collapse figure's two legend rows above the arch
COORDINATE_TICKS = 6  # the collapse figure's x ticks at most: a wide arch's coordinates in mm are long labels
PATH_HEADROOM = 1.15  # the hinge figure's scale: the largest value on the path, with this room
SETTLEMENT_DEG = -90.0  # a support moving straight down settles; any other direction is a displacement


def delta_label(case: dict) -> str:
    """The x-axis label: "settlement" for a support moving straight down, else "displacement" in the
    direction the moving support itself takes (the left one mirrors the right one's), or along its
    path for a turning support or a prescribed path."""
    loading = case.get("loading", {})
    side = loading.get("moving_support", "right")
    who = "supports" if side == "both" else f"{side} support"
    if loading.get("support_motion", "translation") != "translation":
        return rf"{who} displacement along its path $\delta$ (mm)"
    direction = float(loading.get("support_direction_deg", SETTLEMENT_DEG))
    if side == "left":
        direction = 180.0 - direction - (360.0 if direction < 0.0 else 0.0)  # the mirror image, in (-180, 180]
    movement = "settlement" if direction == SETTLEMENT_DEG else f"displacement (at {direction:g}°)"
    return rf"{who} {movement} $\delta$ (mm)"


def loading_path(series: pd.DataFrame) -> pd.DataFrame:
    """Series rows on the equilibrium path: the end of the self-weight stage, then each accepted
    equilibrium of the loading (monotonic in delta); the moves and relaxations between them, and
    the increments that failed, are left out."""
    selfweight = series[series["stage"] == Stage.SELFWEIGHT].tail(1)
    equilibria = series[series["stage"] == Stage.EQUILIBRIUM]
    return pd.concat([selfweight, equilibria]).sort_values("delta_mm", kind="stable")


def _against_delta(run: RunFolder, height_cm: float) -> tuple[pd.DataFrame, np.ndarray, Figure]:
    """The loading path's rows, their support displacements (mm) and a new figure to draw them on."""
    path = loading_path(run.series)
    return path, path["delta_mm"].to_numpy(), new_figure(height_cm=height_cm)


def _mark_du(ax, du_mm: float | None, legend: bool = False) -> None:
    """A dotted vertical line at du, named in the legend of the axes that has one."""
    if du_mm is not None:
        ax.axvline(du_mm, color="0.4", lw=0.7, ls=":", zorder=0, label=rf"$d_u$ = {du_mm:.2f} mm" if legend else None)


def _plot_until_du(ax, delta: np.ndarray, value: np.ndarray, du_mm: float | None, **style) -> None:
    """A curve, solid up to du and faded past it (the arch is already running away there)."""
    if du_mm is None:
        ax.plot(delta, value, **style)
        return
    before = delta <= du_mm
    ax.plot(delta[before], value[before], **style)
    after = np.flatnonzero(~before)
    if len(after):
        tail = np.r_[after[0] - 1, after] if after[0] > 0 else after
        ax.plot(delta[tail], value[tail], **{**style, "label": None, "alpha": PAST_DU_ALPHA})


@house_style
def collapse_figure(
    run: RunFolder,
    analysis: RunAnalysis,
    ax: Axes | None = None,
    width_cm: float = COLUMN_CM,
    snapshot: str = "collapse",
) -> Figure:
    """The arch at collapse drawn to scale over its undeformed outline, hinges marked and labelled
    (label, pivot side), the counterpart of the paper's Fig. 9: into `ax`, or a new figure sized to
    the arch at `width_cm`; returns the figure."""
    geometry = case_geometry(run.case)
    state = run.snapshots.get(snapshot) or run.snapshots.get("end")
    if state is None:
        raise RunFolderError(f"{run.path} has no {snapshot!r} or 'end' snapshot to draw")
    outlines = snapshot_outlines(geometry, state)
    all_xy = np.vstack([front_face(b) for b in geometry.blocks] + outlines) * 1e3
    held = held_arrow(run.case, geometry, state, np.vstack(outlines) * 1e3)  # a load held while the support moved
    if held is not None:
        all_xy = np.vstack([all_xy, [held.tail]])
    span = np.ptp(all_xy[:, 0])
    xlim = (all_xy[:, 0].min() - LABEL_ROOM * span, all_xy[:, 0].max() + LABEL_ROOM * span)
    ylim = (all_xy[:, 1].min() - 0.03 * span, all_xy[:, 1].max() + 0.07 * span)
    own_figure = ax is None
    if ax is None:
        axes_width_cm = width_cm - AXIS_MARGINS_CM[0]
        height_cm = axes_width_cm * np.ptp(ylim) / np.ptp(xlim) + AXIS_MARGINS_CM[1] + LEGEND_ROWS_CM
        ax = new_figure(height_cm=height_cm, width_cm=width_cm).add_subplot()
    undeformed = [front_face(vertices) * 1e3 for vertices in geometry.blocks]
    draw_blocks(ax, [moved * 1e3 for moved in outlines], undeformed)
    pivots = {side: joint_points(geometry, state, side) * 1e3 for side in ("I", "E")}
    marks = [
        mark_hinge(
            ax,
            pivots[track.side][track.interface - 1],
            f"{track.paper_label} ({track.interface}{track.side})"
            if track.paper_label
            else f"{track.interface}{track.side}",
            track.side,
            hinge_colour(track.paper_label, k),
        )
        for k, track in enumerate(analysis.tracks)
    ]
    blocks = rf"$\delta$ = {state['delta_mm']:.2f} mm"
    if snapshot == "collapse" and analysis.du_mm is not None:  # the first state past the path's end
        blocks += rf", past $d_u$ = {analysis.du_mm:.2f} mm"
    block_legend_entries(ax, blocks)
    if held is not None:
        draw_held_arrow(ax, held, span)
    if own_figure:  # rows above the drawing, room made for them: inside, a free corner may be a hinge label's
        ax.legend(loc="lower center", bbox_to_anchor=(0.5, 1.0), handlelength=1.5, frameon=False)
    else:  # a caller's axes: inside, under the crown, clear of a title or a panel above
        ax.legend(loc="lower center", handlelength=1.5)
    ax.set_aspect("equal")
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    ax.xaxis.set_major_locator(MaxNLocator(nbins=COORDINATE_TICKS))  # a wide arch's ticks in mm stay apart
    place_hinge_labels(ax, marks)
    return cast(Figure, ax.get_figure())


@house_style
def plot_collapse(
    run: RunFolder, analysis: RunAnalysis, stem: Path, width_cm: float = COLUMN_CM, snapshot: str = "collapse"
) -> tuple[Path, Path]:
    """`collapse_figure` written as STEM.pdf and STEM.png."""
    return save_figure(collapse_figure(run, analysis, width_cm=width_cm, snapshot=snapshot), stem)


@house_style
def plot_reactions(run: RunFolder, analysis: RunAnalysis, stem: Path) -> tuple[Path, Path]:
    """Vertical and horizontal forces of both supports on the arch against the settlement."""
    path, delta, fig = _against_delta(run, height_cm=9.0)
    top, bottom = fig.subplots(2, 1, sharex=True)
    for ax, component, name in ((top, "Ry", "vertical"), (bottom, "Rx", "horizontal")):
        for support, colour, ls in (("left", LEFT_COLOUR, "-"), ("right", RIGHT_COLOUR, "--")):
            _plot_until_du(
                ax,
                delta,
                path[f"{support}_{component}_N"].to_numpy(),
                analysis.du_mm,
                color=colour,
                ls=ls,
                label=f"{support} support",
            )
        _mark_du(ax, analysis.du_mm, legend=ax is top)
        ax.set_ylabel(f"{name} reaction (N)")
    top.legend(loc="best")
    bottom.set_xlabel(delta_label(run.case))
    return save_figure(fig, stem)


@house_style
def plot_hinge_openings(run: RunFolder, analysis: RunAnalysis, stem: Path) -> tuple[Path, Path]:
    """Opening and rotation of every hinge against the settlement, its formation marked; scaled to the
    equilibrium path, the runaway past du fading off the top."""
    delta = analysis.history.delta_mm
    fig = new_figure(height_cm=9.0)
    top, bottom = fig.subplots(2, 1, sharex=True)
    on_path = delta <= analysis.du_mm if analysis.du_mm is not None else np.ones(len(delta), bool)
    highest = {top: 0.0, bottom: 0.0}
    for k, track in enumerate(analysis.tracks):
        colour = hinge_colour(track.paper_label, k)
        label = (
            f"{track.paper_label}: {track.interface}{track.side}"
            if track.paper_label
            else f"{track.interface}{track.side}"
        )
        r = track.formed_record
        for ax, values, name in ((top, track.opening_mm, label), (bottom, track.rotation_mrad, None)):
            _plot_until_du(ax, delta, values, analysis.du_mm, color=colour, label=name)
            ax.plot(delta[r], values[r], "o", ms=3.5, color=colour)
            highest[ax] = max(highest[ax], float(np.nanmax(values[on_path], initial=0.0)))
    for ax in (top, bottom):
        _mark_du(ax, analysis.du_mm, legend=ax is top)
        # the runaway past du would dwarf the path: the scale is the path's, the collapse runs off it
        ax.set_ylim(0, PATH_HEADROOM * highest[ax] if highest[ax] > 0 else None)
    top.plot([], [], "o", ms=3.5, color="0.3", label="hinge formed")
    if analysis.tracks and np.any(~on_path):  # the faded lines: the states past the path's end
        top.plot([], [], color="0.3", alpha=PAST_DU_ALPHA, label="past $d_u$ (running away)")
    top.legend(loc="upper left", ncols=2)  # two columns: short enough to stay above the curves' start
    top.set_xlim(left=0.0)  # the path from the start, as the other figures of the run
    top.set_ylabel("hinge opening (mm)")
    bottom.set_ylabel("hinge rotation (mrad)")
    bottom.set_xlabel(delta_label(run.case))
    return save_figure(fig, stem)


@house_style
def plot_crown_displacement(run: RunFolder, analysis: RunAnalysis, stem: Path) -> tuple[Path, Path]:
    """Horizontal and vertical displacement of the crown voussoir against the settlement."""
    path, delta, fig = _against_delta(run, height_cm=5.5)
    ax = fig.add_subplot()
    _plot_until_du(ax, delta, path["crown_dx_mm"].to_numpy(), analysis.du_mm, color=LEFT_COLOUR, label="horizontal")
    _plot_until_du(
        ax, delta, path["crown_dy_mm"].to_numpy(), analysis.du_mm, color=RIGHT_COLOUR, ls="--", label="vertical"
    )
    _mark_du(ax, analysis.du_mm, legend=True)
    ax.legend(loc="lower left")
    ax.set_xlabel(delta_label(run.case))
    ax.set_ylabel("crown displacement (mm)")
    return save_figure(fig, stem)


@house_style
def plot_stability(run: RunFolder, analysis: RunAnalysis, stem: Path) -> tuple[Path, Path]:
    """The smallest eigenvalue of the free blocks' tangent stiffness at each equilibrium state: it
    falls toward zero as du, a fold of the equilibrium path, approaches (docs/numerics.md)."""
    path = loading_path(run.series).dropna(subset=[STIFFNESS_COLUMN])
    fig = new_figure(height_cm=5.0)
    ax = fig.add_subplot()
    ax.plot(path["delta_mm"], path[STIFFNESS_COLUMN], "o-", color=LEFT_COLOUR, ms=2.5, lw=0.8)
    ax.axhline(0.0, color="0.4", lw=0.6)
    _mark_du(ax, analysis.du_mm, legend=True)
    if analysis.du_mm is not None:  # a run that stands has no du to name
        ax.legend(loc="upper right")
    ax.set_xlabel(delta_label(run.case))
    ax.set_ylabel("smallest eigenvalue of $K_s$ (N/m)")
    ax.set_title("$K_s$: symmetric tangent, rotations × ring thickness", fontsize="small")
    return save_figure(fig, stem)


# what drawing each figure costs, relative (CPU seconds of set 2's static run, measured): splits the work
FIGURE_COSTS = {"strip": 0.83, "hinges": 0.40, "reactions": 0.37, "collapse": 0.26, "crown": 0.24, "stability": 0.22}


def write_figures(run: RunFolder, analysis: RunAnalysis, out: Path, jobs: int = 1) -> dict[str, tuple[Path, Path]]:
    """Every figure of a run into `out`; returns {name: (pdf, png)}: collapse (if the run has a final
    snapshot), reactions, hinges, crown, stability (if the run recorded it) and the strip of four
    states (if it kept its states). `jobs` 2 draws them in two processes (`plotting.parallel`)."""
    drawers = {"reactions": plot_reactions, "hinges": plot_hinge_openings, "crown": plot_crown_displacement}
    if STIFFNESS_COLUMN in run.series and run.series[STIFFNESS_COLUMN].notna().any():
        drawers["stability"] = plot_stability
    if run.snapshots.get("collapse") or run.snapshots.get("end"):
        drawers = {"collapse": plot_collapse, **drawers}
    if run.states is not None:  # runs written before states.npz have no strip
        drawers["strip"] = plot_strip
    draw_all(
        [Drawing(name, FIGURE_COSTS[name], partial(draw, run, analysis, out / name)) for name, draw in drawers.items()],
        jobs,
    )
    return {name: (out / f"{name}.pdf", out / f"{name}.png") for name in drawers}
