"""Is a rigid-block analysis's state a DEM equilibrium, and how far does the DEM carry the support
from it? The arch loaded by its self-weight, its voussoirs and supports put where the limit analysis
(or a given three-hinge linkage) has them at a support displacement, released from rest; optionally
loaded on by the run's increments to collapse, into a run folder (docs/validation.md,
`scripts/rigid_state_check.py`)."""

from __future__ import annotations

import json
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from yadearch.atomic import write_text_atomically
from yadearch.case.config import ArchCase
from yadearch.dem.loading import EquilibriumPath
from yadearch.dem.runner import Runner
from yadearch.dem.scene_state import place_voussoirs
from yadearch.errors import YadearchError
from yadearch.model import units
from yadearch.results.rundir import hinge_list, write_run
from yadearch.results.summary import HingeRef, RunSummary, collapse_fields
from yadearch.solve.pose import linkage_pose, rigid_pose
from yadearch.solve.stages import Stage, Verdict

COMMAND_FILE = "command.json"  # beside the run folder's files: how the state was placed
PLACEMENT_TOLERANCE_MM = 1e-6  # the placed support must read the displacement asked for


def hinge_text(runner: Runner) -> str:
    """The hinges of the scene now, with their rotations."""
    _, hinges = runner.recorder.joint_snapshot()
    return " ".join(f"{h.interface}{h.side} ({abs(h.rotation) * 1e3:.1f} mrad)" for h in hinges)


def check_rigid_state(
    case: ArchCase,
    at_mm: float,
    *,
    mirrored: bool = False,
    compliant: bool = False,
    hinges: tuple[str, ...] | None = None,
    load_on: bool = False,
    out: Path | None = None,
    command: dict[str, Any] | None = None,
    log: Callable[[str], None] = print,
) -> Verdict:
    """Place the arch at `at_mm` on the rigid march's state (its mirrored branch, the compliant march,
    or the linkage of `hinges` such as ("8I", "28E", "46I")), release it and say how it ends; with
    `load_on`, follow the path from there to collapse and write it to `out` with `command` (how the
    state was placed) in command.json. The hold's verdict at the placed state."""
    if hinges:
        centroids, turns = linkage_pose(case, at_mm, hinges)
    else:
        centroids, turns = rigid_pose(case, at_mm, mirrored, compliant)
    runner = Runner(case, log=log if load_on else (lambda _: None))
    try:
        runner.selfweight()
        place_voussoirs(runner.scene, centroids, turns, with_supports=True)
        placed_mm = units.to_mm(runner.delta())
        if abs(placed_mm - at_mm) > PLACEMENT_TOLERANCE_MM:
            raise YadearchError(f"the placed support reads {placed_mm:.6f} mm, not {at_mm:g}")
        where = (
            f"linkage {','.join(hinges)}"
            if hinges
            else f"{'mirrored' if mirrored else 'direct'} branch{', compliant hinges' if compliant else ''}"
        )
        log(f"placed at {at_mm:g} mm ({where}): {hinge_text(runner)}")
        runner.stage = Stage.RELAX
        verdict = runner.hold(max_s=case.numerics.hold_max_s)
        log(
            f"released: {verdict}, largest block motion {units.to_mm(runner.hold_move):.3f} mm; "
            f"now on {hinge_text(runner)}"
        )
        if load_on and verdict == Verdict.STABLE:
            _load_on(runner, at_mm, out, command or {}, log)
    finally:
        runner.close()
    return verdict


def _load_on(runner: Runner, start_mm: float, out: Path | None, command: dict, log: Callable[[str], None]) -> None:
    """Follow the equilibrium path from the placed state at `start_mm` to collapse and report it."""
    loading = EquilibriumPath(runner)
    path = loading.follow(start=units.mm(start_mm))
    hinges = loading.collapse_state(path.upper) if path.collapsed else []
    summary = RunSummary(
        name=runner.case.name,
        kn_N_per_mm3=runner.case.interface.kn_N_per_mm3,
        **collapse_fields(path, runner.movement),
        hinges_last_equilibrium=loading.last_equilibrium_hinges,
        relaxations=loading.relaxations,
        hinges_at_collapse=tuple(HingeRef.of(h) for h in hinges),
        hinges_detail=[h.to_json() for h in hinges],
        steps=runner.total_steps,
        wall_s=time.time() - runner.wall0,
    )
    if path.collapsed:
        log(
            f"du = {summary.du_mm:.2f} mm ({path.upper_verdict} at {units.to_mm(path.upper):.3f}); "
            f"last equilibrium on {hinge_list(loading.last_equilibrium_hinges)}"
        )
    if out is not None:  # a run folder from the placed state on, with the command that placed it
        records = runner.records
        write_run(
            out,
            runner.case.to_toml(),
            records.series,
            records.joints,
            records.snapshots,
            summary,
            tables=runner.case.numerics.keeps_tables,
        )
        write_text_atomically(out / COMMAND_FILE, json.dumps({**command, "start_mm": start_mm}, indent=1) + "\n")
