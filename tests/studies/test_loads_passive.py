"""The passive-fill study (studies/loads/passive.py, reporting/loads_passive.py): a stiffer fill (a shorter
mobilisation u_p) carries more, below the rigid LP's capacity and above the arch without passive
resistance; the report counts the engines' agreement from its table, and each engine's largest move of
the settling arch's du under its numerics from that engine's own default."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from yadearch.reporting.loads_passive import grid_markdown, passive_markdown, settling_numerics_markdown
from yadearch.reporting.passive_arches import arches_markdown
from yadearch.solve.load_lp import load_analysis
from yadearch.solve.load_path import static_load_path
from yadearch.studies.loads.passive import mobilisation_table, passive_case
from yadearch.studies.loads.passive_arches import arches_verdicts


def test_a_stiffer_fill_carries_more_between_no_passive_push_and_the_rigid_capacity():
    table = mobilisation_table()
    capacities = table["static_N"].to_numpy()
    assert np.all(np.diff(capacities) < 0.0)  # u_p ascending: the capacity falls
    without = static_load_path(passive_case("paper", 0.0), descend_to=None).capacity
    assert without < capacities.min() and capacities.max() < table["rigid_N"].iloc[0]
    assert load_analysis(passive_case("paper", 0.0)).multiplier < table["rigid_N"].iloc[0]


def test_the_report_counts_the_engines_within_one_per_cent():
    capacities = pd.DataFrame(
        {
            "case": ["small_fill_kp1", "paper_fill_kp1"],
            "kp": [1.0, 1.0],
            "u_p_mm": [1.0, 1.0],
            "rigid_N": [10.0, 20.0],
            "rigid_hinges": ["1I", "2I"],
            "mechanism_N": [10.0, None],
            "stiff_static_N": [9.9, 19.0],
            "static_N": [8.0, 15.0],
            "static_first_loss_N": [8.0, 15.0],
            "static_hinges": ["1I", "2I"],
            "static_kind": ["four-hinge mechanism"] * 2,
            "dem_N": [8.05, 16.0],
            "dem_hinges": ["1I", "2I"],
            "dem_failure": ["", ""],
        }
    )
    numerics = pd.DataFrame(
        {
            "variant": ["default", "damping_x2"],
            "dem_N": [8.0, 8.04],
            "dem_held_N": [7.99, 8.03],
            "dem_hinges": ["1I"] * 2,
            "dem_failure": [""] * 2,
        }
    )
    numerics["relative_to_default"] = numerics["dem_N"] / 8.0 - 1.0
    mobilisation = pd.DataFrame({"u_p_mm": [1.0], "static_N": [15.0], "hinges": ["2I"], "rigid_N": [20.0]})
    settlement = pd.DataFrame(
        [
            {
                "case": "paper_settling_kp1",
                "kp": 1.0,
                "engine": "static",
                "outcome": "collapse",
                "du_mm": 49.87,
                "du_first_mm": 41.35,
                "hinges": "10E",
                "failure": "",
            }
        ]  # fmt: skip
    )
    text = passive_markdown(capacities, numerics, mobilisation, settlement)
    assert "Static and DEM within 1 % in 1 of 2 cases" in text
    assert "within 2 % of the rigid blocks in 1 of 2" in text
    assert "Largest move from the default: 0.50 %" in text and "(0.25 % of it wide" in text


def test_the_grid_report_counts_outcomes_and_names_each_error():
    grid = pd.DataFrame(
        [
            {"kp": 1.0, "u_p_mm": 1.0, "kn_N_per_mm3": 5.2, "test": "load", "outcome": "collapse", "error": ""},
            {"kp": 3.0, "u_p_mm": 1.0, "kn_N_per_mm3": 5.2, "test": "settlement", "outcome": "error", "error": "boom"},
        ]
    )
    text = grid_markdown(grid)
    assert "load collapse 1; settlement error 1; errors 1." in text
    assert "- settlement Kp 3 u_p 1 kn 5.2: boom" in text


def test_the_settling_numerics_are_measured_against_each_engines_own_default():
    """Each engine, and the DEM with each reading of its path's states, against its own default."""
    rows = [
        ("static", "", "default", 50.0, 40.0),
        ("static", "", "runaway_thickness_ratio x2", 50.2, 40.0),
        ("dem", "", "default", 52.0, 42.0),
        ("dem", "", "damping x0.5", 54.6, 54.6),
        ("dem", "static", "default", 52.0, 42.0),
        ("dem", "static", "damping x0.5", 52.1, 42.2),
    ]
    table = pd.DataFrame(
        [
            {"variant": v, "case": "c", "kp": 1.0, "engine": e, "outcome": "collapse", "du_mm": du,
             "du_first_mm": first, "hinges": "1I", "failure": "", "path_states": states}
            for e, states, v, du, first in rows
        ]
    )  # fmt: skip
    text = settling_numerics_markdown(table)
    assert "static du 0.40 % (a result); static du_first 0.00 % (a result); dem du 5.00 % (not a result)" in text
    assert "| dem | damping x0.5 | 54.600 | 5.00 % | 54.600 | 30.00 % | 1I |" in text
    assert "dem, static states du 0.19 % (a result); dem, static states du_first 0.48 % (a result)" in text


