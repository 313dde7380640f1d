"""The live-load figures: a point load's capacity along the paper's arch (its influence line), the
collapse acceleration of semicircles against t/R, the residual capacity after a settlement (static
path and rigid blocks), an engine's load-displacement curve, and the DEM against the static engine."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd

from yadearch.plotting.house import CM, COLUMN_CM, ENGINE_NAMES, house_style, new_figure, save_figure
from yadearch.solve.load_path import BRANCH, DESCENDING
from yadearch.solve.load_path_result import LoadPath

HEIGHT_CM = 15.0
INFLUENCE_HEIGHT_CM = 6.0
RESIDUAL_HEIGHT_CM = 8.0  # its legend sits above the axes
LEGEND_ROW_CM = 0.45  # a legend row above the axes
ENGINES_ROW_CM = 0.45  # the engines figure's height per case
DESCENT_ROW_CM = 6.0  # the descent figure's height per row of panels
PASSIVE_HEIGHT_CM = 8.0
LEGEND_ROOM = 1.45  # panel (a)'s height over its largest capacity: the legend sits above the curves
PASSIVE_ARCHES = (("small", "o"), ("paper", "s"))  # the passive study's arches by case prefix, and their markers
PASSIVE_SERIES = (  # column of the passive study's capacities, colour, legend
    ("rigid_N", "k", "rigid blocks"),
    ("stiff_static_N", "C2", r"static, $k_n$ 10$^5$ N/mm$^3$"),
    ("static_N", "C0", r"static, $k_n$ 5.2 N/mm$^3$"),
    ("dem_N", "C1", r"DEM, $k_n$ 5.2 N/mm$^3$"),
)
# a live load's work-conjugate displacement: its points' mean displacement along their forces
LOAD_DISPLACEMENT_LABEL = "mean displacement along the load (mm)"
LOG_TICKS = (1.0, 2.0, 5.0)  # the labelled ticks of each decade of a log axis
DEM_MARKER_PT = 2.2  # the DEM's filled marks, inside the static engine's open ones where they agree


def load_label(unit: str) -> str:
    """A live load's axis label in its unit: N for a load, g for a horizontal acceleration."""
    return f"{'horizontal acceleration' if unit == 'g' else 'live load'} ({unit})"


@house_style
def plot_loads(
    influence: pd.DataFrame, accelerations: pd.DataFrame, residual: pd.DataFrame, arch_weight_N: float, stem: Path
) -> tuple[Path, Path]:
    """STEM.pdf and .png: three panels, one column wide."""
    fig = new_figure(height_cm=HEIGHT_CM, width_cm=COLUMN_CM)
    top, middle, bottom = fig.subplots(3, 1)
    _draw_influence(top, influence, arch_weight_N)
    top.set_title("(a) rigid blocks: a point load along the span", loc="left")
    middle.plot(accelerations["t_over_R"], accelerations["collapse_acceleration_g"], "s-", ms=2.5, color="C1")
    middle.set_title("(b) rigid blocks: semicircle's collapse acceleration", loc="left")
    middle.set_xlabel("t/R of a semicircle (55 voussoirs)")
    middle.set_ylabel("collapse acceleration (g)")
    middle.set_ylim(bottom=0.0)
    _draw_residual(bottom, residual, "quarter-span load (N)", title="(c) the load after a settlement")
    return save_figure(fig, stem)


@house_style
def plot_residual(residual: pd.DataFrame, unit: str, stem: Path) -> tuple[Path, Path]:
    """STEM.pdf and .png: the live load's capacity after each support movement (one column wide)."""
    fig = new_figure(height_cm=RESIDUAL_HEIGHT_CM, width_cm=COLUMN_CM)
    _draw_residual(fig.add_subplot(), residual, f"live load at collapse ({unit})")
    return save_figure(fig, stem)


