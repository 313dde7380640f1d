"""Whether the snaps that move du_first with the snap floor are snaps (pure, the static engine): each atlas
arch whose du_first the floor halved or doubled moved (`invariance.csv`) solved again with that floor and
the default one, its bracket refined 4 and 16 times. A jump whose landing stays as the bracket shrinks is a
discontinuity of the path, a snap whatever the floor; one that vanishes was the coarse bracket's
prediction error (docs/atlas.md, "What the snap floor moves")."""

from __future__ import annotations

import math
from typing import Any

import pandas as pd

from yadearch.case.config import ArchCase
from yadearch.model import units
from yadearch.results.summary import collapse_fields
from yadearch.solve.static_path import StaticLoading
from yadearch.studies.atlas.grid import geometries

SNAP_FLOOR = "snap_floor"  # the invariance table's name of the floor's variants
BRACKET_REFINEMENTS = (1.0, 0.25, 0.0625)  # du_tolerance_mm x these
SAME_FOLD = 0.01  # du_first within 1 % at the finest bracket (or inside the default one): the same first loss
CONFIRMED, VANISHED, MOVED = "confirmed", "vanished", "moved"
FIRST_BRACKET = ("du_first_low_mm", "du_first_high_mm")  # the bracket du_first is the middle of


def snap_cases(invariance: pd.DataFrame) -> list[tuple[str, float, float]]:
    """(arch name, kn, floor factor) of every arch whose du_first the floor moved most, with the factor
    that moved it and the default (1)."""
    moved = invariance[invariance["du_first_mm_by"].astype(str).str.startswith(SNAP_FLOOR)]
    cases = []
    for row in moved.itertuples():
        name = str(row.case).rsplit("-kn", 1)[0]
        factor = float(str(row.du_first_mm_by).rsplit("_x", 1)[1])
        cases += [(name, float(row.kn_N_per_mm3), 1.0), (name, float(row.kn_N_per_mm3), factor)]
    return cases


def refinement_rows(base: ArchCase, name: str, kn: float, floor_factor: float) -> list[dict[str, Any]]:
    """One arch at one floor, solved at each bracket of BRACKET_REFINEMENTS: du, du_first and the first
    snap (where, how far its landing is from the prediction)."""
    (geometry,) = [g for g in geometries() if g.name == name]
    numerics = base.numerics
    rows = []
    for refinement in BRACKET_REFINEMENTS:
        case = base.with_overrides(
            {
                **geometry.overrides(),
                "kn_N_per_mm3": kn,
                "du_tolerance_mm": numerics.du_tolerance_mm * refinement,
                "snap_thickness_ratio": numerics.snap_thickness_ratio * floor_factor,
            }
        )
        loading = StaticLoading.of(case)
        loading.selfweight()
        path = loading.follow()
        first = loading.snaps[0] if loading.snaps else None
        answer = collapse_fields(path, loading.arch.movement, loading.first_loss)  # as the summaries give them
        rows.append(
            {
                "case": f"{name}-kn{kn:g}",
                "floor_x": floor_factor,
                "floor_mm": units.to_mm(loading.snap_floor),
                "bracket_x": refinement,
                "du_mm": answer["du_mm"] if answer["du_mm"] is not None else math.nan,
                "du_first_mm": answer.get("du_first_mm", math.nan),
                **dict(zip(FIRST_BRACKET, answer.get("du_first_bracket_mm", (math.nan, math.nan)))),
                "first_snap_mm": first["fold_mm"][0] if first else math.nan,
                "landing_mm": first["move_mm"] if first else math.nan,
            }
        )
    return rows


def verdicts(rows: pd.DataFrame) -> pd.DataFrame:
    """Per arch and floor: the first snap at the default bracket and at the finest, and whether it is
    `confirmed` (a snap there, du_first within SAME_FOLD or inside the default bracket), `vanished` (no
    snap there any more: du_first moves later) or `moved`."""
    out = []
    for (case, floor_x), group in rows.groupby(["case", "floor_x"], sort=False):
        coarse, fine = group.iloc[0], group.iloc[-1]
        if math.isnan(coarse["first_snap_mm"]):
            continue
        low, high = coarse[list(FIRST_BRACKET)]
        same = not math.isnan(fine["first_snap_mm"]) and (
            math.isclose(fine["du_first_mm"], coarse["du_first_mm"], rel_tol=SAME_FOLD)
            or low <= fine["du_first_mm"] <= high
        )
        verdict = CONFIRMED if same else (VANISHED if fine["du_first_mm"] > coarse["du_first_mm"] else MOVED)
        out.append(
            {
                "case": case,
                "floor_x": floor_x,
                "floor_mm": coarse["floor_mm"],
                "snap_at_mm": coarse["first_snap_mm"],
                "landings_mm": " / ".join(f"{v:.3f}" for v in group["landing_mm"]),
                "du_first_finest_mm": fine["du_first_mm"],
                "verdict": verdict,
            }
        )
    return pd.DataFrame(out)


def refinement_markdown(table: pd.DataFrame) -> str:
    """The verdicts as the report's page: counts by floor, then the table."""
    lines = [
        "# What the snap floor moves: snaps against a refined bracket (static engine)",
        "",
        "Regenerate with `.venv/bin/python scripts/atlas.py --snap-refinement` (after `--invariance`; "
        "docs/atlas.md). Each atlas arch whose du_first the snap floor halved or doubled moved, at the "
        "default floor and at the one that moved it, its bracket (`du_tolerance_mm`) x "
        + ", ".join(f"{r:g}" for r in BRACKET_REFINEMENTS)
        + ": a first snap whose landing stays as the bracket shrinks is a jump of the path (confirmed); "
        "one that is gone at the finest bracket was the coarse bracket's prediction error (vanished).",
        "",
    ]
    for floor_x, group in table.groupby("floor_x"):
        counts = group["verdict"].value_counts()
        said = ", ".join(f"{counts.get(v, 0)} {v}" for v in (CONFIRMED, VANISHED, MOVED))
        lines.append(f"- floor x{floor_x:g}: {len(group)} first snaps, {said}.")
    lines += ["", "| case | floor x | floor (mm) | snap at (mm) | landings (mm) | du_first, finest (mm) | verdict |"]
    lines.append("|---|---|---|---|---|---|---|")
    for row in table.itertuples():
        lines.append(
            f"| {row.case} | {row.floor_x:g} | {row.floor_mm:.3f} | {row.snap_at_mm:.2f} | {row.landings_mm} | "
            f"{row.du_first_finest_mm:.2f} | {row.verdict} |"
        )
    return "\n".join(lines) + "\n"
