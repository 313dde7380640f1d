"""Hinges of one state from the joint openings, in pure numpy.

A joint whose extrados opens pivots about its intrados: an I hinge; intrados open: an E hinge
(paper's labels: the side of the pivot). Adjacent joints open on the same side form one spread hinge,
reported by its interfaces and its peak.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np


@dataclass(frozen=True)
class Hinge:
    """One hinge: interfaces it spans (1-based), the peak interface, pivot side and peak opening (m)."""

    interfaces: tuple[int, ...]
    interface: int
    side: str
    opening: float

    def to_json(self) -> dict:
        data = asdict(self)
        data["interfaces"] = list(self.interfaces)
        data["opening_mm"] = self.opening * 1e3
        del data["opening"]
        return data


def hinges_at(opening_intrados: np.ndarray, opening_extrados: np.ndarray,
              threshold: float) -> list[Hinge]:
    """Hinges, left to right, of the joints whose larger opening exceeds `threshold` (m)."""
    sides: list[str | None] = []
    for gap_in, gap_ex in zip(opening_intrados, opening_extrados):
        if max(gap_in, gap_ex) <= threshold:
            sides.append(None)
        else:
            sides.append("E" if gap_in > gap_ex else "I")
    hinges: list[Hinge] = []
    k = 0
    while k < len(sides):
        side = sides[k]
        if side is None:
            k += 1
            continue
        end = k
        while end + 1 < len(sides) and sides[end + 1] == side:
            end += 1
        gaps = opening_intrados if side == "E" else opening_extrados
        members = range(k, end + 1)
        peak = max(members, key=lambda m: gaps[m])
        hinges.append(Hinge(tuple(m + 1 for m in members), peak + 1, side, float(gaps[peak])))
        k = end + 1
    return hinges
