"""kn-curve.md: the whole du(kn) curve in words and tables, for a reader who takes it into a paper."""

from __future__ import annotations

import math

import pandas as pd

KN = "kn_N_per_mm3"


def kn_curve_markdown(
    static: pd.DataFrame,
    jumps: pd.DataFrame,
    moves: pd.DataFrame,
    dem: pd.DataFrame | None,
    limits: pd.DataFrame,
    du_rigid_mm: float,
    static_wall_s: float,
    dem_wall_s: float | None,
) -> str:
    """The report: how the curve was made and what it cost, its jumps, the DEM's points against it,
    the stiff end against the compliant march and the rigid limit."""
    done = static[static["status"] == "done"].sort_values(KN)
    lines = [
        "# du against kn, the whole curve (static engine)",
        "",
        "Regenerate with `.venv/bin/python scripts/kn_curve.py` (about a minute on two cores). The paper's "
        "arch (55 voussoirs) settling at its right support, at 200 log-spaced kn from "
        f"{done[KN].min():g} to {done[KN].max():g} N/mm³ plus the DEM sweep's kn, each jump of du bisected in "
        f"kn to 1 %: {len(static)} static runs in {static_wall_s:.0f} s of campaign wall time on two cores"
        + (f" (the DEM's 31-point sweep took {dem_wall_s / 60:.1f} min)" if dem_wall_s else "")
        + ".",
        "",
        "![du against kn](du_vs_kn.png)",
        "",
        "*du against the joint stiffness kn: the static engine's curve, the DEM's sweep points, the compliant "
        "march from kn 16 up, the rigid-block limit and the paper's two calibrated cases; below, the interfaces "
        "of hinges A and B ([PDF](du_vs_kn.pdf)).*",
        "",
        "## Jumps",
        "",
        "| kn below → above (N/mm³) | du below → above (mm) | hinges below → above | what moves |",
        "|---|---|---|---|",
    ]
    for j in jumps.itertuples():
        below = "—" if math.isnan(j.du_below_mm) else f"{j.du_below_mm:.2f}"
        lines.append(
            f"| {j.kn_below:.4g} → {j.kn_above:.4g} | {below} → {j.du_above_mm:.2f} | "
            f"{j.hinges_below or '—'} → {j.hinges_above} | {j.what} |"
        )
    if not moves.empty:
        lines += [
            "",
            "Hinge moves without a jump of du (located to the grid's spacing, not bisected): "
            + "; ".join(
                f"{m.what} between kn {m.kn_below:.4g} and {m.kn_above:.4g} ({m.du_mm:.2f} mm)"
                for m in moves.itertuples()
            )
            + ".",
        ]
    if dem is not None:
        lines += [
            "",
            "## The DEM's sweep points",
            "",
            "| kn (N/mm³) | DEM du (mm) | static du (mm) | difference (%) | DEM hinges | static hinges |",
            "|---|---|---|---|---|---|",
        ]
        by_kn = done.set_index(KN)
        for d in dem[dem["status"] == "done"].sort_values(KN).itertuples():
            s = by_kn.loc[d.kn_N_per_mm3] if d.kn_N_per_mm3 in by_kn.index else None
            static_du = float(s["du_mm"]) if s is not None else math.nan
            static_hinges = s["hinges"] if s is not None else "—"
            lines.append(
                f"| {d.kn_N_per_mm3:g} | {d.du_mm:.2f} | {static_du:.2f} | "
                f"{100 * (static_du / d.du_mm - 1):+.2f} | {d.hinges} | {static_hinges} |"
            )
    lines += [
        "",
        "## Toward stiff joints",
        "",
        f"The rigid-block limit is {du_rigid_mm:.2f} mm; the static engine reaches "
        f"{done['du_mm'].iloc[-1]:.2f} mm at kn {done[KN].iloc[-1]:g} "
        f"({100 * (done['du_mm'].iloc[-1] / du_rigid_mm - 1):+.2f} %).",
        "",
        "| kn (N/mm³) | static du (mm) | compliant march (mm) | difference (%) |",
        "|---|---|---|---|",
    ]
    for r in limits.itertuples():
        lines.append(
            f"| {r.kn_N_per_mm3:g} | {r.static_du_mm:.2f} | {r.compliant_du_mm:.2f} | "
            f"{100 * (r.static_du_mm / r.compliant_du_mm - 1):+.2f} |"
        )
    return "\n".join(lines) + "\n"
