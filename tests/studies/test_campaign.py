"""Campaigns without YADE: values and grids, run names, tables, resumability and failures with a
stand-in task, hinge labels, the yade-batch table, the kn figure and the sweep command's usage errors."""

from __future__ import annotations

import json
import math
import re
import shutil
import sys
import threading
from pathlib import Path

import pandas as pd
import pytest
from click.testing import CliRunner
from conftest import REPO

from yadearch.case.config import preset
from yadearch.cli.campaigns import sweep
from yadearch.errors import CampaignError, CaseError, YadearchError
from yadearch.launch.process import exit_reason
from yadearch.plotting.sweep import kn_sweep_figure
from yadearch.results.summary import RunSummary
from yadearch.studies.campaigns.executors import local_pool
from yadearch.studies.campaigns.failures import record_failure
from yadearch.studies.campaigns.grid import RUN_COLUMN, grid, parse_values, read_table, run_tag
from yadearch.studies.campaigns.runner import (
    FAILED_FILE,
    RESULTS_EVERY_S,
    RESULTS_FILE,
    batch_run,
    plan,
    results_interval,
    run_campaign,
)
from yadearch.studies.campaigns.sessions import SESSIONS_FILE, campaign_wall_s
from yadearch.studies.campaigns.table import RESULTS_COST_SHARE, label_hinges

BASE = preset("set1").with_overrides({"n_voussoirs": 15})
HINGES = [
    {"interface": 1, "side": "E"},
    {"interface": 3, "side": "I"},
    {"interface": 8, "side": "E"},
    {"interface": 12, "side": "I"},
    {"interface": 16, "side": "E"},
]


class FakeRuns:
    """A stand-in for the simulation process: du = 50 + 10 log10(kn); kn in `fail` fails; counts calls."""

    def __init__(self, fail: tuple[float, ...] = (), interrupt_after: int | None = None) -> None:
        self.fail, self.interrupt_after, self.calls = fail, interrupt_after, []
        self.lock = threading.Lock()

    def __call__(self, case, folder: Path, timeout_s):
        with self.lock:
            self.calls.append(case.name)
            if self.interrupt_after is not None and len(self.calls) > self.interrupt_after:
                raise KeyboardInterrupt
        folder.mkdir(parents=True, exist_ok=True)
        (folder / "case.toml").write_text(case.to_toml())
        kn = case.interface.kn_N_per_mm3
        if kn in self.fail:
            record_failure(folder, case, f"run {case.name!r} timed out after 1 s", 1.0)
            return {"status": "failed", "reason": "timed out"}
        (folder / "summary.json").write_text(
            json.dumps(
                {
                    "du_mm": 50 + 10 * math.log10(kn),
                    "collapsed": True,
                    "hinges_at_collapse": HINGES,
                    "steps": 100,
                    "wall_s": 2.0,
                }
            )
        )
        return {"status": "done", "reason": ""}


def campaign(out: Path, task: FakeRuns, rows: list[dict]) -> pd.DataFrame:
    with local_pool(2) as pool:
        return run_campaign(BASE, rows, out, pool, progress=False, task=task)


def test_parse_values_lists_and_ranges():
    assert parse_values("0.25,5.2") == [0.25, 5.2]
    assert parse_values("0.1:100:log:13") == [
        0.1,
        0.1778,
        0.3162,
        0.5623,
        1.0,
        1.778,
        3.162,
        5.623,
        10.0,
        17.78,
        31.62,
        56.23,
        100.0,
    ]
    assert parse_values("9:15:lin:4") == [9, 11, 13, 15]
    assert parse_values("true,false") == [True, False]
    for bad in ("1:2:cubic:3", "0:10:log:3", "1:2:lin:0", ""):
        with pytest.raises(YadearchError):
            parse_values(bad)


