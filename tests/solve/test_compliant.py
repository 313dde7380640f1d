"""The compliant-hinge march (no YADE): below the rigid limit by a gap that falls as kn^(-1/3), on the
rigid collapse mechanism, and where the DEM of the same stiffness collapses (docs/validation.md)."""

from __future__ import annotations

import json

import pytest
from conftest import REPO

from yadearch.case.config import load_case, preset
from yadearch.solve.limit import limit_analysis
from yadearch.solve.rigid import LimitError

COARSE_45 = {"n_voussoirs": 15, "support_direction_deg": -45.0}
DEM_RUN = REPO / "reports/movements/validation-fine/paper_inclined45_kn3000_inc0.5"  # 0.5 mm increments
DEM_TOLERANCE = 0.01  # the march against a DEM run of the same stiffness (measured: 0.1-0.6 %)


def _du(overrides: dict, compliant: bool) -> tuple[float, tuple[str, ...]]:
    result = limit_analysis(preset("set2").with_overrides(overrides), mirror=False, compliant=compliant)
    return result.du_rigid_mm, result.collapse_hinges


@pytest.mark.xfail(
    reason="since the rigid march re-seats hinges (solve/reseat.py) the coarse -45 deg arch's rigid limit takes the "
    "keystone's other joint (8E) and ends at 41.20 mm through re-seatings the compliant march does not make "
    "(37.82 mm at kn 300, 39.39 at 19200): the premise is to be re-examined (issue 41)",
    strict=False,
)
def test_the_gap_to_the_rigid_limit_halves_with_eight_times_the_stiffness():
    """The fold margin goes as kn^(-1/3) and the rigid thrust reaches the edge linearly, so the gap
    between the compliant and the rigid limit halves for each factor 8 on kn, on the same mechanism."""
    rigid, rigid_hinges = _du(COARSE_45, compliant=False)
    gaps = []
    for kn in (300.0, 2400.0, 19200.0):
        du, hinges = _du({**COARSE_45, "kn_N_per_mm3": kn}, compliant=True)
        assert du < rigid and hinges == rigid_hinges
        gaps.append(rigid - du)
    assert gaps[1] / gaps[0] == pytest.approx(0.5, abs=0.03)
    assert gaps[2] / gaps[1] == pytest.approx(0.5, abs=0.03)


def test_the_march_collapses_where_the_dem_run_of_the_same_stiffness_does():
    """The paper arch moved 45 deg down and out with joints of kn 3000 N/mm^3: the DEM run (0.5 mm
    increments, committed under reports/) collapses at 37.97 mm on 8I 28E 46I, 7 % short of the rigid
    40.82 mm; the compliant march moves its hinges as that run does and collapses within 1 %."""
    summary = json.loads((DEM_RUN / "summary.json").read_text())
    overrides = {
        "support_direction_deg": -45.0,
        "kn_N_per_mm3": load_case(DEM_RUN / "case.toml").interface.kn_N_per_mm3,
    }
    result = limit_analysis(preset("set2").with_overrides(overrides), mirror=False, compliant=True)
    assert result.du_rigid_mm == pytest.approx(summary["du_mm"], rel=DEM_TOLERANCE)
    followed = {h.label for h in result.hinge_history if h.to_mm is None}
    dem = {f"{h['interface']}{h['side']}" for h in summary["hinges_last_equilibrium"]}
    assert followed == dem == {"8I", "28E", "46I"}
    assert result.compliant_kn_N_per_mm3 == 3000.0


def test_stiff_joints_collapse_at_the_compliant_limit_not_at_the_rigid_one(tmp_path):
    """The static engine (the DEM's blocks and joint law, no YADE) on a 15-voussoir arch at kn 300
    settles to the compliant march's du, short of rigid blocks, on the rigid mechanism. Measured: static
    104.95 mm, the DEM 104.71 (when this test ran it on YADE), compliant march 105.12, rigid 106.82, all
    on 3I 9E 16E."""
    from yadearch.static.simulate import simulate_static

    case = preset("set2").with_overrides({"n_voussoirs": 15, "kn_N_per_mm3": 300.0, "numerics.engine": "static"})
    compliant = limit_analysis(case, mirror=False, compliant=True).du_rigid_mm
    rigid = limit_analysis(case, mirror=False)
    summary = simulate_static(case, tmp_path / "run", log=lambda _line: None)
    du = summary.du_mm
    assert summary.collapsed and du == pytest.approx(compliant, rel=DEM_TOLERANCE)
    assert rigid.du_rigid_mm - du > 3 * abs(du - compliant)  # nearer the compliant limit than the rigid one
    followed = {h.label for h in rigid.hinge_history if h.to_mm is None}
    assert {f"{h['interface']}{h['side']}" for h in summary.hinges_last_equilibrium} == followed


