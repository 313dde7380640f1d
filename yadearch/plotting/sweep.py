"""The kn sweep figure (paper Fig. 8): du against kn, and the hinges' interfaces against kn.

Drawn from a campaign's results table, with the paper's two calibrated points for comparison.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import matplotlib
import numpy as np
import pandas as pd
from matplotlib.axes import Axes
from matplotlib.cm import ScalarMappable
from matplotlib.colors import LogNorm, Normalize
from matplotlib.figure import Figure
from matplotlib.ticker import MaxNLocator

from yadearch.analysis.samples import collapse_displacement
from yadearch.case import reference
from yadearch.plotting.house import MIN_TEXT_PT, hinge_colour, save_figure
from yadearch.plotting.parameter_labels import parameter_label, parameter_name, parameter_setting

COLUMN_WIDTH_IN = 3.5  # one journal column
ENGINE_LABELS = {"dem": "DEM", "static": "static"}  # numerics.engine as a figure names it
HINGE_STYLE = {  # a column of hinge interfaces: its letter, marker and legend entry
    "hinge_A": ("A", "o", "A (intrados)"),
    "hinge_B": ("B", "s", "B (extrados)"),
    "hinge_C": ("C", "^", "C (moving support)"),
}
LEGEND_HEADROOM = 1.45  # hinge panel's y range as a multiple of the last interface
PAPER_MECHANISM = "E-I-E-E"  # hinges D, A, B, C from left to right (paper: collapse when D opens)
DECADE = 10.0
BASE_CASE = "as the base case"  # a parameter a sweep's row leaves empty
MAX_LEGEND_LINES = 8  # more lines than this, of one numeric setting: a colour scale instead of a legend
SHADES = "viridis"
LEGEND_SETTINGS = 2  # more parameters differing between a sweep's lines: each line named by its runs
MAX_NAMED_POINTS = 12  # a table that is not a grid: its runs named beside their points up to this many
NEAR_FRACTION = 0.03  # points this close (a fraction of the du range) at one value share a name label
SWEEP_STYLE = {
    "font.size": 8,
    "axes.labelsize": 8,
    "legend.fontsize": MIN_TEXT_PT,
    "xtick.labelsize": MIN_TEXT_PT,
    "ytick.labelsize": MIN_TEXT_PT,
}


def kn_sweep_figure(
    table: pd.DataFrame, stem: Path, du_rigid_mm: float | None = None, engine: str = "DEM", paper: bool = False
) -> list[Path]:
    """Write STEM.pdf and STEM.png from the collapsed runs of a kn sweep by `engine`, with the
    rigid-block limit `du_rigid_mm` as the stiff asymptote when given, and the paper's FE points and
    hinge ranges only for the `paper`'s arch; returns both paths."""
    runs = _collapsed(table).sort_values("kn_N_per_mm3")
    with matplotlib.rc_context(SWEEP_STYLE):
        fig = Figure(figsize=(COLUMN_WIDTH_IN, 4.4), layout="constrained")
        ax_du, ax_h = fig.subplots(2, 1, sharex=True, gridspec_kw={"height_ratios": [3, 2]})
        _du_panel(ax_du, runs, du_rigid_mm, engine, paper)
        _failed_marks(ax_du, table[table["status"] == "failed"])
        _hinge_panel(ax_h, runs, paper)
        ax_h.set_xscale("log")
        ax_h.set_xlabel(r"joint normal stiffness $k_n$ (N/mm$^3$)")
        return list(save_figure(fig, stem))


def _collapsed(table: pd.DataFrame) -> pd.DataFrame:
    """The finished runs of a campaign that collapsed; ValueError if there is none to plot."""
    runs = table[(table["status"] == "done") & (table["collapsed"] == True)]  # noqa: E712
    if runs.empty:
        raise ValueError("no collapsed run to plot")
    return runs


