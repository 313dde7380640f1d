"""The capacity map's tables and figures, without YADE: du's components along the direction, the
moving support's reaction projected on its path, and the polar figure."""

import math

import pandas as pd
import pytest

from yadearch.plotting.capacity import capacity_polar_figure, reaction_curves_figure
from yadearch.studies.capacity.directions import (
    DIRECTIONS_DEG,
    RigidLimit,
    du_components,
    map_markdown,
    map_table,
    reaction_curve,
    with_rigid,
)


def test_the_directions_cover_the_half_plane_below_the_horizontal_every_15_degrees():
    assert DIRECTIONS_DEG[0] == 0.0 and DIRECTIONS_DEG[-1] == -180.0
    assert len(DIRECTIONS_DEG) == 13 and -90.0 in DIRECTIONS_DEG


@pytest.mark.parametrize(
    "direction, expected",
    [
        (0.0, (10.0, 0.0)),
        (-90.0, (0.0, -10.0)),
        (-45.0, (10 / math.sqrt(2), -10 / math.sqrt(2))),
        (-180.0, (-10.0, 0.0)),
    ],
)
def test_du_splits_into_its_horizontal_and_vertical_components(direction, expected):
    du_x, du_y = du_components(10.0, direction)
    assert du_x == pytest.approx(expected[0], abs=1e-9) and du_y == pytest.approx(expected[1], abs=1e-9)
    assert math.hypot(du_x, du_y) == pytest.approx(10.0, abs=1e-9)


def test_a_settling_support_carries_the_arch_s_weight_share_along_its_path_at_equilibrium_states():
    series = pd.DataFrame(
        {
            "stage": ["increment", "equilibrium", "equilibrium"],
            "delta_mm": [0.5, 1.0, 2.0],
            "right_Rx_N": [3.0, -5.0, -4.0],
            "right_Ry_N": [9.0, 15.0, 14.0],
        }
    )
    settlement = reaction_curve(series, -90.0)
    assert settlement["delta_mm"].tolist() == [1.0, 2.0]
    assert settlement["force_N"].tolist() == pytest.approx([15.0, 14.0])
    spreading = reaction_curve(series, 0.0)  # the arch's thrust pushes a spreading support outward
    assert spreading["force_N"].tolist() == pytest.approx([5.0, 4.0])


def _results() -> pd.DataFrame:
    return pd.DataFrame(
        {
            "support_direction_deg": [0.0, -90.0, -180.0],
            "du_mm": [20.0, 88.0, None],
            "du_first_mm": [15.0, 88.0, None],
            "status": ["done", "done", "failed"],
            "hinges": ["9I 29E 49I", "1E 9I 29E 56E", None],
            "mechanism": ["I-E-I", "E-I-E-E", None],
            "steps": [1, 2, 3],
            "wall_s": [1.0, 2.0, 3.0],
            "folder": ["a", "b", "c"],
        }
    )


RIGID = {
    0.0: RigidLimit(27.9, "9I 28E 47I 56E"),
    -90.0: RigidLimit(113.5, "1E 8I 32E 56E", 113.5, "1E 25I 49E 56E"),
    -180.0: RigidLimit(None, ""),
}


def test_the_map_puts_each_direction_beside_its_rigid_limit_and_keeps_failed_runs_visible():
    table = map_table("set2", _results(), RIGID)
    assert table["direction_deg"].tolist() == [0.0, -90.0, -180.0]
    settlement = table.iloc[1]
    assert settlement.du_y_mm == pytest.approx(-88.0) and settlement.du_x_mm == pytest.approx(0.0, abs=1e-9)
    assert settlement.du_over_rigid == pytest.approx(88.0 / 113.5)
    assert math.isnan(table.iloc[2].du_mm) and table.iloc[2].status == "failed"
    text = "\n".join(map_markdown(table))
    assert (
        "| -90 | 88.00 | 88.00 | (0.0, -88.0) | 1E 9I 29E 56E | 113.50 | 1E 8I 32E 56E | 113.50 | 1E 25I 49E 56E |"
        in text
    )
    assert "| -180 | - | - | - | - | - | - | - | - |" in text
    assert "| 0 | 15.00 | 20.00 | (20.0, 0.0) |" in text  # a snap survived: the first loss of stability before du


def test_the_rigid_columns_are_rewritten_without_the_runs(tmp_path):
    table = map_table("set2", _results(), RIGID)
    table.to_csv(tmp_path / "capacity.csv", index=False)
    changed = {**RIGID, 0.0: RigidLimit(30.0, "9I 28E 47I")}
    again = with_rigid(pd.read_csv(tmp_path / "capacity.csv"), changed)
    assert again["du_rigid_mm"].tolist()[:2] == [30.0, 113.5] and again.iloc[0].rigid_hinges == "9I 28E 47I"
    assert again.iloc[0].du_over_rigid == pytest.approx(20.0 / 30.0)
    assert again["du_mm"].tolist()[:2] == table["du_mm"].tolist()[:2] and list(again.columns) == list(table.columns)


def test_the_figures_are_written_as_pdf_and_png(tmp_path):
    table = pd.concat([map_table("set1", _results(), RIGID), map_table("set2", _results(), RIGID)])
    written = capacity_polar_figure(table, tmp_path / "map")
    curve = pd.DataFrame({"delta_mm": [1.0, 2.0], "force_N": [15.0, 14.0]})
    written += reaction_curves_figure({"set1": {-90.0: curve}, "set2": {0.0: curve}}, tmp_path / "reactions")
    assert sorted(p.name for p in written) == ["map.pdf", "map.png", "reactions.pdf", "reactions.png"]
    assert all(p.stat().st_size > 1000 for p in written)


def test_a_direction_the_rigid_analysis_cannot_follow_says_why(monkeypatch, tmp_path):
    """Four rigid directions of a shallow ring stood empty in capacity.csv with no word (seventh user
    trial): a failure is kept with its reason as the rigid mode, in the cache and in the table."""
    from yadearch.case.config import preset
    from yadearch.solve.rigid import LimitError
    from yadearch.studies.capacity import campaign

    def refuse(case):
        raise LimitError("kinematic LP failed at 0.000 mm: as a test says")

    monkeypatch.setattr(campaign, "limit_analysis", refuse)
    cache = tmp_path / "rigid.csv"
    limits = campaign.rigid_limits(preset("set2"), (-90.0,), cache, progress=False)
    assert limits[-90.0].du_mm is None
    assert limits[-90.0].mode == "failed: kinematic LP failed at 0.000 mm: as a test says"
    assert campaign.rigid_limits(preset("set2"), (-90.0,), cache, progress=False) == limits  # read back
