"""The residual capacity curve (`ya.residual_curve`, `yadearch loads --residual N`, issue 44 item 3):
the live load an arch carries after its support has moved part of the way to its du; at no
settlement it is the static load path's capacity, a settled arch carries less (but a small settlement
can raise a soft arch's capacity, below); bad counts are refused in one line."""

from __future__ import annotations

import pytest

import yadearch as ya
from yadearch.errors import CaseError

CASE = ya.preset("set2").replace(n_voussoirs=15, live_load="vertical")


def test_a_settled_arch_carries_less_and_the_curve_starts_at_the_load_paths_capacity(tmp_path):
    table = ya.residual_curve(CASE, 4, out=tmp_path)
    assert table["settlement_over_du"].tolist() == [0.0, 0.25, 0.5, 0.75]
    at_rest = ya.load_path(CASE, engine="static", descend_to=None)
    assert table["static_capacity"].iloc[0] == pytest.approx(at_rest.capacity, rel=1e-9)
    capacities = table["static_capacity"].to_numpy()
    assert (capacities[1:] < capacities[:-1]).all()  # each settlement takes some of the capacity away
    assert (table["static_first_loss"] <= table["static_capacity"] * (1 + 1e-12)).all()
    assert {p.name for p in tmp_path.iterdir()} == {"custom_residual.csv", "custom_residual.pdf", "custom_residual.png"}


@pytest.mark.parametrize("points", [0, 51, 2.5, True])
def test_a_count_outside_its_range_is_refused(points):
    with pytest.raises(CaseError, match=r"points must be an integer in \[1, 50\]"):
        ya.residual_curve(CASE, points)


def test_an_arch_without_a_live_load_is_refused():
    with pytest.raises(CaseError, match="loads.live_load is .none.: say which load grows"):
        ya.residual_curve(ya.preset("set2"), 2)


def test_an_arch_that_stands_to_the_end_of_its_movement_names_the_setting():
    """It said "does not carry its support movement to inf mm (collapse at 3172.45 mm)" (sixth user trial)."""
    with pytest.raises(CaseError, match=r"^loading.max_support_displacement_mm = 20: the arch stands to the end"):
        ya.residual_curve(CASE.replace(max_support_displacement_mm=20.0), 2)


def test_the_command_takes_a_joint_stiffness_and_says_each_settlement_as_it_is_made(tmp_path):
    """--residual runs the static engine: --kn is read without --engine static (it was refused)."""
    from click.testing import CliRunner

    from yadearch.cli.commands import cli

    options = ["--set", "n_voussoirs=15", "--set", "live_load=vertical", "--kn", "10", "--residual", "2"]
    result = CliRunner().invoke(cli, ["loads", "--preset", "set2", *options, "--out", str(tmp_path)])
    assert result.exit_code == 0, result.output
    said = result.output.splitlines()
    assert said[1].startswith("after   0.00 mm (0% of du): collapse") and said[2].startswith("after ")
    assert (tmp_path / "custom_residual.csv").is_file()  # a new arch is not filed as the paper's


FILLED = {"live_load": "vertical", "fill_depth_mm": 20.0, "fill_lateral_coefficient": 0.3}


def _capacity(after_mm: float, **overrides) -> float:
    case = ya.preset("set2").with_overrides({**FILLED, **overrides})
    return ya.load_path(case, engine="static", after_mm=after_mm, descend_to=None).capacity


def test_a_small_settlement_raises_a_soft_arch_capacity_where_it_recentres_the_loaded_joint():
    """Under 20 mm of fill a quarter-span load's static capacity rises with the first millimetres of
    settlement (19.86 -> 20.67 N after 5 mm at kn 5.2): the settlement moves the thrust at the loaded
    joint (18, which pivots on its extrados at collapse) away from that corner more than it brings
    the other three hinges' joints toward theirs. Mechanics of soft joints, not numerics: it fades
    as kn grows (none at kn 10 000), and the same settlement lowers the capacity of a load at the
    other quarter, whose joint it pushes toward its corner (docs/loads.md)."""
    left, right = 0.25, 0.75
    assert _capacity(5.0, load_position_over_span=left) > 1.03 * _capacity(0.0, load_position_over_span=left)
    assert _capacity(5.0, load_position_over_span=right) < 0.95 * _capacity(0.0, load_position_over_span=right)
    stiff = {"load_position_over_span": left, "kn_N_per_mm3": 10_000.0}
    assert _capacity(5.0, **stiff) < _capacity(0.0, **stiff)