def _du_panel(ax: Axes, runs: pd.DataFrame, du_rigid_mm: float | None, engine: str, paper: bool) -> None:
    ax.plot(runs["kn_N_per_mm3"], runs["du_mm"], "o-", color="C0", ms=3.5, lw=1, label=f"yadearch ({engine})")
    other = runs[runs["mechanism"] != PAPER_MECHANISM]
    if paper and not other.empty:  # the paper's mechanism is a reference for the paper's arch only
        ax.plot(
            other["kn_N_per_mm3"],
            other["du_mm"],
            "o",
            mfc="white",
            mec="C3",
            ms=5.5,
            mew=1,
            label="collapse by another mechanism (see results.csv)",
        )
    if du_rigid_mm is not None:
        ax.axhline(du_rigid_mm, color="0.3", ls="--", lw=0.8, label=f"rigid-block limit analysis: {du_rigid_mm:.1f} mm")
    else:
        stiffest = runs.iloc[-1]
        ax.axhline(
            stiffest["du_mm"],
            color="0.5",
            ls="--",
            lw=0.8,
            label=f"stiffest run ({stiffest['kn_N_per_mm3']:g} N/mm$^3$): {stiffest['du_mm']:.1f} mm",
        )
    if paper:
        kn = [s["kn_N_per_mm3"] for s in reference.SETS.values()]
        du = [s["numerical"]["du_mm"] for s in reference.SETS.values()]
        ax.plot(kn, du, "D", mfc="none", color="C3", ms=5, label="paper FE, calibrated (sets 1, 2)")
    ax.set_ylabel(r"collapse displacement $d_u$ (mm)")
    ax.legend(loc="lower right", frameon=False)
    ax.grid(True, which="major", lw=0.3, alpha=0.5)


def _failed_marks(ax: Axes, failed: pd.DataFrame) -> None:
    """Runs without a converged du, as crosses on the kn axis (their reasons are in results.csv)."""
    if failed.empty:
        return
    ax.plot(
        failed["kn_N_per_mm3"],
        [0.02] * len(failed),
        "x",
        color="0.4",
        ms=4,
        clip_on=False,
        transform=ax.get_xaxis_transform(),
        label="no converged du (failed, see results.csv)",
    )
    ax.legend(loc="lower right", frameon=False)


def _hinge_panel(ax: Axes, runs: pd.DataFrame, paper: bool) -> None:
    """Hinge interfaces against kn; the paper's ranges as bars half an interface beyond each end,
    so that a single interface still shows."""
    for column, (letter, marker, label) in HINGE_STYLE.items():
        present = runs[runs[column].notna()]
        ax.plot(
            present["kn_N_per_mm3"],
            present[column].astype(float),
            marker,
            color=hinge_colour(letter),
            ms=3.5,
            mfc="none",
            label=label,
        )
    if paper and set(runs["n_voussoirs"]) == {reference.GEOMETRY["n_voussoirs"]}:
        for s in reference.SETS.values():
            for column in HINGE_STYLE:
                interfaces = s["numerical"][column]
                ax.plot(
                    [s["kn_N_per_mm3"]] * 2,
                    [min(interfaces) - 0.5, max(interfaces) + 0.5],
                    "-",
                    color="C3",
                    lw=2.5,
                    alpha=0.5,
                    solid_capstyle="round",
                )
        ax.plot([], [], "-", color="C3", lw=2.5, alpha=0.5, label="paper FE")
    ax.set_ylabel("hinge interface\n(1 = left support)")
    ax.yaxis.set_major_locator(MaxNLocator(integer=True))
    last_interface = int(runs["n_voussoirs"].max()) + 1
    ax.set_ylim(0, LEGEND_HEADROOM * last_interface)  # room above the right-support hinge for the legend
    ax.legend(loc="upper center", frameon=False, ncol=2)
    ax.grid(True, which="major", lw=0.3, alpha=0.5)


def parameter_sweep_figure(table: pd.DataFrame, column: str, stem: Path, parameters: Sequence[str]) -> list[Path]:
    """du against one swept `column` (results.csv's name for it), one line per combination of the
    other swept `parameters` that vary, numbers or not (a shape, a movement), where the runs form a grid
    of them; else (a table of unlike cases) one unjoined point a run, named; log scale when the values
    span more than a decade; an arch that cannot stand is drawn at du 0 and marked. Writes STEM.pdf/.png."""
    du = collapse_displacement(table)  # cannot stand: 0, as the studies count it
    runs = table.assign(du_mm=du)[np.isfinite(du)]
    if runs.empty:
        raise ValueError("no collapsed run to plot")
    # a parameter left at the base case in some rows (an empty cell) takes a value of its own there
    others = [c for c in parameters if c != column and c in table and table[c].nunique(dropna=False) > 1]
    grid = _is_grid(table, [column, *others])
    groups = _lines(runs, others) if grid else []
    if grid and all(len(group) < 2 for _, group in groups):
        raise ValueError(f"du against {column}: no two finished runs differ in it alone")
    with matplotlib.rc_context(SWEEP_STYLE):
        fig = Figure(figsize=(COLUMN_WIDTH_IN, 2.6), layout="constrained")
        ax = fig.subplots()
        if not grid:
            _run_points(ax, runs, column)
        shade = _shades(others, groups) if grid else None  # many lines of one setting: a colour scale
        for key, group in groups:
            group = group.sort_values(column)
            values_of = key if isinstance(key, tuple) else (key,)
            label = ", ".join(_setting(c, v) for c, v in zip(others, values_of))
            if len(others) > LEGEND_SETTINGS and "run" in group:  # a table of unlike arches: name its runs
                label = ", ".join(group["run"].astype(str))
            style = {"color": shade.to_rgba(values_of[0])} if shade is not None else {"label": label or None}
            ax.plot(group[column], group["du_mm"], "o-", ms=3.5 if shade is None else 2.0, lw=1, **style)
        values = runs[column].astype(float)
        if (values > 0).all() and values.max() > DECADE * values.min():
            ax.set_xscale("log")
        ax.set_xlabel(parameter_label(column))
        ax.set_ylabel(r"collapse displacement $d_u$ (mm)")
        fell = runs[runs["du_mm"] == 0.0]
        if not fell.empty:
            ax.plot(fell[column], fell["du_mm"], "x", color="C3", ms=5, label="cannot stand (du 0)")
        if shade is not None:
            fig.colorbar(shade, ax=ax, label=parameter_label(others[0]))
        if ax.get_legend_handles_labels()[0]:
            ax.legend(frameon=False)
        ax.grid(True, lw=0.3, alpha=0.5)
        return list(save_figure(fig, stem))


