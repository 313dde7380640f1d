"""A DEM run's stages on a live scene (`dem.runner.Runner`): the self-weight, a live load the run holds
grown to its value (`dem.load_ramp`), then the support movement along the equilibrium path to collapse
(`dem.loading`), and what the run found and cost."""

from __future__ import annotations

import time

from yadearch.case.held import held_multiplier
from yadearch.dem.load_ramp import hold_the_live_load
from yadearch.dem.loading import EquilibriumPath
from yadearch.dem.runner import Runner
from yadearch.model import units
from yadearch.model.loads import UNITS
from yadearch.results.summary import HingeRef, RunSummary, collapse_fields
from yadearch.solve.collapse_mode import FoldMode, fold_mode
from yadearch.solve.mirror import mirror_hinges
from yadearch.solve.stages import Stage


def run_stages(runner: Runner) -> RunSummary:
    """Every stage of `runner`'s case; the summary of what it found (the case's own fields are the
    caller's to add)."""
    from yade import O

    name = runner.case.name
    selfweight = runner.selfweight()
    if held_multiplier(runner.case) > 0.0:
        held = hold_the_live_load(runner)
        runner.log(f"[{name}] the live load held at {held:g} {UNITS[runner.case.loads.live_load]}")
    loading = EquilibriumPath(runner)
    path = loading.follow()
    outcome = collapse_fields(path, runner.movement, loading.first_loss)
    mode = None
    if path.collapsed:
        hinges = loading.collapse_state(path.upper)
        mode = collapse_mode(runner, loading, path.lower)
        runner.log(
            f"[{name}] du = {outcome['du_mm']:.2f} mm (no equilibrium at "
            f"{units.to_mm(path.upper):.2f}, equilibrium at {units.to_mm(path.lower):.2f})"
        )
    elif path.unresolved:
        runner.log(
            f"[{name}] unresolved: neither equilibrium nor runaway at {units.to_mm(path.upper):.2f} mm "
            f"after the holds' retries (last stable state {units.to_mm(path.lower):.2f} mm); no du"
        )
        runner.stage = Stage.END
        hinges = runner.recorder.joints(Stage.END)
    else:
        runner.log(f"[{name}] no collapse up to {units.to_mm(loading.settings.max_displacement):g} mm")
        runner.stage = Stage.END
        hinges = runner.recorder.joints(Stage.END)
    refs = tuple(HingeRef.of(h) for h in hinges) if path.collapsed else ()
    mode_hinges = mode.labels if mode is not None else None
    wall = time.time() - runner.wall0
    runner.progress("done", force=True)
    return RunSummary(
        **outcome,
        selfweight=selfweight,
        increments=len(path.steps),
        equilibria=len(path.equilibria),
        hinges_last_equilibrium=loading.last_equilibrium_hinges,
        friction=dict(runner.recorder.friction),
        relaxations=loading.relaxations,
        snaps=loading.snaps,
        hinges_at_collapse=refs,
        hinges_detail=[h.to_json() for h in hinges],
        collapse_kind=mode.kind if mode is not None else None,
        collapse_mode_hinges=mode_hinges,
        mirror_hinges=mirror_hinges(runner.case, runner.movement, [h.label for h in refs]),
        mirror_mode_hinges=mirror_hinges(runner.case, runner.movement, mode_hinges),
        steps=runner.total_steps,
        steps_by_stage=dict(runner.steps_by_stage),
        dt_s=O.dt,
        wall_s=wall,
        steps_per_s=runner.total_steps / wall if wall > 0 else None,
        profile=runner.clock.profile(wall),
    )


def collapse_mode(runner: Runner, loading: EquilibriumPath, lower: float) -> FoldMode | None:
    """The collapse's mode as the static engine reads its own (`solve.collapse_mode.fold_mode`): the
    motion from the last equilibrium (the static model's, from the DEM's last accepted state at `lower`)
    toward the runaway the scene shows now (`EquilibriumPath.collapse_state`: at the default bound, as
    the static engine reads it); None where the static model is not the scene's (CGAL) or finds no
    stable equilibrium there. Leaves the scene at the last accepted state."""
    check = runner.static_check
    if check is None:
        return None
    failed = check.scene_u()
    loading.back_to_accepted()
    found = check.equilibrium(lower, runner.live_multiplier)
    if found is None:
        return None
    return fold_mode(check.loading.arch, found.u, found.stiffness, failed, found.springs)
