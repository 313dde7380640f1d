"""A live load's capacity by the static engine (pure numpy, no YADE): the self-weight, optionally a
support movement, then the live load's multiplier as the path's parameter, followed by the same
continuation, fold bracketing and descent as a support movement (`solve.static_path`): its first loss
of stability, the end of its path (collapse, unresolved, or none up to the largest load tried), the
mechanism from the fold's softest mode, and the load-displacement curve (docs/loads.md).

Load control up to the limit point; past it, the descending branch by arc length
(`solve.descending`), the curve's rows past the peak marked `descending`."""

from __future__ import annotations

import math
import time
from dataclasses import replace
from typing import TYPE_CHECKING, Any

import numpy as np

from yadearch.case.config import ArchCase
from yadearch.case.held import HELD_SETTINGS, held_multiplier
from yadearch.case.numerics_section import HALVED_INCREMENTS_CHECK
from yadearch.errors import CaseError, RunFailedError
from yadearch.model import units
from yadearch.model.loads import UNITS, VERTICAL, load_displacement
from yadearch.solve.collapse_mode import FoldMode
from yadearch.solve.descending import DESCEND_TO, descend
from yadearch.solve.load_lp import LoadCapacity, load_analysis, residual_capacity
from yadearch.solve.load_path_result import LoadPath
from yadearch.solve.path import PathResult, PathSettings, first_snap, follow_path, path_settings
from yadearch.solve.refined import SKIPPED, check_record, halved_loading, mode_record
from yadearch.solve.rigid import LimitError
from yadearch.solve.stages import Outcome
from yadearch.solve.static_path import StaticLoading
from yadearch.solve.static_state import PathParameter, StaticState
from yadearch.solve.statics import StaticArch

if TYPE_CHECKING:
    import pandas as pd

FIRST_FRACTION = 0.05  # the load's first increment: this x the load scale (the rigid capacity)
LARGEST_FRACTION = 0.1  # ... its largest increment
TOLERANCE_FRACTION = 1e-3  # ... the bracket that ends the search (0.1 % of the capacity)
REACH = 4.0  # ... and the path stops, the arch standing, at this many times the scale
BRANCH, ASCENDING, DESCENDING = "branch", "ascending", "descending"  # the curve's column of branches: up
# to the peak, past it


def load_settings(scale: float, growth: float) -> PathSettings:
    """The load path's increments for a capacity near `scale` (N or g)."""
    return PathSettings(
        first_increment=FIRST_FRACTION * scale,
        max_increment=LARGEST_FRACTION * scale,
        growth=growth,
        tolerance=TOLERANCE_FRACTION * scale,
        max_displacement=REACH * scale,
    )


def static_load_path(
    case: ArchCase, after_mm: float = 0.0, scale: float | None = None, descend_to: float | None = DESCEND_TO
) -> LoadPath:
    """The live load of `case` grown to collapse on the static engine's path, the self-weight held,
    after the case's support movement to `after_mm` (0: at rest); `scale` (N or g; default
    `load_scale`) sets the increments; past a collapse's limit point the descending branch until the
    multiplier falls to `descend_to` x the capacity (None: not traced). CaseError for an arch without a
    live load, or one that collapses or stops before `after_mm`; StaticEngineError for one that does
    not stand."""
    at_rest = load_analysis(case)  # refuses a case without a live load
    scale = load_scale(at_rest) if scale is None else scale
    if not (math.isfinite(scale) and scale > 0.0):
        raise ValueError(f"the load scale must be a positive number, got {scale}")
    num = case.numerics
    loading = StaticLoading.of(case)
    arch = loading.arch
    loading.selfweight()
    if after_mm > 0.0:
        _move_supports(loading, case, after_mm)
    load_the_live_load(loading, load_settings(scale, num.increment_growth))
    start = loading.accepted[0]
    path = follow_path(loading, loading.settings)
    mode = loading.fold_mode(path.upper) if path.collapsed else None
    collapse = [loading.collapse_state(path.upper)] if path.collapsed else []
    first = first_snap(loading.snaps)
    check = _load_check(loading, start, path, first, mode) if num.increments_check == HALVED_INCREMENTS_CHECK else None
    descent = descend(loading, path.du, descend_to) if path.collapsed and descend_to is not None else None
    branches = loading.accepted + (descent.states if descent is not None else [])
    return LoadPath(
        capacity=path.du if path.collapsed else math.nan,
        first_loss=first_loss_multiplier(path, first),
        outcome=path.outcome,
        unit=UNITS[case.loads.live_load],
        hinges=tuple(mode.labels) if mode is not None else (),
        kind=str(mode.kind) if mode is not None else None,
        curve=load_curve(arch, start, branches),
        after_mm=after_mm,
        reach=path.lower,
        iterations=loading.iterations,  # the load control's: the descending branch has its own solver
        **rigid_answer(case, after_mm, at_rest),
        descent_end=str(descent.end) if descent is not None else "",
        descent_hinges=descent.hinges if descent is not None else (),
        states=tuple(branches + collapse),
        increments_check=check,
    )