def _is_grid(table: pd.DataFrame, columns: list[str]) -> bool:
    """Whether the table's rows hold every combination of `columns`' values (an empty cell, the base
    case's value, one of its own): then a line through the runs alike but for one column means a trend."""
    values = table[columns].astype(object).where(table[columns].notna(), BASE_CASE)
    return len(values.drop_duplicates()) == int(np.prod([values[c].nunique() for c in columns]))


def _run_points(ax: Axes, runs: pd.DataFrame, column: str) -> None:
    """A table's runs that are no grid as points, unjoined (a line would suggest a trend the other
    parameters break) and open (coinciding points stay visible), named where there are few: the names
    of points at one value and within NEAR_FRACTION of the du range of each other in one label."""
    ax.plot(runs[column], runs["du_mm"], "o", mfc="none", color="C0", ms=4, mew=0.8)
    ax.margins(x=0.08, y=0.12)  # room for the names above and right of the outer points
    if "run" not in runs or len(runs) > MAX_NAMED_POINTS:
        return
    near = NEAR_FRACTION * max(float(np.ptp(runs["du_mm"])), 1e-9)
    labels: list[tuple[float, float, list[str]]] = []  # x, du and the names drawn there
    for _, run in runs.sort_values([column, "du_mm"]).iterrows():
        x, du = float(run[column]), float(run["du_mm"])
        if labels and labels[-1][0] == x and du - labels[-1][1] <= near:
            labels[-1][2].append(str(run["run"]))
        else:
            labels.append((x, du, [str(run["run"])]))
    for x, du, names in labels:
        ax.annotate(", ".join(names), (x, du), xytext=(4, 3), textcoords="offset points", fontsize=MIN_TEXT_PT)


def _shades(others: list[str], groups: list[tuple[object, pd.DataFrame]]) -> ScalarMappable | None:
    """A colour scale for the lines where there are more than MAX_LEGEND_LINES of them, all of one
    numeric setting (a legend of 40 kn levels covered the data); None: a legend names them."""
    values = pd.to_numeric(pd.Series([key for key, _ in groups]), errors="coerce")
    if len(others) != 1 or len(groups) <= MAX_LEGEND_LINES or values.isna().any():
        return None
    low, high = float(values.min()), float(values.max())
    norm = LogNorm(low, high) if low > 0 and high > DECADE * low else Normalize(low, high)
    return ScalarMappable(norm=norm, cmap=SHADES)


def _lines(runs: pd.DataFrame, others: list[str]) -> list[tuple[object, pd.DataFrame]]:
    """The runs grouped by their values of `others` (an empty cell, the base case's value, a group of its
    own): one line of the figure each, keyed by those values."""
    if not others:
        return [((), runs)]
    keys = runs[others].astype(object).where(runs[others].notna(), BASE_CASE)
    return list(runs.groupby(keys[others[0]] if len(others) == 1 else [keys[c] for c in others]))


def _setting(column: str, value: object) -> str:
    """A legend's "name = value" (the base case's value where the row left it empty)."""
    if value == BASE_CASE:
        return f"{parameter_name(column)} {BASE_CASE}"
    return parameter_setting(column, value)


def swept_columns(table: pd.DataFrame, parameters: Sequence[str]) -> list[str]:
    """The swept `parameters` (results.csv's names) that take more than one numeric value in `table`:
    the x axes of a sweep's figures (an answer such as du_first_mm is never one)."""
    return [
        c
        for c in parameters
        if c in table and pd.api.types.is_numeric_dtype(table[c]) and table[c].nunique(dropna=True) > 1
    ]
