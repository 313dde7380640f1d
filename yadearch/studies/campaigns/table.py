"""A campaign's runs and its tidy results table: one row per run, read from the run folders (the
folders stay the truth; the table is rewritten from them)."""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.case.config import ArchCase
from yadearch.errors import CANNOT_STAND, UNRESOLVED
from yadearch.model.hinges import PAPER_LABELS
from yadearch.results.check_text import mode_kept
from yadearch.results.reuse import current_summary, outdated
from yadearch.results.rundir import CAMPAIGN_TABLE
from yadearch.results.summary import RunSummary
from yadearch.solve.stages import Outcome
from yadearch.studies.campaigns.failures import FAILED_FILE
from yadearch.studies.campaigns.grid import RUN_COLUMN

RESULTS_FILE = CAMPAIGN_TABLE
RESULTS_EVERY_S = 5.0  # results.csv is rewritten at most this often while runs finish (and at the end)
RESULTS_COST_SHARE = 0.05  # ... and no more often than keeps its rewriting to this share of the parent's time


@dataclass
class RunSpec:
    """One run of a campaign: its name, overrides, folder and case."""

    name: str
    overrides: dict[str, Any]
    folder: Path
    case: ArchCase


def override_columns(overrides: dict[str, Any]) -> dict[str, Any]:
    """The overrides as table columns, named by their last part (`interface.kn_N_per_mm3` -> `kn_N_per_mm3`)."""
    return {k.split(".")[-1]: v for k, v in overrides.items()}


def label_hinges(summary: RunSummary, n_voussoirs: int) -> dict[str, int | None]:
    """The interface of each of the paper's hinges A-D in a run's collapse mechanism (None where
    the mechanism has no such hinge)."""
    by_label = {label: h.interface for h, label in summary.paper_labels(n_voussoirs + 1).items() if label}
    return {f"hinge_{label}": by_label.get(label) for label in PAPER_LABELS}


EMPTY_RESULT = {
    "du_mm": math.nan,
    "du_first_mm": math.nan,
    "collapsed": None,
    "outcome": "",
    "collapse_kind": "",
    "hinges": "",
    "mechanism": "",
    "hinge_A": None,
    "hinge_B": None,
    "hinge_C": None,
    "hinge_D": None,
    "steps": None,
    "wall_s": math.nan,
    "max_slip_mm": math.nan,
    "max_friction_use": math.nan,
    "friction_interface": None,
}  # the result columns of a run without a result (failed, pending)


def run_row(spec: RunSpec, out: Path) -> dict[str, Any]:
    """One results row: the run's parameters and what its folder says (done, failed or pending)."""
    summary = current_summary(spec.folder)  # an outdated run's du is no result (its remake may have failed)
    if summary is not None:
        row = done_row(spec, summary)
    elif (spec.folder / FAILED_FILE).is_file():
        failed = json.loads((spec.folder / FAILED_FILE).read_text())
        row = failed_row(spec, failed.get("reason", ""), failed.get("wall_s", math.nan))
    elif outdated(spec.folder):
        row = pending_row(spec, "made by another revision of the static engine: to be run again")
    else:
        row = pending_row(spec, "not run yet (interrupted?)")
    row["folder"] = str(spec.folder.relative_to(out)) if spec.folder.is_relative_to(out) else str(spec.folder)
    return row


def _parameters(spec: RunSpec) -> dict[str, Any]:
    """A row's first columns: the run's name and overrides, kn and the voussoir count."""
    row: dict[str, Any] = {RUN_COLUMN: spec.name, **override_columns(spec.overrides)}
    row.setdefault("kn_N_per_mm3", spec.case.interface.kn_N_per_mm3)
    row.setdefault("n_voussoirs", spec.case.geometry.n_voussoirs)
    return row


