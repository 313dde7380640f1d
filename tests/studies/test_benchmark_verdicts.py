"""The benchmark's verdicts without YADE: decided from the figures of its JSON report, they give back
the committed reports' PASS and FAIL lines, fail a measurement past its target or missing, and the
report is written whole."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pandas as pd
import pytest
from conftest import REPO

from yadearch.studies.benchmark.campaign_runs import campaign_runs_verdicts
from yadearch.studies.benchmark.dem_runs import campaign_status, montecarlo_wall_s, slow_reference
from yadearch.studies.benchmark.run_files import run_files_verdicts
from yadearch.studies.benchmark.static_engine import static_floor_verdicts, static_verdicts
from yadearch.studies.benchmark.verdicts import (
    TARGET_MONTECARLO_SAMPLES,
    TARGET_SET2_WALL_S,
    Verdict,
    dem_verdicts,
    write_report,
)

REPORTS = REPO / "reports"
# the static campaigns' runs done (of how many) in reports/benchmark.txt: not among the JSON's figures
COMMITTED_STATIC_DONE = {"sweep100": (95, 100), "mc200": (199, 200)}


def _committed(name: str) -> tuple[dict, list[str]]:
    """A committed benchmark report's figures and its printed verdict lines."""
    lines = (REPORTS / f"{name}.txt").read_text().splitlines()
    return json.loads((REPORTS / f"{name}.json").read_text()), [s for s in lines if s.startswith(("PASS", "FAIL"))]


def _dem(**changes) -> dict[str, Verdict]:
    """The DEM verdicts of the committed report with `changes` to its figures, by target."""
    report = {**_committed("benchmark")[0], **changes}
    return {v.target: v for v in dem_verdicts(report, "joint")}


def test_the_committed_reports_verdicts_follow_from_their_figures():
    report, lines = _committed("benchmark")
    verdicts = dem_verdicts(report, "joint") + static_verdicts(report, report["set2_du_mm"], COMMITTED_STATIC_DONE)
    assert [v.line() for v in verdicts] == lines
    for name, decide in (
        ("benchmark_run_files", run_files_verdicts),
        ("benchmark_static_floor", static_floor_verdicts),
        ("benchmark_campaign_runs", campaign_runs_verdicts),
    ):
        figures, lines = _committed(name)
        assert [v.line() for v in decide(figures)] == lines


def test_set2_fails_past_its_wall_time_target_and_says_by_how_much():
    target = f"set 2 wall <= {TARGET_SET2_WALL_S:g} s"
    assert _dem(set2_wall_s=9.6)[target].met
    late = _dem(set2_wall_s=25.0)[target]
    assert not late.met and late.detail == "25 s (2.5x the target)"
    assert late.line().startswith("FAIL  set 2 wall")


def test_du_must_be_within_one_percent_of_the_reference_on_the_same_hinges():
    target = "set 2 du within 1 % of the slow reference, same hinges"
    assert _dem(set2_du_rel_diff=0.009)[target].met
    assert not _dem(set2_du_rel_diff=0.011)[target].met
    other_hinges = _dem(set2_same_hinges=False)[target]
    assert not other_hinges.met and other_hinges.detail.endswith("hinges differ")
    assert _dem(set2_du_rel_diff=None)[target] == Verdict(target, False, "no du")


def test_the_driver_overhead_is_judged_only_when_measured():
    measured = {model: {"driver_overhead_ratio": 1.2} for model in ("joint", "cgal")}
    target = "driver overhead <= 5 %"
    assert _dem(driver_overhead_ratio=1.04, loading_measurement=measured)[target].met
    over = _dem(driver_overhead_ratio=1.06, loading_measurement=measured)[target]
    assert not over.met and "= 1.060 (joint contacts; CGAL: 1.200)" in over.detail
    assert _dem()[target].detail == "not measured (--measure-mm)"


def test_missing_measurements_fail_with_their_reason():
    verdicts = _dem(kn100_wall_s=None, sweep=None, sweep_wall_s=None, montecarlo=None, step_us=None)
    missing = {v.detail for v in verdicts.values() if not v.met}
    assert {
        "not run (--stiff)",
        "no sweep folder given (sweep_wall_s null)",
        "no Monte Carlo folder given (--montecarlo)",
        "not measured",
    } <= missing


def test_a_sweep_passes_only_whole_in_time_and_without_failures():
    target = "25-point sweep <= 10 min on 2 cores"
    quick = {"done": 25, "failed": 0, "run_wall_s": 900.0}
    assert _dem(sweep=quick, sweep_wall_s=500.0)[target].met
    assert not _dem(sweep=quick, sweep_wall_s=700.0)[target].met
    assert not _dem(sweep={**quick, "failed": 1}, sweep_wall_s=500.0)[target].met
    assert not _dem(sweep={**quick, "done": 24}, sweep_wall_s=500.0)[target].met


