"""How far each accepted increment's relaxation moved the blocks (summary.json's `relaxations`),
kept as the DEM's path is accepted and discarded."""

from __future__ import annotations

from yadearch.model import units

MOVE_KEYS = ("delta_mm", "increment_mm", "move_mm")  # one entry per accepted state of the path


class Relaxations(dict):
    """summary.json's `relaxations` record, a plain dict for JSON: the runaway bound, per accepted state
    its support position, increment and relaxation move (mm), and the states a hold called equilibria
    that the static model moved (`off_equilibrium`: [delta_mm, move_mm or None])."""

    def __init__(self, runaway_m: float):
        super().__init__(runaway_mm=units.to_mm(runaway_m), **{key: [] for key in MOVE_KEYS}, off_equilibrium=[])

    def record(self, delta_m: float, increment_m: float, move_m: float) -> None:
        """An accepted state at support displacement `delta_m`, reached by `increment_m` and a relaxation
        that moved a block `move_m` (all m)."""
        for key, value in zip(MOVE_KEYS, (delta_m, increment_m, move_m)):
            self[key].append(units.to_mm(value))

    def drop_last(self) -> float:
        """Forget the last accepted state (it did not settle): its support displacement (mm)."""
        dropped = self["delta_mm"][-1]
        for key in MOVE_KEYS:
            self[key].pop()
        return dropped
