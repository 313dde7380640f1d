"""Live loads by rigid-block limit analysis (solve.load_lp): the linear programme's multiplier is the
least over the four-hinge mechanisms found by virtual work (solve.mechanisms, independent of it), the
reactions balance the loads at collapse, a symmetric arch gives mirrored answers, Milankovitch's
semicircle at its minimum thickness carries no acceleration, and bad loads are refused in one line."""

from __future__ import annotations

import math

import numpy as np
import pytest

from yadearch.case.config import ArchCase, preset
from yadearch.case.plan import plan_run
from yadearch.errors import CaseError
from yadearch.solve.limit_lp import weight_load
from yadearch.solve.load_lp import live_forces, load_analysis, load_capacity, residual_capacity
from yadearch.solve.mechanisms import mechanism_multiplier
from yadearch.solve.rigid import at_rest, rigid_arch

HIGH_FRICTION = {"friction_deg": 80.0}  # the mechanism method knows no sliding


def small(overrides: dict, **loads) -> ArchCase:
    return ArchCase(name="small").with_overrides({**HIGH_FRICTION, **overrides, **loads})


CASES = [
    small({"embrace_deg": 180.0, "n_voussoirs": 13, "thickness_mm": 40.0}, live_load="horizontal_acceleration"),
    small({"embrace_deg": 180.0, "n_voussoirs": 13, "thickness_mm": 80.0}, live_load="horizontal_acceleration"),
    small({"n_voussoirs": 15}, live_load="vertical", load_position_over_span=0.25),
    small({"n_voussoirs": 15}, live_load="vertical", load_position_over_span=0.4, load_width_mm=50.0),
    small({"n_voussoirs": 15}, live_load="vertical", load_inclination_deg=-30.0),  # leaning (a raking force)
    small({"n_voussoirs": 15}, live_load="vertical", load_inclination_deg=30.0),
    small({"n_voussoirs": 15}, live_load="vertical", further_loads=[[60.0, 1.0]]),  # a tandem axle
]
CASE_IDS = ["semicircle-t40-acc", "semicircle-t80-acc", "point-0.25", "spread", "lean-30", "lean+30", "tandem"]


@pytest.mark.parametrize("case", CASES, ids=CASE_IDS)
def test_the_lp_multiplier_is_the_least_mechanism_multiplier(case):
    arch = rigid_arch(case)
    live = live_forces(case, arch)
    dead = -weight_load(arch, at_rest(arch)).reshape(-1, 3)
    lp = load_capacity(arch, live)
    kinematic, pivots = mechanism_multiplier(arch, dead, live)
    assert lp.multiplier == pytest.approx(kinematic, rel=1e-9)
    assert lp.hinge_labels == " ".join(p.label for p in pivots)


def test_the_supports_carry_the_weight_and_the_load_at_collapse():
    case = small({"n_voussoirs": 15}, live_load="vertical", load_position_over_span=0.3)
    found = load_analysis(case)
    arch = rigid_arch(case)
    first, last = 0, arch.n_joints - 1  # the springing joints: their forces are the reactions
    vertical = sum(
        float(found.normal[j].sum() * arch.normal0[j, 1] + found.shear[j] * arch.normal0[j, 0]) * sign
        for j, sign in ((first, 1.0), (last, -1.0))
    )
    assert vertical == pytest.approx(arch.weight[1:-1].sum() + found.multiplier, rel=1e-6)


def test_a_mechanism_that_slides_names_its_sliding_joints_at_their_friction_cap():
    """At 10 degrees of friction the quarter-span load slides set 2 at joints 17 and 56 between two
    hinges (it said "on 18E 46I" alone: sixth user trial); with the paper's 41.2 degrees nothing slides."""
    sliding = load_analysis(preset("set2").with_overrides({"live_load": "vertical", "friction_deg": 10.0}))
    assert sliding.sliding == (17, 56) and sliding.hinge_labels == "18E 46I"
    for k in sliding.sliding:
        cap = math.tan(math.radians(10.0)) * sliding.normal[k - 1].sum()
        assert abs(sliding.shear[k - 1]) == pytest.approx(cap, rel=1e-6)
    assert load_analysis(preset("set2").with_overrides({"live_load": "vertical"})).sliding == ()


def test_a_symmetric_arch_mirrors_its_capacity():
    left = load_analysis(preset("set2").with_overrides({"live_load": "vertical", "load_position_over_span": 0.25}))
    right = load_analysis(preset("set2").with_overrides({"live_load": "vertical", "load_position_over_span": 0.75}))
    assert left.multiplier == pytest.approx(right.multiplier, rel=1e-9)
    n = rigid_arch(preset("set2")).n_joints
    assert {(n - 1 - p.joint, p.side) for p in left.pivots} == {(p.joint, p.side) for p in right.pivots}


