"""Calibrate the joint stiffness kn to a measured collapse displacement du.

du grows with kn (stiffer joints, larger du), so a bracket [kn_min, kn_max] whose ends straddle the
target holds the answer; Brent's method (scipy's brentq) on du(log kn) narrows it in a few runs,
stopping at the first run within the tolerance. Each run is a campaign run folder, so a repeated
calibration reuses them.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.atomic import write_text_atomically
from yadearch.case.bounds import MAX_TARGET_DU_MM
from yadearch.case.config import ArchCase
from yadearch.errors import YadearchError
from yadearch.results.rundir import is_complete
from yadearch.studies.campaigns.executors import Pool
from yadearch.studies.campaigns.grid import round_sig, run_tag
from yadearch.studies.campaigns.runner import run_campaign


@dataclass
class Evaluation:
    """One run of the calibration: kn, the du it gave, its hinges, its wall time, reused or not."""

    kn_N_per_mm3: float
    du_mm: float
    hinges: str = ""
    hinge_labels: dict[str, int | None] = field(default_factory=dict)
    wall_s: float = 0.0
    cached: bool = False


Evaluator = Callable[[list[float]], list[Evaluation]]


@dataclass
class Calibration:
    """The outcome: the kn found, the du it reaches, and every run it took."""

    target_du_mm: float
    tolerance_mm: float
    kn_range_N_per_mm3: tuple[float, float]
    converged: bool
    kn_N_per_mm3: float
    du_mm: float
    hinges: str
    hinge_labels: dict[str, int | None]
    runs: int
    new_runs: int
    history: list[Evaluation]
    case: str = ""  # the case calibrated, by name
    engine: str = ""  # the engine whose du was matched

    def to_json(self) -> dict[str, Any]:
        return asdict(self)

    def write(self, path: Path) -> None:
        path.parent.mkdir(parents=True, exist_ok=True)
        write_text_atomically(path, json.dumps(self.to_json(), indent=2) + "\n")


def calibrate(
    evaluate: Evaluator,
    target_du_mm: float,
    tolerance_mm: float = 0.5,
    kn_min: float = 0.1,
    kn_max: float = 100.0,
    max_runs: int = 12,
    log: Callable[[str], None] = lambda line: None,
) -> Calibration:
    """The kn in [kn_min, kn_max] whose du is within `tolerance_mm` of `target_du_mm`.

    Evaluates both bracket ends first (together, so they can run in parallel) and raises
    YadearchError if the target lies outside the du they span. `converged` is False if `max_runs`
    runs end the search, or the bracket shrinks around a jump in du."""
    if not (math.isfinite(target_du_mm) and 0 < target_du_mm <= MAX_TARGET_DU_MM):
        raise YadearchError(f"target du must be in (0, {MAX_TARGET_DU_MM:g}] mm, got {target_du_mm}")
    if not (math.isfinite(kn_min) and math.isfinite(kn_max) and 0 < kn_min < kn_max):
        raise YadearchError(f"need 0 < kn-min < kn-max (finite), got {kn_min} and {kn_max}")
    if not (math.isfinite(tolerance_mm) and tolerance_mm > 0):
        raise YadearchError(f"tolerance must be a finite number > 0 mm, got {tolerance_mm}")
    history: list[Evaluation] = []

    def run(kns: list[float]) -> list[Evaluation]:
        log(f"running kn = {', '.join(f'{kn:.6g}' for kn in kns)} N/mm3")
        found = evaluate(kns)
        for e in found:
            history.append(e)
            log(
                f"run {len(history)}: kn = {e.kn_N_per_mm3:.6g} N/mm3 -> du = {e.du_mm:.2f} mm "
                f"(target {target_du_mm:g} +- {tolerance_mm:g}), hinges {e.hinges or '-'}, "
                f"{e.wall_s:.0f} s{' (reused)' if e.cached else ''}"
            )
        return found

    def within(e: Evaluation) -> bool:
        return abs(e.du_mm - target_du_mm) <= tolerance_mm

    low, high = run([kn_min, kn_max])
    if not (within(low) or within(high)) and (low.du_mm - target_du_mm) * (high.du_mm - target_du_mm) > 0:
        raise YadearchError(
            f"target du {target_du_mm:g} mm is outside what kn in [{kn_min:g}, {kn_max:g}] N/mm3 "
            f"reaches (du {low.du_mm:.2f} to {high.du_mm:.2f} mm); widen --kn-min/--kn-max"
        )
    if within(low) or within(high):
        converged = True
    else:
        converged = _brent(run, within, target_du_mm, low, high, max_runs - len(history))
    best = min(history, key=lambda e: abs(e.du_mm - target_du_mm))
    return Calibration(
        target_du_mm,
        tolerance_mm,
        (kn_min, kn_max),
        converged,
        best.kn_N_per_mm3,
        best.du_mm,
        best.hinges,
        best.hinge_labels,
        len(history),
        sum(1 for e in history if not e.cached),
        history,
    )


class _Converged(Exception):
    """Raised inside brentq's objective to stop as soon as du is within the tolerance."""


