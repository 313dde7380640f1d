"""Imperfect arches and Monte Carlo campaigns with a coarse arch (9 voussoirs, set 2's joints; uniform
wear of 0, 1.5 and 3 mm gives 122.2, 107.2 and 88.6 mm on the same hinges 1E 2I 6E 10E): worn joint
edges (a Monte Carlo campaign on the static engine) and thinner voussoirs (real YADE at kn 0.5, about 20 s)
make an arch that collapses earlier, every sample records what it drew, and on YADE a seed without
amplitudes is the perfect arch to the step."""

from __future__ import annotations

import json
from pathlib import Path

import pandas as pd
import pytest
from click.testing import CliRunner
from conftest import needs_yade

from yadearch.cli.campaigns import sweep
from yadearch.cli.montecarlo import montecarlo
from yadearch.results.rundir import IMPERFECTIONS_FILE, SUMMARY_FILE

pytestmark = [pytest.mark.yade, needs_yade]

STATIC_COARSE = ["--preset", "set2", "--set", "n_voussoirs=9", "--set", "progress_every_s=1e9"]
# the DEM's (the static engine refuses a rate), on joints ten times softer than set 2's: a 9-voussoir
# run takes 24 s instead of 68 (its time step grows with the softness)
COARSE = [*STATIC_COARSE, "--set", "support_rate_mm_per_s=30", "--set", "kn_N_per_mm3=0.5"]
WORN = ["--set", "edge_radius_mm=3", "--set", "edge_radius_sd_mm=0.5"]  # an eighth of the 24 mm thickness
SAMPLES = 3


@pytest.fixture(scope="module")
def perfect(tmp_path_factory) -> pd.DataFrame:
    """The perfect coarse arch, with the default seed and with another (no amplitude: no effect)."""
    out = tmp_path_factory.mktemp("perfect") / "campaign"
    result = CliRunner().invoke(
        sweep, [*COARSE, "--param", "seed=0,9", "--out", str(out), "--jobs", "2", "--no-figures"]
    )
    assert result.exit_code == 0, result.output
    return pd.read_csv(out / "results.csv")


@pytest.fixture(scope="module")
def worn(tmp_path_factory) -> Path:
    """The worn campaign on the static engine (the same blocks and joints, seconds instead of minutes;
    the engines agree within 0.07 % on this arch, tests/dem/test_static_vs_dem_yade.py)."""
    out = tmp_path_factory.mktemp("worn") / "campaign"
    result = CliRunner().invoke(
        montecarlo,
        [
            *STATIC_COARSE,
            *WORN,
            "--samples",
            str(SAMPLES),
            "--seed",
            "5",
            "--out",
            str(out),
            "--jobs",
            "2",
            "--engine",
            "static",
        ],
    )
    assert result.exit_code == 0, result.output
    return out


def test_a_seed_without_amplitudes_is_the_perfect_arch_to_the_step(perfect):
    assert (perfect["status"] == "done").all()
    first, second = perfect.iloc[0], perfect.iloc[1]
    assert first["du_mm"] == second["du_mm"] and first["steps"] == second["steps"]
    assert first["hinges"] == second["hinges"]


def test_worn_edges_make_the_arch_collapse_earlier(worn, tmp_path):
    """The contact cannot reach a worn corner: every hinge pivots about 3 mm inside the arch's
    faces, a thinner arch, which reaches its mechanism at a smaller support displacement."""
    from yadearch.cli.commands import run

    table = pd.read_csv(worn / "montecarlo.csv")
    assert (table["status"] == "done").all() and len(table) == SAMPLES
    result = CliRunner().invoke(run, [*STATIC_COARSE, "--engine", "static", "--out", str(tmp_path / "perfect")])
    assert result.exit_code == 0, result.output
    du_perfect = json.loads((tmp_path / "perfect" / SUMMARY_FILE).read_text())["du_mm"]
    assert (table["du_mm"] < 0.95 * du_perfect).all(), (table["du_mm"].tolist(), du_perfect)
    assert table["edge_mean_mm"].between(2.0, 4.0).all()  # drawn around 3 mm
    assert table["hinge_A"].notna().all() and (table["hinge_C"] == 10).all()  # the settlement mechanism


def test_every_sample_records_its_draw_and_its_self_weight_equilibrium(worn):
    table = pd.read_csv(worn / "montecarlo.csv")
    draws = []
    for folder in table["folder"]:
        defects = pd.read_csv(worn / folder / IMPERFECTIONS_FILE)
        assert len(defects) == 10  # 9 voussoirs, 10 joints
        assert defects["left_intrados_edge_mm"].iloc[0] == 0.0  # the support's face is perfect
        draws.append(defects["right_intrados_edge_mm"].to_numpy())
        summary = json.loads((worn / folder / SUMMARY_FILE).read_text())
        weight = summary["selfweight"]["arch_weight_N"]
        assert summary["selfweight"]["vertical_reaction_sum_N"] == pytest.approx(weight, rel=0.005)
    assert not (draws[0] == draws[1]).all()  # another seed, another geometry
    markdown = (worn / "montecarlo.md").read_text()
    assert f"{SAMPLES} samples: {SAMPLES} collapsed, 0 cannot stand" in markdown
    assert (worn / "du_distribution.pdf").is_file() and (worn / "hinge_positions.png").is_file()


def test_thinner_voussoirs_make_the_arch_collapse_earlier_and_the_run_records_them(perfect, tmp_path):
    """Voussoirs 3 mm thinner on average (an eighth of the ring), with 0.3 mm of scatter in length and
    thickness: a thinner ring reaches its mechanism at a smaller support displacement, as the rigid
    analysis of the same blocks says, and imperfections.csv holds each voussoir's errors."""
    from yadearch.case.config import preset
    from yadearch.cli.commands import run
    from yadearch.solve.limit import limit_analysis

    thinner = [
        "--set",
        "voussoir_thickness_mm=-3",
        "--set",
        "voussoir_thickness_sd_mm=0.3",
        "--set",
        "voussoir_length_sd_mm=0.3",
        "--set",
        "seed=4",
    ]
    result = CliRunner().invoke(run, [*COARSE, *thinner, "--out", str(tmp_path / "thinner")])
    assert result.exit_code == 0, result.output
    summary = json.loads((tmp_path / "thinner" / SUMMARY_FILE).read_text())
    assert summary["du_mm"] < 0.95 * perfect["du_mm"].iloc[0]
    coarse = preset("set2").with_overrides({"n_voussoirs": 9})
    settings = {"voussoir_thickness_mm": -3, "voussoir_thickness_sd_mm": 0.3, "voussoir_length_sd_mm": 0.3, "seed": 4}
    assert limit_analysis(coarse.with_overrides(settings)).du_rigid_mm < limit_analysis(coarse).du_rigid_mm
    drawn = pd.read_csv(tmp_path / "thinner" / IMPERFECTIONS_FILE)
    assert drawn["right_voussoir_thickness_error_mm"].iloc[:-1].between(-4.0, -2.0).all()
    assert drawn["joint_shift_mm"].iloc[[0, -1]].tolist() == [0.0, 0.0]  # the springings stay
    assert summary["imperfections"]["thickness_error_mean_mm"] == pytest.approx(-3.0, abs=0.3)