def done_row(spec: RunSpec, summary: RunSummary) -> dict[str, Any]:
    """The row of a finished run, from its summary."""
    case = spec.case
    du, friction = summary.du_mm, summary.friction
    return {
        **_parameters(spec),
        **EMPTY_RESULT,
        "du_mm": math.nan if du is None else du,
        "du_first_mm": math.nan if summary.du_first_mm is None else summary.du_first_mm,
        "collapsed": summary.collapsed,
        "outcome": summary.path_outcome,
        "collapse_kind": summary.collapse_kind or "",
        "hinges": summary.hinge_labels,
        "mechanism": "-".join(h.side for h in summary.hinges_at_collapse),
        **label_hinges(summary, case.geometry.n_voussoirs),
        "steps": summary.steps,
        "wall_s": summary.wall_s,
        "max_slip_mm": friction.get("max_slip_mm", math.nan),
        "max_friction_use": friction.get("max_friction_use", math.nan),
        "friction_interface": friction.get("friction_interface"),
        **_check_columns(summary),
        "engine": summary.engine,
        "status": "done",
        "reason": _reason(summary, case),
    }


def _check_columns(summary: RunSummary) -> dict[str, Any]:
    """A static run's increments check (numerics.increments_check) as columns: du and du_first with the
    increments halved, whether both stayed within 1 % and whether the collapse mode kept its mechanism
    (`results.check_text.mode_kept`; none without a check)."""
    check = summary.increments_check
    if not check or "resolved" not in check:
        return {}
    return {
        "du_halved_increments_mm": math.nan if check["du_mm"] is None else check["du_mm"],
        "du_first_halved_increments_mm": math.nan if check["du_first_mm"] is None else check["du_first_mm"],
        "increments_resolved": check["resolved"],
        "increments_mode_resolved": mode_kept(check),
    }


def failed_row(spec: RunSpec, reason: str, wall_s: float) -> dict[str, Any]:
    """The row of a failed run, with its reason: an arch that cannot stand has that outcome, a run whose
    self-weight the solver left unresolved is `unresolved` (never counted as an arch that falls)."""
    outcome = Outcome.CANNOT_STAND if CANNOT_STAND in reason else ""
    if f"{UNRESOLVED}:" in reason:
        outcome = Outcome.UNRESOLVED
    return {
        **_parameters(spec),
        **EMPTY_RESULT,
        "wall_s": wall_s,
        "outcome": outcome,
        "engine": spec.case.numerics.engine,
        "status": "failed",
        "reason": reason,
    }


def pending_row(spec: RunSpec, reason: str) -> dict[str, Any]:
    """The row of a run still to do, with why."""
    return {
        **_parameters(spec),
        **EMPTY_RESULT,
        "engine": spec.case.numerics.engine,
        "status": "pending",
        "reason": reason,
    }


def _reason(summary: RunSummary, case: ArchCase) -> str:
    """Why a finished run has no du ("" when it collapsed)."""
    if summary.path_outcome == Outcome.UNRESOLVED:
        return (
            f"unresolved: the solver found neither equilibrium nor collapse past {summary.last_equilibrium_mm:g} mm "
            "(the last stable state)"
        )
    return "" if summary.collapsed else f"no collapse up to {_path_end_mm(summary, case):g} mm"


def _path_end_mm(summary: RunSummary, case: ArchCase) -> float:
    """Where a run that did not collapse stopped: its path's end, or the case's largest displacement."""
    return summary.loading.max_displacement_mm if summary.loading else case.loading.max_support_displacement_mm


def results_table(specs: list[RunSpec], out: Path) -> pd.DataFrame:
    """The tidy results table of a campaign (one row per run), read from its run folders."""
    return tidy(pd.DataFrame([run_row(s, out) for s in specs]))


def tidy(table: pd.DataFrame) -> pd.DataFrame:
    """The results table with its integer columns as integers where a run has none (pending, failed)."""
    for column in ("n_voussoirs", "hinge_A", "hinge_B", "hinge_C", "hinge_D", "steps", "friction_interface"):
        table[column] = table[column].astype("Int64")
    return table


def results_interval(write_s: float) -> float:
    """Seconds until results.csv is rewritten while runs finish, after a rewrite that took `write_s`:
    RESULTS_EVERY_S, or longer for a table so large that its rewriting would take more than
    RESULTS_COST_SHARE of the parent's time (57 000 runs take 1.7 s: every 5 s was a third of a core)."""
    return max(RESULTS_EVERY_S, write_s / RESULTS_COST_SHARE)