def test_each_other_arch_is_judged_against_its_own_default_and_a_changed_outcome_is_no_result():
    rows = [
        ("semi", 5.2, "base", "collapse", 50.0, 40.0),
        ("semi", 5.2, "increments_x0.5", "collapse", 50.4, 40.0),
        ("semi", 5.2, "snap_floor_x2", "collapse", 50.0, 48.0),
        ("semi", 5.2, "increments_x0.125", "collapse", 60.0, 40.0),  # a refinement: reported, not a variant
        ("semi", 1e4, "base", "collapse", 60.0, 30.0),
        ("semi", 1e4, "bracket_x2", "unresolved", 60.1, 30.1),
    ]
    table = pd.DataFrame(
        [{"arch": a, "kn_N_per_mm3": kn, "variant": v, "outcome": o, "du_mm": du, "du_first_mm": first}
         for a, kn, v, o, du, first in rows]
    )  # fmt: skip
    verdicts = arches_verdicts(table)
    soft, stiff = verdicts.iloc[0], verdicts.iloc[1]
    assert soft["du_mm_spread"] == pytest.approx(0.008) and soft["du_mm_by"] == "increments_x0.5"
    assert soft["du_first_mm_spread"] == pytest.approx(0.2) and soft["du_first_mm_by"] == "snap_floor_x2"
    assert soft["du_mm_x0.125"] == 60.0 and stiff["outcome_changed_by"] == "bracket_x2"
    text = arches_markdown(verdicts)
    assert "du in 1 of 2, du_first in 0 of 2" in text  # the stiff arch moves 0.33 % but one variant ends otherwise
    assert (
        "| semi (kn 5.2) | collapse | 50.00 | 0.80 % (increments_x0.5) | 60.00 | 40.00 | 20.00 % (snap_floor_x2) |"
        in text
    )


def test_the_other_arches_campaign_is_kept_and_read_back_and_its_halved_increments_agree(tmp_path, monkeypatch):
    import yadearch.studies.loads.passive_arches as arches
    from yadearch.studies.atlas.invariance import variants

    monkeypatch.setattr(arches, "ARCHES", {"paper, left support settling": {"moving_support": "left"}})
    monkeypatch.setattr(arches, "ARCHES_KN", (5.2,))
    chosen = {"base": {}, "increments_x0.5": {}}
    monkeypatch.setattr(arches, "variants", lambda case: {v: variants(case)[v] for v in chosen})
    table = arches.arches_numerics_table(tmp_path / "arches", jobs=1)
    assert list(table["variant"]) == list(chosen) and set(table["outcome"]) == {"collapse"}
    assert table["du_mm"].iloc[1] == pytest.approx(table["du_mm"].iloc[0], rel=0.01)  # 56.27 and 56.32 mm measured
    assert any((tmp_path / "arches").rglob("*.jsonl"))  # the lean campaign's batches: a rerun reads them back
    pd.testing.assert_frame_equal(arches.arches_numerics_table(tmp_path / "arches", jobs=1), table)
