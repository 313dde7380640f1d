"""Figures of a capacity map: du against the direction of the support movement as a polar plot (one
curve per joint set and the rigid-block limit) beside each direction's collapse hinges, and the
force of the arch on the moving support against its displacement for every direction."""

from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np
import pandas as pd
from matplotlib.figure import Figure
from matplotlib.ticker import MaxNLocator

from yadearch.plotting.house import save_figure
from yadearch.plotting.sweep import COLUMN_WIDTH_IN, SWEEP_STYLE

RADIAL_TICKS = 4  # du rings of the polar plot
# 13 directions told apart: the Okabe-Ito colours, solid on the opening side (0 to -90 deg), dashed beyond
DIRECTION_COLOURS = ("#000000", "#E69F00", "#56B4E9", "#009E73", "#0072B2", "#D55E00", "#CC79A7")
RIGID_COLOR = "0.35"
RIGID_STYLE = {"color": RIGID_COLOR, "ls": "--", "marker": "x", "ms": 3, "lw": 0.8}
OTHER_BRANCH_STYLE = {"color": RIGID_COLOR, "ls": ":", "marker": "+", "ms": 3, "lw": 0.8}
SAME_DU_MM = 0.01  # the two branches of the keystone tie end alike: one line drawn


def capacity_polar_figure(table: pd.DataFrame, stem: Path, engine: str = "DEM") -> list[Path]:
    """Left: du (radius, mm) against the direction of the support movement (angle, degrees from +x;
    the half-plane below the horizontal) for every `set` of `table`, with the rigid limit
    (`du_rigid_mm`) and that of the keystone tie's other branch (`du_rigid_other_mm`). Right: the
    collapse mechanism of each direction, its hinges' interfaces (I = intrados, E = extrados); the
    curves are labelled with the `engine` that made them. STEM.pdf and STEM.png."""
    with matplotlib.rc_context(SWEEP_STYLE):
        fig = Figure(figsize=(2 * COLUMN_WIDTH_IN, 3.4), layout="constrained")
        polar = fig.add_subplot(1, 2, 1, projection="polar")
        hinges = fig.add_subplot(1, 2, 2)
        groups = list(table.groupby("set", sort=False))
        for k, (name, runs) in enumerate(groups):
            runs = runs.sort_values("direction_deg")
            polar.plot(
                np.radians(runs["direction_deg"].to_numpy(dtype=float)),
                runs["du_mm"],
                marker="o",
                ms=3,
                lw=1,
                color=f"C{k}",
                label=f"{name} ({engine})",
            )
            offset = (k - (len(groups) - 1) / 2) * SET_OFFSET_DEG
            _hinge_marks(hinges, runs["direction_deg"], runs["hinges"], f"C{k}", offset)
            hinges.plot([], [], "-", lw=KEY_LINE_WIDTH, color=f"C{k}", label=f"{name} ({engine})")
        rigid = table.drop_duplicates("direction_deg").sort_values("direction_deg")
        if rigid["du_rigid_mm"].notna().any():
            polar.plot(
                np.radians(rigid["direction_deg"].to_numpy(dtype=float)),
                rigid["du_rigid_mm"],
                label="rigid blocks",
                **RIGID_STYLE,
            )
            _hinge_marks(
                hinges, rigid["direction_deg"], rigid["rigid_hinges"], RIGID_COLOR, len(groups) / 2 * SET_OFFSET_DEG
            )
            hinges.plot([], [], "-", lw=KEY_LINE_WIDTH, color=RIGID_COLOR, label="rigid blocks")
        # the other branch only where it ends elsewhere: a gap (NaN) where both branches end alike
        same = np.isclose(rigid["du_rigid_other_mm"], rigid["du_rigid_mm"], rtol=0.0, atol=SAME_DU_MM)
        other = rigid["du_rigid_other_mm"].mask(same)
        if other.notna().any():
            polar.plot(
                np.radians(rigid["direction_deg"].to_numpy(dtype=float)),
                other,
                label="rigid, other branch",
                **OTHER_BRANCH_STYLE,
            )
        _half_plane(polar, legend_columns=3)
        for side, marker in SIDE_MARKERS.items():  # the marker legend: which corner a hinge turns about
            name = "intrados" if side == "I" else "extrados"
            hinges.plot([], [], marker, ms=3, color="0.3", mfc="none" if side == "E" else "0.3", label=f"{name} hinge")
        hinges.legend(loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2, frameon=False)  # colours, markers
        hinges.set_xlabel("direction of the support movement (deg from +x)")
        hinges.set_ylabel("interface of each hinge at collapse")
        hinges.set_xticks(np.arange(-180, 1, 30))
        hinges.grid(alpha=0.3, lw=0.5)
        return list(save_figure(fig, stem))


RATIO_CEILING = 1.5  # du / du_rigid above this (a rigid march locked early) is cut off the panel


def _half_plane(polar, legend_columns: int) -> None:
    """A polar axis over the directions below the horizontal, du rings, title and legend under it."""
    polar.set_thetamin(-180)
    polar.set_thetamax(0)
    polar.set_xticks(np.radians(np.arange(-180, 1, 30)))
    polar.yaxis.set_major_locator(MaxNLocator(RADIAL_TICKS))
    polar.set_title("$d_u$ (mm) against the direction (deg from +x)")
    polar.legend(loc="upper center", bbox_to_anchor=(0.5, -0.02), ncol=legend_columns, frameon=False)