def test_a_held_acceleration_ends_where_stiff_joints_fold_not_at_the_rigid_limit(tmp_path):
    """The paper's arch with 0.1 g held, settling: on the rigid march's last linkage joint 25's thrust
    comes within 0.02 mm of its extrados (measured 0.014 mm at 103 mm) and rigid blocks carry the
    settlement to 145.69 mm on 26E; joints of kn 100 000 fold there, and the compliant march and the
    static engine both collapse on 5I 25E 42I 56E, within 0.1 % of each other (135.82 and 135.80 mm when
    measured), 6.8 % short of rigid blocks."""
    from yadearch.static.simulate import simulate_static

    held = {"live_load": "horizontal_acceleration", "held_acceleration_g": 0.1}
    rigid = limit_analysis(preset("set2").with_overrides(held), mirror=False)
    assert rigid.closest_edge_joint == "25E" and rigid.closest_edge_mm < 0.02 and "26E" in rigid.collapse_hinges
    case = preset("set2").with_overrides({**held, "kn_N_per_mm3": 100_000.0, "numerics.engine": "static"})
    compliant = limit_analysis(case, mirror=False, compliant=True)
    summary = simulate_static(case, tmp_path / "run", log=lambda _line: None)
    assert summary.collapsed and compliant.du_rigid_mm == pytest.approx(summary.du_mm, rel=1e-3)
    assert (
        set(compliant.collapse_hinges) == {h.label for h in summary.hinges_at_collapse} == {"5I", "25E", "42I", "56E"}
    )
    assert summary.du_mm < 0.95 * rigid.du_rigid_mm


def test_a_fold_that_takes_a_hinge_far_is_a_snap_followed_to_its_landing(tmp_path):
    """A pointed arch (t/R 0.08) settling at kn 10 000: at 2.74 mm a joint beside hinge 33E folds and
    its chain takes the hinge to 24E, nine joints away; the march follows the snap to its landing and
    goes on (it counted a move of more than three joints as the collapse, at 2.74 mm), as the static
    engine does (a 0.3 mm snap at 2.7 mm, collapse at 5.02 mm; the march 5.14, measured)."""
    from yadearch.static.simulate import simulate_static

    pointed = {
        "shape": "pointed",
        "span_mm": 600.0,
        "pointed_radius_over_span": 1.0,
        "support_motion": "translation",
        "support_direction_deg": -90.0,
        "kn_N_per_mm3": 10_000.0,
        "numerics.engine": "static",
    }
    case = preset("set2").with_overrides(pointed)
    compliant = limit_analysis(case, mirror=False, compliant=True)
    summary = simulate_static(case, tmp_path / "run", log=lambda _line: None)
    (far,) = [s for s in compliant.snaps if "33E" in s.hinges_before.split() and "24E" in s.hinges_after.split()]
    assert far.at_mm < 0.6 * compliant.du_mm and far.largest_move_mm < case.geometry.thickness_mm  # survived
    static_folds = [s["fold_mm"] for s in summary.snaps]
    assert any(low - 0.1 < far.at_mm < high + 0.1 for low, high in static_folds), static_folds  # the same snap
    assert summary.collapsed and compliant.du_mm == pytest.approx(summary.du_mm, rel=0.03)


def test_joints_too_soft_for_the_arch_to_stand_give_no_compliant_du():
    """A semicircle 35 mm thick (t/R 0.11, near the least thickness that stands) does not stand on
    joints of kn 100 in the static engine; the compliant march, which folds only the joints beside its
    hinges, gave 2.02 mm there (seventh user trial). It now refuses in one line; at kn 10 000, where
    the static engine stands and collapses at 4.57 mm, it answers (4.73 mm; rigid 5.96)."""
    thin = preset("set2").with_overrides({"embrace_deg": 180.0, "thickness_mm": 35.0})
    with pytest.raises(LimitError, match="kn_N_per_mm3 = 100: the static engine finds .* does not stand.*too soft"):
        limit_analysis(thin.with_overrides({"kn_N_per_mm3": 100.0}), mirror=False, compliant=True)
    stiff = limit_analysis(thin.with_overrides({"kn_N_per_mm3": 10_000.0}), mirror=False, compliant=True)
    assert stiff.du_mm == pytest.approx(4.73, abs=0.01)


def test_a_fold_whose_chain_climbs_to_the_runaway_bound_holds_whatever_the_bound():
    """An elliptical arch (span 600, rise 200, t 75 mm) moved down and in at kn 10 000: at 63.40 mm the
    joint beside hinge 40I folds, and its chain climbs (the weights rise 0.2 J) until it closes hinge
    39 after a block has moved 37.9 mm, just past the default runaway bound (0.5 t, 37.5 mm). A chain
    that climbs cannot run away at a fixed support, so the fold holds and the march goes on to the
    same collapse with the bound at 0.5 and 1 ring thickness (it stopped at 63.40 mm at 0.5 t)."""
    elliptical = {
        "shape": "elliptical",
        "span_mm": 600.0,
        "rise_mm": 200.0,
        "thickness_mm": 75.0,
        "support_motion": "translation",
        "support_direction_deg": -135.0,
        "kn_N_per_mm3": 10_000.0,
    }
    case = preset("set2").with_overrides(elliptical)
    default = limit_analysis(case, mirror=False, compliant=True)
    doubled = limit_analysis(case, mirror=False, compliant=True, runaway_thicknesses=1.0)
    assert case.numerics.runaway_thickness_ratio == 0.5
    assert default.du_mm == pytest.approx(doubled.du_mm, rel=1e-6)
    assert default.du_mm > 100.0 and set(default.collapse_hinges) == set(doubled.collapse_hinges)