def _draw_residual(ax, residual: pd.DataFrame, ylabel: str, title: str | None = None) -> None:
    """The residual capacity against the settlement before loading: the static path's collapse and
    first loss, and the load that first moves rigid blocks in the settled state (`title`: the legend's)."""
    from matplotlib.ticker import LogLocator, StrMethodFormatter

    settled = residual["settlement_mm"]
    ax.plot(settled, residual["static_capacity"], "o-", ms=3.0, color="C0", label="static: collapse")
    ax.plot(settled, residual["static_first_loss"], "o", ms=3.0, mfc="none", color="C0", label="static: first loss")
    ax.plot(settled, residual["rigid_first_motion"], "^", ms=4.0, color="C2", label="rigid blocks: first motion")
    # no line through the rigid points: their value drops at once when the hinges open, not along a slope
    ax.set_xlabel(r"support movement before loading $\delta$ (mm)")
    ax.set_ylabel(ylabel)
    ax.set_yscale("log")
    ax.yaxis.set_major_locator(LogLocator(subs=LOG_TICKS))  # a label at 1, 2 and 5 of each decade
    ax.yaxis.set_major_formatter(StrMethodFormatter("{x:g}"))
    ax.yaxis.set_minor_formatter(StrMethodFormatter(""))
    # above the axes, its title to the left: it hides no point
    ax.legend(loc="lower left", bbox_to_anchor=(0.0, 1.0), frameon=False, title=title, alignment="left")


@house_style
def plot_influence(
    influence: pd.DataFrame, arch_weight_N: float, stem: Path, engine: str = "rigid"
) -> tuple[Path, Path]:
    """STEM.pdf and .png: the case's vertical load's capacity against its position by `engine` (one column
    wide); positions where nothing collapses are left out."""
    fig = new_figure(height_cm=INFLUENCE_HEIGHT_CM, width_cm=COLUMN_CM)
    _draw_influence(fig.add_subplot(), influence, arch_weight_N, engine)
    return save_figure(fig, stem)


def _draw_influence(ax, influence: pd.DataFrame, arch_weight_N: float, engine: str = "rigid") -> None:
    """The influence line of the capacity, in N and (right axis) in arch weights."""
    label = ENGINE_NAMES.get(engine, "rigid blocks")
    ax.plot(influence["position_over_span"], influence["collapse_load_N"], "o-", ms=2.5, color="C0", label=label)
    if "rigid_load_N" in influence:  # an engine's line, with rigid blocks' for scale
        ax.plot(
            influence["position_over_span"], influence["rigid_load_N"], "--", lw=0.8, color="0.4", label="rigid blocks"
        )
    if "sampled" in influence and not influence["sampled"].all():  # the critical positions found between samples
        critical = influence[~influence["sampled"].astype(bool)]
        x, load = critical["position_over_span"], critical["collapse_load_N"]
        ax.plot(x, load, "v", ms=5.0, mfc="none", color="C3", label=f"critical: {load.min():.4g} N")
    if not np.isfinite(influence["collapse_load_N"]).any():  # a load spread over the span, say: nothing to draw
        ax.text(0.5, 0.5, "no collapse at any position", transform=ax.transAxes, ha="center", va="center")
        ax.set_xlim(0.0, 1.0)
    ax.legend(loc="best", frameon=False)  # the engine named, clear of the lines
    ax.set_xlabel("load's position (its centre) / span, from the left springing")
    ax.set_ylabel("collapse load (N)")
    ax.set_ylim(bottom=0.0)
    twin = ax.secondary_yaxis("right", functions=(lambda n: n / arch_weight_N, lambda r: r * arch_weight_N))
    twin.set_ylabel("load / arch weight (-)")


