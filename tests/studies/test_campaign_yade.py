"""Campaigns and calibration on real YADE with a coarse arch (9 voussoirs, soft joints, 30 mm/s:
~15-40 s a run): local and dask executors agree, a restart redoes nothing finished, failures are
recorded, and a short calibration converges. The sweep runs once (module fixture); the other tests
reuse its run folders."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import pandas as pd
import pytest
from click.testing import CliRunner
from conftest import REPO, needs_yade

from yadearch.cli.campaigns import calibrate, sweep
from yadearch.errors import YadearchError
from yadearch.studies.campaigns.runner import RESULTS_FILE, batch_run

pytestmark = [pytest.mark.yade, needs_yade]

COARSE = [
    "--preset",
    "set1",
    "--set",
    "n_voussoirs=9",
    "--set",
    "support_rate_mm_per_s=30",
    "--set",
    "progress_every_s=1e9",
]
SLOW_RATE = "support_rate_mm_per_s=3"  # a run ten times longer than COARSE's, for an interrupt to land in it
SLOWER_RATE = "support_rate_mm_per_s=10"  # ... three times longer


def slowed(arguments: list[str], rate: str) -> list[str]:
    """`arguments` with the support's rate set to `rate` (`--set` text) instead of COARSE's."""
    return [rate if a.startswith("support_rate_mm_per_s=") else a for a in arguments]


TABLE = "kn_N_per_mm3\n0.1\n0.12\n0.2\n"  # three coarse arches
COMPARED = [
    "run",
    "kn_N_per_mm3",
    "collapsed",
    "hinges",
    "mechanism",
    "hinge_A",
    "hinge_B",
    "hinge_C",
    "hinge_D",
    "status",
    "reason",
]


def run_sweep(out: Path, *extra: str):
    table = out.parent / "table.csv"
    table.write_text(TABLE)
    return CliRunner().invoke(sweep, [*COARSE, "--table", str(table), "--out", str(out), *extra])


@pytest.fixture(scope="module")
def local_sweep(tmp_path_factory) -> Path:
    """The coarse campaign through `yadearch sweep` on two local processes."""
    out = tmp_path_factory.mktemp("local") / "sweep"
    result = run_sweep(out, "--jobs", "2")
    assert result.exit_code == 0, result.output
    return out


def test_local_campaign_writes_the_results_table(local_sweep):
    table = pd.read_csv(local_sweep / RESULTS_FILE)
    assert table["status"].tolist() == ["done", "done", "done"]
    done = table[table["status"] == "done"]
    assert done["du_mm"].between(50, 150).all() and done["collapsed"].all()
    assert (done["hinge_C"] == 10).all() and done["hinge_A"].notna().all()
    assert (done["wall_s"] > 0).all()
    assert (local_sweep / "du_vs_kn.pdf").is_file() and (local_sweep / "du_vs_kn.png").is_file()


def test_dask_cluster_gives_the_same_results(local_sweep, tmp_path):
    from distributed import LocalCluster

    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        result = run_sweep(tmp_path / "sweep", "--scheduler", cluster.scheduler_address, "--no-figures")
    assert result.exit_code == 0, result.output
    local = pd.read_csv(local_sweep / RESULTS_FILE)
    remote = pd.read_csv(tmp_path / "sweep" / RESULTS_FILE)
    pd.testing.assert_frame_equal(local[COMPARED], remote[COMPARED])
    # a run never restarts YADE's simulation thread (yadearch.stepping), so it is bit-reproducible
    pd.testing.assert_series_equal(local["du_mm"], remote["du_mm"])


def test_restart_redoes_nothing_finished_and_records_a_timeout(local_sweep, tmp_path):
    out = tmp_path / "sweep"
    for name in ("kn0.1", "kn0.12", "kn0.2"):
        shutil.copytree(local_sweep / name, out / name)
    (out / "kn0.2" / "summary.json").unlink()  # killed while kn0.2 ran
    finished = {p: p.stat().st_mtime_ns for p in out.glob("kn0.1*/*")}
    result = run_sweep(out, "--jobs", "1", "--timeout-min", str(1 / 60), "--no-figures")
    assert "1 of 3 runs failed" in str(result.exception), result.output
    assert {p: p.stat().st_mtime_ns for p in out.glob("kn0.1*/*")} == finished
    table = pd.read_csv(out / RESULTS_FILE)
    assert table["status"].tolist() == ["done", "done", "failed"]
    assert "timed out after 1 s" in table.loc[2, "reason"]
    assert "timed out" in json.loads((out / "kn0.2" / "failed.json").read_text())["reason"]
    local = pd.read_csv(local_sweep / RESULTS_FILE)
    assert table["du_mm"][:2].tolist() == local["du_mm"][:2].tolist()


def test_short_real_calibration(local_sweep, tmp_path):
    local = pd.read_csv(local_sweep / RESULTS_FILE).set_index("run")
    runs = tmp_path / "set1"
    for name in ("kn0.1", "kn0.12"):  # the bracket ends are reused, the search runs in between
        shutil.copytree(local_sweep / name, runs / name)
    low, high = local.loc["kn0.1", "du_mm"], local.loc["kn0.12", "du_mm"]
    assert high - low > 2.0, "the coarse arch's du must grow with kn for this test"
    target, tolerance = 0.5 * (low + high), max(0.5, (high - low) / 5)
    args = [
        *COARSE,
        "--kn-min",
        "0.1",
        "--kn-max",
        "0.12",
        "--tolerance-mm",
        f"{tolerance:.3f}",
        "--max-runs",
        "6",
        "--jobs",
        "1",
        "--runs-dir",
        str(runs),
        "--out",
        str(tmp_path / "set1.json"),
    ]
    result = CliRunner().invoke(calibrate, [*args, "--target-du", f"{target:.3f}"])
    assert result.exit_code == 0, result.output
    data = json.loads((tmp_path / "set1.json").read_text())
    assert abs(data["du_mm"] - target) <= tolerance and 0.1 < data["kn_N_per_mm3"] < 0.12
    assert data["runs"] == len(data["history"]) >= 3 and data["new_runs"] == data["runs"] - 2
    assert "run 3: kn = " in result.output
    refused = CliRunner().invoke(calibrate, [*args, "--target-du", f"{high + 30:.3f}"])
    assert isinstance(refused.exception, YadearchError) and "outside what kn" in str(refused.exception)


def test_yade_reads_the_batch_table(tmp_path):
    """yade's own TableParamReader parses scripts/yade_batch_table.txt; every line maps to a run."""
    code = (
        "import json, sys; from yadearch.dem.yade_env import import_yade; import_yade(); "
        "from yade.utils import TableParamReader; "
        "print(json.dumps(TableParamReader(sys.argv[1]).paramDict()))"
    )
    done = subprocess.run(
        [sys.executable, "-c", code, str(REPO / "scripts" / "yade_batch_table.txt")],
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    )
    lines = json.loads(done.stdout.strip().splitlines()[-1])
    assert len(lines) == 13
    for line in lines.values():
        params = {k: (v if k == "description" else eval(v)) for k, v in line.items()}
        params["out"] = str(tmp_path)  # not the real reports/
        case, folder = batch_run(params)
        assert folder.name == line["description"] and case.geometry.n_voussoirs == 55