def test_grid_is_the_product_and_names_are_deterministic():
    rows = grid({"kn_N_per_mm3": [0.1, 1.0], "numerics.damping": [0.1, 0.2]})
    assert rows[1] == {"kn_N_per_mm3": 0.1, "numerics.damping": 0.2} and len(rows) == 4
    assert [run_tag(r) for r in rows] == ["kn0.1_damping0.1", "kn0.1_damping0.2", "kn1_damping0.1", "kn1_damping0.2"]
    long = {
        "kn_N_per_mm3": 0.1,
        "support_direction_deg": -90.0,
        "max_support_displacement_mm": 150.0,
        "hinge_rotation_mrad": 2.0,
        "first_increment_mm": 2.0,
    }
    assert run_tag(long) == run_tag(dict(long)) and len(run_tag(long)) <= 64
    assert run_tag(long) != run_tag({**long, "first_increment_mm": 1.0})
    with pytest.raises(CaseError, match="unknown parameter 'knn'"):
        grid({"knn": [1]})


def test_explicit_table(tmp_path):
    table = tmp_path / "runs.csv"
    table.write_text("run,kn_N_per_mm3,interface.ks_over_kn\nsoft,0.1,\nstiff,10,0.4\n")
    rows = read_table(table)
    assert rows == [
        {"run": "soft", "kn_N_per_mm3": 0.1},
        {"run": "stiff", "kn_N_per_mm3": 10, "interface.ks_over_kn": 0.4},
    ]
    specs = plan(BASE, rows, tmp_path / "c")
    assert [s.folder.name for s in specs] == ["soft", "stiff"]
    assert specs[1].case.interface.ks_over_kn == 0.4 and specs[0].case.interface.ks_over_kn == 0.5
    table.write_text("kn_N_per_mm3,colour\n1,red\n")
    with pytest.raises(CaseError, match="colour"):
        read_table(table)
    table.write_text("kn_N_per_mm3,thickness_mm\n5,24\n10\n")  # a short row: a mistake, not an empty cell
    with pytest.raises(CampaignError, match=r"row 3 has 1 of the header's 2 cells; leave a cell empty"):
        read_table(table)


def test_a_table_names_a_movement_and_a_material_as_set_does(tmp_path):
    """Found in a user trial: `--set movement=spreading` worked where a `movement` column was an unknown
    parameter; a named movement (and a named material) stands for its parameters in a table too."""
    table = tmp_path / "runs.csv"
    table.write_text("run,movement,material\nspread,spreading,\nclose,closing,\n")
    specs = plan(BASE, read_table(table), tmp_path / "c")
    assert [s.case.loading.support_direction_deg for s in specs] == [0.0, 180.0]
    table.write_text("run,movement\nx,sideways\n")
    with pytest.raises(CaseError, match="movement must be one of .*got 'sideways'"):
        plan(BASE, read_table(table), tmp_path / "d")
    table.write_text("run,movement,support_direction_deg\nx,spreading,-45\n")  # which one wins? neither
    with pytest.raises(CaseError, match="support_direction_deg is given beside a named movement"):
        plan(BASE, read_table(table), tmp_path / "e")
    from yadearch.studies.campaigns.grid import check_parameter

    with pytest.raises(CaseError, match="movement names a choice, not a number"):
        check_parameter("movement", numeric=True)


def test_a_table_naming_two_runs_alike_is_refused_naming_them(tmp_path):
    rows = [{"run": "a", "kn_N_per_mm3": 1}, {"run": "b", "kn_N_per_mm3": 2}, {"run": "a", "kn_N_per_mm3": 3}]
    with pytest.raises(YadearchError, match=r"duplicate runs \['a'\]"):
        plan(BASE, rows, tmp_path / "c")


def test_the_costliest_runs_start_first(tmp_path):
    """Stiff joints need the most steps (smaller time step, slower loading): they start first."""
    task = FakeRuns()
    with local_pool(1) as pool:
        run_campaign(BASE, grid({"kn_N_per_mm3": [0.1, 100.0, 1.0, 31.62]}), tmp_path, pool, progress=False, task=task)
    assert task.calls == ["kn100", "kn31.62", "kn1", "kn0.1"]


