"""scripts/benchmark.py runs end to end in its quickest mode (a benchmark nothing runs breaks
unseen): a summary-only run folder solves the same arches as a whole one and weighs a tenth or less."""

from __future__ import annotations

import json
import subprocess
import sys

from conftest import REPO


def test_the_run_files_benchmark_measures_the_same_du_on_lighter_folders(tmp_path):
    out = tmp_path / "run_files.json"
    command = [sys.executable, str(REPO / "scripts" / "benchmark.py"), "--run-files", "2"]
    done = subprocess.run(
        [*command, "--runs", str(tmp_path / "runs"), "--out", str(out)], capture_output=True, text=True, check=True
    )
    measured = json.loads(out.read_text())
    assert measured["run_files_same_du"] is True and measured["run_files_samples"] == 2
    assert measured["run_files_disk_ratio"] < 0.1
    assert "a summary-only folder" in done.stdout.splitlines()[-1]