def test_a_sigkilled_campaign_leaves_no_orphan_and_resumes_where_it_stopped(tmp_path):
    """Kill -9 the campaign while its second run works: the running child dies with it (no orphan
    YADE), results.csv already holds the finished run, and the next invocation redoes only the rest."""
    import os
    import signal
    import time

    out = tmp_path / "sweep"
    table = tmp_path / "table.csv"
    # runs start in decreasing expected cost (sqrt(kn)): kn 0.12 first, then kn 0.1 (about 10 s at
    # SLOWER_RATE; 3 s at the coarse rate on a fast day, too short for the kill 2 s in to land in it)
    table.write_text("kn_N_per_mm3\n0.12\n0.1\n")
    argv = [
        sys.executable,
        "-m",
        "yadearch.cli",
        "sweep",
        *slowed(COARSE, SLOWER_RATE),
        "--table",
        str(table),
        "--out",
        str(out),
        "--jobs",
        "1",
        "--no-figures",
    ]
    campaign = subprocess.Popen(argv, cwd=REPO, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.time() + 300
    first, second = "kn0.12", "kn0.1"
    while not list(out.glob(f".{second}.partial/run.log")) and time.time() < deadline:
        time.sleep(0.1)
    time.sleep(2.0)  # the second run is inside YADE now
    os.kill(campaign.pid, signal.SIGKILL)
    campaign.wait(timeout=30)

    def orphans() -> list[str]:
        found = subprocess.run(["pgrep", "-f", str(out)], capture_output=True, text=True).stdout.split()
        return [pid for pid in found if int(pid) != os.getpid()]

    for _ in range(50):
        if not orphans():
            break
        time.sleep(0.2)
    assert not orphans(), "a run outlived its killed campaign"
    results = pd.read_csv(out / RESULTS_FILE)
    assert results.set_index("run").loc[first, "status"] == "done"
    assert not (out / second / "summary.json").exists()
    finished = {p: p.stat().st_mtime_ns for p in (out / first).iterdir()}
    subprocess.run(argv, cwd=REPO, check=True, capture_output=True, timeout=600)
    assert {p: p.stat().st_mtime_ns for p in (out / first).iterdir()} == finished
    results = pd.read_csv(out / RESULTS_FILE)
    assert results["status"].tolist() == ["done", "done"] and results["du_mm"].notna().all()


def test_ctrl_c_at_a_terminal_interrupts_a_run_instead_of_failing_it(tmp_path):
    """SIGINT to the whole process group of `yadearch run`, as a terminal's Ctrl-C sends it, while
    YADE runs: the run ends as interrupted (the simulation stopped by SIGTERM from its parent, its
    log says so), not as failed (before: "RuntimeError: release unlocked lock"); and leaves behind
    no yade-XXXXXX folder of its own (only the one its simulation recorded is counted: another YADE
    process on the machine makes and keeps its own)."""
    import os
    import signal
    import time

    from yadearch.dem.simulate import SCRATCH_RECORD

    out = tmp_path / "run"
    argv = [sys.executable, "-m", "yadearch.cli", "run", *slowed(COARSE, SLOW_RATE), "--kn", "0.1", "--out", str(out)]
    run = subprocess.Popen(
        argv,
        cwd=REPO,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,  # a group of its own, as a terminal's foreground job
        # ... which takes Ctrl-C: a test worker (pytest-xdist's) may ignore SIGINT, and children inherit that
        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL),
    )
    log, record = tmp_path / ".run.partial" / "run.log", tmp_path / ".run.partial" / SCRATCH_RECORD
    deadline = time.time() + 120
    while not (log.is_file() and record.is_file() and record.read_text().strip()) and time.time() < deadline:
        time.sleep(0.1)
    scratch = Path(record.read_text().strip())  # the yade-XXXXXX folder this run's YADE made
    assert scratch.name.startswith("yade-") and scratch.is_dir()
    time.sleep(3.0)  # inside YADE now (the run takes ~30 s at SLOW_RATE; 3 s at the coarse rate on a fast day)
    os.killpg(run.pid, signal.SIGINT)
    _, stderr = run.communicate(timeout=60)
    assert run.returncode == 1 and "was interrupted" in stderr and "run it again to resume" in stderr, stderr
    assert "INTERRUPTED: SIGTERM" in (out / "run.log").read_text()
    assert not (out / "summary.json").exists()
    assert not scratch.exists()  # YADE's temporary folder went with the run
    assert not (out / ".yade_scratch").exists()