def test_results_table_with_a_failed_run(tmp_path):
    task = FakeRuns(fail=(10.0,))
    rows = grid({"kn_N_per_mm3": [0.1, 1.0, 10.0]})
    table = campaign(tmp_path, task, rows)
    assert sorted(task.calls) == ["kn0.1", "kn1", "kn10"]
    read = pd.read_csv(tmp_path / RESULTS_FILE)
    for column in (
        "run",
        "kn_N_per_mm3",
        "du_mm",
        "hinges",
        "mechanism",
        "hinge_A",
        "hinge_B",
        "hinge_C",
        "hinge_D",
        "status",
        "reason",
        "wall_s",
    ):
        assert column in read.columns
    assert list(read["status"]) == ["done", "done", "failed"]
    assert read["du_mm"].tolist()[:2] == pytest.approx([40.0, 50.0])
    assert "timed out" in read.loc[2, "reason"]
    assert json.loads((tmp_path / "kn10" / FAILED_FILE).read_text())["reason"].endswith("after 1 s")
    assert read.loc[0, "mechanism"] == "E-I-E-I-E" and read.loc[0, "hinges"] == "1E 3I 8E 12I 16E"
    assert table.loc[0, ["hinge_A", "hinge_B", "hinge_C", "hinge_D"]].tolist() == [3, 8, 16, 1]


def test_an_invalid_value_anywhere_in_the_grid_refuses_the_campaign_before_any_run(tmp_path):
    task = FakeRuns()
    with pytest.raises(
        CaseError,
        match=r"run kn-1: kn_N_per_mm3 must be in \(0, 100000\], got -1.0 \(and 1 more of "
        r"the 4 runs\); nothing was run",
    ):
        campaign(tmp_path, task, grid({"kn_N_per_mm3": [0.1, -1.0, 1.0, -2.0]}))
    assert task.calls == [] and not (tmp_path / RESULTS_FILE).exists()


@pytest.mark.parametrize(
    "params, message",
    [
        ({"kn_N_per_mm3": []}, "kn_N_per_mm3: no values to run"),
        (
            {"kn_N_per_mm3": list(range(1, 400)), "n_voussoirs": list(range(3, 303))},
            "campaign of 119700 runs exceeds the bound of 100000; set YADEARCH_MAX_RUNS to raise it",
        ),
    ],
)
def test_empty_and_huge_grids_are_refused_in_one_line(params, message):
    with pytest.raises(CampaignError, match=re.escape(message)):
        grid(params)


def test_a_scalar_where_a_list_of_values_is_expected_is_a_type_error():
    with pytest.raises(TypeError, match="kn_N_per_mm3: give a list of values, got 5"):
        grid({"kn_N_per_mm3": 5})


def test_a_resumed_campaign_plans_only_the_runs_it_has_to_make(tmp_path, monkeypatch):
    """A finished run of the same case was checked when it ran: planning a grown campaign (the
    sensitivity study's 57 000 runs, half of them done) checks only the new and the failed ones."""
    from yadearch.studies.campaigns import runner as campaign_module

    rows = grid({"kn_N_per_mm3": [0.1, 1.0, 10.0]})
    campaign(tmp_path, FakeRuns(fail=(0.1,)), rows)
    planned = []
    monkeypatch.setattr(campaign_module, "plan_run", lambda case: planned.append(case.name))
    specs = plan(BASE, grid({"kn_N_per_mm3": [0.1, 1.0, 10.0, 100.0]}), tmp_path)
    assert len(specs) == 4 and sorted(planned) == ["kn0.1", "kn100"]


def test_a_large_results_table_is_rewritten_less_often_than_a_small_one():
    assert results_interval(0.01) == RESULTS_EVERY_S
    assert results_interval(1.7) == pytest.approx(1.7 / RESULTS_COST_SHARE)  # 57 000 runs: every 34 s