def test_a_spread_load_is_carried_better_than_the_same_load_concentrated():
    point = load_analysis(preset("set2").with_overrides({"live_load": "vertical"}))
    spread = load_analysis(preset("set2").with_overrides({"live_load": "vertical", "load_width_mm": 200.0}))
    assert spread.multiplier > point.multiplier


def test_milankovitchs_semicircle_stands_on_its_minimum_and_carries_no_acceleration():
    # t / R >= 0.1075 for a semicircular arch under self-weight (R the centre-line radius)
    def semicircle(t_over_r: float) -> ArchCase:
        radius = 300.0
        thickness = 2.0 * radius * t_over_r / (2.0 - t_over_r)  # t / (radius + t/2) = t_over_r
        return small(
            {"embrace_deg": 180.0, "n_voussoirs": 101, "thickness_mm": thickness, "internal_radius_mm": radius},
            live_load="horizontal_acceleration",
        )

    assert 0.0 < load_analysis(semicircle(1.03 * 0.1075)).multiplier < 0.02
    assert math.isnan(load_analysis(semicircle(0.97 * 0.1075)).multiplier)


def test_the_minimum_thickness_of_a_semicircle_converges_to_milankovitchs_with_more_voussoirs():
    """Self-weight only, radial joints, no sliding: the least t/R (R the centre-line radius) at which
    the rigid LP finds an admissible equilibrium rises with the voussoir count (hinges only at joints)
    toward Milankovitch's 0.1075 for a continuous ring (as quoted by Makris and Alexakis 2013, Arch.
    Appl. Mech., doi:10.1007/s00419-013-0763-4); measured 0.10736 / 0.10746 / 0.10748 with 55 / 101 /
    201 voussoirs."""
    from yadearch.studies.loads.published import least_t_over_r

    least = [least_t_over_r(HIGH_FRICTION["friction_deg"], n) for n in (55, 101, 201)]
    assert least[0] < least[1] < least[2] < 0.1075
    assert least[2] == pytest.approx(0.1075, rel=5e-4)


def test_a_settled_rigid_arch_is_a_three_hinge_arch_with_little_capacity_left():
    case = preset("set2").with_overrides({"live_load": "vertical"})
    at_rest_capacity = load_analysis(case).multiplier
    settled = residual_capacity(case, 20.0)
    assert settled.multiplier < 0.2 * at_rest_capacity
    assert np.isfinite(settled.multiplier) and settled.multiplier > 0.0


def test_bad_loads_are_refused_in_one_line():
    with pytest.raises(CaseError, match="live_load"):
        load_analysis(preset("set2"))
    with pytest.raises(CaseError, match="load_position_over_span must be in"):
        preset("set2").with_overrides({"load_position_over_span": -0.1})
    with pytest.raises(CaseError, match="with nothing of it held"):
        plan_run(preset("set2").with_overrides({"live_load": "vertical"}))


def test_the_influence_line_is_symmetric_and_written(tmp_path):
    import yadearch as ya

    table = ya.load_influence(preset("set2"), 5, out=tmp_path)
    table = table[table["sampled"]]  # the critical positions refined between them aside
    assert table["position_over_span"].tolist() == pytest.approx([k / 6 for k in range(1, 6)])
    loads = table["collapse_load_N"].to_numpy()
    assert loads == pytest.approx(loads[::-1], rel=1e-9)  # a symmetric arch
    assert (tmp_path / "set2_influence.csv").is_file() and (tmp_path / "set2_influence.png").is_file()
    with pytest.raises(CaseError, match=r"positions must be an integer in \[2, 200\], got 1"):
        ya.load_influence(preset("set2"), 1)


def test_a_load_over_a_voussoir_is_the_load_at_its_extrados_middle():
    """load_voussoir k puts the load where its extrados's middle is: the same capacity as that
    position given as a fraction of the span; a voussoir the arch does not have is refused in one line."""
    from yadearch.case.mechanics import arch_geometry, load_position

    case = small({"n_voussoirs": 15}, live_load="vertical", load_voussoir=4)
    geometry = arch_geometry(case)
    at = load_position(case, geometry)
    joints = geometry.joints
    assert at == pytest.approx(0.5 * (joints[3].extrados[0] + joints[4].extrados[0]) - joints[0].intrados[0])
    same = case.with_overrides({"load_voussoir": 0, "load_position_over_span": at / geometry.span})
    assert load_analysis(case).multiplier == pytest.approx(load_analysis(same).multiplier, rel=1e-12)
    with pytest.raises(CaseError, match=r"loads.load_voussoir must be in \[0, 15\]"):
        load_analysis(case.with_overrides({"load_voussoir": 16}))


