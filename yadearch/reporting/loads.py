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
from yadearch.reporting.loads_published import point_load_markdown, published_markdown
from yadearch.solve.load_lp import load_analysis
from yadearch.solve.rigid import rigid_arch
from yadearch.studies.loads.published import friction_table, point_load_table
from yadearch.studies.loads.rigid import (
    check_cases,
    influence_line,
    mechanism_check,
    paper_arch,
    residual_capacities,
    semicircle_accelerations,
)
from yadearch.studies.loads.static import STIFF_KNS, backfill_capacities, paper_cases, paper_loads, stiff_check

CHECK_TOLERANCE = 1e-9  # relative: the LP and the mechanism method are one answer to round-off
QUARTERS = (0.25, 0.5, 0.75)
PAPER_STIFFNESSES = (0.25, 5.2)  # N/mm3: the paper's voussoir sets 1 and 2
STIFF_TOLERANCE = 0.02  # stiff static within 2 % of rigid blocks (issue 44)
FILL_DEPTHS_MM = (0.0, 20.0, 50.0, 100.0)  # backfill over the crown's extrados
FILL_COEFFICIENTS = (0.0, 0.3)  # its lateral pressure coefficient: none, and about 1 - sin(45 deg)


def write_loads_report(out: Path) -> Path:
    """Run the study and write its files into `out`; the report's path."""
    out.mkdir(parents=True, exist_ok=True)
    paper = paper_arch()
    checks = mechanism_check(check_cases())
    influence = influence_line(paper)
    accelerations = semicircle_accelerations()
    quarter = paper.with_overrides({"live_load": "vertical", "load_position_over_span": QUARTERS[0]})
    residual = residual_capacities(quarter)
    stiff = stiff_check([*check_cases(), *paper_cases(paper)])
    at_paper_kn = paper_loads(paper, PAPER_STIFFNESSES)
    filled = backfill_capacities(paper, FILL_DEPTHS_MM, FILL_COEFFICIENTS, (PAPER_STIFFNESSES[-1], STIFF_KNS[-1]))
    tables = {
        "mechanism_check": checks,
        "influence_line": influence,
        "semicircle_acceleration": accelerations,
        "residual_capacity": residual,
        "static_stiff_check": stiff,
        "static_paper_arch": at_paper_kn,
        "backfill": filled,
        "semicircle_friction": friction_table(),
        "published_point_load": point_load_table(),
    }
    for name, table in tables.items():
        write_csv_atomically(out / f"{name}.csv", table)
    weight = float(rigid_arch(paper).weight[1:-1].sum())
    plot_loads(influence, accelerations, residual, weight, out / "loads")
    plot_load_collapse(quarter, arch_geometry(quarter), load_analysis(quarter), out / "quarter_span_collapse")
    path = out / "loads.md"
    text = (
        _markdown(paper, checks, influence, accelerations, residual, weight)
        + static_markdown(stiff, at_paper_kn)
        + backfill_markdown(filled)
        + published_markdown(tables["semicircle_friction"])
        + point_load_markdown(tables["published_point_load"])
    )
    write_text_atomically(path, text)
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
        "to fractions of du (the static engine's, kn 5.2 N/mm3): on the static path from the settled "
        "state (its first loss of stability and its collapse), and the load that first moves rigid blocks in "
        "the rigid march's state at the same settlement (its open hinges act as pins; at rest, their collapse):",
        "",
        *markdown_table(
            [
                "settlement / du",
                "settlement (mm)",
                "static first loss (N)",
                "static collapse (N)",
                "static hinges",
                "rigid blocks first move (N)",
                "rigid hinges",
            ],
            [
                [
                    f"{r.settlement_over_du:g}",
                    f"{r.settlement_mm:.2f}",
                    f"{r.static_first_loss:.3f}",
                    f"{r.static_capacity:.3f}",
                    r.static_hinges,
                    f"{r.rigid_first_motion:.3f}",
                    r.rigid_hinges,
                ]
                for r in residual.itertuples()
            ],
        ),  # fmt: skip
        "",
        "The two answers differ by design, not by numerics. A rigid arch that has settled stands on three "
        "open hinges, which are pins: the load that moves it is a fraction of its capacity at rest (the "
        "first motion of a four-hinge mechanism). The compliant arch's hinges are joints partly open, "
        "and under the load they re-seat: its path goes on past the rigid arch's first motion (its first "
        "loss of stability, where a hinge snaps to another joint, comes earlier or later than it) and "
        "collapses at a load that falls with the settlement but stays a large part of the capacity at rest. "
        "A residual capacity from rigid blocks alone is the load that first moves the settled arch, "
        "not the load it carries.",
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