def test_resume_redoes_only_unfinished_runs(tmp_path):
    rows = grid({"kn_N_per_mm3": [0.1, 1.0, 10.0]})
    with pytest.raises(KeyboardInterrupt):  # "killed" after its first finished run (the stiffest)
        with local_pool(1) as pool:
            run_campaign(BASE, rows, tmp_path, pool, progress=False, task=FakeRuns(interrupt_after=1))
    statuses = pd.read_csv(tmp_path / RESULTS_FILE)["status"].tolist()
    assert statuses == ["pending", "pending", "done"]
    first = (tmp_path / "kn10" / "summary.json").stat().st_mtime_ns
    again = FakeRuns(fail=(0.1,))
    campaign(tmp_path, again, rows)
    assert sorted(again.calls) == ["kn0.1", "kn1"]
    kept = FakeRuns()
    with local_pool(1) as pool:
        run_campaign(BASE, rows, tmp_path, pool, progress=False, task=kept, retry_failed=False)
    assert kept.calls == [] and (tmp_path / "kn0.1" / FAILED_FILE).exists()  # the failure stays
    assert (tmp_path / "kn10" / "summary.json").stat().st_mtime_ns == first
    third = FakeRuns()
    table = campaign(tmp_path, third, rows)
    assert third.calls == ["kn0.1"] and set(table["status"]) == {"done"}  # failed runs are redone
    assert not (tmp_path / "kn0.1" / FAILED_FILE).exists()
    sessions = json.loads((tmp_path / SESSIONS_FILE).read_text())
    assert [s["runs_attempted"] for s in sessions] == [3, 2, 1]  # invocations that ran something
    assert campaign_wall_s(tmp_path) == pytest.approx(sum(s["wall_s"] for s in sessions))
    campaign(tmp_path, FakeRuns(), rows)  # nothing to do: no session recorded
    assert len(json.loads((tmp_path / SESSIONS_FILE).read_text())) == 3
    for name in ("kn0.1", "kn1", "kn10"):  # every run made again: the record starts again
        shutil.rmtree(tmp_path / name)
    campaign(tmp_path, FakeRuns(), rows)
    assert [s["runs_attempted"] for s in json.loads((tmp_path / SESSIONS_FILE).read_text())] == [3]


def test_resume_refuses_a_folder_of_another_case(tmp_path):
    rows = grid({"kn_N_per_mm3": [0.1]})
    campaign(tmp_path, FakeRuns(), rows)
    with local_pool(1) as pool, pytest.raises(YadearchError, match="damping"):
        run_campaign(BASE.with_overrides({"damping": 0.3}), rows, tmp_path, pool, progress=False, task=FakeRuns())


def test_resume_accepts_a_run_that_predates_a_parameter_at_its_default(tmp_path):
    rows = grid({"kn_N_per_mm3": [0.1]})
    campaign(tmp_path, FakeRuns(), rows)
    case_file = tmp_path / "kn0.1" / "case.toml"
    text = case_file.read_text()
    assert "hold_damping = 0.2\n" in text
    case_file.write_text(text.replace("hold_damping = 0.2\n", ""))
    again = FakeRuns()
    campaign(tmp_path, again, rows)
    assert again.calls == []  # a run made before hold_damping existed ran it at its default


def test_hinge_labels_follow_the_paper():
    detail = [{**h, "rotation_mrad": r} for h, r in zip(HINGES, (147, 460, 231, 8, 93))]

    def summary(hinges: list[dict], detail: list[dict]) -> RunSummary:
        return RunSummary.from_json(
            {"du_mm": 50.0, "steps": 1, "wall_s": 1.0, "hinges_at_collapse": hinges, "hinges_detail": detail}
        )

    labels = label_hinges(summary(HINGES, detail), 15)
    assert labels == {"hinge_A": 3, "hinge_B": 8, "hinge_C": 16, "hinge_D": 1}
    assert label_hinges(summary([], []), 15) == dict.fromkeys(labels)


