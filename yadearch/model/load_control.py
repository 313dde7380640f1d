"""A live load driven by the displacement of its own points through a spring (pure numpy), as a testing
machine drives a specimen: the load's multiplier is the spring's stiffness times the gap between the
machine's anchor, which moves at a set rate, and the load's displacement along its forces
(`model.loads.load_displacement`). Past the peak of the load-displacement curve a spring stiffer than
the curve falls keeps each state stable, so a dynamic engine follows the descending branch that load
control cannot reach (docs/loads.md, "The DEM past the peak")."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from yadearch.model.loads import load_displacement

SPRING_RATIO = 10.0  # the machine's stiffness: this x the path's secant (load over displacement) at its last
# stable state; past the peak the curve falls far less steeply than it rose (set 2: -0.8 against 7.8 N/mm)
STEP_THICKNESS_RATIO = 0.01  # each move of the anchor: this x the ring's thickness of the load's displacement


@dataclass(frozen=True)
class DisplacementControl:
    """How a dynamic engine follows a load past its peak: until the load falls to `descend_to` x the
    capacity, through a spring `spring_ratio` x the path's secant stiffness at its last stable state,
    the anchor moved `step_thickness_ratio` x the ring's thickness a step (both numerics: halved and
    doubled they must not move the branch, docs/loads.md)."""

    descend_to: float
    spring_ratio: float = SPRING_RATIO
    step_thickness_ratio: float = STEP_THICKNESS_RATIO

    def __post_init__(self) -> None:
        if not 0.0 <= self.descend_to <= 1.0:
            raise ValueError(f"descend_to must be in [0, 1], got {self.descend_to}")
        if not (self.spring_ratio > 1.0 and 0.0 < self.step_thickness_ratio <= 1.0):
            raise ValueError(
                f"a displacement control needs spring_ratio > 1 and step_thickness_ratio in (0, 1], got "
                f"{self.spring_ratio}, {self.step_thickness_ratio}"
            )


@dataclass
class LoadSpring:
    """The machine: `loads` (n_blocks, 4) of multiplier 1 (`model.loads.block_loads`), their displacement
    measured from the poses `pos0` (n_blocks, 2; m) and turns `turn0` (n_blocks; rad), a `stiffness`
    (multiplier per metre of that displacement), the anchor's position `anchor` (m) moving toward
    `target` at `rate` (m/s)."""

    loads: np.ndarray
    pos0: np.ndarray
    turn0: np.ndarray
    stiffness: float
    anchor: float
    rate: float
    target: float = field(init=False, default=0.0)  # where the anchor is going (m): where it is, at first

    def __post_init__(self) -> None:
        if not (self.stiffness > 0.0 and self.rate > 0.0):
            raise ValueError(f"a load spring needs a positive stiffness and rate, got {self.stiffness}, {self.rate}")
        self.target = self.anchor

    @classmethod
    def holding(
        cls, loads: np.ndarray, pos0: np.ndarray, turn0: np.ndarray, poses: np.ndarray, multiplier: float, **machine
    ) -> LoadSpring:
        """The machine that holds the blocks at `poses` (n_blocks, 3: x, y, turn) under `multiplier`: its
        anchor placed that far ahead of the load's displacement, so that taking over changes nothing."""
        stiffness = machine["stiffness"]
        moved = load_displacement(loads, pos0, turn0, poses[:, 0:2], poses[:, 2])
        return cls(loads, pos0, turn0, anchor=moved + multiplier / stiffness, **machine)

    def displacement(self, poses: np.ndarray) -> float:
        """The load's displacement along its forces at `poses` (m)."""
        return load_displacement(self.loads, self.pos0, self.turn0, poses[:, 0:2], poses[:, 2])

    def multiplier(self, poses: np.ndarray) -> float:
        """The load the spring puts on the blocks at `poses`: stiffness x (anchor - displacement)."""
        return self.stiffness * (self.anchor - self.displacement(poses))

    def advance(self, seconds: float) -> None:
        """Move the anchor toward its target by `rate` x `seconds` at most."""
        gap = self.target - self.anchor
        self.anchor = (
            self.target if abs(gap) <= self.rate * seconds else self.anchor + np.sign(gap) * self.rate * seconds
        )

    def reached(self) -> bool:
        """Whether the anchor is at its target."""
        return self.anchor == self.target
