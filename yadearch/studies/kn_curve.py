"""The whole du(kn) curve on the static engine: a log grid of kn, every jump of du located by
bisection in kn and tied to the hinge that moves there (docs/validation-stiff.md, "The whole kn curve").

A jump is a change of du by more than JUMP_FRACTION between neighbouring kn; each is bisected
(geometric midpoints, all jumps of a round as one campaign) until its bracket spans less than
BRACKET_RATIO in kn. The lowest kn at which the arch stands under its
own weight is bracketed the same way.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from yadearch.case.config import ArchCase
from yadearch.studies.campaigns.executors import Pool
from yadearch.studies.campaigns.grid import round_sig
from yadearch.studies.campaigns.runner import run_campaign

KN = "kn_N_per_mm3"
KN_RANGE = (0.05, 10000.0)  # N/mm^3
GRID_POINTS = 200
JUMP_FRACTION = 0.03  # du changing by more than this between neighbouring kn is a jump
BRACKET_RATIO = 1.01  # a jump is located once its bracket spans less than this ratio of kn
MAX_ROUNDS = 12  # bisection rounds at most (each halves every bracket's log-width)
STEEP = "a steep stretch, no hinge A or B moving"
DROP = "du drops, no hinge A or B moving (a snap counted as collapse?)"
KN_DIGITS = 6  # significant figures of a bisection's kn (the run folders' names)


@dataclass(frozen=True)
class Jump:
    """Two neighbouring runs between which du jumps (or the arch starts to stand): their rows."""

    below: pd.Series
    above: pd.Series

    @property
    def ratio(self) -> float:
        return float(self.above[KN] / self.below[KN])

    @property
    def midpoint(self) -> float:
        return round_sig(math.sqrt(float(self.below[KN] * self.above[KN])), KN_DIGITS)


def grid_values(extra: list[float] | None = None) -> list[float]:
    """GRID_POINTS log-spaced kn over KN_RANGE, and `extra` values (e.g. the DEM's sweep points)."""
    values = {round_sig(v) for v in np.geomspace(*KN_RANGE, GRID_POINTS)}
    return sorted(values | set(extra or []))


def _stands(row: pd.Series) -> bool:
    return row["status"] == "done" and bool(row["collapsed"])


def find_jumps(table: pd.DataFrame) -> list[Jump]:
    """The jumps between neighbouring kn of `table` (a campaign's results): du changing by more than
    JUMP_FRACTION, or the arch starting to stand."""
    runs = table.sort_values(KN).drop_duplicates(KN).reset_index(drop=True)
    jumps = []
    for k in range(len(runs) - 1):
        below, above = runs.iloc[k], runs.iloc[k + 1]
        if not _stands(above):
            continue
        if not _stands(below):
            if below["status"] == "failed":
                jumps.append(Jump(below, above))
            continue
        if abs(above["du_mm"] / below["du_mm"] - 1.0) > JUMP_FRACTION:
            jumps.append(Jump(below, above))
    return jumps


def hinge_moves(table: pd.DataFrame) -> pd.DataFrame:
    """Neighbouring kn between which hinge A or B moves without a jump of du (located to the spacing
    of `table`'s kn, not bisected)."""
    runs = table[table["status"] == "done"].sort_values(KN).drop_duplicates(KN).reset_index(drop=True)
    rows = []
    for k in range(len(runs) - 1):
        b, a = runs.iloc[k], runs.iloc[k + 1]
        moved = [f"{h[-1]} {_at(b[h])} -> {_at(a[h])}" for h in ("hinge_A", "hinge_B") if _differs(b[h], a[h])]
        if moved and abs(a["du_mm"] / b["du_mm"] - 1.0) <= JUMP_FRACTION:
            rows.append({"kn_below": b[KN], "kn_above": a[KN], "du_mm": a["du_mm"], "what": ", ".join(moved)})
    return pd.DataFrame(rows)


def bisect_jumps(base: ArchCase, table: pd.DataFrame, out: Path, pool: Pool, log=print) -> pd.DataFrame:
    """Bisect every jump of `table` until located to BRACKET_RATIO; returns `table` with every run
    added (one campaign a round, out/bisectN)."""
    for number in range(1, MAX_ROUNDS + 1):
        wide = [j for j in find_jumps(table) if j.ratio > BRACKET_RATIO]
        if not wide:
            break
        values = sorted({j.midpoint for j in wide} - set(table[KN]))
        if not values:
            break
        log(f"bisection round {number}: {len(wide)} jumps, {len(values)} runs")
        found = run_campaign(base, [{KN: v} for v in values], out / f"bisect{number}", pool)
        table = pd.concat([table, found], ignore_index=True)
    return table


def jumps_table(table: pd.DataFrame) -> pd.DataFrame:
    """One row a located jump: its kn bracket, du and hinges on both sides, the hinge that moved; a
    run of adjacent brackets whose du changes without any hinge A or B moving is one row, a steep
    stretch of the curve rather than a jump."""
    rows: list[dict] = []
    for jump in find_jumps(table):
        b, a = jump.below, jump.above
        standing = not _stands(b)
        moved = [f"{h[-1]} {_at(b[h])} -> {_at(a[h])}" for h in ("hinge_A", "hinge_B") if _differs(b[h], a[h])]
        what = (
            "the arch starts to stand under its own weight"
            if standing
            else ", ".join(moved) or (STEEP if a["du_mm"] > b["du_mm"] else DROP)
        )
        last = rows[-1] if rows else None
        if what == STEEP and last is not None and last["what"] == STEEP and last["kn_above"] == b[KN]:
            last.update(
                kn_above=a[KN], bracket_ratio=a[KN] / last["kn_below"], du_above_mm=a["du_mm"], hinges_above=a["hinges"]
            )
            continue
        rows.append(
            {
                "kn_below": b[KN],
                "kn_above": a[KN],
                "bracket_ratio": jump.ratio,
                "du_below_mm": math.nan if standing else b["du_mm"],
                "du_above_mm": a["du_mm"],
                "hinges_below": "" if standing else b["hinges"],
                "hinges_above": a["hinges"],
                "what": what,
            }
        )
    return pd.DataFrame(rows)


def _differs(x: object, y: object) -> bool:
    """Two hinge interfaces differ (a hinge present on one side only counts as a move)."""
    if pd.isna(x) or pd.isna(y):
        return not (pd.isna(x) and pd.isna(y))
    return bool(x != y)


def _at(interface: object) -> str:
    return "—" if interface is None or pd.isna(interface) else str(int(interface))  # type: ignore[call-overload]
