"""Backfill as dead loads (model/backfill.py) and spread loads' shapes (model/loads.py): the fill's
weight is the fill's volume above the extrados, its lateral thrust Rankine's K gamma H^2 / 2 on each
side; the rigid LP, the rigid march and the static engine carry it (supports balance weights, fill and
load; stiff joints within 2 % of rigid blocks); CGAL contacts refuse it in one line (the DEM: tests/dem)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from yadearch.case.config import preset
from yadearch.case.mechanics import arch_geometry, backfill, live_load
from yadearch.case.plan import plan_run
from yadearch.errors import CaseError
from yadearch.model.backfill import backfill_points, fill_surface
from yadearch.model.loads import FALLING, RISING, UNIFORM, _extrados_shares, extrados_segments, live_load_points
from yadearch.solve.limit import limit_analysis
from yadearch.solve.load_lp import load_analysis
from yadearch.solve.load_path import static_load_path
from yadearch.solve.static_path import StaticLoading
from yadearch.solve.statics import static_arch

FILL = {"fill_depth_mm": 50.0, "fill_lateral_coefficient": 0.3}
QUARTER = {"live_load": "vertical", "load_position_over_span": 0.25}


def _filled(**overrides):
    return preset("set2").with_overrides({**FILL, **overrides})


def test_the_fills_weight_is_its_volume_above_the_extrados_and_its_thrust_rankines():
    case = _filled()
    geometry = arch_geometry(case)
    fill = backfill(case)
    points = backfill_points(geometry, fill)
    surface = fill_surface(geometry, fill)
    # the region between the level surface and the extrados polyline, by the shoelace formula
    extrados = np.array([j.extrados[:2] for j in geometry.joints[:-1]] + [geometry.joints[-1].extrados[:2]])
    polygon = np.vstack([extrados, [extrados[-1, 0], surface], [extrados[0, 0], surface]])
    x, y = polygon[:, 0], polygon[:, 1]
    area = 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))
    assert -points.force[:, 1].sum() == pytest.approx(fill.unit_weight * geometry.depth * area, rel=1e-12)
    # horizontal pressure K gamma z on each side's vertical projection: K gamma d (H^2 - h_crown^2) / 2
    springing = surface - float(geometry.joints[0].extrados[1])
    crown = surface - max(float(j.extrados[1]) for j in geometry.joints)  # the fill's depth
    side = fill.lateral_coefficient * fill.unit_weight * geometry.depth * (springing**2 - crown**2) / 2.0
    left = points.force[points.point[:, 0] < 0.0, 0]
    right = points.force[points.point[:, 0] > 0.0, 0]
    assert (left >= 0.0).all() and (right <= 0.0).all()  # toward the arch from both sides
    assert left.sum() == pytest.approx(side, rel=1e-9) and -right.sum() == pytest.approx(side, rel=1e-9)


def test_an_acceleration_pushes_the_fill_by_its_weight_at_its_centroid():
    """Under a horizontal acceleration the fill the voussoirs carry moves with them (sixth user trial: its
    weight held the arch, its mass was not pushed, and 50 mm of fill raised set 2's capacity from 0.37 to
    1.78 g): 1 g pushes it by its weight, and the pushes' first moment is the fill region's (shoelace)."""
    case = _filled(live_load="horizontal_acceleration")
    geometry = arch_geometry(case)
    fill = backfill(case)
    surface = fill_surface(geometry, fill)
    extrados = np.array([j.extrados[:2] for j in geometry.joints[:-1]] + [geometry.joints[-1].extrados[:2]])
    polygon = np.vstack([extrados, [extrados[-1, 0], surface], [extrados[0, 0], surface]])
    x, y = polygon[:, 0], polygon[:, 1]
    cross = x * np.roll(y, -1) - np.roll(x, -1) * y
    area = 0.5 * cross.sum()
    centroid_y = ((y + np.roll(y, -1)) * cross).sum() / (6.0 * area)
    fill_weight = fill.unit_weight * geometry.depth * abs(area)
    rigid = static_arch(case)
    live = live_load_points(geometry, rigid.centroid0, rigid.weight, live_load(case, geometry))
    on_fill = np.arange(len(live.block)) >= len(rigid.weight) - 2  # after the voussoirs' own pushes
    assert live.force[:, 1] == pytest.approx(0.0) and live.force[:, 0].sum() == pytest.approx(
        rigid.weight[1:-1].sum() + fill_weight, rel=1e-12
    )
    pushed = live.force[on_fill, 0]
    assert (pushed @ live.point[on_fill, 1]) / pushed.sum() == pytest.approx(centroid_y, rel=1e-12)
    bare = load_analysis(preset("set2").with_overrides({"live_load": "horizontal_acceleration"})).multiplier
    assert load_analysis(case).multiplier < bare  # the fill's mass sits high on the ring


@pytest.mark.parametrize(("shape", "centre"), [(UNIFORM, 0.5), (RISING, 2.0 / 3.0), (FALLING, 1.0 / 3.0)])
def test_a_spread_load_keeps_its_size_and_puts_its_resultant_at_its_shapes_centroid(shape, centre):
    geometry = arch_geometry(preset("set2"))
    width, position = 0.2, 0.3
    shares = _extrados_shares(geometry, position, width, shape)
    total = sum(share for _, share, _ in shares)
    resultant = sum(share * point[0] for _, share, point in shares) / total
    origin = geometry.joints[0].intrados[0]
    assert total == pytest.approx(1.0, rel=1e-12)
    assert resultant == pytest.approx(origin + position - width / 2 + centre * width, abs=1e-12)
    assert len(shares) == sum(
        1 for _, a, b in extrados_segments(geometry) if b[0] > origin + 0.2 and a[0] < origin + 0.4
    )


def test_a_deeper_fill_carries_more_and_the_supports_carry_weight_fill_and_load():
    capacities = [load_analysis(_filled(**QUARTER, fill_depth_mm=d)).multiplier for d in (0.0, 20.0, 50.0, 100.0)]
    assert capacities == sorted(capacities) and capacities[-1] > 5.0 * capacities[0]
    loading = StaticLoading.of(_filled())
    loading.selfweight()
    state = loading.accepted[0]
    arch = loading.arch
    pressing = -state.forces.block_force[[0, -1]].sum(axis=0)
    assert pressing[1] == pytest.approx(arch.weight[1:-1].sum() - arch.dead[:, 1].sum(), rel=1e-9)
    assert abs(pressing[0]) < 1e-9 * pressing[1]  # the two sides' fill pressures balance


def test_stiff_joints_carry_the_rigid_capacity_of_a_filled_arch():
    """kn 100 000 N/mm3, fill 50 mm, K 0.3: the static path within 2 % of the rigid multiplier (the
    fill multiplies the quarter-span capacity by about five: 9.92 -> 49.0 N)."""
    case = _filled(**QUARTER, **{"interface.kn_N_per_mm3": 100_000.0})
    rigid = load_analysis(case).multiplier
    static = static_load_path(case)
    assert static.outcome == "collapse"
    assert -0.02 < static.capacity / rigid - 1.0 < 0.0
    assert math.isclose(static.rigid, rigid)


def test_the_rigid_march_carries_the_fill_at_every_state():
    """The rigid march under a settlement holds the fill's loads: at its last admissible state the
    supports carry the voussoirs' and the fill's weight."""
    case = _filled()
    result = limit_analysis(case, mirror=False)
    voussoirs = float(static_arch(case).weight[1:-1].sum())
    fill = -float(static_arch(case).dead[:, 1].sum())
    carried = result.reactions_N["left"][1] + result.reactions_N["right"][1]
    assert result.collapse_mode == "none"  # with K 0.3 the filled ring stands to the path's end (150 mm)
    assert math.isclose(carried, voussoirs + fill, rel_tol=1e-6)


def test_under_fill_the_rigid_linkage_hangs_on_a_joint_whose_thrust_grazes_its_corner(tmp_path):
    """50 mm of fill (K 0), settling: the thrust follows the extrados, so on the rigid march's path
    hinged at 41E joint 40 keeps its thrust within 0.03 mm of its extrados corner (measured 0.023 mm at
    10 mm); stiff joints hinge there instead, and the rigid linkage hinged at 40E stands to between 142
    and 143 mm, where the static engine at kn 100 000 collapses on 40E (142.13 mm measured), past the
    rigid march's 41E (139.11 mm): two linkages of one arch, not two answers of one."""
    from yadearch.solve.limit_lp import solve_statics
    from yadearch.solve.rigid import Pivot, at_rest, close_linkage, rigid_arch
    from yadearch.static.simulate import simulate_static

    case = _filled(fill_lateral_coefficient=0.0)
    rigid = limit_analysis(case, mirror=False)
    assert "41E" in rigid.collapse_hinges and rigid.closest_edge_joint == "40E" and rigid.closest_edge_mm < 0.03
    arch = rigid_arch(case)
    hinged_at_40 = (Pivot(6, 0), Pivot(39, 1), Pivot(55, 1))  # 7I 40E 56E

    def stands(at_mm: float) -> bool:
        placement = close_linkage(arch, at_rest(arch), hinged_at_40, at_mm / 1000.0)
        return placement is not None and solve_statics(arch, placement).feasible

    assert stands(142.0) and not stands(143.0)
    stiff = case.with_overrides({"interface.kn_N_per_mm3": 100_000.0, "numerics.engine": "static"})
    summary = simulate_static(stiff, tmp_path / "stiff", log=lambda _line: None)
    assert summary.collapsed and 142.0 < summary.du_mm < 143.0
    assert "40E" in {h.label for h in summary.hinges_at_collapse}


def test_who_does_not_take_backfill_says_so_in_one_line():
    with pytest.raises(CaseError, match="contact_model = 'cgal': backfill .* needs the joint elements"):
        plan_run(_filled(**{"numerics.contact_model": "cgal"}))
    with pytest.raises(CaseError, match="fill_depth_mm must be"):
        _filled(fill_depth_mm=-1.0)
    plan_run(_filled(**{"numerics.engine": "static"}))  # both engines take it with the joint elements
    plan_run(_filled())
