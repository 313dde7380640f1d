"""The atlas's grid, table and report without running it: every shape and movement builds a case,
the three solvers' answers line up by run, and the targets are read on the right rows."""

from __future__ import annotations

import math
import re

import pandas as pd
import pytest

from yadearch.case.config import preset
from yadearch.case.numerics_section import SCENE_PATH_STATES, STATIC_PATH_STATES
from yadearch.solve.standing import stands
from yadearch.studies.atlas.grid import (
    KNS_N_PER_MM3,
    MOVEMENTS,
    SHAPES,
    THICKNESS_OVER_RADIUS,
    dem_rows,
    engine_base,
    geometries,
    static_rows,
)
from yadearch.studies.atlas.report import REPORT, atlas_markdown, write_atlas
from yadearch.studies.atlas.rigid import KEY, rigid_row
from yadearch.studies.atlas.table import atlas_table, gap_pct, nearest_branch_mm, rising, stored_engine
from yadearch.studies.campaigns.grid import RUN_COLUMN
from yadearch.studies.dem_settings import dem_arguments

STATIC_STATES = {"numerics.support_path_states": STATIC_PATH_STATES}  # a study's --dem-set


def test_the_grid_is_five_shapes_six_movements_three_thicknesses_four_stiffnesses():
    assert len(static_rows()) == len(SHAPES) * len(MOVEMENTS) * len(THICKNESS_OVER_RADIUS) * len(KNS_N_PER_MM3)
    assert len({r[RUN_COLUMN] for r in static_rows()}) == len(static_rows())  # names are unique
    assert len(dem_rows()) >= 40 and {r[RUN_COLUMN] for r in dem_rows()} <= {r[RUN_COLUMN] for r in static_rows()}


@pytest.mark.parametrize("geometry", geometries()[:: len(THICKNESS_OVER_RADIUS)], ids=lambda g: g.name)
def test_every_shape_and_movement_is_a_valid_case(geometry):
    case = preset("set2").with_overrides(geometry.overrides())
    assert case.geometry.thickness_mm == pytest.approx(geometry.thickness_mm)


def test_a_semicircle_thinner_than_its_rigid_minimum_cannot_stand_in_the_rigid_march():
    """t/R 0.08 is below the semicircle's rigid minimum (about 0.107, Heyman): the row says so."""
    thin = next(g for g in geometries() if g.shape == "semicircular" and g.thickness_over_radius == 0.08)
    assert not stands(preset("set2").with_overrides(thin.overrides()))
    assert rigid_row(preset("set2"), thin)["rigid_outcome"] == "cannot stand"


def test_the_nearest_rigid_branch_and_gaps():
    assert nearest_branch_mm(40.0, 50.0, 41.0) == 41.0
    assert nearest_branch_mm(40.0, 50.0, math.nan) == 50.0
    assert math.isnan(nearest_branch_mm(40.0, math.nan, math.nan))
    assert gap_pct(99.0, 100.0) == pytest.approx(-1.0)
    assert math.isnan(gap_pct(math.nan, 100.0))


def _synthetic() -> tuple[pd.DataFrame, pd.DataFrame, pd.DataFrame]:
    """Static results for every run (du rising to 0.99 x rigid), the rigid table, one DEM run."""
    rigid = pd.DataFrame(
        [
            {
                KEY: g.name,
                "rigid_outcome": "collapse",
                "rigid_du_mm": 50.0,
                "rigid_du_first_mm": 40.0,
                "rigid_hinges": "9I 28E 46I 56E",
                "rigid_other_du_mm": math.nan,
            }
            for g in geometries()
        ]
    )
    rows = []
    for g in geometries():
        for k, kn in enumerate(KNS_N_PER_MM3):
            rows.append(
                {
                    RUN_COLUMN: g.row(kn)[RUN_COLUMN],
                    "status": "done",
                    "outcome": "collapse",
                    "du_first_mm": 30.0 + k,
                    "du_mm": 49.5 - 3.0 * (len(KNS_N_PER_MM3) - 1 - k),
                    "collapse_kind": "four-hinge mechanism",
                    "hinges": "9I 28E 46I 56E",
                    "reason": "",
                }
            )
    static = pd.DataFrame(rows)
    first = dem_rows()[0][RUN_COLUMN]
    dem = static[static[RUN_COLUMN] == first].assign(du_mm=lambda t: t["du_mm"] * 1.02)
    return static, rigid, dem


def test_the_table_lines_up_the_three_solvers_and_reads_the_targets(tmp_path):
    static, rigid, dem = _synthetic()
    table = atlas_table(static, rigid, dem)
    assert len(table) == len(static_rows())
    stiff = table[table["kn_N_per_mm3"] == max(KNS_N_PER_MM3)]
    assert stiff["static_rigid_gap_pct"].to_numpy() == pytest.approx(-1.0)
    assert stiff["static_rigid_first_gap_pct"].to_numpy() == pytest.approx(-17.5)  # du_first 33 against 40 mm
    assert table["dem_static_gap_pct"].dropna().to_numpy() == pytest.approx([2.0])
    assert rising(table)["rises"].all()
    text = atlas_markdown(table)
    assert f"{len(geometries())} of {len(geometries())} arches where both collapse are within 2 %" in text
    assert "du within 1 % in 0" in text  # the one DEM run is 2 % off: listed
    n = len(geometries())
    assert f"or the collapse): 0 of {n} within 2 %, 0 of {n} within 10 %." in text
    write_atlas(tmp_path, tmp_path / "runs", static, rigid, dem)
    assert (tmp_path / "atlas.csv").is_file() and (tmp_path / "atlas.pdf").is_file()


