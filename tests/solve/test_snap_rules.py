"""The rules a compliant march's snap obeys (`solve.snap_rules`), on hand-made chains and heights (no YADE)."""

from __future__ import annotations

from yadearch.solve.limit_lp import Mechanism
from yadearch.solve.rigid import Pivot
from yadearch.solve.snap_rules import climbs, moves_a_hinge

I, E = 0, 1
TIE_J = 5e-10  # the shallow arch's energy tie (1e-9 of its weight, 22.3 N, times its thickness, 24 mm)


def test_a_chain_that_climbs_a_barrier_and_returns_to_its_height_within_the_tie_does_not_snap():
    """Past a fold the chain may climb first, but must end lower: the shallow arch's hinge 39E moving
    to 40E at 66.0 mm climbs 2e-5 J and comes back 1.4e-10 J lower, round-off of one level, not a snap."""
    back_to_level = [0.0, 8e-6, 1.4e-5, 2e-5, 1.6e-5, 9e-6, -1.4e-10]
    assert climbs(back_to_level, past_fold=True, tie=TIE_J)
    assert not climbs(back_to_level, past_fold=True)  # without the tie, round-off decided it
    lower = [*back_to_level[:-1], -1.2e-9]  # 1 mm further on the support, the landing is lower
    assert not climbs(lower, past_fold=True, tie=TIE_J)


def test_a_rigid_snap_may_not_rise_by_more_than_the_tie():
    assert not climbs([0.0, -1e-6, -1e-6 + 1e-10, -2e-6], past_fold=False, tie=TIE_J)
    assert climbs([0.0, -1e-6, -1e-6 + 1e-8, -2e-6], past_fold=False, tie=TIE_J)


def test_a_chain_turning_back_two_hinges_moves_the_one_beside_its_new_hinge():
    """A fold at 40E beside hinge 39E opens a chain that turns back both extrados hinges (39E and
    56E): whichever closes first re-seats, so it moves a hinge (39E -> 40E); a new hinge further than
    the reach from every hinge it turns back does not."""
    hinges = (Pivot(0, I), Pivot(38, E), Pivot(55, E))
    chain = Mechanism((Pivot(0, I), Pivot(38, E), Pivot(39, E), Pivot(55, E)), (1.0,) * 4, -0.09, closing=(38, 55))
    assert moves_a_hinge(chain, hinges, reach=1)
    far = Mechanism((Pivot(0, I), Pivot(30, E), Pivot(38, E), Pivot(55, E)), (1.0,) * 4, -0.09, closing=(38, 55))
    assert not moves_a_hinge(far, hinges, reach=1) and moves_a_hinge(far, hinges, reach=8)
    assert not moves_a_hinge(Mechanism(chain.pivots, chain.rates, -0.09, closing=()), hinges, reach=56)
