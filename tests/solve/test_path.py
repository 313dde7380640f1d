"""The equilibrium-path search with a fake arch: du bracketed from equilibrium states only."""

from __future__ import annotations

import math

import pytest

from yadearch.case.numerics_section import LEAST_BRACKET
from yadearch.solve.path import PathSettings, follow_path
from yadearch.solve.stages import Verdict


class FakeArch:
    """An arch that holds equilibrium up to `du`. Moves from its accepted state longer than
    `dynamic_reach` fail even below du (a dynamic overshoot); a state reached by a move longer than
    `creep_reach` is accepted still creeping, and every move from it fails until it is settled; a
    relaxation judges states up to `du + false_margin` stable, but those beyond du never settle."""

    at_rest_when_accepted = False  # its states may creep: a failure is tried again once settled

    def __init__(
        self,
        du: float,
        dynamic_reach: float = math.inf,
        verdict: str = Verdict.RUNAWAY,
        creep_reach: float = math.inf,
        false_margin: float = 0.0,
        start: float = 0.0,
    ):
        self.du, self.dynamic_reach, self.verdict = du, dynamic_reach, verdict
        self.creep_reach, self.false_margin = creep_reach, false_margin
        self.stack, self.reached, self.reached_from = [(start, True)], start, start
        self.tries: list[tuple[float, float]] = []

    @property
    def accepted(self) -> float:
        return self.stack[-1][0]

    def try_increment(self, target: float) -> str:
        self.tries.append((self.accepted, target))
        self.reached, self.reached_from = target, self.accepted
        if not self.stack[-1][1] or target > self.du + self.false_margin or target - self.accepted > self.dynamic_reach:
            return self.verdict
        return Verdict.STABLE

    def accept(self) -> None:
        assert self.reached <= self.du + self.false_margin
        self.stack.append((self.reached, self.reached - self.reached_from <= self.creep_reach))

    def settle(self) -> bool:
        if self.accepted > self.du:
            return False
        self.stack[-1] = (self.accepted, True)
        return True

    def discard(self) -> None:
        self.stack.pop()

    def resolve(self, target: float) -> str:
        return Verdict.TIMEOUT  # a slow failure stays as slow when followed further


SETTINGS = PathSettings(first_increment=2.0, max_increment=5.0, growth=1.5, tolerance=0.1, max_displacement=150.0)


@pytest.mark.parametrize("du", [0.35, 15.3, 88.29, 109.07])
def test_du_is_bracketed_within_the_tolerance(du):
    result = follow_path(FakeArch(du), SETTINGS)
    assert result.collapsed
    assert result.lower <= du < result.upper
    assert result.upper - result.lower <= SETTINGS.tolerance
    assert abs(result.du - du) <= SETTINGS.tolerance / 2


RELATIVE = PathSettings(
    first_increment=2.0, max_increment=5.0, growth=1.5, tolerance=0.1, max_displacement=150.0, relative_tolerance=0.005
)


@pytest.mark.parametrize("du", [0.013, 0.35, 2.07, 15.3, 88.29])
def test_a_relative_bracket_locates_a_short_du_as_finely_relative_as_a_long_one(du):
    result = follow_path(FakeArch(du), RELATIVE)
    assert result.lower <= du < result.upper
    width = result.upper - result.lower
    least = LEAST_BRACKET * RELATIVE.tolerance
    assert width <= max(RELATIVE.relative_tolerance * result.upper, least)
    assert width <= RELATIVE.tolerance
    assert abs(result.du - du) <= 0.5 * max(RELATIVE.relative_tolerance * du, least) * 1.01


def test_the_bracket_is_the_narrower_of_its_width_and_its_share_of_the_upper_end():
    assert RELATIVE.bracket(100.0) == RELATIVE.tolerance  # 0.5 % of 100 is wider than 0.1
    assert RELATIVE.bracket(2.0) == pytest.approx(0.01)
    assert RELATIVE.bracket(0.0) == pytest.approx(LEAST_BRACKET * RELATIVE.tolerance)  # never below that
    assert SETTINGS.bracket(2.0) == SETTINGS.tolerance  # no relative part: the width alone
    with pytest.raises(ValueError, match="relative_tolerance"):
        PathSettings(2.0, 5.0, 1.5, 0.1, 150.0, relative_tolerance=1.5)


def test_a_path_started_from_an_equilibrium_part_way_goes_on_from_there():
    """A scene put in a known equilibrium at 30 mm (a rigid analysis's state) is loaded from it:
    the first increment starts there, and a discarded state falls back to it, not to zero."""
    arch = FakeArch(31.0, false_margin=0.5, start=30.0)
    result = follow_path(arch, SETTINGS, start=30.0)
    assert arch.tries[0] == (30.0, 32.0)
    assert result.lower <= 31.0 < result.upper <= 31.0 + SETTINGS.tolerance
    assert all(e > 30.0 for e in result.equilibria)


def test_increments_grow_while_the_arch_follows_and_shrink_near_collapse():
    result = follow_path(FakeArch(88.29), SETTINGS)
    sizes = [s.target - s.start for s in result.steps]
    assert sizes[:3] == pytest.approx([2.0, 3.0, 4.5])
    assert max(sizes) == pytest.approx(5.0)
    assert sizes[-1] < SETTINGS.tolerance  # the last try is within the bracket
    assert len(result.steps) < 35  # 88 mm in 5 mm strides, then bisection