SET_OFFSET_DEG = 3.0  # the sets' hinge marks side by side at one direction
KEY_LINE_WIDTH = 3.0  # the hinge panel's colour key: a thick short line a set
SIDE_MARKERS = {"I": "o", "E": "s"}


def _hinge_marks(ax, directions: pd.Series, hinge_labels: pd.Series, color: str, offset_deg: float) -> None:
    """One mark per hinge ("9I 29E ...") at its interface, beside its direction."""
    for direction, labels in zip(directions, hinge_labels.fillna("")):
        for label in str(labels).split():
            side = label[-1]
            ax.plot(
                direction + offset_deg,
                int(label[:-1]),
                SIDE_MARKERS.get(side, "x"),
                ms=2.5,
                color=color,
                mfc="none" if side == "E" else color,
                mew=0.7,
            )


def reaction_curves_figure(curves: dict[str, dict[float, pd.DataFrame]], stem: Path) -> list[Path]:
    """The force of the arch on the moving support along its path (N; `studies.capacity.directions.reaction_curve`)
    against the support displacement (mm) at the equilibrium states of every direction, one panel
    per set: `curves[set][direction_deg]` holds the `delta_mm` and `force_N` columns."""
    with matplotlib.rc_context(SWEEP_STYLE):
        fig = Figure(figsize=(2 * COLUMN_WIDTH_IN, 2.8), layout="constrained")
        axes = fig.subplots(1, len(curves), sharey=True, squeeze=False)[0]
        for ax, (name, by_direction) in zip(axes, curves.items()):
            for direction, curve in sorted(by_direction.items(), reverse=True):
                ax.plot(
                    curve["delta_mm"], curve["force_N"], lw=0.9, label=f"{direction:g}°", **_direction_style(direction)
                )
            ax.set_title(name)
            ax.set_xlabel("support displacement along its path (mm)")
            ax.axhline(0.0, color="0.6", lw=0.5)
        axes[0].set_ylabel("force of the arch on the moving\nsupport along its path (N)")
        axes[-1].legend(title="direction", ncol=1, loc="upper left", bbox_to_anchor=(1.02, 1.0), frameon=False)
        return list(save_figure(fig, stem))


def _direction_style(direction_deg: float) -> dict[str, str]:
    """The colour and line style of one direction's curve: every 15 deg a colour, solid from spreading
    to settlement, dashed beyond it toward closing."""
    step = int(round(abs(direction_deg) / 15.0))
    opening = direction_deg >= -90.0
    colour = DIRECTION_COLOURS[step % len(DIRECTION_COLOURS)] if opening else DIRECTION_COLOURS[(step - 7) % 7]
    return {"color": colour, "ls": "-" if opening else "--"}


def stiffness_figure(table: pd.DataFrame, dem: pd.DataFrame, stem: Path) -> list[Path]:
    """Capacity maps at several stiffnesses (`table`: direction_deg, label, du_mm, du_rigid_mm, one
    `label` a curve, e.g. "kn 5.2, runaway 1 mm") with the DEM's points (`dem`: direction_deg, label,
    du_mm) on top. Left: du (radius, mm) against the direction; right: du / du_rigid against it."""
    with matplotlib.rc_context(SWEEP_STYLE):
        fig = Figure(figsize=(2 * COLUMN_WIDTH_IN, 3.6), layout="constrained")
        polar = fig.add_subplot(1, 2, 1, projection="polar")
        ratio = fig.add_subplot(1, 2, 2)
        for k, (label, runs) in enumerate(table.groupby("label", sort=False)):
            runs = runs.sort_values("direction_deg")
            angle = np.radians(runs["direction_deg"].to_numpy(dtype=float))
            style = {"color": f"C{k // 2}", "ls": "-" if k % 2 == 0 else "--", "lw": 0.9}
            polar.plot(angle, runs["du_mm"], label=label, **style)
            ratio.plot(runs["direction_deg"], runs["du_mm"] / runs["du_rigid_mm"], **style)
        rigid = table.drop_duplicates("direction_deg").sort_values("direction_deg")
        polar.plot(
            np.radians(rigid["direction_deg"].to_numpy(dtype=float)),
            rigid["du_rigid_mm"],
            label="rigid blocks",
            **RIGID_STYLE,
        )
        for k, (label, points) in enumerate(dem.groupby("label", sort=False)):
            polar.plot(
                np.radians(points["direction_deg"].to_numpy(dtype=float)),
                points["du_mm"],
                "o",
                mfc="none",
                mec=f"C{k}",
                ms=4,
                mew=0.8,
                label=label,
            )
            ratio.plot(
                points["direction_deg"],
                points["du_mm"] / points["du_rigid_mm"],
                "o",
                mfc="none",
                mec=f"C{k}",
                ms=4,
                mew=0.8,
            )
        _half_plane(polar, legend_columns=2)
        ratio.axhline(1.0, color=RIGID_COLOR, lw=0.6, ls="--")
        ratio.set_ylim(0.0, RATIO_CEILING)  # where the rigid march locks early the ratio leaves the frame
        ratio.set_xlabel("direction of the support movement (deg from +x)")
        ratio.set_ylabel(f"du / du of rigid blocks (clipped at {RATIO_CEILING:g})")
        ratio.set_xticks(np.arange(-180, 1, 30))
        ratio.grid(alpha=0.3, lw=0.5)
        return list(save_figure(fig, stem))
