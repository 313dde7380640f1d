"""Follow the equilibrium path of an arch under a support movement and bracket its collapse: pure
logic over an injected equilibrium oracle (YADE in a run, a fake in the tests).

The support advances by increments; each increment starts from the last equilibrium state and ends in
a relaxation that either finds equilibrium (the state is accepted and the increment grows) or does not
(the increment's end is an upper bound of du and the next increment is half the gap). Before the
bracket closes, its lower state is settled completely and the failure is tried again from there. du
is therefore bracketed by two states reached from the same settled equilibrium state, never from a
dynamic path (docs/numerics.md).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Protocol

import numpy as np

from yadearch.case.config import NumericsConfig
from yadearch.case.numerics_section import LEAST_BRACKET, SNAP_THICKNESS_RATIO
from yadearch.model import units
from yadearch.solve.stages import Outcome, Verdict


class EquilibriumOracle(Protocol):
    """Moves the support from the last accepted equilibrium state and relaxes the arch there."""

    at_rest_when_accepted: bool  # an accepted state is at rest already (a static equilibrium): settling
    # it changes nothing, and a failure tried from it stands without trying again

    def try_increment(self, target: float) -> Verdict:
        """Restore the last accepted state, move the support to `target`, relax: a Verdict."""

    def accept(self) -> None:
        """Make the state the last `try_increment` ended in (a stable one) the accepted state."""

    def settle(self) -> bool:
        """Relax the accepted state further (until it is at rest, or for a bounded time) and keep
        that as the accepted state; False if it runs away (it was not an equilibrium)."""

    def discard(self) -> None:
        """Drop the accepted state: the one accepted before it is the accepted state again."""

    def resolve(self, target: float) -> Verdict:
        """Go on with the failure at `target` that found neither equilibrium nor runaway, up to the
        oracle's budget: 'runaway', 'timeout', or 'stable' with that state live (then accepted)."""


@dataclass(frozen=True)
class PathSettings:
    """Increments of support displacement (any length unit, the oracle's): the first one, the
    largest one, the growth factor after an accepted increment, the bracket width that ends the
    search and the displacement at which the path stops without collapse."""

    first_increment: float
    max_increment: float
    growth: float
    tolerance: float
    max_displacement: float
    snap_ratio: float = SNAP_THICKNESS_RATIO  # a snap moves a block this x the ring's thickness off its branch
    relative_tolerance: float = 0.0  # the bracket at most this x its upper end too (0: `tolerance` alone)

    def __post_init__(self) -> None:
        if not 0 < self.tolerance < self.first_increment <= self.max_increment:
            raise ValueError("increments must satisfy 0 < tolerance < first <= max")
        if self.growth < 1.0:
            raise ValueError(f"growth must be >= 1, got {self.growth}")
        if not 0.0 <= self.relative_tolerance < 1.0:
            raise ValueError(f"relative_tolerance must be in [0, 1), got {self.relative_tolerance}")

    def bracket(self, upper: float) -> float:
        """The width that ends a search whose bracket's upper end is `upper` (du's, or a fold's): the
        narrower of `tolerance` and `relative_tolerance` x `upper`, so that a short du is located as
        finely, relative, as a long one; never below LEAST_BRACKET x `tolerance`."""
        if self.relative_tolerance <= 0.0:
            return self.tolerance
        return min(self.tolerance, max(self.relative_tolerance * abs(upper), LEAST_BRACKET * self.tolerance))


@dataclass(frozen=True)
class PathStep:
    """One increment tried: where it started and ended, and the relaxation's verdict."""

    start: float
    target: float
    verdict: str


