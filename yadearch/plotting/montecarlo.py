"""Figures of a Monte Carlo campaign: du's distribution (histogram and ECDF with the median and the
5-95 % band), where each hinge formed (share of samples per interface), and du against an
imperfection amplitude (median and band per level)."""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path

import matplotlib
import numpy as np
import pandas as pd
from matplotlib.figure import Figure

from yadearch.analysis.samples import BAND, COMMON_SHARE, du_statistics, hinge_frequencies, unlettered_hinges
from yadearch.model.hinges import PAPER_LABELS
from yadearch.plotting.house import hinge_colour, save_figure
from yadearch.plotting.parameter_labels import parameter_label, parameter_setting
from yadearch.plotting.sweep import COLUMN_WIDTH_IN, SWEEP_STYLE

HINGE_SIDES = {"A": "intrados", "B": "extrados", "C": "extrados, moving support", "D": "extrados, fixed support"}
BINS = 20  # histogram bins at most
PANELS_PER_ROW = 3  # du against amplitude: panels side by side
PANEL_HEIGHT_IN = 2.4
DU_LABEL = "collapse displacement $d_u$ (mm)"
UNLETTERED_COLOUR = "0.6"  # hinges without a paper letter, in grey
REFERENCE_STYLES = ("--", ":", "-.")  # one reference du each, in black


def _done(table: pd.DataFrame) -> pd.DataFrame:
    done = table[(table["status"] == "done") & table["du_mm"].notna()]
    if done.empty:
        raise ValueError("no finished sample to plot")
    return done


