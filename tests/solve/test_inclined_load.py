"""An inclined load on the extrados (loads.load_inclination_deg: a braking or raking force): a
symmetric arch mirrors a load leaning one way at one quarter into the other, stiff joints carry the
rigid capacity within 2 %, and no lean is the vertical load (the LP against the mechanisms by virtual
work: tests/solve/test_loads.py; the supports carrying it at every state: test_load_path.py)."""

from __future__ import annotations

import pytest

from yadearch.case.config import ArchCase, preset
from yadearch.case.plan import check_dem_load
from yadearch.cli.commands import main
from yadearch.errors import CaseError
from yadearch.solve.load_lp import load_analysis
from yadearch.solve.load_path import static_load_path
from yadearch.solve.rigid import rigid_arch

SMALL = {"n_voussoirs": 15, "live_load": "vertical", "load_position_over_span": 0.25}
HIGH_FRICTION = {"friction_deg": 80.0}  # the mechanism method knows no sliding
LEAN_DEG = 30.0
RIGID_TOLERANCE = 0.02  # stiff static within 2 % of the rigid capacity (issue 44)


def _case(lean_deg: float, **more) -> ArchCase:
    return preset("set2").with_overrides({**SMALL, "load_inclination_deg": lean_deg, **more})


def test_a_symmetric_arch_mirrors_a_leaning_load_and_no_lean_is_the_vertical_load():
    left = load_analysis(_case(LEAN_DEG))
    right = load_analysis(_case(-LEAN_DEG, load_position_over_span=0.75))
    assert left.multiplier == pytest.approx(right.multiplier, rel=1e-9)
    n = rigid_arch(_case(0.0)).n_joints
    assert {(n - 1 - p.joint, p.side) for p in left.pivots} == {(p.joint, p.side) for p in right.pivots}
    vertical = preset("set2").with_overrides(SMALL)
    assert load_analysis(_case(0.0)).multiplier == load_analysis(vertical).multiplier
    assert left.multiplier != pytest.approx(load_analysis(_case(-LEAN_DEG)).multiplier, rel=1e-3)  # it matters


def test_stiff_joints_carry_the_rigid_capacity_of_a_leaning_load():
    case = _case(LEAN_DEG).with_overrides({"interface.kn_N_per_mm3": 10_000.0})
    rigid = load_analysis(case)
    path = static_load_path(case)
    assert path.outcome == "collapse"
    assert -RIGID_TOLERANCE < path.capacity / rigid.multiplier - 1.0 < 0.0


def test_a_lean_beyond_the_horizontal_is_refused_in_one_line(capsys):
    assert main(["loads", "--preset", "set2", "--set", "live_load=vertical", "--set", "load_inclination_deg=95"]) != 0
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "load_inclination_deg" in err[0] and "95" in err[0]


def test_the_dem_takes_a_leaning_load_and_a_tandem_before_yade_starts():
    """The DEM's load path checks its case with the live load set apart (`case.plan.check_dem_load`):
    a lean and further loads pass, a further load that could never stand on the arch is refused there."""
    check_dem_load(_case(LEAN_DEG))
    check_dem_load(_case(0.0, further_loads=[[60.0, 1.0]]))
    with pytest.raises(CaseError, match="longer than the span"):
        check_dem_load(_case(0.0, further_loads=[[5000.0, 1.0]]))