def test_monte_carlo_samples_count_on_two_cores_only_when_the_campaign_tried_them_all():
    target = "200 Monte Carlo samples <= 20 min on 2 cores"
    quick = {"done": 190, "failed": 10, "run_wall_s": 2000.0}  # 1000 s on 2 cores
    assert montecarlo_wall_s(quick) == 1000.0 and _dem(montecarlo=quick)[target].met
    short = {**quick, "done": TARGET_MONTECARLO_SAMPLES - 11}
    assert montecarlo_wall_s(short) is None and not _dem(montecarlo=short)[target].met
    assert not _dem(montecarlo={**quick, "run_wall_s": 2500.0})[target].met


def test_a_summary_only_folder_fails_on_another_du_more_disk_or_more_cpu():
    good = {"run_files_same_du": True, "run_files_disk_ratio": 0.06, "run_files_cpu_ratio": 0.8}
    assert run_files_verdicts(good)[0].met
    for change in ({"run_files_same_du": False}, {"run_files_disk_ratio": 0.11}, {"run_files_cpu_ratio": 1.01}):
        assert not run_files_verdicts({**good, **change})[0].met


def test_the_static_engine_fails_on_a_slow_solver_or_a_du_off_the_dems():
    report = _committed("benchmark")[0]
    targets = {v.target: v for v in static_verdicts(report, report["set2_du_mm"], COMMITTED_STATIC_DONE)}
    assert all(v.met for v in targets.values())
    slow = static_verdicts({**report, "static_set2_solver_s": 0.6}, report["set2_du_mm"], COMMITTED_STATIC_DONE)
    assert not slow[0].met and slow[0].target == "static set 2 solver <= 0.5 s, whole run <= 10 s"
    off = static_verdicts(report, report["set2_du_mm"] * 1.02, COMMITTED_STATIC_DONE)[1]
    assert not off.met and off.detail == "1.96%"


def test_a_campaign_run_passes_at_25_ms_with_the_same_answers_and_the_study_at_20_minutes():
    good = {
        "campaign_lean_run_cpu_s": 0.02,
        "campaign_folders_run_cpu_s": 0.2,
        "campaign_same_answers": True,
        "sensitivity_4096_estimate_s": 1100.0,
    }
    assert [v.met for v in campaign_runs_verdicts(good)] == [True, True]
    for change in ({"campaign_lean_run_cpu_s": 0.026}, {"campaign_same_answers": False}):
        assert not campaign_runs_verdicts({**good, **change})[0].met
    slow = campaign_runs_verdicts({**good, "sensitivity_4096_estimate_s": 1260.0})[1]
    assert not slow.met and slow.detail == "21 min"


def test_each_case_of_the_static_floor_is_judged_against_the_floor_ratio():
    figures = {"static_floor_set2": {"ratio": 1.4}, "static_floor_imperfect": {"ratio": 1.6}}
    verdicts = static_floor_verdicts({**figures, "measured": "2026-01-01T00:00:00"})
    assert [(v.target.split(" <=")[0], v.met) for v in verdicts] == [
        ("static solver of set2", True),
        ("static solver of imperfect", False),
    ]


def test_the_report_is_indented_json_written_whole(tmp_path, monkeypatch):
    path = tmp_path / "new" / "benchmark.json"
    write_report(path, {"set2_wall_s": 99.5, "sweep": None, "loading_measurement": {"joint": {"steps": 3}}})
    text = path.read_text()
    assert text.endswith("}\n") and '\n  "sweep": null' in text
    assert json.loads(text)["loading_measurement"] == {"joint": {"steps": 3}}

    def interrupted(source, target):
        raise OSError("disk full")

    monkeypatch.setattr(os, "replace", interrupted)
    with pytest.raises(OSError):
        write_report(path, {"set2_wall_s": 1.0})
    assert path.read_text() == text and [p.name for p in path.parent.iterdir()] == ["benchmark.json"]


def test_a_campaigns_status_counts_its_runs_and_adds_their_wall_times(tmp_path):
    pd.DataFrame({"status": ["done", "failed", "done", "interrupted"], "wall_s": [10.0, 2.5, 12.0, 1.0]}).to_csv(
        tmp_path / "results.csv", index=False
    )
    assert campaign_status(Path(tmp_path)) == {"done": 2, "failed": 1, "run_wall_s": 25.5}


def test_the_slow_reference_is_set2_at_half_the_settlement_rate():
    from yadearch.case.config import preset

    base = preset("set2")
    slow = slow_reference(base)
    assert slow.name == "set2_half_rate"
    assert slow.numerics.support_rate_mm_per_s == base.numerics.support_rate_mm_per_s / 2