@house_style
def plot_load_path(path: LoadPath, stem: Path) -> tuple[Path, Path]:
    """STEM.pdf and .png: an engine's load-displacement curve up to its limit point and, where traced,
    past it (the descending branch), its first loss of stability and capacity, and the rigid-block
    capacity of the same state for scale."""
    fig = new_figure(height_cm=INFLUENCE_HEIGHT_CM, width_cm=COLUMN_CM)
    ax = fig.add_subplot()
    curve, unit, capacity, first_loss, rigid = path.curve, path.unit, path.capacity, path.first_loss, path.rigid
    past = (curve[BRANCH] == DESCENDING).to_numpy() if BRANCH in curve else np.zeros(len(curve), bool)
    up = curve[~past]
    ax.plot(up["load_displacement_mm"], up["multiplier"], "o-", ms=2.0, color="C0", label=ENGINE_NAMES[path.engine])
    if past.any():  # from the peak on, so that the two branches join
        down = curve.iloc[len(up) - 1 :]
        ax.plot(
            down["load_displacement_mm"], down["multiplier"], ".-", ms=2.0, lw=0.8, color="C3", label="past the peak"
        )
    if math.isfinite(rigid):  # after a movement: the load that first moves the settled rigid arch
        what = "rigid blocks' first motion" if path.after_mm > 0.0 else "rigid blocks"
        ax.axhline(rigid, color="0.4", lw=0.8, ls="--", label=f"{what} ({rigid:.3g} {unit})")
    if math.isfinite(capacity):
        ax.axhline(capacity, color="C0", lw=0.6, ls=":", label=f"collapse ({capacity:.3g} {unit})")
    if math.isfinite(first_loss) and first_loss < capacity:
        ax.axhline(first_loss, color="C1", lw=0.6, ls=":", label=f"first loss of stability ({first_loss:.3g} {unit})")
    ax.set_xlabel(LOAD_DISPLACEMENT_LABEL)
    ax.set_ylabel(load_label(unit))
    ax.set_xlim(left=0.0)
    ax.set_ylim(bottom=0.0)
    # above the axes: the horizontal lines span the axes, so no corner inside stays clear
    rows = len(ax.get_legend_handles_labels()[1])
    ax.legend(loc="lower left", bbox_to_anchor=(0.0, 1.0), frameon=False, borderaxespad=0.2)
    fig.set_size_inches(fig.get_size_inches()[0], (INFLUENCE_HEIGHT_CM + rows * LEGEND_ROW_CM) * CM)
    return save_figure(fig, stem)


@house_style
def plot_engines(table: pd.DataFrame, tolerance: float, stem: Path) -> tuple[Path, Path]:
    """STEM.pdf and .png: each case's DEM capacity against the static engine's (%), with the band of
    +-`tolerance` the two engines should agree within."""
    # a page wide: the rows are named in words (`studies.loads.engines.case_label`)
    fig = new_figure(height_cm=ENGINES_ROW_CM * (len(table) + 2), width_cm=2 * COLUMN_CM)
    ax = fig.add_subplot()
    rows = range(len(table))
    ax.axvspan(-100.0 * tolerance, 100.0 * tolerance, color="0.9", lw=0, label=f"\u00b1{100 * tolerance:g} %")
    ax.plot(100.0 * table["dem_over_static"], rows, "o", ms=3.0, color="C0", label="collapse")
    ax.plot(100.0 * table["first_loss_dem_over_static"], rows, "x", ms=3.0, color="0.2", label="first loss")
    ax.set_yticks(list(rows), list(table["label"]))
    ax.invert_yaxis()
    ax.set_xlabel("(DEM \u2212 static) / static (%)")
    ax.legend(loc="lower right", frameon=False, ncols=3, bbox_to_anchor=(1.0, 1.0))
    return save_figure(fig, stem)


@house_style
def plot_descent(paths: dict[str, tuple[LoadPath, LoadPath | None]], stem: Path) -> tuple[Path, Path]:
    """STEM.pdf and .png: each case's load-displacement curve on the static engine (a line, past the peak
    by arc length) and the DEM's states (markers, past the peak under displacement control), a panel each."""
    columns = 2
    rows = math.ceil(len(paths) / columns)
    fig = new_figure(height_cm=DESCENT_ROW_CM * rows, width_cm=2 * COLUMN_CM)
    for k, (name, (static, dem)) in enumerate(paths.items()):
        ax = fig.add_subplot(rows, columns, k + 1)
        curve = static.curve
        ax.plot(curve["load_displacement_mm"], curve["multiplier"], "-", lw=0.9, color="C0", label="static")
        if dem is not None:
            past = (
                (dem.curve[BRANCH] == DESCENDING).to_numpy() if BRANCH in dem.curve else np.zeros(len(dem.curve), bool)
            )
            for mask, marker, label in ((~past, "o", "DEM, load control"), (past, "s", "DEM, past the peak")):
                shown = dem.curve[mask]
                ax.plot(shown["load_displacement_mm"], shown["multiplier"], marker, ms=2.5, mfc="none", mew=0.6,
                        color="C3" if marker == "s" else "C1", label=label)  # fmt: skip
        ax.set_title(f"({chr(ord('a') + k)}) {name}", loc="left")
        ax.set_xlabel(LOAD_DISPLACEMENT_LABEL)
        ax.set_ylabel(load_label(static.unit))
        ax.set_xlim(left=0.0)
        ax.set_ylim(bottom=0.0)
        if k == 0:
            ax.legend(loc="lower center", frameon=False)
    return save_figure(fig, stem)