LOAD_ANSWERS = ("capacity", "first_loss")  # a load path's answers in its increments check (N or g)


def _load_check(
    loading: StaticLoading,
    start: StaticState,
    path: PathResult,
    first: tuple[float, float] | None,
    mode: FoldMode | None,
) -> dict[str, Any]:
    """The load path solved again from `start` with its increments halved (`solve.refined`): its outcome,
    capacity and first loss of stability (N or g), their moves, whether the answer is resolved and,
    where both collapse, the collapse mode beside the path's `mode` (`solve.refined.mode_record`)."""
    wall0 = time.time()
    again = halved_loading(loading, start)
    if again is None:
        return {"skipped": SKIPPED}
    checked = follow_path(again, again.settings)
    ours, theirs = _load_answers(path, first), _load_answers(checked, first_snap(again.snaps))
    modes = mode_record(loading, mode.labels, again, checked) if mode is not None else {}
    return {**check_record(ours, theirs, LOAD_ANSWERS, again.iterations, time.time() - wall0), **modes}


def _load_answers(path: PathResult, first: tuple[float, float] | None) -> dict[str, Any]:
    """A load path's outcome, capacity and first loss of stability (None where it has none)."""
    capacity = path.du if path.collapsed else None
    loss = first_loss_multiplier(path, first)
    return {"outcome": path.outcome, "capacity": capacity, "first_loss": loss if math.isfinite(loss) else None}


def rigid_answer(case: ArchCase, after_mm: float, at_rest: LoadCapacity) -> dict:
    """The rigid-block capacity of the same state: at rest, or in the rigid march's state after the
    movement (NaN where the rigid arch collapses before it)."""
    try:
        rigid = residual_capacity(case, after_mm) if after_mm > 0.0 else at_rest
    except LimitError as exc:
        return {"rigid": math.nan, "rigid_hinges": (), "rigid_note": str(exc)}
    return {"rigid": rigid.multiplier, "rigid_hinges": tuple(p.label for p in rigid.pivots)}


def load_scale(rigid: LoadCapacity) -> float:
    """The size of the load the path's increments are made for: the rigid arch's capacity at rest
    `rigid` (a settled arch carries less), or, where rigid blocks carry any load, the arch's weight
    (N) or 1 g."""
    if math.isfinite(rigid.multiplier) and rigid.multiplier > 0.0:
        return rigid.multiplier
    return rigid.arch_weight_N if rigid.unit == UNITS[VERTICAL] else 1.0


def _move_supports(loading: StaticLoading, case: ArchCase, after_mm: float) -> None:
    """The support movement to `after_mm` along its path, which the arch must carry in equilibrium."""
    loading.settings = path_settings(case.numerics, after_mm)
    check_carried(loading.follow(), after_mm)


def hold_the_live_load(loading: StaticLoading, case: ArchCase) -> float:
    """Grow the case's live load to the value a run holds (`case.mechanics.held_multiplier`) on the load
    path, then make the supports' movement the path's parameter with the load held (load, then
    movement); the value. CaseError if the arch does not carry it."""
    held = held_multiplier(case)
    moving = loading.settings
    load_the_live_load(loading, held_load_settings(case))
    check_held(loading.follow(), case)
    move_the_supports(loading, moving)
    return held


def held_load_settings(case: ArchCase) -> PathSettings:
    """The load path's increments up to the live load a run holds (both engines grow it alike)."""
    growing = load_settings(load_scale(load_analysis(case)), case.numerics.increment_growth)
    return replace(growing, max_displacement=held_multiplier(case))


