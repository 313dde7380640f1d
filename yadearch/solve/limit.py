"""Rigid-block limit analysis of the arch under a moving support: the kn -> infinity reference of the
DEM (Gilbert's rigid-block LP as in LimitState RING; Portioli & Cascini 2017 for settlements).

Incremental, geometry updated. The kinematic LP gives the three-hinge mechanism that follows the
support; the support moves in steps along it, each configuration reached exactly by closing the
linkage (no drift), and the static LP checks that an admissible equilibrium remains with forces only
at touching corners. A corner that closes on the way (a hinge turning back) ends the step there and
the mechanism is solved again. When equilibrium is lost, bisection locates the limit, where the
thrust line touches a fourth corner, and the mechanism at a fixed support just past it (a four-hinge
chain that lowers the weights) is read. If it moves an open hinge to the next interface (it opens
the neighbour and turns the open hinge back), the arch snaps along it at the fixed support until that
hinge closes: a rigid hinge cannot migrate smoothly, since with both open the thrust line would have
to pass four pivots. If equilibrium exists after the snap the march goes on (unless the snap moves a
block further than `max_snap_mm`, then the collapse); any other chain, or no equilibrium after the
snap, is collapse (a failure of the friction alone: sliding). A DEM run at kn 300 loaded gently
passes snaps of 1.1-1.3 mm (docs/validation.md), so every snap is survived by default. du_rigid
is the last support displacement with an admissible equilibrium. Without the snaps the paper arch
would "collapse" at 8.4 mm, where its extrados hinge moves from 33E to 32E.
"""

from __future__ import annotations

import math
import time
from dataclasses import replace
from typing import TypeGuard

import numpy as np

from yadearch.case.config import ArchCase
from yadearch.case.imperfect import amplitudes
from yadearch.model import units
from yadearch.model.hinges import mirror_hinge_labels
from yadearch.solve.limit_lp import Mechanism, Statics, solve_kinematics, solve_statics
from yadearch.solve.limit_result import HingeRecord, LimitResult, interface_forces
from yadearch.solve.rigid import (
    LimitError,
    Pivot,
    Placement,
    RigidArch,
    at_rest,
    close_linkage,
    contacts,
    rigid_arch,
    turn_four_bar,
)

DEFAULT_STEP_MM = 0.5  # support step between equilibrium checks
DEFAULT_TOLERANCE_MM = 1e-3  # width of the bisection bracket that locates a limit
COLLAPSE_PROBE_MM = 0.05  # past a limit, where the four-hinge chain is read (clear of LP tolerances)
CLOSURE_BISECTIONS = 60  # halvings that put a closing corner on its contact to round-off
SNAP_FIRST_RAD, SNAP_MAX_RAD = 1e-7, 0.5  # search range of the rotation that closes a snapping hinge
SNAP_SAMPLES = 9  # points along a snap where the weights must keep descending
MAX_SNAPS = 5  # successive snaps at one support displacement before giving up
MIRRORED = {"right": "left", "left": "right"}  # the moving support of a case's mirror image


def mirror_image(case: ArchCase) -> ArchCase:
    """`case` with the other support moving the mirrored way: on a symmetric arch, the keystone's
    tie broken toward its other joint (the other branch of the rigid march)."""
    return case.with_overrides({"moving_support": MIRRORED[case.loading.moving_support]})


def has_other_branch(case: ArchCase) -> bool:
    """Whether the rigid march of `case` has a second branch, the keystone's tie broken toward its
    other joint: an odd number of voussoirs without dimension errors (else there is no mirror image),
    one support moving, and a movement that is not its own mirror image (it moves vertically or turns)."""
    if not (case.geometry.n_voussoirs % 2 and case.loading.moving_support in MIRRORED):
        return False
    return amplitudes(case).perfect_dimensions and not rigid_arch(case).movement.mirror_is_itself


def stands(case: ArchCase) -> bool:
    """Whether the undeformed arch admits an equilibrium (thrust line inside, friction enough)."""
    arch = rigid_arch(case)
    return solve_statics(arch, at_rest(arch)).feasible


