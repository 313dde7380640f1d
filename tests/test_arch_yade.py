"""A coarse arch on real YADE: equilibrium under self-weight, then three hinges under settlement."""

from __future__ import annotations

import pytest

from conftest import HAS_YADE, needs_yade
from yadearch import units
from yadearch.case import preset
from yadearch.yade_env import import_yade

pytestmark = [needs_yade, pytest.mark.yade]
if HAS_YADE:
    import_yade()

COARSE = {"n_voussoirs": 15, "kn_N_per_mm3": 0.25, "equilibrium_tolerance": 1e-4,
          "progress_every_s": 1e9}


@pytest.fixture(scope="module")
def settled():
    """A 15-voussoir version of the paper's arch after the self-weight stage."""
    from yadearch.runner import Runner

    runner = Runner(preset("set1").with_overrides(COARSE), log=lambda line: None)
    info = runner.selfweight()
    return runner, info


def test_self_weight_is_carried_by_the_supports(settled):
    runner, info = settled
    assert info["vertical_reaction_sum_N"] == pytest.approx(info["arch_weight_N"], rel=0.005)
    assert abs(info["horizontal_reaction_sum_N"]) < 0.005 * info["thrust_N"]  # equal, opposite thrusts
    # a no-tension arch of this shape pushes outwards: thrust between 0.2 and 0.6 of its weight
    assert 0.2 < info["thrust_N"] / info["arch_weight_N"] < 0.6


def test_settlement_opens_three_hinges_where_the_mechanism_puts_them(settled):
    runner, _ = settled
    runner.stage = "loading"
    runner.move_to(units.mm(8.0))
    assert runner.hold() == "stable"  # 8 mm is far from collapse: the arch follows the support
    _, hinges = runner.joint_snapshot()
    labels = [(h.interface, h.side) for h in hinges]
    n = 15
    assert len(hinges) == 3, labels
    a, b, c = hinges
    assert a.side == "I" and 2 <= a.interface <= n // 2  # A: intrados, left haunch
    assert b.side == "E" and n // 2 < b.interface < n + 1  # B: extrados, right of the crown
    assert (c.interface, c.side) == (n + 1, "E")  # C: extrados at the settling support
