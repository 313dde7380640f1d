"""A live load's dispersal through the fill (pure numpy, SI): a vertical load standing on the fill's
surface reaches the extrados spread by the fill above it, as bridge assessment takes it (docs/loads.md,
"A load through the fill"). A unit point load above abscissa x, with the extrados `depth` below the
surface there, spreads either uniformly over x +- depth tan(angle) (the slope rule of the assessment
codes, 2 vertical to 1 horizontal: 26.57 deg) or as the vertical stress under a line load on an elastic
half-plane (Boussinesq's problem in plane strain, Flamant's solution, 2 P depth^3 / (pi r^4)) cut at
`angle` either side of the vertical and scaled back to the whole load. Each gives, for a stretch
[start, end] of the extrados, its share of the load and the abscissa of that share's resultant."""

from __future__ import annotations

import math
from dataclasses import dataclass

NONE, SPREAD, BOUSSINESQ = "none", "spread", "boussinesq"
DISPERSALS = (NONE, SPREAD, BOUSSINESQ)
STRIP_POINTS = 32  # a load spread over a width at the surface disperses as this many point loads


@dataclass(frozen=True)
class Dispersal:
    """How a load on the fill's surface reaches the extrados: the rule (`DISPERSALS`), its angle from the
    vertical (rad: the spread's slope, or where Boussinesq's stress is cut) and the surface's level (m)."""

    kind: str
    angle: float
    level: float


def dispersed_share(dispersal: Dispersal, x: float, depth: float, start: float, end: float) -> tuple[float, float]:
    """The share of a unit load on the surface above `x` that reaches the extrados between the abscissae
    `start` < `end`, `depth` below the surface, and the abscissa of that share's resultant (0 and x where
    none reaches it). Without depth the load stands on the extrados at x."""
    if depth <= 0.0:
        return (1.0, x) if start <= x <= end else (0.0, x)
    if dispersal.kind == SPREAD:
        reach = depth * math.tan(dispersal.angle)
        low, high = max(start, x - reach), min(end, x + reach)
        return ((high - low) / (2.0 * reach), 0.5 * (low + high)) if high > low else (0.0, x)
    low, high = (max(-dispersal.angle, min(dispersal.angle, math.atan((u - x) / depth))) for u in (start, end))
    if high <= low:
        return 0.0, x
    whole = _stress_integral(dispersal.angle) - _stress_integral(-dispersal.angle)
    part = _stress_integral(high) - _stress_integral(low)
    return part / whole, x + depth * (math.sin(high) ** 2 - math.sin(low) ** 2) / part


def _stress_integral(angle: float) -> float:
    """pi x the share of Flamant's vertical stress at a depth between the vertical under the load and the
    ray at `angle` from it (the stress is (2/pi) cos^2 of the ray's angle per radian of it)."""
    return angle + 0.5 * math.sin(2.0 * angle)