class _March:
    """The incremental analysis of one arch; counts its LPs."""

    def __init__(self, arch: RigidArch, step: float, tolerance: float, max_snap_mm: float) -> None:
        self.arch, self.step, self.tolerance, self.n_lp = arch, step, tolerance, 0
        self.max_snap_mm = max_snap_mm  # a larger snap counts as collapse (inf: any snap is survived)
        self.snap_collapse_mm: float | None = None  # the snap that ended the march, if one did
        self.history: list[HingeRecord] = []

    def statics(self, placement: Placement, friction: bool = True, refine: bool = False) -> Statics:
        self.n_lp += 1
        return solve_statics(self.arch, placement, friction, refine)

    def kinematics(self, placement: Placement, support_speed: float = 1.0) -> Mechanism | None:
        self.n_lp += 1
        return solve_kinematics(self.arch, placement, support_speed)

    def admissible(self, placement: Placement | None) -> bool:
        return placement is not None and self.statics(placement).feasible

    def valid(self, placement: Placement | None, base: Placement) -> bool:
        """Reached, and no corner open in `base` passed through its neighbour."""
        if placement is None:
            return False
        was_open = ~contacts(self.arch, base).touching
        return not np.any(contacts(self.arch, placement).gap[was_open] < 0.0)

    def moved(self, base: Placement, mechanism: Mechanism, offset: float) -> Placement | None:
        """`offset` further along a three-hinge `mechanism`; None if unreachable or overlapping."""
        placement = close_linkage(self.arch, base, mechanism.pivots, base.delta + offset)
        return placement if self.valid(placement, base) else None

    def run(self, limit: float) -> tuple[Placement, Placement | None, Mechanism, Mechanism | None]:
        """March to collapse or to `limit`: the last admissible placement, the one where the collapse
        mechanism was read, the mechanism followed last and the collapse mechanism."""
        state = at_rest(self.arch)
        if not self.admissible(state):
            raise LimitError("the arch admits no equilibrium at rest (too thin, or too little friction)")
        mechanism = self.switch(state, None, 0.0)
        corners = [c for c in self.arch.movement.corners if c < limit]
        while state.delta < limit - 1e-12:
            corner = next((c for c in corners if c > state.delta + 1e-12), limit)
            offset = min(self.step, corner - state.delta)
            trial, capped = self.moved(state, mechanism, offset), False
            if trial is None:  # a corner closes, or the linkage straightens, within the step
                offset = _bisect(lambda h: self.moved(state, mechanism, h) is not None, offset,
                                 offset / 2**CLOSURE_BISECTIONS)
                trial, capped = self.moved(state, mechanism, offset), True
            if trial is not None and self.admissible(trial):
                state = trial
                if not capped and abs(state.delta - corner) < 1e-12 and corner < limit:  # the path turns
                    mechanism = self.switch(state, mechanism, 0.0)
                elif capped:  # a corner has closed (or the linkage straightened): solve the mechanism again
                    new = self.switch(state, mechanism, 0.0)
                    if set(new.pivots) == set(mechanism.pivots):
                        raise LimitError(f"at {units.to_mm(state.delta):.3f} mm the mechanism can go no "
                                         "further (its linkage straightens) and no other follows")
                    mechanism = new
                continue
            offset = _bisect(lambda h: self.admissible(self.moved(state, mechanism, h)), offset,
                             self.tolerance)
            last = self.moved(state, mechanism, offset) if offset > 0 else state
            if last is None:  # the bisection accepted `offset`, so the linkage reaches it
                raise RuntimeError(f"at {units.to_mm(state.delta + offset):.3f} mm the last admissible "
                                   "placement found by bisection can no longer be reached")
            past = self.moved(state, mechanism, offset + self.tolerance)
            read_at = self.moved(last, mechanism, units.mm(COLLAPSE_PROBE_MM)) or past
            chain = self.kinematics(read_at, support_speed=0.0) if read_at is not None else None
            if past is None or not _migrates(chain, mechanism.pivots):
                return last, read_at, mechanism, chain
            snapped, jump, chain = self.snap(past, chain, mechanism.pivots)
            if snapped is not None and jump > self.max_snap_mm:
                self.snap_collapse_mm = jump
            if snapped is None or self.snap_collapse_mm is not None:
                return last, read_at, mechanism, chain
            state, mechanism = snapped, self.switch(snapped, mechanism, jump)
        return state, None, mechanism, None

    def snap(self, start: Placement, chain: Mechanism | None,
             pivots: tuple[Pivot, ...]) -> tuple[Placement | None, float, Mechanism | None]:
        """Follow hinge-migrating chains at a fixed support from `start` until the turned-back hinge
        closes and equilibrium exists again: that placement, the largest block movement (mm) and the
        last chain; None for the placement if the arch finds no equilibrium so (collapse)."""
        state = start
        for _ in range(MAX_SNAPS):
            if not _migrates(chain, pivots):
                return None, 0.0, chain
            sign = np.sign(chain.rates[0])  # the first segment turns with its hinge's relative rate

            def turned(angle: float, base: Placement = state, chain_pivots=chain.pivots) -> Placement | None:
                placement = turn_four_bar(self.arch, base, chain_pivots, sign * angle)
                return placement if self.valid(placement, base) else None

            angle = SNAP_FIRST_RAD
            while turned(angle) is not None and angle < SNAP_MAX_RAD:
                angle *= 2.0
            if angle >= SNAP_MAX_RAD:
                return None, 0.0, chain
            angle = _bisect(lambda a: turned(a) is not None, angle, angle / 2**CLOSURE_BISECTIONS)
            path = _reached([turned(a) for a in np.linspace(0.0, angle, SNAP_SAMPLES)], start)
            height = [float(self.arch.weight @ p.centroids(self.arch)[:, 1]) for p in path]
            if np.any(np.diff(height) > 0):
                raise LimitError(f"at {units.to_mm(start.delta):.3f} mm the arch comes to rest on four "
                                 "open hinges, which this analysis does not follow")
            closed = np.flatnonzero((contacts(self.arch, path[-1]).touching
                                     & ~contacts(self.arch, state).touching).any(axis=1))
            if list(closed) != list(chain.closing):
                return None, 0.0, chain  # the chain straightened, or closed another corner first
            state = path[-1]
            pivots = tuple(p for p in chain.pivots if p.joint not in chain.closing)
            if self.admissible(state):
                moved = np.linalg.norm(state.centroids(self.arch) - start.centroids(self.arch), axis=1)
                return state, units.to_mm(float(moved.max())), chain
            chain = self.kinematics(state, support_speed=0.0)
        return None, 0.0, chain

    def switch(self, state: Placement, mechanism: Mechanism | None, jump_mm: float) -> Mechanism:
        """The three-hinge mechanism that follows the support from `state`, recorded in the history
        (hinges that stop, hinges that start)."""
        new = self.kinematics(state)
        if new is None or len(new.pivots) != 3:
            found = "none" if new is None else " ".join(p.label for p in new.pivots) or "none"
            raise LimitError(f"at {units.to_mm(state.delta):.3f} mm the support is followed by no "
                             f"three-hinge mechanism (hinges: {found})")
        old = set() if mechanism is None else set(mechanism.pivots)
        d_mm = units.to_mm(state.delta)
        stopped = {p.label for p in old - set(new.pivots)}
        for k, record in enumerate(self.history):
            if record.to_mm is None and record.label in stopped:
                self.history[k] = HingeRecord(record.interface, record.side, record.from_mm, d_mm,
                                              record.jump_mm)
        self.history += [HingeRecord(p.joint + 1, "IE"[p.side], d_mm, None, jump_mm)
                         for p in new.pivots if p not in old]
        return new


