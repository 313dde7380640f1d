"""The incremental rigid-block march of `solve.limit`: follow the three-hinge mechanism that the support
drives, locate where equilibrium is lost, re-seat the hinges at the fixed support, read the collapse.

The kinematic LP gives the mechanism that follows the support (ties to first order told apart by the
weights' energy a step on, `reseat.follow_tie`); each step closes the linkage exactly (no drift) and the
static LP checks that an admissible equilibrium remains with forces only at touching corners; a corner
that closes on the way ends the step and the mechanism is solved again. Where equilibrium is lost (a
fourth corner, located by bisection), the four-hinge chains that lower the weights at the fixed support
are followed until one closes one of its open hinges (`reseat`): the admissible landing with the lowest
weights is kept (ties toward the left) and the march goes on from it; a chain that closes none before a
block has moved `runaway` (a multiple of the ring's thickness), or no chain at all (sliding), is the
collapse. `first_limit` is the first limit point whose snap passes the engines' snap floor, or the
collapse; `snaps` the re-seatings survived. With a joint stiffness `kn` the joints beside the hinges
must also keep their fold margin (`solve.compliant`): a folded joint's chain may climb first and take a
hinge to any joint (a snap that lands is survived however far it moves); where it finds no landing the
weights decide.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from yadearch.model import units
from yadearch.solve import compliant
from yadearch.solve.compliant import Margin, folds, joint_margins, opening_chain, potential
from yadearch.solve.limit_lp import Mechanism, Statics, solve_kinematics, solve_statics
from yadearch.solve.limit_result import HingeRecord, SnapRecord
from yadearch.solve.reseat import closing_path, descending_chains, energy_tolerance, follow_tie, land, migrates
from yadearch.solve.rigid import MarchStopped, Pivot, Placement, RigidArch, close_linkage, contacts
from yadearch.solve.snap_rules import climbs, largest_accepted, moves_a_hinge

COLLAPSE_PROBE_MM = 0.05  # past a limit, where the four-hinge chains are read (clear of LP tolerances)
CLOSURE_BISECTIONS = 60  # halvings that put a closing corner on its contact to round-off


class March:
    """The incremental analysis of one arch; counts its LPs."""

    def __init__(
        self,
        arch: RigidArch,
        step: float,
        tolerance: float,
        runaway: float,
        kn: float | None = None,
        max_snap_mm: float = math.inf,
        start: tuple[Pivot, ...] = (),
        snap_floor_mm: float = 0.0,
    ) -> None:
        self.arch, self.step, self.tolerance, self.n_lp = arch, step, tolerance, 0
        self.start = Mechanism(start, (0.0,) * len(start), 0.0) if start else None  # None: leave rest on the LP's
        self.runaway = runaway  # a re-seating chain moving a block further (m) runs away: the collapse
        self.kn = kn  # joint stiffness (N/m^3) whose fold margins the joints keep (None: rigid blocks)
        self.folding = False  # the chain followed now opens a joint that folded (it may climb first)
        self.armed: dict[Pivot, bool] = {}  # joints that can fold (`compliant.folds`)
        self.largest_margin = 0.0  # the largest fold margin met (m)
        self.max_snap_mm = max_snap_mm  # a larger snap counts as collapse, as a DEM run's runaway (inf: none)
        self.snap_collapse_mm: float | None = None  # the snap that ended the march, if one did
        self.snap_floor_mm = snap_floor_mm  # a re-seating moving no block further is no loss of stability
        self.first_limit: float | None = None  # the first limit point met whose snap passes the floor (m)
        self.reseated: list[SnapRecord] = []  # the re-seatings survived
        self.history: list[HingeRecord] = []
        self.pivots: tuple[Pivot, ...] = ()  # the hinges of the mechanism followed now
        self.accepted: Statics  # the equilibrium `admissible` solved last
        # per closed joint beside an open hinge, its thrust's nearest approach to the hinge side's corner
        # on the path followed: distance (m), support position (m)
        self.closest: dict[Pivot, tuple[float, float]] = {}
        # re-seatings one limit may chain (each lowers the weights, so they cannot cycle)
        self.max_stages = 2 * arch.n_joints
        self.progress: Callable[[float], None] = lambda delta: None  # told each admitted position (m)

    def statics(self, placement: Placement, friction: bool = True, refine: bool = False) -> Statics:
        self.n_lp += 1
        return solve_statics(self.arch, placement, friction, refine)

    def kinematics(self, placement: Placement, support_speed: float = 1.0) -> Mechanism | None:
        self.n_lp += 1
        return solve_kinematics(self.arch, placement, support_speed)

    def admissible(self, placement: Placement | None) -> bool:
        """An admissible equilibrium exists at `placement` (and, with `kn`, no joint folds into a snap
        or a collapse)."""
        if placement is None:
            return False
        statics = self.accepted = self.statics(placement)
        if not statics.feasible or self.kn is None:
            return statics.feasible
        return not any(self.snaps(placement, self.opening(placement, fold)) for fold in self.folds(placement, statics))

    def folds(self, placement: Placement, statics: Statics) -> list[Margin]:
        """The joints that fold at `placement`, given its admissible equilibrium `statics`
        (`compliant.folds`); keeps the largest fold margin met."""
        assert self.kn is not None
        margins = joint_margins(self.arch, placement, statics.normal, statics.contacts, self.pivots, self.kn)
        self.largest_margin = max([self.largest_margin, *(m.critical for m in margins)])
        return folds(margins, self.armed)

    def opening(self, placement: Placement, fold: Margin) -> Mechanism:
        """The chain that opens the folded joint of `fold` from `placement` (`compliant.opening_chain`)."""
        return opening_chain(self.arch, placement, self.pivots, fold)

    def snaps(self, placement: Placement, chain: Mechanism) -> bool:
        """Whether a folded joint's opening `chain` snaps (ends lower where it closes a hinge or reaches the
        runaway bound) or straightens; else it climbs, and the two joints share the hinge until it descends."""
        path = closing_path(self.arch, placement, chain, placement, self.runaway, to_bound=True)
        return path is None or not climbs([potential(self.arch, p) for p in path], True, energy_tolerance(self.arch))

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

    def run(self, limit: float, start: Placement) -> tuple[Placement, Placement | None, Mechanism, Mechanism | None]:
        """March to collapse or to `limit` from the admissible placement `start` (at rest, or placed on the
        `start` linkage): the last admissible placement, the one where the collapse mechanism was read, the
        mechanism followed last and the collapse mechanism."""
        state = start
        mechanism = self.switch(state, None, 0.0)
        corners = [c for c in self.arch.movement.corners if c < limit]
        while state.delta < limit - 1e-12:
            corner = next((c for c in corners if c > state.delta + 1e-12), limit)
            offset = min(self.step, corner - state.delta)
            trial, capped = self.moved(state, mechanism, offset), False
            if trial is None:  # a corner closes, or the linkage straightens, within the step
                offset = largest_accepted(
                    lambda h: self.moved(state, mechanism, h) is not None, offset, offset / 2**CLOSURE_BISECTIONS
                )
                trial, capped = self.moved(state, mechanism, offset), True
            if trial is not None and self.admissible(trial):
                state = trial
                self.admit(state)
                if not capped and abs(state.delta - corner) < 1e-12 and corner < limit:  # the path turns
                    mechanism = self.switch(state, mechanism, 0.0)
                elif capped:  # a corner has closed (or the linkage straightened): solve the mechanism again
                    new = self.switch(state, mechanism, 0.0)
                    if set(new.pivots) == set(mechanism.pivots):
                        raise MarchStopped(
                            f"at {units.to_mm(state.delta):.3f} mm the mechanism can go no "
                            "further (its linkage straightens) and no other follows"
                        )
                    mechanism = new
                continue
            offset = largest_accepted(
                lambda h: self.admissible(self.moved(state, mechanism, h)), offset, self.tolerance
            )
            last = self.moved(state, mechanism, offset) if offset > 0 else state
            if last is None:  # the bisection accepted `offset`, so the linkage reaches it
                at = f"at {units.to_mm(state.delta + offset):.3f} mm"
                raise RuntimeError(f"{at} the last admissible placement found by bisection can no longer be reached")
            past = self.moved(state, mechanism, offset + self.tolerance)
            read_at = self.moved(last, mechanism, units.mm(COLLAPSE_PROBE_MM)) or past
            if past is None:
                self.first_limit = last.delta if self.first_limit is None else self.first_limit
                return last, read_at, mechanism, self.kinematics(read_at, 0.0) if read_at is not None else None
            chain, snapped = self.fold_chain(past), None
            if chain is not None:
                snapped, jump, chain = self.snap(past, chain, mechanism.pivots)
            if snapped is None:  # no fold, or a fold's snap that finds no landing: the weights decide
                self.pivots, self.folding = mechanism.pivots, False
                snapped, jump, descending = self.reseat(past, read_at or past)
                chain = chain or descending
            if snapped is not None and jump > self.max_snap_mm:
                self.snap_collapse_mm = jump
            if snapped is None or self.snap_collapse_mm is not None or jump > self.snap_floor_mm:
                self.first_limit = last.delta if self.first_limit is None else self.first_limit
            if snapped is None or self.snap_collapse_mm is not None:
                if chain is None and read_at is not None:
                    chain = self.kinematics(read_at, support_speed=0.0)
                return last, read_at, mechanism, chain
            before = " ".join(p.label for p in mechanism.pivots)
            state, mechanism = snapped, self.switch(snapped, mechanism, jump)
            after = " ".join(p.label for p in mechanism.pivots)
            self.reseated.append(SnapRecord(units.to_mm(last.delta), jump, before, after))
        return state, None, mechanism, None

    def admit(self, state: Placement) -> None:
        """At `state`, just admitted: keep each hinge's nearest thrust to its corner; tell `progress`."""
        self.progress(state.delta)
        for distance, pivot in compliant.edge_distances(
            self.arch, self.accepted.normal, self.accepted.contacts, self.pivots
        ):
            if pivot not in self.closest or distance < self.closest[pivot][0]:
                self.closest[pivot] = (distance, state.delta)

    def fold_chain(self, past: Placement) -> Mechanism | None:
        """With `kn`, the chain that opens a joint folded at `past` and takes a hinge by a snap
        (`compliant`; sets `folding`); None if none (the rigid re-seating then decides)."""
        self.folding = False
        if self.kn is None:
            return None
        statics = self.statics(past)
        chains = (self.opening(past, f) for f in (self.folds(past, statics) if statics.feasible else []))
        chain = next((c for c in chains if self.snaps(past, c)), None)
        self.folding = chain is not None
        return chain

    def reseat(self, start: Placement, read_at: Placement) -> tuple[Placement | None, float, Mechanism | None]:
        """Re-seat the hinges at the fixed support from `start`, just past a limit (`reseat`): follow the
        steepest chain that lowers the weights (ties to the left) until it closes a hinge, again while no
        admissible equilibrium holds: that placement (None at a collapse), the largest block move (mm)
        and the last chain tried; the first chains read at `read_at`, clear of the LP's round-off."""
        state, probe, pivots = start, read_at, self.pivots
        last: Mechanism | None = None  # the steepest chain last tried: at a collapse, the one it runs away on
        for _ in range(self.max_stages):
            chains = descending_chains(self.arch, probe, pivots)
            last = chains[0] if chains else last
            landings = []
            for chain in [c for c in chains if migrates(c, pivots)] or chains[:1]:
                landing = land(self.arch, state, chain, start, self.runaway)
                if landing is None:
                    continue
                self.pivots = landing.pivots
                if self.admissible(landing.placement):
                    return landing.placement, units.to_mm(landing.move), last
                landings.append(landing)
            if not landings:
                self.pivots = pivots
                return None, 0.0, last
            state = probe = landings[0].placement
            pivots = self.pivots = landings[0].pivots
        raise MarchStopped(
            f"at {units.to_mm(start.delta):.3f} mm the hinges re-seat more than {self.max_stages} "
            "times at the fixed support without finding an equilibrium"
        )

    def snap(
        self, start: Placement, chain: Mechanism | None, pivots: tuple[Pivot, ...]
    ) -> tuple[Placement | None, float, Mechanism | None]:
        """Follow a folded joint's hinge-migrating chains (compliant march) at a fixed support from `start`
        until the turned-back hinge closes and equilibrium exists again: that placement (None: collapse),
        the largest block movement (mm) and the last chain."""
        state = start
        for _ in range(self.max_stages):
            if not moves_a_hinge(chain, pivots, self.reach):
                return None, 0.0, chain
            path = closing_path(self.arch, state, chain, start, self.runaway)
            if path is None:
                return None, 0.0, chain
            height = [potential(self.arch, p) for p in path]
            if climbs(height, self.folding, energy_tolerance(self.arch)):
                raise MarchStopped(
                    f"at {units.to_mm(start.delta):.3f} mm the arch comes to rest on four "
                    "open hinges, which this analysis does not follow"
                )
            closed = np.flatnonzero(
                (contacts(self.arch, path[-1]).touching & ~contacts(self.arch, state).touching).any(axis=1)
            )
            if not len(closed) or not set(closed) <= {p.joint for p in chain.pivots}:
                return None, 0.0, chain  # the chain straightened, or closed a corner off its hinges
            state = path[-1]  # landed where a hinge closed: the one it turned back, or another first
            pivots = self.pivots = tuple(p for p in chain.pivots if p.joint not in closed)
            if self.admissible(state):
                moved = np.linalg.norm(state.centroids(self.arch) - start.centroids(self.arch), axis=1)
                return state, units.to_mm(float(moved.max())), chain
            chain = self.fold_chain(state)
            if chain is None:
                return self.reseat(state, state)
        return None, 0.0, chain

    @property
    def reach(self) -> int:
        """How many interfaces a chain may move a hinge (`snap_rules.moves_a_hinge`): a folded joint's any
        number (its landing decides), a rigid re-seating's the next one."""
        return self.arch.n_joints if self.folding else 1

    def switch(self, state: Placement, mechanism: Mechanism | None, jump_mm: float) -> Mechanism:
        """The three-hinge mechanism that follows the support from `state` (the LP's, or one tied with
        it to first order that lowers the weights more: `reseat.follow_tie`), recorded in the history
        (hinges that stop, hinges that start)."""
        named = mechanism is None and self.start is not None
        new = self.start if named else self.kinematics(state)
        if new is None or len(new.pivots) != 3:
            found = "none" if new is None else " ".join(p.label for p in new.pivots) or "none"
            raise MarchStopped(
                f"at {units.to_mm(state.delta):.3f} mm the support is followed by no "
                f"three-hinge mechanism (hinges: {found})"
            )
        if not named:
            new = follow_tie(self.arch, state, new, lambda placement: self.statics(placement).feasible)
        old = set() if mechanism is None else set(mechanism.pivots)
        self.pivots = new.pivots
        d_mm = units.to_mm(state.delta)
        stopped = {p.label for p in old - set(new.pivots)}
        for k, record in enumerate(self.history):
            if record.to_mm is None and record.label in stopped:
                self.history[k] = HingeRecord(record.interface, record.side, record.from_mm, d_mm, record.jump_mm)
        self.history += [
            HingeRecord(p.joint + 1, "IE"[p.side], d_mm, None, jump_mm) for p in new.pivots if p not in old
        ]
        return new
