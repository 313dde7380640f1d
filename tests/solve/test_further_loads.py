"""Further loads that go with the live load (loads.further_loads: a tandem or tridem axle): a second
load on the first is the first doubled (the capacity halves, the LP being linear in the load), a
symmetric arch mirrors a tandem, one beyond a springing stands on the support, and bad rows are refused
in one line (the LP against the mechanisms by virtual work: tests/solve/test_loads.py; the supports
carrying every load at every state: test_load_path.py)."""

from __future__ import annotations

import pytest

from yadearch.case.config import ArchCase, preset
from yadearch.case.plan import plan_run
from yadearch.cli.commands import main
from yadearch.errors import CaseError
from yadearch.solve.load_lp import load_analysis

SMALL = {"n_voussoirs": 15, "live_load": "vertical", "load_position_over_span": 0.25}
TANDEM = [[60.0, 1.0]]  # a second equal load 60 mm to the right (a 1:10 axle pair)


def _case(further: list, **more) -> ArchCase:
    return preset("set2").with_overrides({**SMALL, "further_loads": further, **more})


def test_a_second_load_on_the_first_halves_the_capacity():
    single = load_analysis(_case([]))
    doubled = load_analysis(_case([[0.0, 1.0]]))
    assert doubled.multiplier == pytest.approx(single.multiplier / 2.0, rel=1e-9)
    assert doubled.hinge_labels == single.hinge_labels


def test_a_symmetric_arch_mirrors_a_tandem():
    left = load_analysis(_case(TANDEM))
    right = load_analysis(_case([[-60.0, 1.0]], load_position_over_span=0.75))
    assert left.multiplier == pytest.approx(right.multiplier, rel=1e-9)


def test_a_ratio_out_of_range_is_refused_in_one_line(capsys):
    args = ["loads", "--preset", "set2", "--set", "live_load=vertical", "--set", "further_loads=[[60, 0]]"]
    assert main(args) != 0
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "further_loads row 1" in err[0] and "(0, 100]" in err[0]


def test_a_further_load_that_could_never_stand_on_the_arch_or_beside_an_acceleration_is_refused(tmp_path):
    static = {"numerics.engine": "static"}
    with pytest.raises(CaseError, match=r"further_loads row 1: offset_mm 5000 is longer than the span"):
        plan_run(_case([[5000.0, 1.0]], **static))
    with pytest.raises(CaseError, match="read with loads.live_load = 'vertical' only"):
        plan_run(_case(TANDEM, live_load="horizontal_acceleration", **static))


def test_an_influence_line_moves_a_tandem_across_the_span_its_second_load_onto_the_support():
    """Near the right springing the second load stands beyond it, on the support: the first alone is
    carried there (its capacity the single load's), and the influence line runs to the end."""
    near_end = _case([[60.0, 1.0]], load_position_over_span=0.95)
    alone = preset("set2").with_overrides({**SMALL, "load_position_over_span": 0.95})
    assert load_analysis(near_end).multiplier == pytest.approx(load_analysis(alone).multiplier, rel=1e-9)
