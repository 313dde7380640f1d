"""scripts/benchmark.py runs end to end in its quick modes (a benchmark nothing runs breaks unseen): a
summary-only run folder solves the same arches as a whole one and weighs a tenth or less; the static
solver is judged against its floor; a campaign run is split between the compiled loops and the rest; a
run from the command line against its two targets; and the DEM report, from the committed run folders,
has the committed report's figures without YADE."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest
from conftest import REPO

from yadearch.studies.benchmark.report import BenchmarkPlan, run_benchmark

BENCHMARK = [sys.executable, str(REPO / "scripts" / "benchmark.py")]
REPORTS = REPO / "reports"


def _benchmark(tmp_path, *options: str) -> tuple[dict, list[str]]:
    """The figures the script writes and the lines it prints."""
    out = tmp_path / "benchmark.json"
    done = subprocess.run(
        [*BENCHMARK, *options, "--runs", str(tmp_path / "runs"), "--out", str(out)],
        capture_output=True,
        text=True,
        check=True,
    )
    return json.loads(out.read_text()), done.stdout.splitlines()


def test_the_run_files_benchmark_measures_the_same_du_on_lighter_folders(tmp_path):
    measured, lines = _benchmark(tmp_path, "--run-files", "2")
    assert measured["run_files_same_du"] is True and measured["run_files_samples"] == 2
    assert measured["run_files_disk_ratio"] < 0.1
    assert "a summary-only folder" in lines[-1]
    assert list(measured) == list(json.loads((REPORTS / "benchmark_run_files.json").read_text()))


def test_the_static_floor_benchmark_judges_each_case_by_its_cpu_over_its_floor(tmp_path):
    measured, lines = _benchmark(tmp_path, "--static-floor")
    assert list(measured) == list(json.loads((REPORTS / "benchmark_static_floor.json").read_text()))
    verdicts = [s for s in lines if s.startswith(("PASS", "FAIL"))]
    assert [s.split(":")[0][6:] for s in verdicts] == [
        f"static solver of {name} <= 1.5 x its compiled floor" for name in ("set2", "imperfect")
    ]
    for name, line in zip(("set2", "imperfect"), verdicts):
        cost = measured[f"static_floor_{name}"]
        floor = cost["evaluations"] * cost["evaluation_s"] + cost["iterations"] * cost["solve_s"]
        assert cost["ratio"] == pytest.approx(cost["solver_cpu_s"] / floor)
        assert line.startswith("PASS" if cost["ratio"] <= 1.5 else "FAIL") and line.endswith(f"{cost['ratio']:.2f}")


def test_the_command_line_benchmark_judges_both_targets_against_their_times(tmp_path):
    measured, lines = _benchmark(tmp_path, "--cli-run", "1")
    assert list(measured) == list(json.loads((REPORTS / "benchmark_cli_run.json").read_text()))
    assert (
        0 < measured["cli_bare_interpreter_wall_s"] < measured["cli_no_figures_wall_s"] < measured["cli_figures_wall_s"]
    )
    verdicts = [s for s in lines if s.startswith(("PASS", "FAIL"))]
    for line, key, target in zip(verdicts, ("cli_no_figures_wall_s", "cli_figures_wall_s"), (1.0, 3.0)):
        assert line.startswith("PASS" if measured[key] <= target else "FAIL") and f"{measured[key]:.2f} s" in line


def test_the_run_profile_splits_a_run_between_the_compiled_loops_and_the_rest(tmp_path):
    """Two Saltelli runs profiled: each kernel was called, and the shares of the profiled time add to one."""
    measured, lines = _benchmark(tmp_path, "--run-profile", "2")
    assert list(measured) == list(json.loads((REPORTS / "benchmark_run_profile.json").read_text()))
    kernels = ("descent_kernel", "newton_kernel")
    assert all(measured[f"profile_{k}_calls_a_run"] >= 1 for k in kernels)
    shares = [measured[f"profile_{k}_share"] for k in kernels] + [measured["profile_rest_share"]]
    assert all(0.0 <= share <= 1.0 for share in shares) and sum(shares) == pytest.approx(1.0)
    assert 0 < measured["profile_run_cpu_s"] and lines[0].startswith("a Saltelli run, 2 in one process")


def test_the_dem_report_from_stored_runs_needs_no_yade_and_keeps_the_committed_keys(tmp_path):
    plan = BenchmarkPlan(
        runs=tmp_path / "runs",
        set1_run=str(REPORTS / "set1"),
        set2_run=str(REPORTS / "set2"),
        stiff_run=str(REPORTS / "stiff" / "kn100"),
        reference=str(REPORTS / "convergence" / "set2_half_rate"),
        montecarlo=str(REPORTS / "imperfections" / "final"),
    )
    report, verdicts = run_benchmark(plan)
    committed = json.loads((REPORTS / "benchmark.json").read_text())
    assert list(report) == [key for key in committed if not key.startswith("static_")]
    assert report["du_rigid_mm"] == pytest.approx(committed["du_rigid_mm"], abs=0.01)
    committed_lines = (REPORTS / "benchmark.txt").read_text().splitlines()
    for target in ("set 2 du within", "kn 100 <=", "200 Monte Carlo samples"):
        assert next(v.line() for v in verdicts if v.target.startswith(target)) in committed_lines
    assert not (tmp_path / "runs").exists()  # stored runs stand in for every run
