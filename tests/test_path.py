"""The equilibrium-path search with a fake arch: du bracketed from equilibrium states only."""

from __future__ import annotations

import math

import pytest

from yadearch.solve.path import RUNAWAY, STABLE, TIMEOUT, PathSettings, follow_path


class FakeArch:
    """An arch that holds equilibrium up to `du`; moves from its accepted state longer than
    `dynamic_reach` fail even below du (a dynamic overshoot), like a long increment across a
    change of mechanism."""

    def __init__(self, du: float, dynamic_reach: float = math.inf, verdict: str = RUNAWAY):
        self.du, self.dynamic_reach, self.verdict = du, dynamic_reach, verdict
        self.accepted, self.reached = 0.0, 0.0
        self.tries: list[tuple[float, float]] = []

    def try_increment(self, target: float) -> str:
        self.tries.append((self.accepted, target))
        self.reached = target
        if target > self.du or target - self.accepted > self.dynamic_reach:
            return self.verdict
        return STABLE

    def accept(self) -> None:
        assert self.reached <= self.du  # only equilibrium states are ever accepted
        self.accepted = self.reached


SETTINGS = PathSettings(first_increment=2.0, max_increment=5.0, growth=1.5, tolerance=0.1,
                        max_displacement=150.0)


@pytest.mark.parametrize("du", [0.35, 15.3, 88.29, 109.07])
def test_du_is_bracketed_within_the_tolerance(du):
    result = follow_path(FakeArch(du), SETTINGS)
    assert result.collapsed
    assert result.lower <= du < result.upper
    assert result.upper - result.lower <= SETTINGS.tolerance
    assert abs(result.du - du) <= SETTINGS.tolerance / 2


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


def test_timeouts_count_as_no_equilibrium():
    result = follow_path(FakeArch(40.0, verdict=TIMEOUT), SETTINGS)
    assert result.lower <= 40.0 < result.upper


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
