"""The atlas's invariance study (pure): each setting halved and doubled per arch, the largest move of
du and du_first named by its variant, and changed outcomes listed."""

from __future__ import annotations

import math

import pandas as pd

from yadearch.case.config import preset
from yadearch.studies.atlas.comparison import bracket_comparison, floor_comparison
from yadearch.studies.atlas.invariance import (
    BASE,
    REFINED,
    SETTINGS,
    invariance_markdown,
    invariance_rows,
    invariance_table,
    variants,
)


def test_every_setting_is_halved_and_doubled_beside_the_default():
    base = preset("set2")
    chosen = variants(base)
    assert len(chosen) == 1 + 2 * len(SETTINGS) + len(REFINED) and chosen[BASE] == {}
    assert chosen["increments_x0.5"] == {"first_increment_mm": 0.5, "max_increment_mm": 1.25}
    assert chosen["increments_x0.125"] == {"first_increment_mm": 0.125, "max_increment_mm": 0.3125}
    assert chosen["snap_floor_x2"] == {"snap_thickness_ratio": 0.02}
    relative = variants(base.with_overrides({"numerics.du_tolerance_ratio": 0.005}))
    assert relative["bracket_x0.5"] == {"du_tolerance_mm": 0.05, "du_tolerance_ratio": 0.0025}  # halved together
    rows = invariance_rows(base)
    assert len({r["run"] for r in rows}) == len(rows)


def results(du: dict[str, float], first: dict[str, float], outcome: dict[str, str]) -> pd.DataFrame:
    return pd.DataFrame(
        [
            {
                "run": f"arch-kn5.2-{v}",
                "kn_N_per_mm3": 5.2,
                "du_mm": du[v],
                "du_first_mm": first.get(v, first[BASE]),
                "outcome": outcome.get(v, "collapse"),
            }
            for v in du
        ]
    )


def test_the_largest_move_is_named_by_its_variant_and_a_changed_outcome_listed():
    du = {BASE: 100.0, "bracket_x2": 100.5, "runaway_x2": 100.2, "snap_floor_x0.5": 100.0, "increments_x2": math.nan}
    table = invariance_table(results(du, {BASE: 60.0, "snap_floor_x0.5": 40.0}, {"increments_x2": "stands"}))
    row = table.iloc[0]
    assert row["case"] == "arch-kn5.2" and row["du_mm_by"] == "bracket_x2"
    assert math.isclose(row["du_mm_spread"], 0.005)
    assert row["du_first_mm_by"] == "snap_floor_x0.5" and math.isclose(row["du_first_mm_spread"], 1 / 3)
    assert row["outcome_changed_by"] == "increments_x2"
    text = invariance_markdown(table)
    assert "du within 1 % under every variant: 1 of 1" in text
    assert "du_first within 1 %: 0 of 1" in text
    assert "| arch-kn5.2 | 100.00 | 0.50% | bracket_x2 | 60.00 | 33.33% | snap_floor_x0.5 |" in text


def test_a_collapse_of_another_kind_is_named_by_its_variant_and_counted_by_setting():
    du = {BASE: 100.0, "bracket_x2": 100.1, "runaway_x0.5": 100.0, "runaway_x2": 100.0, "increments_x2": math.nan}
    kinds = {"runaway_x0.5": "snap-through"}  # the others as the default; increments_x2 stands, not compared
    table = results(du, {BASE: 60.0}, {"increments_x2": "stands"})
    table["collapse_kind"] = [kinds.get(v, "four-hinge mechanism") for v in du]
    row = invariance_table(table).iloc[0]
    assert row["kind_changed_by"] == "runaway_x0.5"
    text = invariance_markdown(invariance_table(table))
    assert "- collapse kind changed by a variant: 1 of 1 (increments 0, bracket 0, runaway 1, snap_floor 0)." in text
    assert "collapse kind" not in invariance_markdown(invariance_table(results(du, {BASE: 60.0}, {})))


def test_other_hinges_are_named_by_their_variant_and_counted_by_their_largest_change():
    """A mirror image of the default's mechanism (a symmetric problem's tie) is told apart from a hinge
    a joint away and from another mechanism; a variant that stands is not compared."""
    du = {BASE: 100.0, "bracket_x2": 100.1, "increments_x2": 100.0, "runaway_x2": 100.0, "runaway_x0.5": math.nan}
    hinges = {BASE: "1E 12I 27E 44I", "bracket_x2": "13I 30E 45I 56E", "increments_x2": "1E 13I 27E 44I"}
    table = results(du, {BASE: 60.0}, {"runaway_x0.5": "stands"})
    table["hinges"] = [hinges.get(v, "1E 12I 27E 44I") for v in du]
    table["n_voussoirs"] = 55
    row = invariance_table(table).iloc[0]
    assert row["hinges_changed_by"] == "bracket_x2 (the mirror image) increments_x2 (a joint away)"
    text = invariance_markdown(invariance_table(table))
    assert (
        "- hinges at collapse changed by a variant: 1 of 1; at most to 0 the mirror image, 1 a joint away, "
        "0 another count, 0 another mechanism (`hinges_changed_by`)." in text
    )
    assert "hinges at collapse" not in invariance_markdown(invariance_table(results(du, {BASE: 60.0}, {})))
    unnumbered = table.drop(columns="n_voussoirs")  # the fill's arches (loads.passive_arches) hold no count
    assert "hinges at collapse" not in invariance_markdown(invariance_table(unnumbered))