def _migrates(chain: Mechanism | None, pivots: tuple[Pivot, ...]) -> TypeGuard[Mechanism]:
    """Whether a fixed-support `chain` moves a hinge of `pivots` to the next interface: one new
    hinge, beside the one hinge it turns back (to close). Any other lowering chain is a collapse."""
    if chain is None or chain.power >= 0 or len(chain.pivots) != 4 or len(chain.closing) != 1:
        return False
    new = [p for p in chain.pivots if p not in pivots]
    back = chain.closing[0]
    return len(new) == 1 and back in {p.joint for p in pivots} and abs(new[0].joint - back) == 1


def _reached(path: list[Placement | None], start: Placement) -> list[Placement]:
    """The placements along a snap, each of which must be reachable: the search only checked its end."""
    reached = [p for p in path if p is not None]
    if len(reached) != len(path):
        raise LimitError(f"at {units.to_mm(start.delta):.3f} mm the snapping chain cannot pass some of its "
                         "intermediate positions, which this analysis does not follow")
    return reached


def _bisect(ok, high: float, width: float) -> float:
    """The largest offset in [0, high] that `ok` accepts (ok(0) assumed), to within `width`."""
    low = 0.0
    while high - low > width:
        mid = 0.5 * (low + high)
        if mid in (low, high):  # adjacent floats: as close as it gets
            break
        low, high = (mid, high) if ok(mid) else (low, mid)
    return low