def check_held(loaded: PathResult, case: ArchCase) -> None:
    """CaseError unless the load path `loaded` stood in equilibrium up to the load the case holds."""
    held = held_multiplier(case)
    if loaded.unresolved:
        raise RunFailedError(
            f"unresolved: the load path found neither equilibrium nor runaway at {loaded.upper:.4g} "
            f"{UNITS[case.loads.live_load]} on its way to the held {held:g} (no verdict on the held load)"
        )
    if loaded.outcome != Outcome.STANDS or loaded.lower < held:
        name = HELD_SETTINGS[case.loads.live_load]
        at = loaded.du if loaded.collapsed else loaded.lower
        unit = UNITS[case.loads.live_load]
        raise CaseError(f"loads.{name} = {held:g}: the arch does not carry it ({loaded.outcome} at {at:.4g} {unit})")


def check_carried(moved: PathResult, after_mm: float) -> None:
    """CaseError unless the support movement's path `moved` stood in equilibrium up to `after_mm`."""
    if moved.outcome != Outcome.STANDS or moved.lower < units.mm(after_mm):
        where = f"{units.to_mm(moved.du):.2f} mm" if moved.collapsed else f"{units.to_mm(moved.lower):.2f} mm"
        raise CaseError(
            f"after_mm: the arch does not carry its support movement to {after_mm:g} mm ({moved.outcome} at {where})"
        )


def first_loss_multiplier(path: PathResult, first: tuple[float, float] | None) -> float:
    """The first loss of stability's multiplier: the first snap's fold, or the collapse's own fold."""
    if first is not None:
        return 0.5 * (first[0] + first[1])
    return path.du if path.collapsed else math.nan


def load_curve(arch: StaticArch, start: StaticState, states: list[StaticState]) -> pd.DataFrame:
    """The load-displacement curve: each state's multiplier, the live load's displacement along its
    own direction (mm; weighted by its forces, the work it does per unit multiplier), the tangent's
    smallest eigenvalue (N/m, zero at the limit point, negative past it) and its branch: `descending`
    past the row of the largest multiplier, `ascending` up to it."""
    rows = [
        {
            "multiplier": s.lam,
            "load_displacement_mm": units.to_mm(live_work(arch, start.u, s.u)),
            "min_stiffness_N_per_m": s.min_stiffness,
            BRANCH: branch,
        }
        for s, branch in zip(states, branches(np.array([s.lam for s in states])))
    ]
    import pandas as pd  # a live load's curve only: a support movement's run does not import pandas

    return pd.DataFrame(rows)


def branches(multipliers: np.ndarray) -> list[str]:
    """Each state's branch along a load path: `ascending` up to the largest multiplier, `descending` past it."""
    peak = int(np.argmax(multipliers)) if len(multipliers) else 0
    return [DESCENDING if k > peak else ASCENDING for k in range(len(multipliers))]


def live_work(arch: StaticArch, u0: np.ndarray, u: np.ndarray) -> float:
    """The live load's displacement along its forces from `u0` to `u` (m; `model.loads.load_displacement`)."""
    pos0, turn0 = arch.poses(u0)
    pos, turn = arch.poses(u)
    return load_displacement(arch.live, pos0, turn0, pos, turn)


def load_the_live_load(loading: StaticLoading, settings: PathSettings) -> None:
    """From `loading`'s last accepted state on, the path's parameter is the live load's multiplier (from 0,
    in `settings`' units), the supports held where they are: movement, then load."""
    support = loading.parameter.support(loading.accepted[-1].lam)
    _go_on(loading, PathParameter(live=True, support_at=support), settings, 0.0)


def move_the_supports(loading: StaticLoading, settings: PathSettings) -> None:
    """From `loading`'s last accepted state on (a live load grown to its multiplier there), the path's
    parameter is the supports' movement from where they stand, the load held: load, then movement."""
    lam = loading.accepted[-1].lam
    support = loading.parameter.support(lam)
    _go_on(loading, PathParameter(support_at=support, held=loading.parameter.multiplier(lam)), settings, support)


def _go_on(loading: StaticLoading, parameter: PathParameter, settings: PathSettings, lam: float) -> None:
    """`loading`'s path goes on from its last accepted state, now at `lam` of the new `parameter`."""
    loading.parameter, loading.settings = parameter, settings
    loading.accepted = [replace(loading.accepted[-1], lam=lam)]
    loading.failures, loading.falls, loading.readings, loading.snaps = {}, {}, {}, []