def test_the_failure_that_closes_the_bracket_comes_from_the_lower_state():
    """A long increment that fails dynamically at 20 mm though the arch holds to 30 mm must not
    end the search: the failure is retried from the last equilibrium state and the path goes on."""
    arch = FakeArch(30.0, dynamic_reach=1.0)
    result = follow_path(arch, SETTINGS)
    assert result.lower <= 30.0 < result.upper
    assert result.upper - result.lower <= SETTINGS.tolerance
    start, target = arch.tries[-1]
    assert target - start <= SETTINGS.tolerance  # the last failure was a short move


def test_a_state_accepted_while_creeping_is_settled_before_it_bounds_du():
    """Every move from a state reached by a 5 mm increment fails until that state is settled."""
    arch = FakeArch(88.29, creep_reach=3.0)
    result = follow_path(arch, SETTINGS)
    assert result.lower <= 88.29 < result.upper <= 88.29 + SETTINGS.tolerance


def test_a_state_that_never_comes_to_rest_is_discarded():
    """Relaxations judge states up to 0.5 mm past du stable; settling shows they are not."""
    arch = FakeArch(40.0, false_margin=0.5)
    result = follow_path(arch, SETTINGS)
    assert result.lower <= 40.0 < result.upper
    assert result.upper - result.lower <= SETTINGS.tolerance
    assert all(e <= 40.0 + 0.5 for e in result.equilibria) and result.equilibria[-1] <= 40.0


def test_timeouts_count_as_no_equilibrium_and_say_so():
    result = follow_path(FakeArch(40.0, verdict=Verdict.TIMEOUT), SETTINGS)
    assert result.lower <= 40.0 < result.upper
    assert result.upper_verdict == Verdict.TIMEOUT
    assert follow_path(FakeArch(40.0), SETTINGS).upper_verdict == Verdict.RUNAWAY
    assert follow_path(FakeArch(500.0), SETTINGS).upper_verdict is None


def test_a_state_that_ran_away_while_settling_bounds_du_as_a_runaway_whatever_an_earlier_try_said():
    """The DEM's pattern (pointed arch spreading, reports/atlas): a move to 62.094 mm timed out from a
    creeping state, succeeded once that state was settled, then the state at 62.094 ran away while
    settling. du's upper end is that runaway: a collapse, not the earlier try's timeout (unresolved)."""
    arch = FakeArch(40.0, verdict=Verdict.TIMEOUT, creep_reach=0.05, false_margin=0.05)
    result = follow_path(arch, SETTINGS)
    timed_out = [s for s in result.steps if s.target == result.upper and s.verdict == Verdict.TIMEOUT]
    accepted = [s for s in result.steps if s.target == result.upper and s.verdict == Verdict.STABLE]
    assert timed_out and accepted  # tried, timed out, then reached and accepted: it never settled
    assert result.upper_verdict == Verdict.RUNAWAY and result.collapsed
    assert result.lower <= 40.0 < result.upper <= 40.0 + SETTINGS.tolerance


class SlowFall(FakeArch):
    """Past du it runs away from a state accepted still creeping, but from the settled state it falls
    too slowly for the hold to see either (kn sweep at kn 0.2371, reports/kn-sweep)."""

    def try_increment(self, target: float) -> str:
        verdict = super().try_increment(target)
        if verdict != Verdict.STABLE and target > self.du:
            return Verdict.TIMEOUT if self.stack[-1][1] else Verdict.RUNAWAY
        return verdict


def test_a_runaway_seen_at_a_position_is_not_undone_by_a_slower_try_from_the_settled_state():
    arch = SlowFall(40.0, creep_reach=0.05)
    result = follow_path(arch, SETTINGS)
    tried = [s.verdict for s in result.steps if s.target == result.upper]
    assert Verdict.RUNAWAY in tried and tried[-1] == Verdict.TIMEOUT  # the retry only timed out
    assert result.collapsed and result.lower <= 40.0 < result.upper <= 40.0 + SETTINGS.tolerance


def test_a_slow_failure_followed_further_that_runs_away_is_a_collapse():
    class Followed(FakeArch):
        def resolve(self, target: float) -> str:
            return Verdict.RUNAWAY

    result = follow_path(Followed(40.0, verdict=Verdict.TIMEOUT), SETTINGS)
    assert result.collapsed and result.upper_verdict == Verdict.RUNAWAY
    assert result.lower <= 40.0 < result.upper <= 40.0 + SETTINGS.tolerance


def test_a_slow_snap_that_comes_to_rest_when_followed_further_is_survived():
    class SlowSnap(FakeArch):
        """Past 30 mm its relaxations time out (a slow snap) until one is followed to rest."""

        passed = False

        def try_increment(self, target: float) -> str:
            if target > 30.0 and not self.passed:
                self.tries.append((self.accepted, target))
                self.reached, self.reached_from = target, self.accepted
                return Verdict.TIMEOUT
            return super().try_increment(target)

        def resolve(self, target: float) -> str:
            self.passed = True
            return Verdict.STABLE

    arch = SlowSnap(40.0)
    result = follow_path(arch, SETTINGS)
    assert arch.passed and any(30.0 < e <= 30.2 for e in result.equilibria)  # accepted where it came to rest
    assert result.collapsed and result.lower <= 40.0 < result.upper <= 40.0 + SETTINGS.tolerance


def test_no_collapse_up_to_the_maximum_displacement():
    result = follow_path(FakeArch(500.0), SETTINGS)
    assert not result.collapsed and math.isinf(result.du)
    assert result.lower == SETTINGS.max_displacement
    assert result.equilibria[-1] == SETTINGS.max_displacement


def test_a_verdict_the_search_does_not_know_is_an_error():
    class Broken(FakeArch):
        def try_increment(self, target: float) -> str:
            return "maybe"

    with pytest.raises(ValueError, match="verdict"):
        follow_path(Broken(10.0), SETTINGS)