def limit_analysis(case: ArchCase, step_mm: float = DEFAULT_STEP_MM,
                   tolerance_mm: float = DEFAULT_TOLERANCE_MM,
                   max_settlement_mm: float | None = None, max_snap_mm: float | None = None,
                   mirror: bool = True) -> LimitResult:
    """The support displacement du_rigid at which the rigid arch of `case` loses its last admissible
    equilibrium, its hinge history and its last admissible state (see the module docstring). A hinge
    snap that moves a block further than `max_snap_mm` is the collapse (default: every snap that
    ends in equilibrium is survived; docs/validation.md). On an odd number of voussoirs a movement
    whose mirror image differs (a support that turns or moves vertically) is solved mirrored too
    (`mirror_du_rigid_mm`; `mirror` false: not): the keystone's two joints tie, and each branch has
    its own limit."""
    result, arch = _solve(case, step_mm, tolerance_mm, max_settlement_mm, max_snap_mm)
    if not (mirror and has_other_branch(case)):
        return result
    try:
        mirrored, _ = _solve(mirror_image(case), step_mm, tolerance_mm, max_settlement_mm, max_snap_mm)
    except LimitError as exc:
        return replace(result, mirror_collapse_mode=f"failed: {exc}")
    return replace(result, mirror_du_rigid_mm=mirrored.du_rigid_mm, mirror_collapse_mode=mirrored.collapse_mode,
                   mirror_collapse_hinges=tuple(mirror_hinge_labels(mirrored.collapse_hinges, arch.n_joints)),
                   wall_s=result.wall_s + mirrored.wall_s)


def _solve(case: ArchCase, step_mm: float, tolerance_mm: float, max_settlement_mm: float | None,
           max_snap_mm: float | None) -> tuple[LimitResult, RigidArch]:
    """`limit_analysis` of `case` as it stands (the keystone's tie broken toward its left joint), and
    the rigid arch it solved."""
    start = time.perf_counter()
    arch = rigid_arch(case)
    snap_cap = math.inf if max_snap_mm is None else max_snap_mm
    march = _March(arch, units.mm(step_mm), units.mm(tolerance_mm), snap_cap)
    limit = min(units.mm(max_settlement_mm or case.loading.max_settlement_mm), arch.movement.length)
    last, read_at, mechanism, chain = march.run(limit)
    mode, hinges = "none", tuple(p.label for p in mechanism.pivots)
    new: tuple[str, ...] = ()
    if read_at is not None:
        if chain is not None and chain.power < 0 and len(chain.pivots) > 3:
            mode = "snap" if march.snap_collapse_mm is not None else "hinging"
            hinges = tuple(p.label for p in chain.pivots)
            new = tuple(p.label for p in chain.pivots if p not in mechanism.pivots)
        else:
            mode = "sliding" if march.statics(read_at, friction=False).feasible else "hinging"
    forces, reactions = interface_forces(arch, march.statics(last, refine=True))
    use = np.array([f.friction_use for f in forces])
    return LimitResult(
        name=case.name, du_rigid_mm=units.to_mm(last.delta) if mode != "none" else None,
        collapse_mode=mode, hinge_history=tuple(march.history), collapse_hinges=hinges,
        new_at_collapse=new, forces=forces, reactions_N=reactions,
        max_friction_use=float(use.max()), max_friction_interface=int(np.argmax(use)) + 1,
        rotation_rad=tuple(float(r) for r in last.rot),
        shift_mm=tuple((units.to_mm(float(x)), units.to_mm(float(y))) for x, y in last.shift),
        settlement_direction_deg=case.loading.settlement_direction_deg,
        max_snap_mm=None if math.isinf(snap_cap) else snap_cap, snap_collapse_mm=march.snap_collapse_mm,
        step_mm=step_mm,
        tolerance_mm=tolerance_mm, n_lp=march.n_lp, wall_s=time.perf_counter() - start), arch
