"""The solver's cost against its floor (static.cost): the floor loop is cheaper than the solver and
the solver is within a small multiple of it on a small arch."""

from __future__ import annotations

from yadearch.case.config import preset
from yadearch.static.cost import solver_cost


def test_the_solver_costs_a_small_multiple_of_its_compiled_floor():
    cost = solver_cost(preset("set2").with_overrides({"engine": "static", "n_voussoirs": 15}), repeats=5)
    assert cost.evaluations > 0 and cost.evaluation_s > 0.0 and cost.solve_s >= 0.0
    assert 1.0 < cost.ratio < 50.0  # the solver does the floor's work and more (its decisions in Python)