@dataclass
class PathResult:
    """The bracket [lower, upper] of du (upper = inf: no collapse up to the maximum displacement)
    and every increment tried, in order."""

    lower: float = 0.0
    upper: float = math.inf
    upper_from: float = math.inf  # where the increment that failed at `upper` started
    steps: list[PathStep] = field(default_factory=list)
    equilibria: list[float] = field(default_factory=list)  # accepted displacements, in order
    failure: str | None = None  # how the arch failed at `upper` (None: read from `steps`)

    @property
    def failed(self) -> bool:
        """An increment failed at `upper`, whether by collapse or by a solver that did not converge."""
        return math.isfinite(self.upper)

    @property
    def collapsed(self) -> bool:
        """The path ended in a runaway at `upper`: no equilibrium there (du)."""
        return self.failed and self.upper_verdict == Verdict.RUNAWAY

    @property
    def unresolved(self) -> bool:
        """The path ended where the solver found neither an equilibrium nor a runaway, after its
        retries: a failure of the numerics, never a collapse (no du; `lower` is the last stable state)."""
        return self.failed and self.upper_verdict == Verdict.TIMEOUT

    @property
    def outcome(self) -> str:
        """How the path ended: Outcome.COLLAPSE, Outcome.UNRESOLVED or Outcome.STANDS."""
        if self.collapsed:
            return Outcome.COLLAPSE
        return Outcome.UNRESOLVED if self.unresolved else Outcome.STANDS

    @property
    def du(self) -> float:
        """The bracket's midpoint (inf without collapse)."""
        return 0.5 * (self.lower + self.upper) if self.collapsed else math.inf

    @property
    def upper_verdict(self) -> str | None:
        """How the arch failed at `upper`: Verdict.RUNAWAY (a block moved the runaway distance, or the state
        there ran away while settling, whatever an earlier increment to it said; a try from the settled
        lower state that only times out there does not undo a runaway seen there) or Verdict.TIMEOUT
        (no equilibrium nor runaway after the solver's retries); None if no increment failed."""
        if not self.failed:
            return None
        if self.failure is not None:
            return self.failure
        failed = (s.verdict for s in reversed(self.steps) if s.target == self.upper and s.verdict != Verdict.STABLE)
        return next(failed, Verdict.RUNAWAY)


def first_snap(snaps: list[dict]) -> tuple[float, float] | None:
    """The bracket (m) of the first snap on a path, from the engines' `snaps` records (each with its
    fold's bracket `fold_mm`, in path order): where the path first lost stability; None without one."""
    if not snaps:
        return None
    low, high = snaps[0]["fold_mm"]
    return units.mm(low), units.mm(high)


def extrapolate(lams: list[float], values: list[np.ndarray], target: float) -> np.ndarray:
    """The Lagrange polynomial through `values` at the distinct path positions `lams`, at `target`:
    where the path's last states put the next (a line through two, a parabola through three)."""
    weights = [
        math.prod((target - lams[m]) / (lams[k] - lams[m]) for m in range(len(lams)) if m != k)
        for k in range(len(lams))
    ]
    return np.asarray(sum(w * v for w, v in zip(weights, values)))


def path_settings(numerics: NumericsConfig, max_displacement_mm: float) -> PathSettings:
    """The increments of a case's numerics (mm) as PathSettings in metres, the path ending at
    `max_displacement_mm`: one reading for the DEM and the static engine."""
    mm = units.mm
    return PathSettings(
        first_increment=mm(numerics.first_increment_mm),
        max_increment=mm(max(numerics.max_increment_mm, numerics.first_increment_mm)),
        growth=numerics.increment_growth,
        tolerance=mm(numerics.du_tolerance_mm),
        max_displacement=mm(max_displacement_mm),
        snap_ratio=numerics.snap_thickness_ratio,
        relative_tolerance=numerics.du_tolerance_ratio,
    )


def bracket_text(numerics: NumericsConfig) -> str:
    """How narrow du's bracket ends, in a protocol's words (`PathSettings.bracket`)."""
    relative = f" and {100 * numerics.du_tolerance_ratio:g} % of its upper end" if numerics.du_tolerance_ratio else ""
    return f"narrowed to < {numerics.du_tolerance_mm} mm{relative}"