def _brent(
    run: Callable[[list[float]], list[Evaluation]],
    within: Callable[[Evaluation], bool],
    target: float,
    low: Evaluation,
    high: Evaluation,
    budget: int,
) -> bool:
    """Brent's method on g(log kn) = du - target inside [low, high] (both already run); True once a
    run lands within the tolerance, False if the budget runs out or the bracket shrinks to nothing
    (du jumps there). kn is rounded to 6 significant figures, which names the run folders."""
    known = {math.log(e.kn_N_per_mm3): e for e in (low, high)}

    def g(x: float) -> float:
        if x not in known:
            evaluation = run([round_sig(math.exp(x), 6)])[0]
            if within(evaluation):
                raise _Converged
            known[x] = evaluation
        return known[x].du_mm - target

    from scipy.optimize import brentq  # here, not at import: scipy.optimize costs a run ~50 ms

    try:
        brentq(
            g,
            math.log(low.kn_N_per_mm3),
            math.log(high.kn_N_per_mm3),
            xtol=1e-5,
            maxiter=max(budget, 1),
            full_output=True,
            disp=False,
        )
    except _Converged:
        return True
    return False


def function_evaluator(du_of_kn: Callable[[float], float]) -> Evaluator:
    """An evaluator from a plain function du(kn) (a stand-in model for tests and experiments)."""
    return lambda kns: [Evaluation(kn, float(du_of_kn(kn))) for kn in kns]


def campaign_evaluator(base: ArchCase, runs_dir: Path, pool: Pool, timeout_s: float | None = None) -> Evaluator:
    """An evaluator that runs `base` at each kn as a campaign in `runs_dir` (finished runs reused);
    a failed run or one without collapse ends the calibration with its reason."""
    rows: list[dict[str, Any]] = []

    def evaluate(kns: list[float]) -> list[Evaluation]:
        rows.extend({"kn_N_per_mm3": kn} for kn in kns if {"kn_N_per_mm3": kn} not in rows)
        cached = {kn: is_complete(runs_dir / run_tag({"kn_N_per_mm3": kn})) for kn in kns}
        table = run_campaign(base, rows, runs_dir, pool, timeout_s=timeout_s, progress=False)
        found = []
        for kn in kns:
            row = table[table["kn_N_per_mm3"] == kn].iloc[0]
            if row["status"] != "done" or not row["collapsed"]:
                raise YadearchError(f"calibration run kn = {kn:g} N/mm3: {row['status']}, {row['reason']}")
            found.append(
                Evaluation(
                    kn,
                    float(row["du_mm"]),
                    row["hinges"],
                    {k: _int_or_none(row[k]) for k in ("hinge_A", "hinge_B", "hinge_C", "hinge_D")},
                    float(row["wall_s"]),
                    cached[kn],
                )
            )
        return found

    return evaluate


def _int_or_none(value: Any) -> int | None:
    return None if pd.isna(value) else int(value)