def static_markdown(stiff: pd.DataFrame, at_paper_kn: pd.DataFrame) -> str:
    """The static engine's part of the report: stiff joints against rigid blocks, the paper's arch."""
    by_kn = {kn: stiff[stiff["kn_N_per_mm3"] == kn] for kn in STIFF_KNS}
    softer, stiffest = (by_kn[kn]["static_over_rigid"].to_numpy() for kn in STIFF_KNS)
    stiff_rows = [
        [r.case, f"{r.kn_N_per_mm3:g}", f"{r.static_capacity:.5g}", f"{r.rigid_capacity:.5g}",
         f"{r.static_over_rigid:+.2%}", r.static_hinges, r.rigid_hinges]
        for r in stiff.itertuples()
    ]  # fmt: skip
    paper_rows = [
        [r.load, f"{r.kn_N_per_mm3:g}", f"{r.static_first_loss:.4g}", f"{r.static_capacity:.4g}", r.unit,
         r.static_hinges, r.collapse_kind, f"{r.rigid_capacity:.4g}", f"{r.static_over_rigid:+.1%}"]
        for r in at_paper_kn.itertuples()
    ]  # fmt: skip
    lines = [
        "## The static engine's load path",
        "",
        "The live load grown on the static engine's path (`yadearch loads --engine static`, "
        "`ya.load_path`): Newton's method on the DEM's blocks and joints, the load's multiplier as the "
        "path's parameter, the fold bracketed to 0.1 % of the rigid capacity; the first loss of stability "
        "and the collapse as for a support movement (docs/loads.md). Load control: the capacities here "
        "stop at the limit point (`yadearch loads --engine static` goes on past it by arc length).",
        "",
        f"**Stiff joints against rigid blocks**: at kn {STIFF_KNS[-1]:g} N/mm3 (the stiffest a case accepts) "
        f"within {STIFF_TOLERANCE:.0%} of the rigid-block multiplier in "
        f"{int((abs(stiffest) <= STIFF_TOLERANCE).sum())} of {len(stiffest)} cases, at {STIFF_KNS[0]:g} in "
        f"{int((abs(softer) <= STIFF_TOLERANCE).sum())}; closer to it at the stiffer kn in "
        f"{int((stiffest > softer).sum())}. The joints' compliance lowers the capacity, the more so the "
        "thinner the ring, and the static answer climbs toward the rigid one as kn grows.",
        "",
        *markdown_table(
            ["case", "kn (N/mm3)", "static", "rigid", "static / rigid - 1", "static hinges", "rigid hinges"],
            stiff_rows,
        ),
        "",
        "**The paper's arch at its own stiffness**: joints of 0.25 and 5.2 N/mm3 (the two voussoir sets) "
        "carry less than rigid blocks; the compliant arch deforms before its hinges form.",
        "",
        *markdown_table(
            ["load", "kn (N/mm3)", "first loss", "collapse", "unit", "hinges", "kind", "rigid", "static / rigid - 1"],
            paper_rows,
        ),
        "",
        "The DEM's load path against this one: reports/loads/engines (`scripts/loads_engines.py`).",
        "",
    ]
    return "\n".join(lines)


def backfill_markdown(filled: pd.DataFrame) -> str:
    """The backfill section: a quarter-span point load's capacity under fills of growing depth."""
    rows = [
        [f"{r.fill_depth_mm:g}", f"{r.fill_lateral_coefficient:g}", f"{r.kn_N_per_mm3:g}", f"{r.static_capacity:.4g}",
         r.static_hinges, f"{r.rigid_capacity:.4g}", r.rigid_hinges, f"{r.static_over_rigid:+.1%}"]
        for r in filled.itertuples()
    ]  # fmt: skip
    stiff = filled[filled["kn_N_per_mm3"] == STIFF_KNS[-1]]
    within = int((stiff["static_over_rigid"].abs() <= STIFF_TOLERANCE).sum())
    lines = [
        "## Backfill",
        "",
        "The paper's arch under a level fill (density 2 g/cm3) of growing depth over the crown's extrados, "
        "its weight on each voussoir's extrados and, with K 0.3, its lateral pressure (docs/loads.md, "
        '"Backfill"); a point load at the quarter span. The fill\'s weight pre-compresses the ring and '
        f"its capacity grows several times; stiff joints within {STIFF_TOLERANCE:.0%} of rigid blocks in "
        f"{within} of {len(stiff)}.",
        "",
        *markdown_table(
            [
                "fill (mm)",
                "K",
                "kn (N/mm3)",
                "static (N)",
                "static hinges",
                "rigid (N)",
                "rigid hinges",
                "static / rigid - 1",
            ],
            rows,
        ),  # fmt: skip
        "",
    ]
    return "\n".join(lines)
