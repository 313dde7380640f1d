"""What the DEM's loading path needs of a live scene (YADE layer, `dem.runner.Runner` provides it), and
the rules by which a hold's verdict is trusted: the static tangent at the poses positive definite, the
self-weight state settled by the path's own test."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, Protocol

import numpy as np

from yadearch.case.config import ArchCase
from yadearch.errors import CANNOT_STAND, UNRESOLVED, RunFailedError
from yadearch.model import units
from yadearch.model.hinges import Hinge
from yadearch.model.movement import Movement
from yadearch.solve.stages import Stage, Verdict

SETTLE_TOLERANCE_FACTOR = 0.01  # a settled state's unbalanced force, relative to equilibrium_tolerance
STABILITY_HOLDS = 2  # an equilibrium whose static tangent is indefinite is held this many times more
JOINT_CONTACTS = "joint"  # numerics.contact_model of the joint elements (quiet at rest, unlike CGAL's)


class PathRecorder(Protocol):
    """What the path records through (dem.recorder.Recorder)."""

    def record_equilibrium(self) -> tuple[tuple[int, int, int], list[Hinge]]: ...

    def discard_since(self, mark: tuple[int, int, int]) -> None: ...

    def record_collapse(self) -> list[Hinge]: ...


class LiveArch(Protocol):
    """What the path needs of a live DEM scene (dem.runner.Runner): move the support, hold it,
    go back to a kept state, record; `stage` labels the records."""

    stage: Stage

    @property
    def case(self) -> ArchCase: ...

    @property
    def movement(self) -> Movement: ...

    @property
    def recorder(self) -> PathRecorder: ...

    @property
    def hold_move(self) -> float: ...  # the largest block displacement of the last hold (m)

    def smallest_stiffness(self) -> float: ...  # the static tangent's smallest eigenvalue at the poses (N/m)

    def reach(self, increment: float) -> float: ...  # how far a path increment moves a block quasi-statically (m)

    def yield_fill(self) -> None: ...  # the blocks rest in an equilibrium of the path: the fill yields for good

    # a branch's first state: the voussoirs' centroids as `path_positions` gives them, and how they move per unit
    # of the path's parameter from there (n, 3; the static model's tangent; None: it does not predict)
    def branch_start(self) -> tuple[np.ndarray, np.ndarray | None]: ...

    # the static model's move to a stable equilibrium (m; `dem.static_check`), None where it has none
    def static_distance(self) -> float | None: ...

    @property
    def total_steps(self) -> int: ...

    @property
    def log(self) -> Callable[[str], None]: ...

    def delta(self) -> float: ...

    def snapshot(self) -> dict[str, Any]: ...

    # the voussoirs' centroids (n, 3; m) the path compares: the scene's, or the static equilibrium's it sits in
    def path_positions(self) -> np.ndarray: ...

    def restore(self, snapshot: dict[str, Any]) -> None: ...

    def move_support(self, target: float, speed_fraction: float) -> None: ...

    def hold(
        self,
        runaway: float | None = None,
        max_s: float | None = None,
        from_rest: bool = True,
        still_speed: float | None = None,
        tolerance: float | None = None,
    ) -> Verdict: ...


def stable_tangent(arch: LiveArch, verdict: Verdict) -> Verdict:
    """A hold's verdict kept only where the static model agrees: an equilibrium whose tangent at the
    blocks' poses is indefinite is held on (STABILITY_HOLDS times), then unresolved (Verdict.TIMEOUT)."""
    holds = 0
    while verdict == Verdict.STABLE and arch.smallest_stiffness() <= 0.0:
        if holds == STABILITY_HOLDS:
            return Verdict.TIMEOUT
        verdict = arch.hold(from_rest=False)
        holds += 1
    return verdict


def hold_on(arch: LiveArch, runaway: float | None = None) -> Verdict:
    """Hold on, the blocks in their motion, until they are at rest by the path's settling test (blocks
    slower than `settle_speed_mm_per_s`, the unbalanced force SETTLE_TOLERANCE_FACTOR x the tolerance),
    a block runs `runaway` (m) or `hold_max_s` passes: a state creeping past a fold, slow where the
    fold was, is given the time to leave or to stop."""
    num = arch.case.numerics
    return arch.hold(
        runaway=runaway,
        from_rest=False,
        still_speed=units.mm(num.settle_speed_mm_per_s),
        tolerance=SETTLE_TOLERANCE_FACTOR * num.equilibrium_tolerance,
    )


def settle_selfweight(arch: LiveArch) -> None:
    """Settle the self-weight state by the path's own test (`settle_speed_mm_per_s`, a hundredth of
    the equilibrium tolerance) and until the static model calls it stable: a state still creeping or
    indefinite is not the path's start (RunFailedError: it cannot stand, or it is unresolved). A settle
    that times out goes on (STABILITY_HOLDS times); with joint elements a state still creeping then is
    unresolved, with CGAL contacts (which never get that quiet) it is kept."""
    num = arch.case.numerics
    verdict, holds = hold_on(arch), 1
    while verdict == Verdict.TIMEOUT and holds <= STABILITY_HOLDS:
        verdict, holds = hold_on(arch), holds + 1
    arch.log(f"[{arch.case.name}] settling the self-weight state: {verdict} after {holds} hold(s)")
    if verdict == Verdict.RUNAWAY:
        raise RunFailedError(f"{CANNOT_STAND}: the self-weight state ran away while settling")
    if verdict == Verdict.TIMEOUT and num.contact_model == JOINT_CONTACTS:
        raise RunFailedError(
            f"{UNRESOLVED}: the self-weight state still creeps after {holds} holds of {num.hold_max_s} s "
            f"(numerics.hold_max_s; a block moved {units.to_mm(arch.hold_move):.3f} mm in the last, blocks "
            f"faster than {num.settle_speed_mm_per_s:g} mm/s): an arch at the edge of standing"
        )
    if verdict == Verdict.STABLE and stable_tangent(arch, verdict) != Verdict.STABLE:
        raise RunFailedError(
            f"{UNRESOLVED}: the self-weight state did not settle to a stable equilibrium within "
            f"{STABILITY_HOLDS + 1} holds of {num.hold_max_s} s (numerics.hold_max_s)"
        )
