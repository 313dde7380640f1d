"""Figures of a capacity map: du against the direction of the support movement as a polar plot (one
curve per joint set and the rigid-block limit, each point labelled with its collapse hinges), and the
moving support's reaction against its displacement for every direction."""

from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np
import pandas as pd
from matplotlib.figure import Figure

from yadearch.plotting.run_figures import save_figure
from yadearch.plotting.sweep import COLUMN_WIDTH_IN, SWEEP_STYLE

RIGID_STYLE = {"color": "0.35", "ls": "--", "marker": "x", "ms": 3, "lw": 0.8}
LABEL_FONT_SIZE = 4.5  # hinge labels beside the polar points
LABEL_OFFSET = 1.06  # hinge labels sit this far out from their point (a fraction of its radius)


def capacity_polar_figure(table: pd.DataFrame, stem: Path) -> list[Path]:
    """du (radius, mm) against the direction of the support movement (angle, degrees from +x; the
    half-plane below the horizontal) for every `set` of `table`, with the rigid limit
    (`du_rigid_mm`) and each point's collapse hinges: STEM.pdf and STEM.png."""
    with matplotlib.rc_context(SWEEP_STYLE):
        fig = Figure(figsize=(2 * COLUMN_WIDTH_IN, 4.2), layout="constrained")
        ax = fig.add_subplot(projection="polar")
        for k, (name, runs) in enumerate(table.groupby("set", sort=False)):
            runs = runs.sort_values("direction_deg")
            theta = np.radians(runs["direction_deg"].to_numpy(dtype=float))
            ax.plot(theta, runs["du_mm"], marker="o", ms=3, lw=1, color=f"C{k}", label=f"{name} (DEM)")
            for angle, du, hinges in zip(theta, runs["du_mm"], runs["hinges"].fillna("")):
                if np.isfinite(du):
                    ax.annotate(hinges, (angle, du * LABEL_OFFSET), fontsize=LABEL_FONT_SIZE, color=f"C{k}",
                                ha="center", va="center")
        rigid = table.drop_duplicates("direction_deg").sort_values("direction_deg")
        if rigid["du_rigid_mm"].notna().any():
            ax.plot(np.radians(rigid["direction_deg"].to_numpy(dtype=float)), rigid["du_rigid_mm"],
                    label="rigid blocks (limit analysis)", **RIGID_STYLE)
        ax.set_thetamin(-180)
        ax.set_thetamax(0)
        ax.set_xticks(np.radians(np.arange(-180, 1, 15)))
        ax.set_xlabel("direction of the support movement (deg from +x); radius: du (mm)")
        ax.legend(loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=3, frameon=False)
        return list(save_figure(fig, stem))


def reaction_curves_figure(curves: dict[str, dict[float, pd.DataFrame]], stem: Path) -> list[Path]:
    """The moving support's reaction along its movement (N, positive against it) against the
    support displacement (mm) at the equilibrium states of every direction, one panel per set:
    `curves[set][direction_deg]` holds the `delta_mm` and `reaction_N` columns."""
    with matplotlib.rc_context(SWEEP_STYLE):
        fig = Figure(figsize=(2 * COLUMN_WIDTH_IN, 2.8), layout="constrained")
        axes = fig.subplots(1, len(curves), sharey=True, squeeze=False)[0]
        colormap = matplotlib.colormaps["viridis"]
        for ax, (name, by_direction) in zip(axes, curves.items()):
            for direction, curve in sorted(by_direction.items()):
                ax.plot(curve["delta_mm"], curve["reaction_N"], lw=0.9,
                        color=colormap((direction + 180.0) / 180.0), label=f"{direction:g}°")
            ax.set_title(name)
            ax.set_xlabel("support displacement along its path (mm)")
            ax.axhline(0.0, color="0.6", lw=0.5)
        axes[0].set_ylabel("reaction of the moving support\nalong its path (N)")
        axes[-1].legend(title="direction", ncol=2, loc="upper right")
        return list(save_figure(fig, stem))
