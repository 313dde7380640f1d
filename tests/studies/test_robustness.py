"""The robustness study's rows, comparisons and verdicts, on a results table built by hand."""

from __future__ import annotations

import pandas as pd
import pytest

from yadearch.case.config import preset
from yadearch.studies.robustness import VARIANTS, robustness_table, same_hinge_set, study_rows, verdicts


def test_rows_cover_every_kn_and_variant_and_name_them():
    rows = study_rows(preset("set2"), (0.1, 100.0))
    assert len(rows) == 2 * (len(VARIANTS) - 1)  # all but the path states the case reads already
    names = {r["run"] for r in rows}
    assert {"kn0.1_base", "kn100_timestep_x0.5", "kn100_rate_x2", "kn100_friction_80"} <= names
    small = next(r for r in rows if r["run"] == "kn0.1_timestep_x0.5")
    assert small["timestep_safety"] == 0.5 * preset("set2").numerics.timestep_safety
    slow = next(r for r in rows if r["run"] == "kn0.1_rate_x0.5")
    assert slow["support_rate_mm_per_s"] == 0.5 * preset("set2").numerics.support_rate_mm_per_s


def test_hinges_may_move_one_interface_not_two_nor_change_side():
    assert same_hinge_set("1E 9I 29E 56E", "1E 10I 28E 56E")
    assert not same_hinge_set("1E 9I 29E 56E", "1E 11I 29E 56E")
    assert not same_hinge_set("1E 9I 29E 56E", "1E 9E 29E 56E")
    assert not same_hinge_set("1E 9I 29E 56E", "9I 29E 56E")


def results(du: dict[str, float], hinges: dict[str, str], slip: float = 0.0) -> pd.DataFrame:
    return pd.DataFrame(
        [
            {
                "run": f"kn5.2_{v}",
                "kn_N_per_mm3": 5.2,
                "du_mm": d,
                "hinges": hinges.get(v, "1E 9I 29E 56E"),
                "max_slip_mm": slip,
                "max_friction_use": 0.3,
                "friction_interface": 1,
                "steps": 1000,
                "wall_s": 10.0,
                "status": "done",
            }
            for v, d in du.items()
        ]
    )


def test_a_numerical_variant_beyond_one_percent_fails_the_kn():
    du = {v: 88.0 for v in VARIANTS}
    assert verdicts(robustness_table(results(du, {})))["verdict"].tolist() == ["PASS"]
    du["damping_x2"] = 89.0  # +1.1 %
    assert verdicts(robustness_table(results(du, {})))["verdict"].tolist() == ["FAIL"]


def test_a_numerical_variant_that_moves_the_first_loss_of_stability_fails_the_kn():
    table = results({v: 88.0 for v in VARIANTS}, {}).assign(du_first_mm=60.0)
    assert verdicts(robustness_table(table))["verdict"].tolist() == ["PASS"]
    table.loc[table["run"] == "kn5.2_rate_x0.5", "du_first_mm"] = 61.0  # +1.7 %
    verdict = verdicts(robustness_table(table))
    assert verdict["verdict"].tolist() == ["FAIL"]
    assert verdict["du_first_spread"].iloc[0] > 0.01


def test_friction_may_move_du_only_where_a_joint_slides():
    du = {**{v: 88.0 for v in VARIANTS}, "friction_60": 95.0}
    assert verdicts(robustness_table(results(du, {}, slip=0.0)))["verdict"].tolist() == ["FAIL"]
    assert verdicts(robustness_table(results(du, {}, slip=0.5)))["verdict"].tolist() == ["PASS"]


def test_a_moved_hinge_fails_the_kn():
    du = {v: 88.0 for v in VARIANTS}
    table = robustness_table(results(du, {"timestep_x0.5": "1E 12I 29E 56E"}))
    assert not table.set_index("variant").loc["timestep_x0.5", "same_hinges"]
    assert verdicts(table)["verdict"].tolist() == ["FAIL"]


