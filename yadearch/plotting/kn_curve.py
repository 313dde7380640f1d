"""The whole du(kn) curve (the paper's Fig. 8 redrawn): the static engine's curve, the DEM's sweep
points on top, the compliant march and the rigid limit toward stiff joints, the paper's two cases,
and below it the interfaces of hinges A and B, whose moves make the curve's jumps."""

from __future__ import annotations

from pathlib import Path

import matplotlib
import pandas as pd
from matplotlib.figure import Figure

from yadearch.case import reference
from yadearch.plotting.house import MIN_TEXT_PT, hinge_colour, save_figure
from yadearch.plotting.sweep import COLUMN_WIDTH_IN, HINGE_STYLE, SWEEP_STYLE

FIGURE_HEIGHT_IN = 4.6


def kn_curve_figure(
    static: pd.DataFrame, dem: pd.DataFrame | None, limits: pd.DataFrame, du_rigid_mm: float, stem: Path
) -> tuple[Path, Path]:
    """STEM.pdf and .png from the static runs (a campaign's results), the DEM's sweep results (or
    None), the compliant march's du (`limits`: kn, compliant_du_mm) and the rigid limit."""
    runs = static[(static["status"] == "done") & (static["collapsed"] == True)].sort_values("kn_N_per_mm3")  # noqa: E712
    with matplotlib.rc_context(SWEEP_STYLE):
        fig = Figure(figsize=(COLUMN_WIDTH_IN, FIGURE_HEIGHT_IN), layout="constrained")
        ax, ax_h = fig.subplots(2, 1, sharex=True, gridspec_kw={"height_ratios": [3, 2]})
        ax.plot(runs["kn_N_per_mm3"], runs["du_mm"], "-", color="C0", lw=1.0, label="static engine")
        if dem is not None:
            done = dem[dem["status"] == "done"]
            ax.plot(done["kn_N_per_mm3"], done["du_mm"], "o", mfc="none", mec="k", ms=3.5, mew=0.7, label="DEM (YADE)")
        if not limits.empty:
            ax.plot(limits["kn_N_per_mm3"], limits["compliant_du_mm"], "^", color="C2", ms=3.5, label="compliant march")
        ax.axhline(du_rigid_mm, color="0.4", ls="--", lw=0.8, label=f"rigid blocks ({du_rigid_mm:.1f} mm)")
        for name, ref in reference.SETS.items():
            ax.plot(
                ref["kn_N_per_mm3"],
                ref["numerical"]["du_mm"],
                "*",
                color="C3",
                ms=7,
                label="paper FE (set 1, set 2)" if name == "set1" else None,
            )
            ax.annotate(  # which set each star is
                name.replace("set", "set "),
                (ref["kn_N_per_mm3"], ref["numerical"]["du_mm"]),
                xytext=(4, -8),
                textcoords="offset points",
                color="C3",
                fontsize=MIN_TEXT_PT,
            )
        ax.set_ylabel(r"collapse displacement $d_u$ (mm)")
        ax.set_ylim(bottom=0.0)
        ax.legend(loc="lower right")
        for column in ("hinge_A", "hinge_B"):
            letter, marker, label = HINGE_STYLE[column]
            ax_h.plot(
                runs["kn_N_per_mm3"], runs[column], marker, color=hinge_colour(letter), ms=1.8, label=f"hinge {label}"
            )
        ax_h.set_ylabel("hinge's interface\n(static; 1: left springing)")
        ax_h.legend(loc="center right")
        ax_h.set_xscale("log")
        ax_h.set_xlabel(r"joint normal stiffness $k_n$ (N/mm$^3$)")
        return save_figure(fig, stem)
