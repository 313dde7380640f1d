"""A static campaign without run folders (`campaigns.lean`): the same rows as the campaign that keeps
them, a failure recorded with its reason while the others go on, its batches committed whole, and a
campaign killed by SIGKILL resumed after its last whole batch."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import threading
import time

import pandas as pd
import pytest
from conftest import REPO

from yadearch.case.config import preset
from yadearch.errors import YadearchError
from yadearch.static import pool as static_pool
from yadearch.static.pool import solve_batch, stop_workers
from yadearch.studies.campaigns.batches import BATCHES_DIR, read_batches
from yadearch.studies.campaigns.executors import local_pool
from yadearch.studies.campaigns.grid import grid
from yadearch.studies.campaigns.runner import RESULTS_FILE, run_campaign
from yadearch.studies.campaigns.sessions import SESSIONS_FILE

BASE = preset("set2").with_overrides({"engine": "static", "n_voussoirs": 9, "numerics.run_files": "summary"})
KN_VALUES = [0.01, 0.05, 0.3, 1.0, 5.2, 30.0]  # kn 0.01 does not stand under its own weight
ANSWERS = ["du_mm", "du_first_mm", "hinges", "outcome", "collapse_kind", "steps", "status", "max_friction_use"]
RESUMED_KN = [0.05, 0.1, 0.2, 0.3, 0.5, 1.0, 2.0, 3.0, 5.2, 10.0, 20.0, 30.0]  # 4 batches of 3 on 1 slot
CAMPAIGN = f"""
import sys
from pathlib import Path
from yadearch.case.config import preset
from yadearch.studies.campaigns.executors import local_pool
from yadearch.studies.campaigns.grid import grid
from yadearch.studies.campaigns.runner import run_campaign

base = preset("set2").with_overrides({{"engine": "static", "n_voussoirs": 9, "numerics.run_files": "summary"}})
with local_pool(1) as pool:
    run_campaign(base, grid({{"kn_N_per_mm3": {RESUMED_KN}}}), Path(sys.argv[1]), pool, progress=False, folders=False)
"""


def test_a_campaign_without_folders_gives_the_rows_of_the_one_with_folders(tmp_path):
    rows = grid({"kn_N_per_mm3": KN_VALUES})
    with local_pool(2) as pool:
        kept = run_campaign(BASE, rows, tmp_path / "folders", pool, progress=False)
        lean = run_campaign(BASE, rows, tmp_path / "lean", pool, progress=False, folders=False)
    assert lean[ANSWERS].equals(kept[ANSWERS])
    assert list(lean["status"]) == ["failed"] + ["done"] * 5
    assert lean["reason"].iloc[0] == kept["reason"].iloc[0].split(" (see ")[0]  # no run.log to point to
    assert "does not stand under its own weight" in lean["reason"].iloc[0]
    assert sorted(p.name for p in (tmp_path / "lean").iterdir()) == [
        BATCHES_DIR,
        RESULTS_FILE,
        "runs.csv",
        SESSIONS_FILE,
    ]
    stored = pd.read_csv(tmp_path / "lean" / RESULTS_FILE)
    assert stored["du_mm"].equals(pd.read_csv(tmp_path / "folders" / RESULTS_FILE)["du_mm"])


def test_a_finished_campaign_without_folders_runs_nothing_again_and_refuses_another_case(tmp_path):
    rows = grid({"kn_N_per_mm3": KN_VALUES[1:3]})
    with local_pool(1) as pool:
        first = run_campaign(BASE, rows, tmp_path, pool, progress=False, folders=False)
        again = run_campaign(BASE, rows, tmp_path, pool, progress=False, folders=False)
        assert again[ANSWERS].equals(first[ANSWERS])
        assert len(json.loads((tmp_path / SESSIONS_FILE).read_text())) == 1  # the second ran nothing
        other = BASE.with_overrides({"friction_deg": 38.0})
        with pytest.raises(YadearchError, match=r"run kn0.05 in batches/ ran another case than this campaign's"):
            run_campaign(other, rows, tmp_path, pool, progress=False, folders=False)


def test_a_batch_over_its_timeout_fails_that_run_and_the_others_go_on():
    cases = [BASE.with_overrides({"kn_N_per_mm3": kn}).to_dict() for kn in (1.0, 30.0)]
    try:
        answers = solve_batch(cases, timeout_s=1e-3)
    finally:
        stop_workers()
    assert answers == [{"error": "timed out after 0 s"}] * 2


def test_a_batch_whose_worker_is_stopped_hands_back_its_finished_runs_and_the_rest_as_interrupted():
    cases = [BASE.with_overrides({"kn_N_per_mm3": 100.0, "n_voussoirs": 31}).to_dict()] * 80
    answers: list[dict] = []
    solving = threading.Thread(target=lambda: answers.extend(solve_batch(cases, timeout_s=60)))
    solving.start()
    deadline = time.time() + 60
    while not static_pool._all and time.time() < deadline:
        time.sleep(0.01)
    time.sleep(3.0)  # the worker's imports, then a few runs
    stop_workers()
    solving.join(timeout=60)
    kinds = [next(iter(answer)) for answer in answers]
    assert len(answers) == len(cases) and "interrupted" in kinds
    assert kinds == sorted(kinds, key=lambda kind: kind == "interrupted")  # the finished ones first


def test_a_campaign_without_folders_killed_resumes_after_its_last_whole_batch(tmp_path):
    out = tmp_path / "campaign"
    script = tmp_path / "campaign.py"
    script.write_text(CAMPAIGN)
    env = dict(os.environ, PYTHONPATH=str(REPO))
    proc = subprocess.Popen([sys.executable, str(script), str(out)], env=env)
    deadline = time.time() + 120
    while not list((out / BATCHES_DIR).glob("*.jsonl")) and time.time() < deadline:
        time.sleep(0.01)
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait(timeout=30)
    committed = set(read_batches(out))
    assert committed and len(committed) % 3 == 0 and len(committed) < len(RESUMED_KN)
    done = subprocess.run([sys.executable, str(script), str(out)], env=env, timeout=300)
    assert done.returncode == 0
    sessions = json.loads((out / SESSIONS_FILE).read_text())
    assert sessions[-1]["runs_attempted"] == len(RESUMED_KN) - len(committed)
    results = pd.read_csv(out / RESULTS_FILE)
    assert set(results["status"]) == {"done"} and len(results) == len(RESUMED_KN)
    assert set(read_batches(out)) == set(results["run"])
    assert not list(out.glob(".*")) and not list((out / BATCHES_DIR).glob(".*")), "a temporary file was left"


def test_batch_files_are_read_in_the_order_written_and_a_cut_line_is_run_again(tmp_path):
    """Batch files are numbered as written: a later one wins whatever the width of its number; a line
    cut short (the machine stopped mid-write) is skipped, so its run counts as not done."""
    import json

    from yadearch.studies.campaigns.batches import BATCHES_DIR, read_batches
    from yadearch.studies.campaigns.grid import RUN_COLUMN

    folder = tmp_path / BATCHES_DIR
    folder.mkdir()
    (folder / "9.jsonl").write_text(json.dumps({"row": {RUN_COLUMN: "a", "du_mm": 1.0}, "case": "k"}) + "\n")
    (folder / "10.jsonl").write_text(
        json.dumps({"row": {RUN_COLUMN: "a", "du_mm": 2.0}, "case": "k"}) + "\n" + '{"row": {"run": "b", "du'
    )
    records = read_batches(tmp_path)
    assert records["a"]["row"]["du_mm"] == 2.0 and "b" not in records
