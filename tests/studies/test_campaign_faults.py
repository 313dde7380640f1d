"""Fault injection without YADE: a campaign whose runs write their folders the way real runs do
(staging folder, atomic files, swap into place) is SIGKILLed at seeded random moments, again and
again; each resume must end with every run done, each with its own answer, and nothing half-written
counted as finished."""

from __future__ import annotations

import json
import math
import os
import random
import signal
import subprocess
import sys
import time

import pandas as pd
import pytest
from conftest import REPO

from yadearch.case.config import preset
from yadearch.studies.campaigns.executors import local_pool
from yadearch.studies.campaigns.grid import grid
from yadearch.studies.campaigns.runner import RESULTS_FILE, run_campaign

KN_VALUES = [0.1, 0.2, 0.3, 0.5, 0.7, 1.0, 2.0, 3.0, 5.0, 7.0, 10.0, 20.0]
KILLS = 6
SEED = 20261123
CAMPAIGN = f"""
import math, random, shutil, sys, time
from pathlib import Path
from yadearch.case.config import preset
from yadearch.launch.process import swap_into_place
from yadearch.results.rundir import staging_folder, write_run
from yadearch.results.summary import RunSummary
from yadearch.studies.campaigns.runner import run_campaign
from yadearch.studies.campaigns.executors import local_pool
from yadearch.studies.campaigns.grid import grid

def slow_run(case, folder, timeout_s):
    # a stand-in for the child process, with the real folder handling and pauses inside the writes
    staging = staging_folder(folder)
    shutil.rmtree(staging, ignore_errors=True)
    staging.mkdir(parents=True)
    time.sleep(random.uniform(0.0, 0.3))
    kn = case.interface.kn_N_per_mm3
    summary = RunSummary(du_mm=50 + 10 * math.log10(kn), collapsed=True, hinges_at_collapse=(), steps=100,
                         wall_s=0.1)
    write_run(staging, case.to_toml(), [{{"stage": "equilibrium", "delta_mm": 1.0}}] * 200,
              [{{"stage": "equilibrium", "interface": 1}}] * 200, {{}}, summary)
    time.sleep(random.uniform(0.0, 0.1))
    swap_into_place(staging, folder)
    return {{"status": "done", "reason": ""}}

base = preset("set1").with_overrides({{"n_voussoirs": 15}})
with local_pool(2) as pool:
    run_campaign(base, grid({{"kn_N_per_mm3": {KN_VALUES}}}), Path(sys.argv[1]), pool, progress=False,
                 task=slow_run)
"""


def expected_du(kn: float) -> float:
    return 50 + 10 * math.log10(kn)


def test_a_campaign_killed_at_random_moments_resumes_to_the_complete_answer(tmp_path):
    out = tmp_path / "campaign"
    script = tmp_path / "campaign.py"
    script.write_text(CAMPAIGN)
    draw = random.Random(SEED)
    env = dict(os.environ, PYTHONPATH=str(REPO))
    finished_before_kill = sorted(draw.sample(range(len(KN_VALUES) - 1), KILLS))
    for target in finished_before_kill:  # kill once `target` runs are done, plus a random moment
        proc = subprocess.Popen([sys.executable, str(script), str(out)], env=env)
        deadline = time.time() + 60
        while len(list(out.glob("kn*/summary.json"))) < target and time.time() < deadline:
            time.sleep(0.01)
        time.sleep(draw.uniform(0.0, 0.3))
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait(timeout=30)
    done = subprocess.run([sys.executable, str(script), str(out)], env=env, timeout=120)
    assert done.returncode == 0
    results = pd.read_csv(out / RESULTS_FILE).set_index("kn_N_per_mm3")
    assert set(results["status"]) == {"done"} and len(results) == len(KN_VALUES)
    for kn in KN_VALUES:
        summary = json.loads((out / results.loc[kn, "folder"] / "summary.json").read_text())
        assert summary["complete"] is True and summary["du_mm"] == expected_du(kn)
        assert results.loc[kn, "du_mm"] == pytest.approx(expected_du(kn), rel=1e-5)  # the table's 6 digits
    assert not list(out.glob(".*")), "a staging folder or a temporary file was left beside the runs"


def test_a_resume_in_process_trusts_only_complete_folders(tmp_path):
    """A folder whose summary.json was cut in half by a crash is run again, the others are kept."""
    out = tmp_path / "campaign"
    calls: list[str] = []

    def quick_run(case, folder, timeout_s):
        from yadearch.results.rundir import write_run
        from yadearch.results.summary import RunSummary

        calls.append(case.name)
        kn = case.interface.kn_N_per_mm3
        write_run(
            folder,
            case.to_toml(),
            [],
            [],
            {},
            RunSummary(du_mm=expected_du(kn), collapsed=True, hinges_at_collapse=(), steps=1, wall_s=0.1),
        )
        return {"status": "done", "reason": ""}

    base = preset("set1").with_overrides({"n_voussoirs": 15})
    rows = grid({"kn_N_per_mm3": KN_VALUES[:3]})
    with local_pool(1) as pool:
        run_campaign(base, rows, out, pool, progress=False, task=quick_run)
    cut = out / "kn0.2" / "summary.json"
    cut.write_text(cut.read_text()[: len(cut.read_text()) // 2])
    calls.clear()
    with local_pool(1) as pool:
        table = run_campaign(base, rows, out, pool, progress=False, task=quick_run)
    assert calls == ["kn0.2"] and set(table["status"]) == {"done"}


def test_an_interrupted_local_pool_stops_its_running_simulations_at_once():
    """Ctrl-C or SIGTERM in a campaign: the simulations it waits on get SIGTERM instead of being
    waited for (each run is then recorded as interrupted and resumed by the next campaign)."""
    from yadearch.launch.process import run_child

    started = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        with local_pool(2) as pool:
            children = [
                pool.executor.submit(run_child, ["sleep", "60"], dict(os.environ), None, True) for _ in range(2)
            ]
            time.sleep(0.5)
            raise KeyboardInterrupt
    assert time.monotonic() - started < 10.0
    assert [child.result()[0] for child in children] == [-signal.SIGTERM] * 2


def test_the_results_table_exists_before_any_run_starts(tmp_path):
    """A campaign killed (SIGKILL) in its first seconds still leaves results.csv: every run pending."""
    out = tmp_path / "campaign"
    seen: list[set] = []

    def first_look(case, folder, timeout_s):
        seen.append(set(pd.read_csv(out / RESULTS_FILE)["status"]))
        return {"status": "failed", "reason": "stand-in"}

    with local_pool(1) as pool:
        run_campaign(preset("set1"), grid({"kn_N_per_mm3": [0.25, 0.5]}), out, pool, progress=False, task=first_look)
    assert seen and seen[0] == {"pending"}
