"""Finished runs against the rigid-block limit analysis of the same case (`scripts/limit_check.py`):
du and the hinges of each run beside du_rigid and the rigid mechanism, the limit that counts what the
run counts as collapse and the compliant-hinge limit at the run's kn, as a Markdown table
(docs/validation.md)."""

from __future__ import annotations

import tomllib
from pathlib import Path

from yadearch.case.config import TEXT_ENCODING, ArchCase, load_case
from yadearch.case.mechanics import runaway_length
from yadearch.model import units
from yadearch.model.hinges import mirror_hinge_labels
from yadearch.results.rundir import CASE_FILE, hinge_list, read_summary
from yadearch.results.summary import RunSummary
from yadearch.solve.limit import limit_analysis
from yadearch.solve.limit_result import LimitResult
from yadearch.solve.mirror import has_other_branch, mirror_image
from yadearch.studies.robustness import same_hinge_set

HINGE_SHIFT = 1  # interfaces a DEM hinge may sit from the rigid one
TABLE_HEADER = (
    "| run | direction (deg) or motion | kn (N/mm3) | rigid branch | du (mm) "
    "| du_rigid, every snap survived (mm) "
    "| du_rigid, a snap beyond the run's runaway distance collapses (mm) | du / du_rigid - 1 "
    "| DEM mechanism at the last equilibrium | rigid mechanism at its limit | DEM hinges at collapse "
    "| rigid collapse chain | du_compliant at the run's kn (mm) | du / du_compliant - 1 "
    "| within tolerance |"
)


def check(folder: Path, tolerance: float) -> tuple[str, bool]:
    """One table row for the run in `folder` and whether it passes: du against the rigid limit that
    counts what the run counts as collapse (a snap moving a block further than the run's runaway
    distance), beside the rigid limit that survives every snap. Where the keystone's tie gives the
    rigid arch two branches, the run is compared with the branch whose mechanism it follows."""
    case = load_case(folder / CASE_FILE)
    summary = read_summary(folder)
    runaway_mm = _run_runaway_mm(case, summary, tomllib.loads((folder / CASE_FILE).read_text(encoding=TEXT_ENCODING)))
    mechanism = hinge_list(summary.hinges_last_equilibrium)
    names = ("direct", "mirrored") if has_other_branch(case) else ("-",)
    branches = [_branch(case, name, runaway_mm) for name in names]
    survived, limit, rigid, chain, name = min(branches, key=lambda b: _distance(mechanism, b[2]))
    compliant = limit_analysis(
        mirror_image(case) if name == "mirrored" else case,
        max_snap_mm=runaway_mm,
        mirror=False,
        compliant=True,
    )
    du, du_rigid = summary.du_mm, limit.du_rigid_mm
    loading = case.loading
    movement = (
        f"{loading.support_direction_deg:g}" if loading.support_motion == "translation" else loading.support_motion
    )
    head = (
        f"| {folder.name} | {movement} | {case.interface.kn_N_per_mm3:g} | {name} "
        f"| {_mm(du)} | {_mm(survived.du_rigid_mm)} | {_mm(du_rigid)}"
    )
    hinges = f"{mechanism} | {rigid} | {summary.hinge_labels} | {chain}"
    if du is None or du_rigid is None:
        return f"{head} | - | {hinges} | {_mm(compliant.du_rigid_mm)} | - | no |", False
    gap = (du - du_rigid) / du_rigid
    ok = abs(gap) <= tolerance and same_hinge_set(mechanism, rigid, HINGE_SHIFT)
    predicted = compliant.du_rigid_mm
    against = "-" if predicted is None else f"{(du - predicted) / predicted:+.1%}"
    return (f"{head} | {gap:+.1%} | {hinges} | {_mm(predicted)} | {against} | {'yes' if ok else 'no'} |"), ok


def _run_runaway_mm(case: ArchCase, summary: RunSummary, stored: dict) -> float:
    """The runaway distance the run counted (mm): its summary's, or for a run made before the bound was
    a share of the ring's thickness its case file's `numerics.runaway_mm` (`stored`: the file as read;
    1 mm), else the case's."""
    recorded = (summary.relaxations or {}).get("runaway_mm", stored.get("numerics", {}).get("runaway_mm"))
    return float(recorded) if recorded is not None else units.to_mm(runaway_length(case))


def _branch(case: ArchCase, name: str, runaway_mm: float) -> tuple[LimitResult, LimitResult, str, str, str]:
    """One branch of the rigid arch: its limit surviving every snap, its limit counting a snap beyond
    the run's runaway distance, the mechanism followed to that limit and its collapse chain (hinges
    in the case's own numbering) and the branch's `name`. The mirrored branch is the mirror image's
    direct one (the keystone's tie broken toward its other joint)."""
    mirrored = name == "mirrored"
    solved = mirror_image(case) if mirrored else case
    survived = limit_analysis(solved, mirror=False)
    limit = limit_analysis(solved, max_snap_mm=runaway_mm, mirror=False)
    followed = [f"{h.interface}{h.side}" for h in limit.hinge_history if h.to_mm is None]
    chain = list(limit.collapse_hinges)
    if mirrored:
        last_interface = case.geometry.n_voussoirs + 1
        followed, chain = (mirror_hinge_labels(labels, last_interface) for labels in (followed, chain))
    return survived, limit, _sorted(followed), _sorted(chain), name


def _sorted(labels: list[str]) -> str:
    return " ".join(sorted(labels, key=lambda h: int(h[:-1])))


def _distance(a: str, b: str) -> float:
    """How far apart two hinge lists are (interfaces, summed; other counts or sides: infinitely)."""
    ha, hb = a.split(), b.split()
    if len(ha) != len(hb) or any(x[-1] != y[-1] for x, y in zip(ha, hb)):
        return float("inf")
    return float(sum(abs(int(x[:-1]) - int(y[:-1])) for x, y in zip(ha, hb)))


def _mm(value: float | None) -> str:
    return "-" if value is None else f"{value:.2f}"


def limit_check_table(runs: list[Path], tolerance: float) -> tuple[str, bool]:
    """The Markdown table of every run folder in `runs` (folders without a case.toml skipped), and
    whether every run is within `tolerance` of its limit with its hinges within HINGE_SHIFT."""
    lines = [TABLE_HEADER, "|" + "---|" * TABLE_HEADER.count(" |")]
    passed = True
    for folder in runs:
        if not (folder / CASE_FILE).is_file():
            continue
        row, ok = check(folder, tolerance)
        lines.append(row)
        passed &= ok
    return "\n".join(lines) + "\n", passed