def test_the_static_engine_takes_only_the_variants_that_can_move_its_answer():
    """Time step, damping, rate and the DEM's equilibrium tolerance cannot move a static result: not
    run, so never reported as passing; the ramp keeps its halved first increment, which the static
    engine does read."""
    from yadearch.case.config import preset
    from yadearch.studies.robustness import study_rows

    static = {r["run"]: r for r in study_rows(preset("set2").with_overrides({"engine": "static"}), (5.2,))}
    assert set(static) == {
        f"kn5.2_{v}"
        for v in ("base", "increment_x0.5", "increment_x2", "runaway_x0.5", "runaway_x2", "ramp")
        + ("friction_60", "friction_80")
    }
    assert "support_acceleration_mm_per_s2" not in static["kn5.2_ramp"]
    assert len(study_rows(preset("set2"), (5.2,))) == len(VARIANTS) - 1  # the DEM takes all but one path reading


def test_the_path_states_variant_reads_the_path_the_other_way():
    """The DEM's path read at the holds' own states or at the static equilibria: the variant runs the
    reading the base case does not have; the one it has is named and not run."""
    scene = {r["run"] for r in study_rows(preset("set2").with_overrides({"support_path_states": "scene"}), (5.2,))}
    assert "kn5.2_path_states_static" in scene and "kn5.2_path_states_scene" not in scene
    static = preset("set2").with_overrides({"support_path_states": "static"})
    said: list[str] = []
    rows = {r["run"]: r for r in study_rows(static, (5.2,), log=said.append)}
    assert rows["kn5.2_path_states_scene"]["support_path_states"] == "scene" and "kn5.2_path_states_static" not in rows
    assert said == ["variant path_states_static: sets only what the case has already: not run"]
    auto = {r["run"] for r in study_rows(static.with_overrides({"support_path_states": "auto"}), (5.2,))}
    assert "kn5.2_path_states_scene" in auto and "kn5.2_path_states_static" not in auto  # auto reads static here
    said.clear()  # each dropped variant with its own reason
    rubble = preset("set2").with_overrides({"engine": "static", "friction_deg": 60.0})
    study_rows(rubble, (5.2,), ("damping_x2", "friction_60", "increment_x2"), log=said.append)
    assert said == [
        "variant damping_x2: only DEM numerics, which the static engine ignores; "
        "variant friction_60: sets only what the case has already: not run"
    ]


def test_variants_the_engine_ignores_are_named_and_a_study_of_none_is_refused():
    """Asked for DEM-only variants, the static study says which it drops, runs the others against
    base, and refuses in one line when nothing is left to test; base alone tests nothing."""
    from yadearch.case.config import preset
    from yadearch.errors import CampaignError
    from yadearch.studies.robustness import study_rows

    static = preset("set2").with_overrides({"engine": "static"})
    said: list[str] = []
    rows = study_rows(static, (5.2,), ("damping_x2", "increment_x2"), log=said.append)
    assert [r["run"] for r in rows] == ["kn5.2_base", "kn5.2_increment_x2"]
    assert said == ["variant damping_x2: only DEM numerics, which the static engine ignores: not run"]
    with pytest.raises(CampaignError, match=r"timestep_x0.5, damping_x2: only DEM numerics.*choose among"):
        study_rows(static, (5.2,), ("timestep_x0.5", "damping_x2"))
    du = {"base": 88.0}
    assert verdicts(robustness_table(results(du, {})))["verdict"].tolist() == ["NOT TESTED"]


def test_the_mechanism_is_compared_by_its_hinges_a_to_d_not_every_joint_open_at_runaway():
    """A longer runaway bound reads the collapse further past the fold, where more joints are open:
    the same mechanism (A-D within an interface) passes, hinge A two joints away does not."""
    du = {v: 88.0 for v in VARIANTS}
    table = results(du, {"runaway_x2": "1E 9I 23E 28E 39I 56E"})
    letters = {"hinge_A": 9, "hinge_B": 29, "hinge_C": 56, "hinge_D": 1}
    table = table.assign(**letters)
    table.loc[table["run"] == "kn5.2_runaway_x2", "hinge_B"] = 28
    assert verdicts(robustness_table(table))["verdict"].tolist() == ["PASS"]
    table.loc[table["run"] == "kn5.2_damping_x2", "hinge_A"] = 11
    assert verdicts(robustness_table(table))["verdict"].tolist() == ["FAIL"]
