"""reports/loads: the live-load validation written as tables, a figure and a Markdown report
(`scripts/loads_validation.py`)."""

from __future__ import annotations

import math
from pathlib import Path

import pandas as pd

from yadearch.atomic import write_csv_atomically, write_text_atomically
from yadearch.case.config import ArchCase
from yadearch.case.mechanics import arch_geometry
from yadearch.markdown import markdown_table
from yadearch.plotting.load_figure import plot_load_collapse
from yadearch.plotting.loads import plot_loads
from yadearch.solve.load_lp import load_analysis
from yadearch.solve.rigid import rigid_arch
from yadearch.studies.loads import (
    check_cases,
    influence_line,
    mechanism_check,
    paper_arch,
    residual_capacities,
    semicircle_accelerations,
)

CHECK_TOLERANCE = 1e-9  # relative: the LP and the mechanism method are one answer to round-off
QUARTERS = (0.25, 0.5, 0.75)


def write_loads_report(out: Path) -> Path:
    """Run the study and write its files into `out`; the report's path."""
    out.mkdir(parents=True, exist_ok=True)
    paper = paper_arch()
    checks = mechanism_check(check_cases())
    influence = influence_line(paper)
    accelerations = semicircle_accelerations()
    residual = residual_capacities(paper.with_overrides({"live_load": "vertical"}))
    tables = {
        "mechanism_check": checks,
        "influence_line": influence,
        "semicircle_acceleration": accelerations,
        "residual_capacity": residual,
    }
    for name, table in tables.items():
        write_csv_atomically(out / f"{name}.csv", table)
    weight = float(rigid_arch(paper).weight[1:-1].sum())
    plot_loads(influence, accelerations, residual, weight, out / "loads")
    quarter = paper.with_overrides({"live_load": "vertical", "load_position_over_span": QUARTERS[0]})
    plot_load_collapse(quarter, arch_geometry(quarter), load_analysis(quarter), out / "quarter_span_collapse")
    path = out / "loads.md"
    write_text_atomically(path, _markdown(paper, checks, influence, accelerations, residual, weight))
    return path


def _capacity_text(multiplier: float, unit: str) -> str:
    """A multiplier in words: infinite means the load's thrust line stays inside the ring at any size."""
    if math.isinf(multiplier):
        return "no collapse however large (its funicular lies within the ring, and rigid blocks do not crush)"
    return f"{multiplier:.2f} {unit}"


def _markdown(
    paper: ArchCase,
    checks: pd.DataFrame,
    influence: pd.DataFrame,
    accelerations: pd.DataFrame,
    residual: pd.DataFrame,
    weight: float,
) -> str:
    """The report's text."""
    agree = int((checks["relative_difference"].abs() <= CHECK_TOLERANCE).sum())
    same = int((checks["lp_hinges"] == checks["mechanism_hinges"]).sum())
    span_mm = rigid_arch(paper).geometry.span * 1e3
    uniform = load_analysis(
        paper.with_overrides({"live_load": "vertical", "load_position_over_span": 0.5, "load_width_mm": span_mm})
    )
    acceleration = load_analysis(paper.with_overrides({"live_load": "horizontal_acceleration"}))
    quarters = influence[influence["position_over_span"].isin(QUARTERS)]
    lines = [
        "# Live loads by rigid-block limit analysis",
        "",
        "The load multiplier of the rigid-block limit analysis (`yadearch loads`, docs/theory.md "
        '"Live loads"): the largest factor on a live load the arch carries, its self-weight held, '
        "in an admissible equilibrium (no tension, Coulomb friction), and its mechanism from the "
        "programme's dual. Regenerate: `.venv/bin/python scripts/loads_validation.py`.",
        "",
        "## The linear programme against the mechanism method",
        "",
        f"Every four-hinge mechanism of small arches tried by virtual work (`solve/mechanisms.py`, no "
        f"linear programme), friction 80 deg so that none slides: the least multiplier equals the "
        f"programme's within {CHECK_TOLERANCE:g} in {agree} of {len(checks)} cases, on the same hinges "
        f"in {same}.",
        "",
        *markdown_table(
            ["case", "LP multiplier", "mechanism method", "difference", "LP hinges", "mechanism hinges"],
            [
                [
                    r.case,
                    f"{r.lp_multiplier:.6g}",
                    f"{r.mechanism_multiplier:.6g}",
                    f"{r.relative_difference:+.1e}",
                    r.lp_hinges,
                    r.mechanism_hinges,
                ]
                for r in checks.itertuples()
            ],
        ),  # fmt: skip
        "",
        "(N for a vertical load of 1 N, g for an acceleration.) Where a load at mid-span meets two "
        "mirror-image mechanisms of equal multiplier, the programme's dual (its velocities) is a blend "
        "of both and lists the hinges of each.",
        "",
        "## The paper's arch",
        "",
        f"55 voussoirs, friction 41.2 deg, the voussoirs weighing {weight:.2f} N. A concentrated load at "
        + ", ".join(
            f"{r.position_over_span:g} of the span: {r.collapse_load_N:.2f} N ({r.collapse_load_N / weight:.3f} W, "
            f"{r.hinges})"
            for r in quarters.itertuples()
        )
        + f". A load spread uniformly over the span ({span_mm:.0f} mm): {_capacity_text(uniform.multiplier, 'N')}. "
        f"A horizontal acceleration: {acceleration.multiplier:.3f} g ({acceleration.hinge_labels}).",
        "",
        "![a point load at the quarter span at collapse](quarter_span_collapse.png)",
        "",
        "![live loads](loads.png)",
        "",
        "Residual capacity to a point load at the quarter span after a settlement of the right support "
        "(the arch in the rigid march's state there, its three hinges open):",
        "",
        *markdown_table(
            ["settlement / du_rigid", "settlement (mm)", "capacity (N)", "hinges"],
            [
                [f"{r.settlement_over_du_rigid:g}", f"{r.settlement_mm:.2f}", f"{r.capacity:.3f}", r.hinges]
                for r in residual.itertuples()
            ],
        ),  # fmt: skip
        "",
        "A rigid arch that has settled is a three-hinge arch: one more hinge makes it a mechanism, so the "
        "capacity falls at once from the arch at rest (statically indeterminate) to a fraction of it. "
        "Joints of finite stiffness make that fall gradual; the static engine and the DEM do not apply "
        "live loads yet.",
        "",
        "## Semicircles under a horizontal acceleration",
        "",
        *markdown_table(
            ["t/R", "collapse acceleration (g)", "hinges"],
            [[f"{r.t_over_R:g}", f"{r.collapse_acceleration_g:.4f}", r.hinges] for r in accelerations.itertuples()],
        ),
        "",
        "55 voussoirs with radial joints, intrados radius 300 mm, friction 41.2 deg. Below Milankovitch's "
        "t/R = 0.1075 no semicircle stands (tests/solve/test_loads.py); not compared here with published "
        "curves (Oppenheim 1992, DeJong 2009, Alexakis and Makris 2014).",
        "",
    ]
    return "\n".join(lines)
