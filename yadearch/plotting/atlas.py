"""The atlas's figure: du against kn for every shape (rows) and support movement (columns), one
colour a ring thickness; the static engine's du (line) and du_first (open), the DEM's du (diamond),
the rigid march's du (the dotted level the curve should rise to), and marks at a panel's top and foot
for the static runs that stand to the path's end, cannot stand or are unresolved."""

from __future__ import annotations

import math
from pathlib import Path

import matplotlib
import numpy as np
import pandas as pd
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

from yadearch.plotting.house import MIN_TEXT_PT, save_figure
from yadearch.plotting.sweep import SWEEP_STYLE

PANEL_IN = (1.05, 1.0)  # width, height of one shape x movement panel: six across fit a page (17.5 cm)
KN_RANGE = (0.1, 3e4)  # N/mm3: the atlas's stiffnesses with a margin
LEGEND_ROW = 0.3  # the key's row (two lines of entries), relative to a panel's height
THICKNESS_COLORS = ("#0072B2", "#D55E00", "#009E73")  # Okabe-Ito: told apart in print and by the colour-blind
MOVEMENT_TITLES = {  # the atlas's movements of the right support as a column's title
    "settlement": "settlement (−90°)",
    "spreading": "spreading (0°)",
    "closing": "closing (180°)",
    "down_out_45": "down and out (−45°)",
    "down_in_135": "down and in (−135°)",
    "tilt": "tilt",
}
# static outcomes without a du, marked where they are on the scale: marker, at the travel's end (True) or
# at 0, legend
OUTCOME_MARKS = {
    "stands": ("^", True, "static: stands to the travel's end"),
    "cannot stand": ("v", False, "static: cannot stand ($d_u$ 0)"),
    "unresolved": ("x", False, "static: unresolved (no $d_u$, at 0)"),
}


def atlas_figure(table: pd.DataFrame, stem: Path, travel_mm: float) -> tuple[Path, Path]:
    """STEM.pdf/.png: one panel per shape and movement of the atlas `table` (atlas.csv's columns); an
    arch that stands to the support's travel `travel_mm` (mm) is marked there."""
    shapes = list(dict.fromkeys(table["shape"]))
    movements = list(dict.fromkeys(table["movement"]))
    thicknesses = sorted(table["thickness_mm"].unique())
    with matplotlib.rc_context(SWEEP_STYLE):
        fig = Figure(
            figsize=(PANEL_IN[0] * len(movements) + 0.6, PANEL_IN[1] * len(shapes) + 0.7), layout="constrained"
        )
        grid = fig.add_gridspec(len(shapes) + 1, len(movements), height_ratios=[1.0] * len(shapes) + [LEGEND_ROW])
        axes = np.array([[fig.add_subplot(grid[i, j]) for j in range(len(movements))] for i in range(len(shapes))])
        for i, shape in enumerate(shapes):
            for j, movement in enumerate(movements):
                ax = axes[i, j]
                panel = table[(table["shape"] == shape) & (table["movement"] == movement)]
                for color, thickness in zip(THICKNESS_COLORS, thicknesses):
                    _draw_thickness(ax, panel[panel["thickness_mm"] == thickness], color, travel_mm)
                ax.set_xscale("log")
                ax.set_xlim(KN_RANGE)
                ax.set_ylim(bottom=0.0)
                ax.tick_params(labelsize=MIN_TEXT_PT)
                if i == 0:
                    ax.set_title(MOVEMENT_TITLES.get(movement, movement.replace("_", " ")), fontsize=MIN_TEXT_PT)
                if j == 0:
                    ax.set_ylabel(f"{shape.replace('_', '-')}\n$d_u$ (mm)", fontsize=MIN_TEXT_PT)
                if i == len(shapes) - 1:
                    ax.set_xlabel("$k_n$ (N/mm³)", fontsize=MIN_TEXT_PT)
        key = fig.add_subplot(grid[len(shapes), :])
        key.axis("off")
        entries = _legend(thicknesses, set(table["static_outcome"]))
        key.legend(handles=entries, loc="center", ncol=math.ceil(len(entries) / 2), fontsize=MIN_TEXT_PT, frameon=False)
        return save_figure(fig, stem)


def _draw_thickness(ax, runs: pd.DataFrame, color: str, travel_mm: float) -> None:
    """One thickness in one panel: static du and du_first against kn, DEM du, the rigid level, and the
    runs without a du at the travel's end (standing) or at 0."""
    runs = runs.sort_values("kn_N_per_mm3")
    kn = runs["kn_N_per_mm3"].to_numpy(dtype=float)
    ax.plot(kn, runs["static_du_mm"], color=color, marker="o", ms=2.5, lw=1.0)
    ax.plot(kn, runs["static_du_first_mm"], color=color, marker="o", ms=3.5, mfc="none", ls="none", mew=0.6)
    if "dem_du_mm" in runs:
        ax.plot(kn, runs["dem_du_mm"], color=color, marker="D", ms=3.5, mfc="none", ls="none", mew=0.8)
    rigid = runs["rigid_du_mm"].dropna()
    if len(rigid):
        ax.axhline(float(rigid.iloc[0]), color=color, ls=":", lw=0.9)
    for outcome, (marker, at_travel, _) in OUTCOME_MARKS.items():
        marked = runs[runs["static_outcome"].eq(outcome)]
        if len(marked):
            height = travel_mm if at_travel else 0.0
            ax.plot(marked["kn_N_per_mm3"], np.full(len(marked), height), color=color, marker=marker, ms=3.5,
                    mfc="none", mew=0.8, ls="none", clip_on=False)  # fmt: skip


def _legend(thicknesses: list[float], outcomes: set[str]) -> list[Line2D]:
    """Thickness colours, then what each mark means (the outcomes' marks only where the atlas has them)."""
    handles = [Line2D([], [], color=c, lw=1.0, label=f"t = {t:g} mm") for c, t in zip(THICKNESS_COLORS, thicknesses)]
    grey = "0.3"
    return (
        handles
        + [
            Line2D([], [], color=grey, marker="o", ms=2.5, lw=1.0, label=r"static $d_u$"),
            Line2D(
                [],
                [],
                color=grey,
                marker="o",
                ms=3.5,
                mfc="none",
                ls="none",
                label=r"static $d_{u,\mathrm{first}}$",
            ),
            Line2D([], [], color=grey, marker="D", ms=3.5, mfc="none", ls="none", label=r"DEM $d_u$"),
            Line2D([], [], color=grey, ls=":", label=r"rigid march $d_u$"),
        ]
        + [
            Line2D([], [], color=grey, marker=marker, mfc="none", ls="none", label=label)
            for outcome, (marker, _, label) in OUTCOME_MARKS.items()
            if outcome in outcomes
        ]
    )