def read_batch_table(path: Path) -> list[dict]:
    """The yade-batch table as yade.utils.readParamsFromTable reads it (blank-separated, # comments,
    values evaluated as Python)."""
    lines = [re.sub(r"\s*#.*", "", line).split() for line in path.read_text().splitlines()]
    lines = [line for line in lines if line]
    return [
        {k: eval(v, math.__dict__) if k != "description" else v for k, v in zip(lines[0], line)} for line in lines[1:]
    ]


def test_yade_batch_table_maps_to_the_sweep_runs(tmp_path):
    rows = read_batch_table(REPO / "scripts" / "yade_batch_table.txt")
    assert [r["kn_N_per_mm3"] for r in rows] == parse_values("0.1:100:log:13")
    assert {r["out"] for r in rows} == {"runs/kn-sweep"} and {r["preset"] for r in rows} == {"set2"}
    runs = [batch_run({**row, "out": str(tmp_path)}) for row in rows]  # not the real reports/
    for row, (case, folder) in zip(rows, runs):
        assert folder == tmp_path / row["description"]
        assert case.interface.kn_N_per_mm3 == row["kn_N_per_mm3"] and case.name == row["description"]
        assert case.geometry.n_voussoirs == 55
    with pytest.raises(CaseError):
        batch_run({"preset": "set2", "kn_N_per_mm3": -1})


def test_kn_figure(tmp_path):
    table = campaign(tmp_path, FakeRuns(fail=(10.0,)), grid({"kn_N_per_mm3": [0.1, 1.0, 10.0, 100.0]}))
    for du_rigid_mm in (None, 113.5):  # the stiffest run, or the rigid-block limit, as the asymptote
        paths = kn_sweep_figure(table, tmp_path / "du_vs_kn", du_rigid_mm)
        assert [p.suffix for p in paths] == [".pdf", ".png"] and all(p.stat().st_size > 1000 for p in paths)


def test_a_sweep_of_other_parameters_draws_du_against_each(tmp_path):
    from yadearch.plotting.sweep import parameter_sweep_figure, swept_columns

    table = campaign(tmp_path, FakeRuns(), grid({"kn_N_per_mm3": [0.1, 1.0, 10.0], "damping": [0.1, 0.3]}))
    swept = ["kn_N_per_mm3", "damping"]
    assert swept_columns(table, swept) == swept
    for column in swept_columns(table, swept):
        paths = parameter_sweep_figure(table, column, tmp_path / f"du_vs_{column}", swept)
        assert all(p.stat().st_size > 1000 for p in paths)


@pytest.mark.parametrize(
    "args, message",
    [
        ([], "nothing to sweep"),
        (["--kn", "1,2", "--table", "t.csv"], "either --table"),
        (["--param", "kn_N_per_mm3"], "NAME=VALUES"),
    ],
)
def test_sweep_usage_errors(tmp_path, args, message):
    result = CliRunner().invoke(sweep, ["--preset", "set1", "--out", str(tmp_path), *args])
    assert result.exit_code != 0 and message in result.output


def test_exit_reason_names_the_signal_that_ended_a_run():
    assert exit_reason(-15) == "killed by SIGTERM"
    assert exit_reason(-9) == "killed by SIGKILL"
    assert exit_reason(1) == "exit code 1"


def test_a_cluster_without_dask_installed_is_a_one_line_error(monkeypatch):
    from yadearch.studies.campaigns.executors import open_pool

    monkeypatch.setitem(sys.modules, "distributed", None)  # as if the 'cluster' extra were not installed
    with pytest.raises(YadearchError, match="needs dask.distributed: install the 'cluster' extra"):
        with open_pool(scheduler="tcp://127.0.0.1:1"):
            pass


