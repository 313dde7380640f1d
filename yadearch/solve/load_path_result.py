"""What a live load's path returns (`solve.load_path`, the DEM's load ramp): the capacity, the first
loss of stability, the mechanism, the load-displacement curve and the rigid answer of the same state."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from yadearch.solve.descending import DescentEnd
from yadearch.solve.static_state import StaticState

if TYPE_CHECKING:
    import pandas as pd


@dataclass(frozen=True)
class LoadPath:
    """An engine's answer for a live load (the static engine's, or the DEM's: `engine`): the multiplier
    at the end of the path (`capacity`, NaN unless it collapsed) and at its first loss of stability, in
    `unit`; the outcome; the collapse's hinges and kind; the load-displacement curve; after a support
    movement of `after_mm`."""

    capacity: float
    first_loss: float
    outcome: str
    unit: str
    hinges: tuple[str, ...]
    kind: str | None
    curve: pd.DataFrame = field(repr=False)  # a notebook shows the answer; the curve stays an attribute
    after_mm: float
    reach: float  # the last stable multiplier of the path (the arch stands at least to it without collapse)
    iterations: int  # the static engine's Newton iterations, or the DEM's time steps
    # the rigid-block capacity of the same state (`solve.load_lp`; NaN where there is none); after a support
    # movement, the load that first moves the settled rigid arch, whose open hinges are pins: not a capacity
    rigid: float
    rigid_hinges: tuple[str, ...]
    rigid_note: str = ""  # why there is no rigid answer, where there is none
    engine: str = "static"
    descent_end: str = ""  # why the branch past the peak ends (`solve.descending.DescentEnd`); "": not traced
    descent_hinges: tuple[str, ...] = ()  # the hinges turning where it ends
    # the static engine's states in the path's order: its start (the self-weight's or the movement's end),
    # each accepted state, the descending branch's, the collapse's; none from the DEM or read from disk
    states: tuple[StaticState, ...] = field(default=(), repr=False, compare=False)
    # the static path again with the increments halved (numerics.increments_check; None: not checked)
    increments_check: dict | None = None

    @property
    def warnings(self) -> tuple[str, ...]:
        """What a reader of the capacity must know: past the peak the load rose above it (the load control
        stopped short of its peak, so the capacity is a lower bound, docs/loads.md)."""
        if self.descent_end != DescentEnd.ROSE:
            return ()
        highest = float(self.curve["multiplier"].max()) if "multiplier" in self.curve else math.nan
        return (
            f"past the peak the load rose to {highest:.4g} {self.unit}, above the capacity {self.capacity:.4g} "
            f"{self.unit}: the load control stopped short of its peak, so the capacity is in doubt (docs/loads.md)",
        )