def follow_path(
    oracle: EquilibriumOracle,
    settings: PathSettings,
    on_step: Callable[[PathStep], None] | None = None,
    start: float = 0.0,
) -> PathResult:
    """Advance by increments from the equilibrium at `start` (the oracle's state; 0 after the
    self-weight) until the bracket of du is narrower than `settings.bracket` or the support
    reaches `settings.max_displacement` in equilibrium.

    The failure that closes the bracket must come from the bracket's own lower state, settled
    completely: a failure reached by a longer move, or from a state that was still creeping, is tried
    again from the settled state (near collapse, a state accepted while creeping by a few hundredths
    of a millimetre fails every move, where the same state at rest holds further); if the arch then
    holds, the path goes on. An oracle whose accepted states are at rest (`at_rest_when_accepted`)
    would only repeat the same failure: it is not tried again. A lower state that runs away while
    settling is discarded."""
    result = PathResult(lower=start)
    increment = settings.first_increment
    settled = False  # the accepted state has been settled completely
    firm_upper = math.inf  # the lowest discarded state: no equilibrium there, whatever the path
    resolved = math.nan  # where a slow failure was followed further (`EquilibriumOracle.resolve`)
    while True:
        narrow = result.upper - result.lower <= settings.bracket(result.upper)
        if narrow and (result.upper_from >= result.lower or result.upper >= firm_upper):
            if settled or not result.equilibria:
                if not result.unresolved or resolved == result.upper:
                    break
                resolved = result.upper  # a slow failure: followed further, once
                verdict = oracle.resolve(result.upper)
                if verdict == Verdict.RUNAWAY:
                    result.failure = Verdict.RUNAWAY
                if verdict != Verdict.STABLE:
                    break
                oracle.accept()  # it came to rest there: a snap survived, the path goes on from it
                result.equilibria.append(result.upper)
                result.lower = result.upper
                _reopen(result, firm_upper)
                settled, increment = False, 2.0 * settings.tolerance
                continue
            settled = True
            if oracle.settle():
                if result.upper < firm_upper and not oracle.at_rest_when_accepted:
                    result.upper_from = -math.inf  # try the failure again from the settled state
                continue
            oracle.discard()  # not an equilibrium: an upper bound, whatever the path
            firm_upper = result.equilibria.pop()
            result.lower = result.equilibria[-1] if result.equilibria else start
            result.upper, result.upper_from = firm_upper, result.lower
            result.failure = Verdict.RUNAWAY  # it ran away while settling, whatever an increment to it said
            settled = False
            continue
        if result.lower >= settings.max_displacement:
            break
        if narrow:
            target = result.upper
        elif result.failed:
            target = 0.5 * (result.lower + result.upper)
        else:
            target = min(result.lower + increment, settings.max_displacement)
        verdict = oracle.try_increment(target)
        if verdict not in tuple(Verdict):
            raise ValueError(f"oracle verdict must be one of {', '.join(Verdict)}, got {verdict!r}")
        step = PathStep(result.lower, target, verdict)
        result.steps.append(step)
        if on_step is not None:
            on_step(step)
        if verdict == Verdict.STABLE:
            oracle.accept()
            settled = False
            result.equilibria.append(target)
            if target >= result.upper:  # the retried failure holds: the path goes on from here
                _reopen(result, firm_upper)
                increment = 2.0 * settings.tolerance
            result.lower = target
            increment = min(increment * settings.growth, settings.max_increment)
        else:  # a runaway seen at this position stands against a slower try's timeout: no equilibrium there
            ran_away = target == result.upper and result.failure == Verdict.RUNAWAY
            result.upper, result.upper_from = target, result.lower
            result.failure = Verdict.RUNAWAY if ran_away else verdict
    return result


def _reopen(result: PathResult, firm_upper: float) -> None:
    """The path goes on past `result.upper`: its upper end is the lowest state that ran away while
    settling (a runaway, whatever the path), or none."""
    result.upper, result.upper_from = firm_upper, math.inf
    result.failure = Verdict.RUNAWAY if math.isfinite(firm_upper) else None