def test_the_dem_column_of_a_written_table_makes_the_same_table_again(tmp_path):
    static, rigid, dem = _synthetic()
    write_atlas(tmp_path, tmp_path / "runs", static, rigid, dem)
    table = pd.read_csv(tmp_path / "atlas.csv")
    again = atlas_table(static, rigid, stored_engine(table, "dem"))
    dem_columns = [c for c in table.columns if c.startswith("dem_")]
    pd.testing.assert_frame_equal(again[dem_columns], table[dem_columns])
    assert again["dem_static_gap_pct"].dropna().to_numpy() == pytest.approx([2.0])


def test_a_stiff_gap_the_compliant_march_explains_is_said_to_be_compliance():
    """Static 3 % under rigid at the stiffest kn, and within 1 % of the compliant march there: the gap
    is listed with the compliant du beside it and counted as the joints' compliance."""
    static, rigid, dem = _synthetic()
    stiff = static[RUN_COLUMN].str.endswith(f"kn{max(KNS_N_PER_MM3):g}")
    static.loc[stiff, "du_mm"] = 48.5
    compliant = pd.DataFrame(
        [{KEY: g.name, "compliant_du_mm": 48.6, "compliant_other_du_mm": math.nan} for g in geometries()]
    )
    table = atlas_table(static, rigid, dem, compliant)
    text = atlas_markdown(table)
    assert f"Of the {len(geometries())} outside, {len(geometries())} are within 1 % of the compliant march" in text
    assert "| compliant du | gap to compliant |" in text


def test_the_static_answers_the_halved_increments_move_are_counted_listed_and_starred():
    static, rigid, dem = _synthetic()
    moved = static[RUN_COLUMN].iloc[0]
    static = static.assign(
        du_halved_increments_mm=static["du_mm"],
        du_first_halved_increments_mm=static["du_first_mm"],
        increments_resolved=True,
    )
    static.loc[static[RUN_COLUMN] == moved, ["du_halved_increments_mm", "increments_resolved"]] = [40.0, False]
    table = atlas_table(static, rigid, dem)
    text = atlas_markdown(table)
    assert f"of the {len(static)} with an answer" in text and f"{len(static) - 1} keep their outcome" in text
    assert "1 do not:" in text
    assert f"| {moved} | collapse | 40.50 | 40.00 |" in text  # listed with the halved du beside its own
    assert "40.50 (30.00)*" in text  # starred in the du table
    assert "The collapse mode changes its mechanism" not in text  # a table made before the mode's column
    other = static[RUN_COLUMN].iloc[1]
    static = static.assign(increments_mode_resolved=static[RUN_COLUMN] != other)
    assert f"The collapse mode changes its mechanism in 1: {other}." in atlas_markdown(atlas_table(static, rigid, dem))
    unchecked = atlas_markdown(atlas_table(_synthetic()[0], rigid, dem))
    assert "Not checked" in unchecked and not re.search(r"\d\*", unchecked)


def test_the_dem_campaigns_alone_take_the_study_dem_settings():
    assert (
        engine_base("dem", {}).to_dict()
        == preset("set2").with_overrides({"numerics.engine": "dem", "numerics.run_files": "summary"}).to_dict()
    )
    dem = engine_base("dem", {"support_rate_mm_per_s": 40.0}, STATIC_STATES)
    assert dem.numerics.support_path_states == STATIC_PATH_STATES and dem.numerics.support_rate_mm_per_s == 40.0
    assert dem.numerics.run_files == "summary"
    scene = engine_base("dem", {"support_path_states": SCENE_PATH_STATES})
    assert scene.numerics.support_path_states == SCENE_PATH_STATES  # --dem-static-states's own numerics, no settings
    static = engine_base("static", {"increments_check": "halved"}, STATIC_STATES)
    assert static.numerics.engine == "static"
    assert static.to_dict() == engine_base("static", {"increments_check": "halved"}).to_dict()


def test_the_report_names_the_dem_settings_in_its_command(tmp_path):
    static, rigid, dem = _synthetic()
    table = atlas_table(static, rigid, dem)
    assert "Regenerate: `.venv/bin/python scripts/atlas.py` (resumes" in atlas_markdown(table)
    arguments = dem_arguments(STATIC_STATES)
    assert f"Regenerate: `.venv/bin/python scripts/atlas.py{arguments}` (resumes" in atlas_markdown(table, arguments)
    write_atlas(tmp_path, tmp_path / "runs", static, rigid, dem, STATIC_STATES)
    assert "scripts/atlas.py --dem-set numerics.support_path_states=static`" in (tmp_path / REPORT).read_text()
