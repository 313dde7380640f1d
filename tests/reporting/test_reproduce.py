"""`yadearch reproduce` resumes: a finished run of exactly the preset's case is reused, anything else
runs (no YADE: the runs and the report are replaced by recorders)."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from yadearch.api import runs as api_runs
from yadearch.case.config import preset
from yadearch.cli import commands as cli
from yadearch.launch import process
from yadearch.results.reuse import holds_case
from yadearch.results.rundir import CASE_FILE, write_run
from yadearch.results.summary import RunSummary


def finished(folder: Path, case_toml: str) -> None:
    write_run(
        folder,
        case_toml,
        [{"stage": "equilibrium", "delta_mm": 0.0}],
        [{"stage": "equilibrium", "interface": 1}],
        {},
        RunSummary(name=folder.name, du_mm=48.0, steps=10, wall_s=1.0, hinges_at_collapse=()),
    )


def test_only_a_finished_run_of_the_same_case_is_reusable(tmp_path):
    case = preset("set1")
    finished(tmp_path / "same", case.to_toml())
    finished(tmp_path / "other", case.with_overrides({"numerics.damping": 0.3}).to_toml())
    (tmp_path / "unfinished").mkdir()
    (tmp_path / "unfinished" / CASE_FILE).write_text(case.to_toml())
    assert holds_case(tmp_path / "same", case)
    assert not holds_case(tmp_path / "other", case)
    assert not holds_case(tmp_path / "unfinished", case)
    renamed = preset("set1")
    renamed.name = "mine"
    assert holds_case(tmp_path / "same", renamed)  # the name is not part of the physics


def test_reproduce_runs_only_what_is_missing(tmp_path, monkeypatch):
    ran: list[str] = []

    def fake_run(case, folder):
        ran.append(folder.name)
        finished(folder, case.to_toml())

    monkeypatch.setattr(process, "run_case_process", fake_run)
    monkeypatch.setattr(api_runs, "report", lambda folders, out: Path(out) / "report.md")
    finished(tmp_path / "set1", preset("set1").to_toml())
    result = CliRunner().invoke(cli.cli, ["reproduce", "--out", str(tmp_path), "--jobs", "1"])
    assert result.exit_code == 0, result.output
    assert ran == ["set2"] and "set1: reusing the finished run" in result.output
    result = CliRunner().invoke(cli.cli, ["reproduce", "--out", str(tmp_path), "--jobs", "1", "--rerun"])
    assert result.exit_code == 0, result.output
    assert ran == ["set2", "set1", "set2"]


def test_the_static_engine_reproduces_the_paper_as_the_dem_does(tmp_path):
    """`yadearch reproduce --engine static`: both paper cases in seconds, no YADE; du within 0.2 % of
    the DEM's committed runs (47.05 and 87.99 mm), the same hinges for set 2, and the report names the
    engine."""
    import json

    result = CliRunner().invoke(cli.cli, ["reproduce", "--engine", "static", "--out", str(tmp_path)])
    assert result.exit_code == 0, result.output
    repo = Path(__file__).resolve().parents[2]
    for name in ("set1", "set2"):
        static = json.loads((tmp_path / name / "summary.json").read_text())
        dem = json.loads((repo / "reports" / name / "summary.json").read_text())
        assert static["engine"] == "static" and dem["engine"] == "dem"
        assert abs(static["du_mm"] - dem["du_mm"]) <= 0.002 * dem["du_mm"], (name, static["du_mm"], dem["du_mm"])
    assert (
        "| set2 | static | right support moving at -90° (settlement) | 87.99 |" in (tmp_path / "report.md").read_text()
    )
