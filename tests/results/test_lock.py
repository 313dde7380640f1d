"""One writer per folder: a run or a campaign whose folder another process is writing is refused at
once, in one line naming that process; the lock goes with its holder, however the holder ends."""

from __future__ import annotations

import os
import subprocess
import sys
import time

import pytest

from yadearch.cli.commands import main
from yadearch.results.lock import FolderBusyError, folder_lock, lock_path

HOLD = """
import sys, time
from pathlib import Path
from yadearch.results.lock import folder_lock
with folder_lock(Path(sys.argv[1])):
    print("held", flush=True)
    time.sleep(60)
"""


@pytest.fixture
def holder(tmp_path):
    """Another process holding the lock of tmp_path/run."""
    proc = subprocess.Popen([sys.executable, "-c", HOLD, str(tmp_path / "run")], stdout=subprocess.PIPE, text=True)
    assert proc.stdout.readline().strip() == "held"
    yield proc
    proc.kill()
    proc.wait()


def test_a_second_run_into_a_busy_folder_is_refused_naming_the_holder(holder, tmp_path, capsys):
    code = main(
        ["run", "--preset", "set2", "--engine", "static", "--set", "n_voussoirs=9", "--out", str(tmp_path / "run")]
    )
    err = capsys.readouterr().err.strip()
    assert code == 1 and "\n" not in err
    assert (
        err == f"error: {tmp_path / 'run'} is in use by another run (process {holder.pid}); wait for it to end "
        "or choose another --out"
    )
    assert not (tmp_path / "run").exists()


def test_the_lock_goes_with_its_holder_however_it_ends(holder, tmp_path):
    holder.kill()  # SIGKILL: no cleanup ran
    holder.wait()
    with folder_lock(tmp_path / "run"):
        assert lock_path(tmp_path / "run").read_text().strip() == str(os.getpid())
    assert not lock_path(tmp_path / "run").exists()


def test_a_campaign_folder_is_locked_too(tmp_path):
    from yadearch.case.config import preset
    from yadearch.studies.campaigns.executors import local_pool
    from yadearch.studies.campaigns.runner import run_campaign

    started = time.time()
    with folder_lock(tmp_path / "campaign", "campaign"):
        proc = subprocess.run(
            [
                sys.executable,
                "-c",
                "import sys; from pathlib import Path; "
                "from yadearch.results.lock import folder_lock\n"
                "with folder_lock(Path(sys.argv[1]), 'campaign'): pass",
                str(tmp_path / "campaign"),
            ],
            capture_output=True,
            text=True,
        )
        assert "is in use by another campaign" in proc.stderr
        with local_pool(1) as pool, pytest.raises(FolderBusyError):
            # the same process, another open file: flock refuses it as it refuses another process
            run_campaign(preset("set2"), [{"kn_N_per_mm3": 1.0}], tmp_path / "campaign", pool, progress=False)
    assert time.time() - started < 30
