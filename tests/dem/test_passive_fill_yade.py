"""The fill's passive resistance in the DEM (dem/dead_load.py, model/passive_fill.py) against the static
engine's, the same blocks, joints and springs: a point load at 0.3 of the span of a 15-voussoir segmental
arch under 20 mm of fill (K 0.3, Kp 1, u_p 1 mm, kn 5.2 N/mm3). The passive push raises the capacity by
more than a third in both engines, which agree within 0.1 % (measured 0.002 %), and the supports carry
the voussoirs and the fill at the self-weight."""

from __future__ import annotations

import pytest
from conftest import needs_yade

from yadearch import api
from yadearch.solve.statics import static_arch
from yadearch.studies.loads.passive import passive_case

pytestmark = [needs_yade, pytest.mark.yade]

ENGINES_TOLERANCE = 0.001  # the DEM's capacity against the static engine's


def test_the_dem_carries_the_static_engines_capacity_with_the_fills_passive_push(tmp_path):
    case = passive_case("small", 1.0)
    static = api.load_path(case, descend_to=None, figures=False)
    dem = api.load_path(case, out=tmp_path, engine="dem", descend_to=None, figures=False)
    without = api.load_path(passive_case("small", 0.0), descend_to=None, figures=False)
    assert static.outcome == dem.outcome == "collapse"
    assert dem.capacity == pytest.approx(static.capacity, rel=ENGINES_TOLERANCE)
    assert static.capacity > 1.3 * without.capacity
    # the supports carry the voussoirs, their fill and the load at every state (the pushes are horizontal)
    arch = static_arch(case)
    carried = arch.weight[1:-1].sum() - arch.dead[:, 1].sum()
    balance = case.geometry.n_voussoirs * case.numerics.equilibrium_tolerance
    assert (abs((dem.curve["vertical_reactions_N"] - dem.curve["multiplier"]) / carried - 1.0) < balance).all()
