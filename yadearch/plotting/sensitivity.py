"""Figures of the sensitivity study: the tornado of one-at-a-time effects on du, the bar chart of
Sobol's first-order and total indices with their bootstrap intervals, and their convergence."""

from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np
import pandas as pd
from matplotlib.figure import Figure
from matplotlib.ticker import LogLocator, NullFormatter, ScalarFormatter

from yadearch.plotting.house import save_figure
from yadearch.plotting.sweep import COLUMN_WIDTH_IN, SWEEP_STYLE

ROW_HEIGHT_IN = 0.24  # one factor's bar
MARGIN_HEIGHT_IN = 0.9  # axes labels and legend
WIDTH_COLUMNS = 2.0  # journal columns: a page wide, room for the factors' labels
BAR_HEIGHT = 0.38  # of a row, for each of the two bars (low and high end; S1 and ST)
LOG_TICKS = (1.0, 2.0, 5.0)  # major ticks of a log axis in each decade


def tornado_figure(tornado: pd.DataFrame, stem: Path) -> tuple[Path, Path]:
    """STEM.pdf/.png: du at the low and the high end of each factor's range (others at the base case),
    as bars from the base du, largest swing on top."""
    rows = tornado.iloc[::-1].reset_index(drop=True)
    base = float(rows["du_base_mm"].iloc[0])
    y = np.arange(len(rows))
    with matplotlib.rc_context(SWEEP_STYLE):
        ax = _bar_axes(len(rows))
        ax.barh(
            y + BAR_HEIGHT / 2,
            rows["du_low_mm"] - base,
            BAR_HEIGHT,
            left=base,
            color="C0",
            label="low end of the range",
        )
        ax.barh(
            y - BAR_HEIGHT / 2,
            rows["du_high_mm"] - base,
            BAR_HEIGHT,
            left=base,
            color="C1",
            label="high end of the range",
        )
        ax.axvline(base, color="k", lw=0.8)
        ax.set_yticks(y, [f"{r.label} [{r.low:g}, {r.high:g}]" for r in rows.itertuples()])
        ax.set_xlabel(rf"collapse displacement $d_u$ (mm); base case {base:.1f} mm")
        ax.legend(loc="lower center", bbox_to_anchor=(0.5, 1.0), ncols=2, frameon=False)  # above: off the base line
        return save_figure(ax.figure, stem)


def indices_figure(indices: pd.DataFrame, labels: dict[str, str], stem: Path) -> tuple[Path, Path]:
    """STEM.pdf/.png: first-order (S1) and total (ST) Sobol indices of du per factor, with their
    bootstrap confidence intervals, from the largest sample in `indices`."""
    largest = indices[indices["base_points"] == indices["base_points"].max()]
    rows = largest.sort_values("ST").reset_index(drop=True)
    y = np.arange(len(rows))
    with matplotlib.rc_context(SWEEP_STYLE):
        ax = _bar_axes(len(rows))
        ax.barh(
            y + BAR_HEIGHT / 2,
            rows["S1"],
            BAR_HEIGHT,
            xerr=rows["S1_conf"],
            color="C0",
            capsize=1.5,
            label="first order $S_1$",
        )
        ax.barh(
            y - BAR_HEIGHT / 2,
            rows["ST"],
            BAR_HEIGHT,
            xerr=rows["ST_conf"],
            color="C1",
            capsize=1.5,
            label="total $S_T$",
        )
        ax.set_yticks(y, [labels.get(name, name) for name in rows["factor"]])
        ax.set_xlabel(f"Sobol index of $d_u$ ({int(rows['used_points'].iloc[0])} base points)")
        ax.axvline(0.0, color="k", lw=0.6)
        ax.legend(loc="lower right")
        return save_figure(ax.figure, stem)


def _bar_axes(rows: int):
    """Axes of a horizontal bar chart of `rows` factors, WIDTH_COLUMNS journal columns wide."""
    size = (COLUMN_WIDTH_IN * WIDTH_COLUMNS, MARGIN_HEIGHT_IN + ROW_HEIGHT_IN * rows)
    fig = Figure(figsize=size, layout="constrained")
    return fig.subplots()


def convergence_figure(
    table: pd.DataFrame, target: float, scale: float, fitted_from: int, stem: Path
) -> tuple[Path, Path]:
    """STEM.pdf/.png: the largest change of a Sobol index at each doubling of the sample and the
    indices' mean bootstrap half-width against the sample size, with the stability target and the
    Monte Carlo rate `scale`/sqrt(N), fitted from `fitted_from` base points up, drawn from there to
    where it meets the target."""
    with matplotlib.rc_context(SWEEP_STYLE):
        fig = Figure(figsize=(COLUMN_WIDTH_IN, COLUMN_WIDTH_IN * 0.8), layout="constrained")
        ax = fig.subplots()
        ax.loglog(table["base_points"], table["largest_change"], "o-", color="C0", label="largest change since N/2")
        ax.loglog(table["base_points"], table["mean_half_width"], "s--", color="C1", label="mean 95 % half-width")
        reach = np.geomspace(fitted_from, max((scale / target) ** 2, table["base_points"].iloc[-1]))
        fit_label = rf"$c/\sqrt{{N}}$ fitted from N = {fitted_from}"
        ax.loglog(reach, scale / np.sqrt(reach), color="0.5", lw=0.8, label=fit_label)
        ax.axhline(target, color="k", lw=0.8, ls=":", label=f"target {target:g}")
        ax.set_xscale("log", base=2)
        ax.set_xlabel("base points N of the Sobol sample")
        ax.set_ylabel("change or half-width of a Sobol index")
        ax.yaxis.set_major_locator(LogLocator(base=10.0, subs=LOG_TICKS))  # a range under a decade still
        ax.yaxis.set_major_formatter(ScalarFormatter())  # gets ticks, written as plain numbers
        ax.yaxis.set_minor_formatter(NullFormatter())
        ax.legend(loc="upper right")
        return save_figure(fig, stem)