@pytest.mark.parametrize("engine, paper", [("static", False), ("DEM", True)])
def test_the_kn_figure_names_its_engine_and_shows_the_paper_only_for_its_arch(tmp_path, engine, paper):
    """A static sweep's curve says static; the paper's FE points are drawn for the paper's arch only."""
    from matplotlib.figure import Figure

    from yadearch.plotting.sweep import _du_panel

    table = campaign(tmp_path, FakeRuns(), grid({"kn_N_per_mm3": [0.1, 1.0, 10.0]}))
    ax = Figure().subplots()
    _du_panel(ax, table[table["status"] == "done"], None, engine, paper)
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert f"yadearch ({engine})" in labels
    assert any("paper FE" in label for label in labels) == paper


@pytest.mark.parametrize("column", ["run", "name", "description"])
def test_a_table_names_its_runs_by_run_name_or_description(tmp_path, column):
    """yade-batch's tables call the run's name `description`; any one of the three names the runs."""
    table = tmp_path / "t.csv"
    table.write_text(f"{column},kn_N_per_mm3\nsoft,0.25\nstiff,100\n")
    assert [r[RUN_COLUMN] for r in read_table(table)] == ["soft", "stiff"]


def test_a_table_naming_its_runs_twice_is_refused(tmp_path):
    table = tmp_path / "t.csv"
    table.write_text("name,description,kn_N_per_mm3\na,b,1\n")
    with pytest.raises(CampaignError, match="names its runs twice"):
        read_table(table)


def test_a_sweep_of_unlike_arches_draws_a_line_per_arch_and_no_answer_as_an_axis(tmp_path):
    from yadearch.plotting.sweep import parameter_sweep_figure, swept_columns

    table = pd.DataFrame(
        {
            "run": ["a0", "a45", "semi0", "semi45"],
            "support_direction_deg": [0.0, -45.0, 0.0, -45.0],
            "embrace_deg": [float("nan"), float("nan"), 180.0, 180.0],  # empty cells: the base case's
            "du_mm": [25.5, 35.3, 13.3, 20.1],
            "du_first_mm": [12.0, 21.5, 13.3, 19.0],
            "collapsed": [True] * 4,
            "status": ["done"] * 4,
        }
    )
    swept = ["support_direction_deg", "embrace_deg"]
    assert swept_columns(table, swept) == ["support_direction_deg"]  # du_first_mm varies too: an answer
    paths = parameter_sweep_figure(table, "support_direction_deg", tmp_path / "du_vs_direction", swept)
    assert all(p.stat().st_size > 1000 for p in paths)
    failed = table.assign(status=["done", "failed", "done", "failed"], du_mm=[25.5, float("nan"), 13.3, float("nan")])
    with pytest.raises(ValueError, match="no two finished runs differ in it alone"):
        parameter_sweep_figure(failed, "support_direction_deg", tmp_path / "none", swept)


def test_a_resumed_campaign_says_how_many_runs_it_kept(tmp_path, capsys):
    from yadearch.studies.campaigns.progress import campaign_bar

    campaign_bar(tmp_path / "sweep", 3, 1, progress=True).close()
    assert "sweep: 2 of 3 runs already made in" in capsys.readouterr().out
    campaign_bar(tmp_path / "fresh", 3, 3, progress=True).close()
    assert "already made" not in capsys.readouterr().out


def test_an_arch_that_cannot_stand_is_an_answer_not_a_failed_campaign(tmp_path):
    """A table with a ring too thin to stand: the campaign says so and exits 0 (seventh user trial: it
    ended "error: 1 of 2 runs failed" for the arch's own answer); the run is still recorded as it was."""
    from yadearch.cli.commands import main

    table = tmp_path / "t.csv"
    table.write_text("name,thickness_mm\nthin,8\nok,24\n")
    args = ["sweep", "--preset", "set2", "--engine", "static", "--table", str(table), "--jobs", "1"]
    assert main([*args, "--no-figures", "--out", str(tmp_path / "out")]) == 0
    results = pd.read_csv(tmp_path / "out" / "results.csv")
    assert results.set_index("run").loc["thin", "outcome"] == "cannot stand"
