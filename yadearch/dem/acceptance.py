"""When the DEM's path takes a hold's 'stable' for an equilibrium (YADE-free): only where the static
model (`dem.static_check`), from the blocks' poses and shear forces, does not move a block further
than the snap floor to a stable equilibrium. A near-equilibrium past a fold is slow and balanced to
the tolerance but is not one; it is held on while it creeps (docs/numerics.md, "Collapse")."""

from __future__ import annotations

import math
from collections.abc import Callable

from yadearch.dem.live_arch import LiveArch, hold_on, stable_tangent
from yadearch.model import units
from yadearch.solve.stages import Verdict


class StaticAcceptance:
    """The static model's word on the live arch's states, each state it moves recorded in `records`
    ([delta_mm, move_mm or None: no stable equilibrium]) and logged with the path's `said` position."""

    def __init__(self, arch: LiveArch, floor: float, records: list, said: Callable[[float], str]):
        self.arch = arch
        self.floor = floor  # (m) the snap floor: a state the static model moves further is off
        self.records = records
        self.said = said
        self.off = False  # the last `accept` ended where the static model still moves the blocks

    def accept(self, verdict: Verdict, near_holds: int, runaway: float | None = None) -> Verdict:
        """A hold's `verdict`, its 'stable' kept only on the static model's equilibrium: a state off it is
        held on, the blocks in their motion, up to `near_holds` times (on while they creep), a block
        `runaway` away running away (the case's bound by default); one still off is not an equilibrium
        (Verdict.TIMEOUT, `off` set)."""
        holds, off = 0, self.distance() if verdict == Verdict.STABLE else None
        while (off is not None or (holds and verdict == Verdict.TIMEOUT)) and holds < near_holds:
            verdict = stable_tangent(self.arch, self.hold(off, runaway))
            holds += 1
            off = self.next_distance(verdict, off)
        self.off = off is not None and verdict != Verdict.RUNAWAY
        return Verdict.TIMEOUT if self.off else verdict

    def next_distance(self, verdict: Verdict, off: float | None) -> float | None:
        """The distance after a hold that ended in `verdict` from a state `off`: measured again at rest,
        kept while the blocks still move, None after a runaway."""
        if verdict == Verdict.STABLE:
            return self.distance()
        return off if verdict == Verdict.TIMEOUT else None

    def hold(self, off: float | None, runaway: float | None = None) -> Verdict:
        """Hold on a state `off` (m) from the static model's stable equilibrium until it is at rest by the
        settling test; with none there (inf) first the whole `hold_max_s` however slowly it creeps, as
        a state past a fold leaves it exponentially slowly."""
        if off is not None and math.isinf(off):
            if self.arch.hold(runaway=runaway, from_rest=False, still_speed=0.0) == Verdict.RUNAWAY:
                return Verdict.RUNAWAY
        return hold_on(self.arch, runaway)

    def distance(self) -> float | None:
        """How far the static model moves a block to a stable equilibrium (m; inf: none there) where it
        is further than the snap floor, else None; such a state is recorded and logged."""
        distance = self.arch.static_distance()
        if distance is None or distance <= self.floor:
            return None
        delta = self.arch.delta()
        self.records.append([units.to_mm(delta), units.to_mm(distance) if math.isfinite(distance) else None])
        found = (
            f"moves the blocks {units.to_mm(distance):.3f} mm to a stable equilibrium"
            if math.isfinite(distance)
            else "finds no stable equilibrium near this state"
        )
        self.arch.log(f"[{self.arch.case.name}] at {self.said(delta)} the static model {found}")
        return distance