@house_style
def plot_passive(
    capacities: pd.DataFrame, mobilisation: pd.DataFrame, without_N: float, stem: Path
) -> tuple[Path, Path]:
    """STEM.pdf and .png: (a) each arch's capacity against the fill's passive coefficient Kp in the rigid
    LP, the static engine nearly rigid and at kn 5.2, and the DEM (colour: solver, marker: arch); (b) the
    paper's arch's static capacity against the spring's mobilisation displacement, between the rigid LP's
    and the static engine's without passive resistance (`without_N`)."""
    from matplotlib.lines import Line2D

    fig = new_figure(height_cm=PASSIVE_HEIGHT_CM, width_cm=2 * COLUMN_CM)
    ax, swept = fig.add_subplot(1, 2, 1), fig.add_subplot(1, 2, 2)
    for arch, marker in PASSIVE_ARCHES:
        rows = capacities[capacities["case"].str.startswith(arch)]
        for column, colour, _ in PASSIVE_SERIES:
            shown = rows.dropna(subset=[column])
            if column == "dem_N":  # points, filled and small: the static engine's open marks stay visible
                ax.plot(shown["kp"], shown[column], marker, ms=DEM_MARKER_PT, color=colour, zorder=3)
            else:
                ax.plot(shown["kp"], shown[column], f"{marker}-", ms=3.5, mfc="none", mew=0.7, lw=0.8, color=colour)
    handles = [
        Line2D([], [], color=colour, ls="none", marker="o", ms=DEM_MARKER_PT, label=label)
        if column == "dem_N"
        else Line2D([], [], color=colour, lw=0.8, label=label)
        for column, colour, label in PASSIVE_SERIES
    ]
    handles += [
        Line2D([], [], color="0.4", ls="none", marker=m, mfc="none", label=f"{a} arch") for a, m in PASSIVE_ARCHES
    ]
    ax.legend(handles=handles, loc="upper left", ncol=2, frameon=False)
    ax.set_ylim(0.0, LEGEND_ROOM * float(np.nanmax(capacities[[c for c, _, _ in PASSIVE_SERIES]].to_numpy(float))))
    ax.set_title(r"(a) capacity against $K_p$", loc="left")
    ax.set_xlabel(r"passive coefficient $K_p$ (-)")
    ax.set_ylabel("collapse load (N)")
    swept.semilogx(mobilisation["u_p_mm"], mobilisation["static_N"], "o-", ms=3, lw=0.8, color="C0",
                   label=r"static, $k_n$ 5.2 N/mm$^3$, $K_p$ 1")  # fmt: skip
    swept.axhline(float(mobilisation["rigid_N"].iloc[0]), color="k", lw=0.8, ls="--", label=r"rigid blocks, $K_p$ 1")
    swept.axhline(without_N, color="C0", lw=0.8, ls=":", label=r"static, $k_n$ 5.2 N/mm$^3$, no passive push")
    swept.set_title(r"(b) the paper's arch against $u_p$", loc="left")
    swept.set_xlabel(r"mobilisation displacement $u_p$ (mm)")
    swept.set_ylabel("collapse load (N)")
    swept.set_ylim(bottom=0.0)
    swept.legend(loc="lower left", frameon=False)
    return save_figure(fig, stem)
