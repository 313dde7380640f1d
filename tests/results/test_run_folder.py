"""Run folders cannot lie (no YADE: the child process is replaced by a fake): a summary that does not
validate means an unfinished run, a run that fails never destroys a finished one, `run` reuses the
same case and refuses to overwrite another."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import pytest

import yadearch as ya
from yadearch.case.config import preset
from yadearch.errors import CaseError, RunFailedError, RunFolderError
from yadearch.launch import process
from yadearch.results.reuse import case_differences
from yadearch.results.rundir import LOG_FILE, SUMMARY_FILE, is_complete, read_run, write_run
from yadearch.results.summary import RunSummary


def summary_of(du_mm: float) -> RunSummary:
    return RunSummary(name="set2", du_mm=du_mm, collapsed=True, hinges_at_collapse=(), steps=10, wall_s=1.0)


def finished(folder: Path, case=None, du_mm: float = 87.0) -> None:
    case = case or preset("set2")
    write_run(
        folder,
        case.to_toml(),
        [{"stage": "equilibrium", "delta_mm": 0.0}],
        [{"stage": "equilibrium", "interface": 1}],
        {},
        summary_of(du_mm),
    )


@pytest.mark.parametrize(
    "damage", ["truncated", "empty object", "not an object", "newer schema", "unmarked", "missing key"]
)
def test_a_summary_that_does_not_validate_is_an_unfinished_run(tmp_path, damage):
    finished(tmp_path)
    summary_file = tmp_path / SUMMARY_FILE
    text = summary_file.read_text()
    summary = json.loads(text)
    damaged = {
        "truncated": text[: len(text) // 2],
        "empty object": "{}",
        "not an object": "[1, 2]",
        "newer schema": json.dumps({**summary, "schema_version": 99}),
        "unmarked": json.dumps({**summary, "complete": False}),
        "missing key": json.dumps({k: v for k, v in summary.items() if k != "du_mm"}),
    }[damage]
    summary_file.write_text(damaged)
    assert not is_complete(tmp_path)
    with pytest.raises(RunFolderError) as error:
        read_run(tmp_path)
    assert str(tmp_path) in str(error.value) and "\n" not in str(error.value)


def test_a_complete_folder_reads_back_with_its_schema_marker(tmp_path):
    finished(tmp_path)
    written = json.loads((tmp_path / SUMMARY_FILE).read_text())
    assert written["complete"] is True and written["schema_version"] >= 1
    assert read_run(tmp_path).summary == dataclasses.replace(summary_of(87.0), table_rows=written["table_rows"])
    assert not list(tmp_path.glob(".*.tmp"))  # every file was renamed into place


class FakeChild:
    """Stands in for `python -m yadearch.dem.simulate`: writes a log, and a finished run if `ok`."""

    def __init__(self, ok: bool):
        self.ok = ok

    def __call__(self, cmd, env, timeout_s, quiet):
        staging = Path(cmd[-1])
        (staging / LOG_FILE).write_text("started\n")
        if self.ok:
            finished(staging, du_mm=42.0)
        return (0, "") if self.ok else (1, "boom")


@pytest.fixture
def no_yade_check(monkeypatch):
    monkeypatch.setattr(process, "check_yade_installed", lambda: None)


def test_a_failed_run_leaves_the_finished_run_in_place(tmp_path, monkeypatch, no_yade_check):
    finished(tmp_path / "run")
    monkeypatch.setattr(process, "run_child", FakeChild(ok=False))
    with pytest.raises(RunFailedError, match="boom") as error:
        process.run_case_process(preset("set2"), tmp_path / "run")
    assert read_run(tmp_path / "run").summary.du_mm == 87.0
    assert ".run.partial" in str(error.value)  # the failed run's log is kept beside it


def test_a_finished_run_replaces_the_folder_only_when_complete(tmp_path, monkeypatch, no_yade_check):
    finished(tmp_path / "run")
    monkeypatch.setattr(process, "run_child", FakeChild(ok=True))
    process.run_case_process(preset("set2"), tmp_path / "run")
    assert read_run(tmp_path / "run").summary.du_mm == 42.0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run"]  # no staging or replaced folder left


def test_run_reuses_the_same_case_and_refuses_another(tmp_path, monkeypatch):
    finished(tmp_path / "run")
    calls = []
    monkeypatch.setattr(process, "run_case_process", lambda case, folder, timeout_s=None: calls.append(1))
    assert ya.run(preset("set2"), out=tmp_path / "run", figures=False).du_mm == 87.0 and calls == []
    with pytest.raises(RunFolderError, match="another case .*kn_N_per_mm3"):
        ya.run(preset("set2").replace(kn_N_per_mm3=10.0), out=tmp_path / "run", figures=False)
    assert read_run(tmp_path / "run").summary.du_mm == 87.0


def test_what_a_folder_keeps_is_not_part_of_its_case(tmp_path):
    """A campaign of runs that keep only their summary resumes over folders that kept everything, not
    the reverse (a summary has no tables to give); a single run refuses 'summary' in one line, its
    result and figures being its tables."""
    finished(tmp_path / "run")
    lean = preset("set2").with_overrides({"numerics.run_files": "summary"})
    assert case_differences(tmp_path / "run", lean) == []  # a whole folder serves a summary
    finished(tmp_path / "lean", lean)
    assert case_differences(tmp_path / "lean", preset("set2")) == [
        "numerics.run_files: ran 'summary' (no tables), wanted 'full'"
    ]
    with pytest.raises(CaseError, match="numerics.run_files = 'summary' keeps no tables"):
        ya.run(lean, out=tmp_path / "other", figures=False)
    assert not (tmp_path / "other").exists()


def test_an_interrupted_run_is_not_a_failure_and_stays_pending(tmp_path, monkeypatch, no_yade_check):
    from yadearch.errors import RunInterruptedError
    from yadearch.studies.campaigns.failures import FAILED_FILE
    from yadearch.studies.campaigns.runner import execute

    def interrupted_child(cmd, env, timeout_s, quiet):
        (Path(cmd[-1]) / LOG_FILE).write_text("INTERRUPTED: SIGTERM\n")
        return 130, "error: interrupted (SIGTERM)"

    monkeypatch.setattr(process, "run_child", interrupted_child)
    with pytest.raises(RunInterruptedError, match="interrupted"):
        process.run_case_process(preset("set2"), tmp_path / "run")
    outcome = execute(preset("set2"), tmp_path / "other", None)
    assert outcome["status"] == "interrupted" and not (tmp_path / "other" / FAILED_FILE).exists()


def test_stale_temporaries_of_killed_writes_are_removed_and_nothing_else(tmp_path):
    from yadearch.atomic import remove_stale_temporaries

    stale = tmp_path / ".results.csv.abc123.tmp"
    stale.write_text("half")
    kept = [tmp_path / "results.csv", tmp_path / ".kn1.partial", tmp_path / "notes.tmp"]
    kept[0].write_text("run\n")
    kept[1].mkdir()
    kept[2].write_text("mine")
    assert remove_stale_temporaries(tmp_path) == [stale]
    assert not stale.exists() and all(p.exists() for p in kept)


def test_a_table_cut_short_after_the_run_is_an_error_not_half_a_table(tmp_path):
    from synthetic_runs import make_run

    make_run(tmp_path / "run")
    joints = tmp_path / "run" / "joints.csv"
    assert len(ya.open_run(tmp_path / "run").joints) > 100
    lines = joints.read_text().splitlines(keepends=True)
    joints.write_text("".join(lines[: len(lines) // 2]))  # a copy that stopped half-way
    with pytest.raises(RunFolderError, match=r"joints.csv has \d+ rows where the run wrote \d+: it was cut short"):
        _ = ya.open_run(tmp_path / "run").joints


def test_a_static_run_of_another_engine_revision_is_made_again_not_reused(tmp_path):
    """The static engine's results change with its revision: a run or a failure it recorded under
    another revision is made again by `run` and by campaigns; a current one is reused."""
    from yadearch.results.reuse import is_current, outdated
    from yadearch.studies.campaigns.failures import FAILED_FILE, failure_stands, record_failure

    case = preset("set1").replace(n_voussoirs=9, kn_N_per_mm3=1.0)
    first = ya.run(case, engine="static", out=tmp_path / "run", quiet=True, figures=False)
    assert is_current(first.path) and not outdated(first.path)
    summary_path = first.path / SUMMARY_FILE
    written = json.loads(summary_path.read_text())
    written.pop("engine_revision")  # as the first revision wrote it
    written["started"] = "2000-01-01T00:00:00"
    summary_path.write_text(json.dumps(written))
    assert outdated(first.path) and is_complete(first.path)
    again = ya.run(case, engine="static", out=tmp_path / "run", quiet=True, figures=False)
    assert not outdated(again.path) and again.summary.started != written["started"]
    assert again.summary.du_mm == pytest.approx(written["du_mm"], rel=1e-9)  # the perfect arch: same du

    static = case.replace(engine="static")
    record_failure(tmp_path, static, "cannot stand", 1.0)
    assert failure_stands(tmp_path, static)
    record = json.loads((tmp_path / FAILED_FILE).read_text())
    record.pop("engine_revision")
    (tmp_path / FAILED_FILE).write_text(json.dumps(record))
    assert not failure_stands(tmp_path, static)  # a static failure of another revision is tried again
    assert failure_stands(tmp_path, case)  # a DEM run's failure stands


def test_a_results_row_never_shows_an_outdated_run_as_today_s(tmp_path):
    """A static run of another engine revision whose remake failed keeps its old folder (a failed
    run never destroys a finished one): its results row is the failure, not the old du; without a
    remake it is pending."""
    from yadearch.studies.campaigns.failures import record_failure
    from yadearch.studies.campaigns.table import RunSpec, run_row

    case = preset("set1").replace(n_voussoirs=9, kn_N_per_mm3=1.0, engine="static")
    ya.run(case, out=tmp_path / "run", quiet=True, figures=False)
    summary_path = tmp_path / "run" / SUMMARY_FILE
    written = json.loads(summary_path.read_text())
    written.pop("engine_revision")  # as the first revision wrote it
    summary_path.write_text(json.dumps(written))
    spec = RunSpec("run", {}, tmp_path / "run", case)
    assert run_row(spec, tmp_path)["status"] == "pending"
    record_failure(tmp_path / "run", case, "the arch does not stand under its own weight", 0.1)
    row = run_row(spec, tmp_path)
    assert row["status"] == "failed" and row["reason"].startswith("the arch does not stand")
    assert row["du_mm"] != row["du_mm"]  # NaN: no du from the outdated run