def test_the_influence_lines_least_is_said_at_every_position_that_ties_with_it(tmp_path, capsys):
    """A symmetric arch carries a load at mirror positions alike: the command names both critical
    positions (refined between the samples at 0.25 and 0.5, and 0.5 and 0.75), the first's hinges beside."""
    from yadearch.cli.commands import main

    args = ["loads", "--preset", "set2", "--set", "live_load=vertical", "--positions", "3", "--no-figures"]
    assert main([*args, "--out", str(tmp_path)]) == 0
    said = [line for line in capsys.readouterr().out.splitlines() if "influence line" in line]
    least = "least 8.557 N at 0.368 and 0.632 of the span (refined between the positions; 10I 23E 41I 56E at 0.368)"
    assert len(said) == 1 and least in said[0], said


def test_rigid_loads_name_the_case_settings_they_do_not_read(tmp_path):
    """A case file's joint stiffness, numerics and fill spring play no part in the rigid capacity:
    NAME_loads.json lists them (a command line's --set of them is refused), the answer unchanged."""
    import json

    from yadearch.api.live_loads import loads

    base = preset("set2").with_overrides(
        {"live_load": "vertical", "fill_depth_mm": 20.0, "fill_passive_coefficient": 3}
    )
    quiet = loads(base)
    told = loads(base.with_overrides({"kn_N_per_mm3": 100.0, "fill_passive_displacement_mm": 3.0}), out=tmp_path)
    written = json.loads((tmp_path / "set2_loads.json").read_text())
    assert written["unused"] == ["interface.kn_N_per_mm3", "loads.fill_passive_displacement_mm"]
    assert told.multiplier == quiet.multiplier


def test_the_answer_gives_the_fills_weight_the_sliding_joints_and_warns_of_the_models_values(tmp_path, capsys):
    """NAME_loads.json gives the fill's weight (the arch's alone was given) and the sliding joints; the
    command reads the load over arch and fill, and warns of a new arch's 1:10 model material."""
    import json

    from yadearch.case.mechanics import arch_geometry, backfill
    from yadearch.cli.commands import main
    from yadearch.model.backfill import backfill_points

    case = preset("set2").with_overrides({"live_load": "vertical", "fill_depth_mm": 20.0})
    fill = -backfill_points(arch_geometry(case), backfill(case)).force[:, 1].sum()
    args = ["loads", "--preset", "set2", "--set", "live_load=vertical", "--no-figures", "--out", str(tmp_path)]
    assert main([*args, "--set", "fill_depth_mm=20", "--set", "friction_deg=10"]) == 0
    written = json.loads((tmp_path / "set2_loads.json").read_text())
    assert written["fill_weight_N"] == pytest.approx(fill, rel=1e-12) and written["sliding_interfaces"]
    share = written["collapse_multiplier"] / (written["arch_weight_N"] + fill)
    assert f"{share:.3f} of arch and fill" in capsys.readouterr().out
    assert main([*args, "--set", "n_voussoirs=15"]) == 0
    said = capsys.readouterr().out.splitlines()
    assert said[-1].startswith("warning: this arch is not the paper's") and "interface." not in said[-1]


def test_a_capacity_in_newtons_is_also_said_per_metre_of_the_arch_width(tmp_path, capsys):
    """Bridge assessment quotes a line load per metre of width (RING, a kN/m axle line): the 1:10 arch's
    9.919 N over its 120 mm depth is 82.65 N/m; a bridge's hundreds of kN a metre read in kN/m."""
    from yadearch.cli.commands import main
    from yadearch.markdown import per_width

    rigid = load_analysis(preset("set2").with_overrides({"live_load": "vertical"}))
    assert per_width(rigid.multiplier, 120.0) == f"{rigid.multiplier / 0.12:.4g} N/m of width"
    assert per_width(412_500.0, 1000.0) == "412.5 kN/m of width"
    args = ["loads", "--preset", "set2", "--set", "live_load=vertical", "--no-figures", "--out", str(tmp_path)]
    assert main(args) == 0
    assert f"collapse at 9.919 N ({rigid.multiplier / 0.12:.4g} N/m of width; 0.315" in capsys.readouterr().out
