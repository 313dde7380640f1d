"""Any recorded state of a run drawn to scale (states.npz): the blocks, the hinges open at that state
with the paper's letters, the line of the joints' contact-force resultants (the thrust line), the
support displacement (a live load's path: the load) and the moving support's reaction; and the strip
of four states (self-weight, a third and two thirds of du, collapse) written with every run's figures."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.text import Annotation

from yadearch.analysis.blocks import case_geometry, joint_points, snapshot_outlines
from yadearch.analysis.run import RunAnalysis, default_thresholds
from yadearch.errors import RunFolderError
from yadearch.model.geometry import ArchGeometry, front_face
from yadearch.model.hinges import Hinge, hinge_rotation, hinges_at
from yadearch.plotting.blocks import draw_blocks
from yadearch.plotting.house import MIN_TEXT_PT, THRUST_COLOUR, hinge_colour, house_style, new_figure, save_figure
from yadearch.plotting.labels import layout, place_corner, place_label
from yadearch.results.rundir import RunFolder
from yadearch.results.states import RunStates

MM_PER_M = 1e3
UNDEFORMED_COLOUR = "0.7"
UNLABELLED_COLOUR = "0.3"  # a hinge that is not one of the collapse mechanism's A-D
MARGIN = 0.1  # of the arch's span, above the drawing
SIDE_MARGIN = 0.15  # of the arch's span, either side: room for the labels of hinges at the springings
LABEL_OFFSET_PT = 5  # a hinge label's distance from its pivot, away from the ring
TEXT_SHARE = 0.35  # of a drawing's height, at least, below the arch: the corner texts' room
MIN_DRAWING_ASPECT = 1.7  # width over height of a drawing: a tall arch's frame widened (room for the texts)
STRIP_FRACTIONS = (0.0, 1 / 3, 2 / 3, 1.0)  # of du: the strip's four states
STRIP_CM = (17.0, 9.0)  # two columns wide
THRUST_LABEL = "line of thrust"  # the joints' resultants, in the strip's key
STAGE_WORDS = {"selfweight": "self-weight"}  # a state's stage as a reader writes it


@dataclass(frozen=True)
class StateView:
    """What one drawn state shows, in mm: block outlines, open hinges (interface, side, pivot point,
    paper letter, the joint's unit direction from intrados to extrados), the thrust line's points,
    where the state is on its path (the support displacement, or a live load's path's load) and a
    support's reaction."""

    outlines: list[np.ndarray]
    hinges: list[tuple[int, str, np.ndarray, str, np.ndarray]]
    thrust: np.ndarray
    place: str  # `RunStates.place`: "δ = 1.20 mm", or "load 3.21 N"
    stage: str
    reaction_N: tuple[float, float] | None  # of the support named by `support` on the arch
    support: str = "right support (moving)"  # the moving one ('both': the right one); on a load path, held


def run_states(run: RunFolder) -> RunStates:
    """The run's states; RunFolderError in one line for a run written before they were recorded."""
    if run.states is None:
        raise RunFolderError(
            f"{run.path} has no states.npz (written before runs kept every state): run the "
            "case again to animate or export it"
        )
    return run.states


def hinge_letters(analysis: RunAnalysis, stage: str, step: int) -> dict[tuple[int, str], str]:
    """The collapse hinges' letters by (interface, side) at the state of `stage` and `step` (a live
    load's last equilibrium and its collapse can share a step): where each hinge's track stood then
    (one that moves later keeps its letter: B at 30E before it moves to 29E), or at collapse for a
    state off the analysed path."""
    history = analysis.history
    records = np.flatnonzero((history.stage == stage) & (history.step == step))
    if not len(records):
        return {(k, t.side): t.paper_label for t in analysis.tracks for k in t.final.interfaces}
    at = [(t, t.per_record[records[-1]]) for t in analysis.tracks]
    return {(k, t.side): t.paper_label for t, hinge in at if hinge is not None for k in hinge.interfaces}


def state_view(run: RunFolder, geometry: ArchGeometry, analysis: RunAnalysis, index: int) -> StateView:
    """State `index` of the run as drawn: its hinges as the run finds them (adjacent joints turning the
    same way beyond the run's threshold, marked at their peak, `model.hinges.hinges_at`), each with the
    letter of the collapse mechanism's hinge whose track holds it then (`hinge_letters`)."""
    states = run_states(run)
    snapshot = states.snapshot(index)
    rows = state_joints(run, geometry, index)
    ends = {side: joint_points(geometry, snapshot, side) * MM_PER_M for side in ("I", "E")}
    letters = hinge_letters(analysis, str(states.stage[index]), int(states.step[index]))
    across = ends["E"] - ends["I"]
    across = across / np.linalg.norm(across, axis=1)[:, None]
    hinges = [
        (
            h.interface,
            h.side,
            ends[h.side][h.interface - 1],
            letters.get((h.interface, h.side), ""),
            across[h.interface - 1],
        )
        for h in state_hinges(run, geometry, rows)
    ]
    loaded = (rows["normal_force_N"].to_numpy() > 0) & np.isfinite(rows["force_position"].to_numpy())
    where = rows["force_position"].to_numpy()[:, None]
    thrust = (ends["I"] + where * (ends["E"] - ends["I"]))[loaded]
    same_step = run.series[run.series["step"] == states.step[index]]
    side = "left" if run.case.get("loading", {}).get("moving_support") == "left" else "right"
    reaction = (
        None
        if same_step.empty
        else (float(same_step[f"{side}_Rx_N"].iloc[-1]), float(same_step[f"{side}_Ry_N"].iloc[-1]))
    )
    outlines = [o * MM_PER_M for o in snapshot_outlines(geometry, snapshot)]
    support = f"{side} support" + (" (moving)" if run.load_path is None else "")
    return StateView(outlines, hinges, thrust, states.place(index), str(states.stage[index]), reaction, support)


def drawing_limits(geometry: ArchGeometry) -> tuple[tuple[float, float], tuple[float, float]]:
    """Axis limits (mm) that hold the arch and its supports with a margin: one frame for every state,
    TEXT_SHARE of it below the arch and at least MIN_DRAWING_ASPECT wide for its height (a tall arch's
    corner texts need the room)."""
    xy = np.vstack([front_face(b) for b in geometry.blocks]) * MM_PER_M
    span = float(np.ptp(xy[:, 0]))
    high = xy[:, 1].max() + MARGIN * span
    below = max(3 * MARGIN * span, TEXT_SHARE / (1.0 - TEXT_SHARE) * (high - xy[:, 1].min()))
    low = xy[:, 1].min() - below
    half_width = max((0.5 + SIDE_MARGIN) * span, 0.5 * MIN_DRAWING_ASPECT * (high - low))
    middle = 0.5 * (xy[:, 0].min() + xy[:, 0].max())
    return (middle - half_width, middle + half_width), (low, high)


def draw_state(ax: Axes, view: StateView, geometry: ArchGeometry, limits: tuple, corner: bool = True) -> None:
    """Draw `view` into `ax` to scale, over the undeformed outline, with its place on the path (the
    support displacement, or the load) and the reaction in the lower left corner (`corner`)."""
    undeformed = [front_face(vertices) * MM_PER_M for vertices in geometry.blocks]
    draw_blocks(ax, view.outlines, undeformed, undeformed_colour=UNDEFORMED_COLOUR)
    if len(view.thrust):
        ax.plot(view.thrust[:, 0], view.thrust[:, 1], "-", color=THRUST_COLOUR, lw=0.8, zorder=3, label=THRUST_LABEL)
    for interface, side, point, letter, across in view.hinges:
        colour = hinge_colour(letter) if letter else UNLABELLED_COLOUR
        ax.plot(*point, "o", ms=4, mfc=colour, mec="white", mew=0.5, zorder=4)
        label = ax.annotate(
            f"{letter} {interface}{side}".strip(), point, xytext=(0, 0), textcoords="offset points", color=colour
        )
        label.set_fontsize(MIN_TEXT_PT)
        label.away = across if side == "E" else -across  # off the ring: out at the extrados, in at the intrados
    if corner:
        text = f"{view.place} ({STAGE_WORDS.get(view.stage, view.stage)})"
        if view.reaction_N is not None:
            rx, ry = view.reaction_N
            text += f"\n{view.support} on the arch:\n$R_x$ = {rx:.2f} N, $R_y$ = {ry:.2f} N"
        ax.text(0.01, 0.02, text, transform=ax.transAxes, va="bottom", ha="left", fontsize=MIN_TEXT_PT)
    ax.set_aspect("equal")
    ax.set_xlim(*limits[0])
    ax.set_ylim(*limits[1])
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")


def place_texts(fig: Figure) -> None:
    """Once every panel of `fig` is drawn: each axes' corner text into a corner the blocks leave
    free, then each hinge label round its pivot where it clears the blocks and the other texts."""
    layout(fig)
    for ax in fig.axes:
        for text in ax.texts:
            if not isinstance(text, Annotation):
                place_corner(ax, text)
        for text in ax.texts:
            if isinstance(text, Annotation):
                place_label(ax, text, text.away, LABEL_OFFSET_PT)


def strip_indices(states: RunStates, du_mm: float | None) -> list[int]:
    """The strip's states: the start (self-weight, or a live load held on it before the support moves),
    a third and two thirds of du (the nearest path states), and the last state (the collapse, or the end
    of a path that did not collapse)."""
    path = states.path()
    last = int(path[-1])
    end = du_mm if du_mm is not None else float(states.delta_mm[last])
    start = 0 if states.load is not None else int(path[states.delta_mm[path] <= states.delta_mm[path[0]]][-1])
    return [start, states.nearest(STRIP_FRACTIONS[1] * end), states.nearest(STRIP_FRACTIONS[2] * end), last]


@house_style
def strip_figure(run: RunFolder, analysis: RunAnalysis) -> Figure:
    """Four states of the run side by side, two by two, at one scale (a page-wide figure)."""
    geometry = case_geometry(run.case)
    limits = drawing_limits(geometry)
    fig = new_figure(height_cm=STRIP_CM[1], width_cm=STRIP_CM[0])
    axes = fig.subplots(2, 2, sharex=True, sharey=True).ravel()
    for ax, index in zip(axes, strip_indices(run_states(run), analysis.du_mm)):
        draw_state(ax, state_view(run, geometry, analysis, index), geometry, limits)
    for ax in axes[:2]:
        ax.set_xlabel("")
    for ax in axes[1::2]:
        ax.set_ylabel("")
    if axes[0].get_legend_handles_labels()[0]:  # the key of the red line, between the two x labels
        fig.legend(*axes[0].get_legend_handles_labels(), loc="lower center", frameon=False, fontsize=MIN_TEXT_PT)
    place_texts(fig)
    return fig


def plot_strip(run: RunFolder, analysis: RunAnalysis, stem: Path) -> tuple[Path, Path]:
    """`strip_figure` written as STEM.pdf and STEM.png."""
    return save_figure(strip_figure(run, analysis), stem)


def state_joints(run: RunFolder, geometry: ArchGeometry, index: int) -> pd.DataFrame:
    """The joints.csv rows of state `index` (states.npz holds the states of joints.csv in its order);
    RunFolderError in one line if the two files do not match."""
    states, n_joints = run_states(run), len(geometry.joints)
    if len(run.joints) != len(states) * n_joints:
        raise RunFolderError(
            f"{run.path}: joints.csv has {len(run.joints)} rows for {len(states)} states of "
            f"{n_joints} joints; run the case again"
        )
    return run.joints.iloc[index * n_joints : (index + 1) * n_joints]


def state_hinges(run: RunFolder, geometry: ArchGeometry, rows: pd.DataFrame) -> list[Hinge]:
    """The hinges of one state's joints.csv `rows` as the run finds them: adjacent joints turning the
    same way beyond the run's threshold, each at its peak (`model.hinges.hinges_at`)."""
    rotation = hinge_rotation(
        rows["opening_intrados_mm"].to_numpy(), rows["opening_extrados_mm"].to_numpy(), geometry.thickness * MM_PER_M
    )
    return hinges_at(rotation, default_thresholds(run.case).rotation_mrad * 1e-3)