def du_distribution_figure(
    table: pd.DataFrame, stem: Path, references: Sequence[tuple[float, str]] = (), drawn: str = ""
) -> list[Path]:
    """Histogram and empirical CDF of the samples' du with the median and the band marked, and each
    reference du of `references` ((du in mm, what it is), e.g. the perfect arch's) as a line:
    STEM.pdf and STEM.png. The title counts the samples drawn that have no du (stand or failed) and
    says what they were drawn with (`drawn`, e.g. "face bump s.d. = 0.18 mm")."""
    du = _done(table)["du_mm"].to_numpy(dtype=float)
    stats = du_statistics(pd.Series(du))
    with matplotlib.rc_context(SWEEP_STYLE):
        fig = Figure(figsize=(COLUMN_WIDTH_IN, 4.0), layout="constrained")
        ax_hist, ax_cdf = fig.subplots(2, 1, sharex=True)
        ax_hist.hist(du, bins=min(BINS, max(5, du.size // 5)), color="C0", alpha=0.75)
        ax_hist.set_ylabel("samples")
        ordered = np.sort(du)
        ax_cdf.step(ordered, np.arange(1, du.size + 1) / du.size, where="post", color="C0")
        ax_cdf.set_ylabel("share of samples with $d_u$ below")
        ax_cdf.set_xlabel(DU_LABEL)
        for ax in (ax_hist, ax_cdf):
            ax.axvspan(stats["low"], stats["high"], color="C0", alpha=0.12, label=f"{BAND[0]:.0%}-{BAND[1]:.0%} band")
            ax.axvline(stats["median"], color="C3", lw=1, label=f"median {stats['median']:.1f} mm")
            for (du_mm, label), style in zip(references, REFERENCE_STYLES):
                ax.axvline(du_mm, color="k", ls=style, lw=0.8, label=f"{label} {du_mm:.1f} mm")
        ax_cdf.legend(loc="lower right", frameon=True, framealpha=0.9)  # under the CDF, where nothing is drawn
        without = len(table) - du.size
        title = f"$d_u$ of {du.size} samples" + (f" ({without} more drawn: no $d_u$)" if without else "")
        title += f"\n{drawn}" if drawn else ""
        ax_hist.set_title(title, fontsize=8)
        return list(save_figure(fig, stem))


def hinge_frequency_figure(table: pd.DataFrame, stem: Path) -> list[Path]:
    """Share of the samples whose hinge A, B, C or D formed at each interface, and of those whose hinge
    without a letter did where half of them or more do (stacked where they share an interface):
    STEM.pdf, STEM.png."""
    frequencies = hinge_frequencies(_done(table))
    others = unlettered_hinges(_done(table))
    others = others[others["share"] >= COMMON_SHARE]  # the rare ones would hide the lettered
    with matplotlib.rc_context(SWEEP_STYLE):
        fig = Figure(figsize=(COLUMN_WIDTH_IN, 3.0), layout="constrained")
        ax = fig.subplots()
        stacked: dict[int, float] = {}
        groups = [(f"{label} ({HINGE_SIDES[label]})", hinge_colour(label), frequencies[frequencies["hinge"] == label])
                  for label in PAPER_LABELS]  # fmt: skip
        if len(others):
            groups.append(("no letter", UNLETTERED_COLOUR, others.groupby("interface", as_index=False)["share"].sum()))
        for name, colour, rows in groups:
            bottom = [stacked.get(int(i), 0.0) for i in rows["interface"]]
            ax.bar(rows["interface"], rows["share"], bottom=bottom, width=0.8, color=colour, label=name)
            for i, share in zip(rows["interface"], rows["share"]):
                stacked[int(i)] = stacked.get(int(i), 0.0) + float(share)
        ax.set_xlabel("interface (1 = left springing)")
        ax.set_ylabel("share of samples")
        ax.set_ylim(0, max(1.0, *stacked.values()) * 1.05 if stacked else 1.0)
        ax.legend(loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=2, frameon=False)  # above the bars
        return list(save_figure(fig, stem))


def _draw_du_against(ax, done: pd.DataFrame, column: str, perfect_du_mm: float | None = None) -> None:
    """The samples' du as dots, the median per amplitude level and its band; from the perfect arch's
    du at amplitude 0 when given."""
    levels = sorted(float(v) for v in done[column].unique())
    stats = [du_statistics(done.loc[np.isclose(done[column], level), "du_mm"]) for level in levels]
    start = [] if perfect_du_mm is None else [perfect_du_mm]
    x = ([0.0] if start else []) + levels
    ax.plot(done[column], done["du_mm"], ".", color="0.6", ms=2.5, label="samples")
    ax.fill_between(
        x,
        start + [s["low"] for s in stats],
        start + [s["high"] for s in stats],
        color="C0",
        alpha=0.2,
        label=f"{BAND[0]:.0%}-{BAND[1]:.0%} band",
    )
    ax.plot(x, start + [s["median"] for s in stats], "o-", color="C0", ms=3.5, lw=1, label="median")


def du_amplitude_figure(table: pd.DataFrame, column: str, stem: Path, label: str | None = None) -> list[Path]:
    """Median du and its band against the amplitude in `column`, samples as dots: STEM.pdf, .png."""
    with matplotlib.rc_context(SWEEP_STYLE):
        fig = Figure(figsize=(COLUMN_WIDTH_IN, 2.6), layout="constrained")
        ax = fig.subplots()
        _draw_du_against(ax, _done(table), column)
        ax.set_xlabel(label or parameter_label(column))
        ax.set_ylabel(DU_LABEL)
        ax.legend(frameon=False)
        return list(save_figure(fig, stem))


def campaign_figures(
    table: pd.DataFrame, folder: Path, level_columns: list[str], references: Sequence[tuple[float, str]] = ()
) -> list[Path]:
    """A campaign's figures in `folder`: du's distribution (with the `references` lines), the hinge
    positions and du against each amplitude swept over two levels or more (one level is no curve).
    ValueError if no sample finished."""
    levels = {c: table[c].nunique() for c in level_columns}
    swept = [c for c, n in levels.items() if n > 1]
    drawn = ", ".join(  # what every sample was drawn with: the amplitudes of one level
        parameter_setting(c, float(table[c].iloc[0])) for c, n in levels.items() if n == 1
    )
    paths = du_distribution_figure(table, folder / "du_distribution", references, drawn)
    paths += hinge_frequency_figure(table, folder / "hinge_positions")
    for column in swept:
        paths += du_amplitude_figure(table, column, folder / f"du_vs_{column}")
    return paths


def amplitude_panels_figure(
    panels: list[tuple[pd.DataFrame, str, str, float]], stem: Path, target_du_mm: float, target_label: str
) -> list[Path]:
    """One panel per imperfection kind (table, amplitude column, axis label, du of its perfect arch):
    median du and band against the amplitude from the perfect arch at 0, with the target du dashed:
    STEM.pdf, .png."""
    with matplotlib.rc_context(SWEEP_STYLE):
        rows = math.ceil(len(panels) / PANELS_PER_ROW)
        columns = min(len(panels), PANELS_PER_ROW)
        fig = Figure(figsize=(2 * COLUMN_WIDTH_IN, PANEL_HEIGHT_IN * rows), layout="constrained")
        grid = fig.subplots(rows, columns, sharey=True, squeeze=False)
        axes = grid.ravel()
        for ax, (table, column, label, perfect_du_mm) in zip(axes, panels):
            _draw_du_against(ax, _done(table), column, perfect_du_mm)
            ax.axhline(target_du_mm, color="C3", ls="--", lw=0.8, label=target_label)
            ax.set_xlabel(label)
        for ax in axes[len(panels) :]:
            ax.set_visible(False)
        for ax in grid[:, 0]:
            ax.set_ylabel(DU_LABEL)
        axes[0].legend(frameon=False, loc="lower left")
        return list(save_figure(fig, stem))