def test_a_shallow_arch_whose_hinges_walk_to_the_springing_collapses_where_the_static_engine_does(tmp_path):
    """The paper's arch cut to an embrace of 75 deg, settling at kn 1000: the intrados hinge walks to
    joint 2 while joint 1 holds its thrust a few micrometres from its corner, and the new crown hinge
    41E opens just before 1I folds. The fold's chain closes 41E first (it turns back 2I too); the march
    took that for a collapse at 29.58 mm. It lands there and goes on to collapse where the static
    engine of the same kn does (117.60 mm on 4I 39E 56E)."""
    from yadearch.static.simulate import simulate_static

    shallow = preset("set2").with_overrides({"embrace_deg": 75.0, "kn_N_per_mm3": 1000.0})
    compliant = limit_analysis(shallow, mirror=False, compliant=True)
    summary = simulate_static(shallow.with_overrides({"numerics.engine": "static"}), tmp_path / "run", log=print)
    assert summary.collapsed and compliant.du_mm == pytest.approx(summary.du_mm, rel=0.005)
    assert {h.label for h in summary.hinges_at_collapse} <= set(compliant.collapse_hinges)


def test_the_march_carries_the_static_engines_answer_and_warns_where_they_part(tmp_path, capsys):
    """The compliant march estimates the compliant model that the static engine solves: `limit
    --compliant` solves it too and says both. A semicircle 45 mm thick spreading at kn 100: the march
    28.40 mm, the static engine 24.40 mm on 1E 12I 28E 45I 56E, 16 % apart, which was not said
    (eighth user trial); the JSON keeps both answers."""
    from yadearch.cli.commands import main

    args = ["limit", "--preset", "set2", "--set", "embrace_deg=180", "--set", "thickness_mm=45"]
    args += ["--set", "movement=spreading", "--kn", "100", "--compliant", "--out", str(tmp_path), "--no-figures"]
    assert main(args) == 0
    out = capsys.readouterr().out
    assert "static engine (same blocks and joints): du = 24.40 mm on 1E 12I 28E 45I 56E" in out
    assert "warning: the compliant march is +16.4% from the static engine" in out
    saved = json.loads((tmp_path / "custom_compliant-kn100.json").read_text())
    assert saved["static_outcome"] == "collapse" and saved["static_du_mm"] == pytest.approx(24.40, abs=0.01)
    assert saved["du_mm"] == pytest.approx(28.40, abs=0.01)
    assert saved["warnings"][0].startswith("the compliant march is +16.4% from the static engine (24.40 mm)")


def test_a_notebook_sees_the_answer_and_its_warnings_in_a_few_lines():
    """`ya.limit(...)` in a notebook cell showed some 10 000 characters of joint forces and no warning
    where the march and the static engine part (ninth user trial); its repr is now the answer, the
    static engine's beside it and the warnings, every field still an attribute."""
    import yadearch as ya

    semicircle = {"embrace_deg": 180.0, "thickness_mm": 45.0, "support_direction_deg": 0.0, "kn_N_per_mm3": 100.0}
    result = ya.limit(preset("set2").with_overrides(semicircle), compliant=True, quiet=True)
    shown = repr(result)
    assert shown.splitlines()[0] == "LimitResult(set2, compliant march: du 28.40 mm, hinging on 1E 11I 28E 46I)"
    assert (
        "static engine beside it: collapse, du 24.40 mm" in shown and "warning: the compliant march is +16.4%" in shown
    )
    assert len(shown) < 600 and len(result.forces) == 56


def test_a_march_that_stops_says_the_static_engines_answer_on_the_same_joints(monkeypatch):
    """A compliant march that cannot follow the arch gives no du (the shallow arch at kn 100 stops at
    56.35 mm on 2I 3I 53E); its error now carries the static engine's answer on the same joints, which
    solves the model the march estimates. A rigid march's failure, and a refusal, are left as they are."""
    import yadearch as ya
    from yadearch.solve import limit
    from yadearch.solve.rigid import MarchStopped

    def stops(*args, **kwargs):
        raise MarchStopped("the march stopped at 56.354 mm")

    monkeypatch.setattr(limit, "limit_analysis", stops)
    with pytest.raises(
        MarchStopped,
        match=r"^the march stopped at 56.354 mm; static engine \(same blocks and joints\): "
        r"du = 87.99 mm on 1E 9I 29E 56E$",
    ):
        ya.limit(preset("set2"), compliant=True, quiet=True)
    with pytest.raises(MarchStopped, match=r"^the march stopped at 56.354 mm$"):
        ya.limit(preset("set2"), quiet=True)

    def refuses(*args, **kwargs):
        raise LimitError("the arch admits no equilibrium at rest")

    monkeypatch.setattr(limit, "limit_analysis", refuses)
    with pytest.raises(LimitError, match=r"^the arch admits no equilibrium at rest$"):
        ya.limit(preset("set2"), compliant=True, quiet=True)
