"""Calibration of kn on cheap monotone stand-in models du(kn): convergence, run counts, refusals."""

from __future__ import annotations

import json
import math

import pytest

from yadearch.errors import YadearchError
from yadearch.studies.calibration import calibrate, function_evaluator


def sigmoid(kn: float) -> float:
    """du rising from 30 mm (soft joints) to 100 mm (rigid blocks), steepest around 1.5 N/mm3."""
    return 30 + 70 / (1 + (1.5 / kn) ** 0.6)


def saturating(kn: float) -> float:
    """du that reaches its rigid-block limit quickly: most of the bracket is flat."""
    return 40 + 60 * (1 - math.exp(-kn / 0.5))


def inverse(model, du: float) -> float:
    """The exact kn of `du` by bisection on log kn (the reference answer)."""
    lo, hi = math.log(1e-3), math.log(1e3)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if model(math.exp(mid)) < du else (lo, mid)
    return math.exp(lo)


@pytest.mark.parametrize(
    "model, target, tolerance",
    [
        (sigmoid, 48.9, 0.5),
        (sigmoid, 91.5, 0.5),
        (sigmoid, 48.9, 0.05),
        (saturating, 60.0, 0.1),
        (saturating, 90.0, 0.1),
    ],
)
def test_converges_in_few_runs(model, target, tolerance):
    result = calibrate(function_evaluator(model), target, tolerance, 0.1, 100.0)
    assert result.converged
    assert abs(result.du_mm - target) <= tolerance
    assert model(result.kn_N_per_mm3) == pytest.approx(result.du_mm)
    true_kn = inverse(model, target)
    slope = (model(true_kn * 1.01) - model(true_kn / 1.01)) / (2 * math.log(1.01))  # d du / d log kn
    assert abs(math.log(result.kn_N_per_mm3 / true_kn)) <= 1.5 * tolerance / slope
    assert result.runs <= 8 and result.runs == len(result.history) == result.new_runs


def test_refuses_a_target_out_of_reach():
    with pytest.raises(YadearchError, match=r"outside what kn in \[0.1, 100\] N/mm3 reaches"):
        calibrate(function_evaluator(sigmoid), 120.0, 0.5, 0.1, 100.0)
    with pytest.raises(YadearchError, match="kn-min < kn-max"):
        calibrate(function_evaluator(sigmoid), 50.0, 0.5, 10.0, 1.0)


def test_a_bracket_end_within_tolerance_is_the_answer():
    result = calibrate(function_evaluator(sigmoid), sigmoid(0.1) - 0.2, 0.5, 0.1, 100.0)
    assert result.converged and result.kn_N_per_mm3 == 0.1 and result.runs == 2


def test_a_jump_in_du_stops_without_convergence():
    result = calibrate(function_evaluator(lambda kn: 50.0 if kn < 1.0 else 90.0), 70.0, 0.5, 0.1, 100.0, max_runs=8)
    assert not result.converged and result.runs <= 8
    assert result.du_mm in (50.0, 90.0)


def test_json_record(tmp_path):
    lines: list[str] = []
    result = calibrate(function_evaluator(sigmoid), 48.9, 0.5, 0.1, 100.0, log=lines.append)
    result.write(tmp_path / "set1.json")
    data = json.loads((tmp_path / "set1.json").read_text())
    for key in ("target_du_mm", "kn_N_per_mm3", "du_mm", "runs", "history", "tolerance_mm", "converged", "hinges"):
        assert key in data
    assert data["runs"] == len(data["history"]) and data["history"][0]["kn_N_per_mm3"] == 0.1
    assert sum(line.startswith("run ") for line in lines) == data["runs"]


def test_the_api_names_the_case_and_the_engine_it_calibrated(tmp_path):
    """A 9-voussoir arch on the static engine: the kn that gives the du of kn 10 is found near 10, and
    the record says which case and engine (the calibration JSON named neither; fourth user trial)."""
    import yadearch as ya

    case = ya.preset("set2").replace(n_voussoirs=9, kn_N_per_mm3=10.0, engine="static")
    target = ya.run(case, out=tmp_path / "target", figures=False, quiet=True).du_mm
    found = ya.calibrate(case.replace(name="nine"), target, tmp_path / "runs", kn_min=1.0, kn_max=100.0, jobs=1)
    assert found.converged and found.case == "nine" and found.engine == "static"
    assert abs(found.du_mm - target) <= found.tolerance_mm
    found.write(tmp_path / "nine.json")
    assert '"engine": "static"' in (tmp_path / "nine.json").read_text()