def test_refined_increments_are_kept_apart_from_the_spread_and_compared_with_the_finest():
    du = {BASE: 100.0, "bracket_x2": 100.2, "increments_x0.25": 90.0, "increments_x0.125": 90.5}
    first = {BASE: 60.0, "increments_x0.25": 50.0, "increments_x0.125": 50.2}
    row = invariance_table(results(du, first, {})).iloc[0]
    assert row["du_mm_by"] == "bracket_x2" and math.isclose(row["du_mm_spread"], 0.002)  # refinement not in it
    assert math.isclose(row["du_first_mm_x0.125"], 50.2) and math.isclose(row["du_first_mm_from_finest"], 9.8 / 50.2)
    text = invariance_markdown(invariance_table(results(du, first, {})))
    assert (
        "- du_first: the default within 1 % of the increments x0.125 in 0 of 1; "
        "x0.25 and x0.125 within 1 % of each other in 1." in text
    )
    assert "| arch-kn5.2 | 100.00 | 60.00 | 50.00 | 50.20 | 19.52% |" in text


def test_a_refined_run_that_does_not_collapse_is_left_out_of_the_comparison():
    du = {BASE: 100.0, "increments_x0.25": 90.0, "increments_x0.125": math.nan}
    row = invariance_table(results(du, {BASE: 60.0}, {"increments_x0.125": "stands"})).iloc[0]
    assert math.isnan(row["du_first_mm_x0.125"]) and math.isnan(row["du_first_mm_from_finest"])
    assert row["outcome_changed_by"] == ""  # a refinement is not one of the halved and doubled settings
    assert row["outcome_refined_by"] == "increments_x0.125"


def collapses(cases: list[str], du: list[float], first: list[float], du_spread: list[float], first_spread: list[float]):
    """An invariance table of arches that all collapse: du, du_first and their spreads over the variants."""
    return pd.DataFrame(
        {
            "case": cases,
            "outcome": ["collapse"] * len(cases),
            "du_mm": du,
            "du_first_mm": first,
            "du_mm_spread": du_spread,
            "du_first_mm_spread": first_spread,
        }
    )


def test_a_study_with_another_snap_floor_is_compared_with_the_default_floors():
    """Three arches collapsing beyond 10 mm at both floors: du_first held under every variant in two at the
    lower floor (one at the default), earlier at the lower floor in one; a short collapse is left out."""

    def table(first: list[float], spread: list[float]) -> pd.DataFrame:
        du, du_spread = [50.0, 60.0, 70.0, 5.0], [0.0, 0.002, 0.0, 0.2]
        return collapses(["a", "b", "c", "short"], du, [*first, 5.0], du_spread, [*spread, 0.2])

    default = table([40.0, 60.0, 30.0], [0.5, 0.0, 0.3])
    lower = table([40.1, 20.0, 30.0], [0.0, 0.0, 0.3])
    text = "\n".join(floor_comparison(lower, default))
    assert "arches both floors collapse beyond 10 mm: 3; under every variant du within 1 % in 3 (3 at" in text
    assert "du_first in 2 (1)" in text
    assert "within 1 % in 2, earlier in 1 (a smaller snap counted), later in 0." in text
    assert "| b | 60.00 | 20.00 | 60.00 |" in text
    study = invariance_table(results({BASE: 100.0}, {BASE: 60.0}, {}))
    assert "Regenerate with `atlas.py --invariance --snap-floor 0.001`" in invariance_markdown(
        study, "atlas.py --invariance --snap-floor 0.001"
    )


def test_a_study_with_a_relative_bracket_is_compared_with_the_default_brackets():
    """Two short collapses whose du the default bracket moved beyond 1 % and the relative one holds, one
    long collapse that neither moves; the relative bracket's changes of the default answers listed."""

    def table(du: list[float], spread: list[float]) -> pd.DataFrame:
        return collapses(["short", "shorter", "long"], du, du, spread, spread)  # du_first = du

    default = table([1.52, 0.156, 60.0], [0.03, 0.2, 0.001])
    relative = table([1.47, 0.163, 60.0], [0.004, 0.003, 0.001])
    text = "\n".join(bracket_comparison(relative, default))
    assert "arches both collapse: 3; under every variant du within 1 % in 3 (1 with the default bracket)" in text
    assert "arches both collapse beyond 10 mm: 1; under every variant du within 1 % in 1 (1 with" in text
    assert "The default answers the relative bracket moves (2):" in text
    assert "| shorter | 0.163 | 0.156 | 0.163 | 0.156 |" in text and "| long |" not in text
