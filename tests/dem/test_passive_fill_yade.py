"""The fill's passive resistance in the DEM (dem/dead_load.py, model/passive_fill.py) against the static
engine's, the same blocks, joints and springs: a point load at 0.3 of the span of a 15-voussoir segmental
arch under 20 mm of fill (K 0.3, Kp 1, u_p 1 mm, kn 5.2 N/mm3). The passive push raises the capacity by
more than a third in both engines, which agree within 0.1 % (measured 0.002 %), and the supports carry
the voussoirs and the fill at the self-weight. Settling under its fill with a short mobilisation (u_p
0.1 mm), the same arch sways into the fill and back: its faces yield the fill for good in both engines,
which agree on du within 1 %, where springs that forgot their yielding would give 22 % less."""

from __future__ import annotations

import pytest
from conftest import needs_yade

from yadearch import api
from yadearch.solve.statics import StaticArch, static_arch
from yadearch.static.simulate import simulate_static
from yadearch.studies.loads.passive import passive_case

pytestmark = [needs_yade, pytest.mark.yade]

ENGINES_TOLERANCE = 0.001  # the DEM's capacity against the static engine's
SETTLING_TOLERANCE = 0.01  # the DEM's du against the static engine's (issue 41's 1 %)


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


def test_the_dem_settling_under_its_fill_yields_it_for_good_as_the_static_engine_does(tmp_path, monkeypatch):
    case = passive_case("small", 1.0, live_load="none", fill_passive_displacement_mm=0.1, name="settling")
    static = api.run(case, out=tmp_path / "static", engine="static", figures=False, quiet=True).summary
    dem = api.run(case, out=tmp_path / "dem", engine="dem", figures=False, quiet=True).summary
    assert static.path_outcome == dem.path_outcome == "collapse"
    assert dem.du_mm == pytest.approx(static.du_mm, rel=SETTLING_TOLERANCE)
    forget = lambda arch, springs, u: arch.springs_or_unyielded(springs)  # noqa: E731 springs that never yield
    monkeypatch.setattr(StaticArch, "yielded", forget)
    forgetful = simulate_static(case.with_overrides({"numerics.engine": "static"}), None, log=lambda _line: None)
    assert forgetful.du_mm < 0.85 * dem.du_mm
