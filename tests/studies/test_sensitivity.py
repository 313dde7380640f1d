"""The sensitivity study: its sampling and estimators on a function whose indices are known, and
`ya.sensitivity` on the static engine (a 9-voussoir arch, seconds) with the mechanics it must show."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

import yadearch as ya
from yadearch.errors import CampaignError, CaseError, YadearchError
from yadearch.studies.campaigns.grid import RUN_COLUMN
from yadearch.studies.sensitivity.checks import check_rows, other_engine
from yadearch.studies.sensitivity.indices import (
    PAPER_FACTORS,
    Factor,
    check_base_points,
    check_factors,
    convergence,
    parse_factor,
    sample_sizes,
    sobol_indices,
    sobol_rows,
    stable_base_points,
    tornado_table,
)

ISHIGAMI = (
    Factor("geometry.thickness_mm", "x1", -math.pi, math.pi),
    Factor("geometry.embrace_deg", "x2", -math.pi, math.pi),
    Factor("material.friction_deg", "x3", -math.pi, math.pi),
)
ISHIGAMI_S1 = (0.3139, 0.4424, 0.0)  # a = 7, b = 0.1 (Saltelli et al. 2008, Global Sensitivity Analysis)
ISHIGAMI_ST = (0.5576, 0.4424, 0.2437)


def _ishigami(row: dict) -> float:
    x1, x2, x3 = (row[f.key] for f in ISHIGAMI)
    return math.sin(x1) + 7.0 * math.sin(x2) ** 2 + 0.1 * x3**4 * math.sin(x1)


def test_factor_values_span_their_ranges_linearly_logarithmically_and_over_integers():
    kn = Factor("interface.kn_N_per_mm3", "kn", 0.25, 100.0, log=True)
    assert (kn.value(0.0), kn.value(1.0), kn.value(0.5)) == pytest.approx((0.25, 100.0, 5.0))
    count = Factor("geometry.n_voussoirs", "n", 45, 65, integer=True)
    assert [count.value(u) for u in (0.0, 0.999, 1.0)] == [45, 65, 65]
    assert {count.value(u) for u in np.linspace(0, 1, 2000)} == set(range(45, 66))  # every count, each end included


def test_a_doubled_sample_starts_with_the_smaller_one_so_a_campaign_resumes():
    small, large = sobol_rows(PAPER_FACTORS, 8), sobol_rows(PAPER_FACTORS, 16)
    assert len(small) == 8 * (len(PAPER_FACTORS) + 2) and len(large) == 2 * len(small)
    assert large[: len(small)] == small
    assert len({row[RUN_COLUMN] for row in large}) == len(large)


def test_sobol_indices_of_the_ishigami_function_match_its_analytic_values():
    rows = sobol_rows(ISHIGAMI, 1024)
    indices = sobol_indices(ISHIGAMI, np.array([_ishigami(r) for r in rows]), 1024)
    assert indices["S1"].to_numpy() == pytest.approx(ISHIGAMI_S1, abs=0.03)
    assert indices["ST"].to_numpy() == pytest.approx(ISHIGAMI_ST, abs=0.03)


def test_indices_converge_on_nested_samples_and_the_stable_sample_is_extrapolated():
    """Ishigami's indices on samples of 32 to 1024 base points: each doubling changes them less, and a
    change that falls as 1/sqrt(N) (0.04 at 1024) reaches 0.02 at four times the sample."""
    assert sample_sizes(1024) == [32, 64, 128, 256, 512, 1024] and sample_sizes(8) == [4, 8]
    rows = sobol_rows(ISHIGAMI, 1024)
    du = np.array([_ishigami(r) for r in rows])
    table = convergence(pd.concat([sobol_indices(ISHIGAMI, du, n) for n in sample_sizes(1024)]))
    assert table["base_points"].tolist() == [64, 128, 256, 512, 1024]
    assert table["largest_change"].iloc[-1] < table["largest_change"].iloc[0]
    assert table["mean_half_width"].is_monotonic_decreasing
    sizes = np.array([256, 512, 1024])
    assert (
        stable_base_points(pd.DataFrame({"base_points": sizes, "largest_change": 0.04 * np.sqrt(1024 / sizes)})) == 4096
    )


def test_the_checks_are_the_ends_of_the_ranges_that_move_du_most():
    factors = (parse_factor("thickness_mm=22:26"), parse_factor("friction_deg=38:44"))
    study_runs = pd.DataFrame(
        {
            RUN_COLUMN: ["base", "thickness_mm_low", "thickness_mm_high", "friction_deg_low", "friction_deg_high"],
            "du_mm": [100.0, 80.0, 109.0, 100.5, math.nan],
        }
    )
    rows = check_rows(ya.preset("set2"), factors, study_runs, 3)
    assert [row[RUN_COLUMN] for row in rows] == ["thickness_mm_low", "thickness_mm_high", "friction_deg_low"]
    assert rows[0]["geometry.thickness_mm"] == 22.0 and rows[2]["material.friction_deg"] == 38.0
    assert other_engine("static") == "dem" and other_engine("dem") == "static"


def test_the_checks_run_on_the_other_engine_with_their_own_settings(tmp_path, monkeypatch):
    """`check_settings` reach the check runs' case alone (e.g. the DEM's path reading for a static study)."""
    import yadearch.studies.sensitivity.checks as checks

    made: list = []

    def campaign(base, rows, folder, pool, **options):
        made.append(base)
        return pd.DataFrame({RUN_COLUMN: [r[RUN_COLUMN] for r in rows], "du_mm": 60.0, "hinges": "", "wall_s": 1.0})

    monkeypatch.setattr(checks, "run_campaign", campaign)
    factors = (parse_factor("thickness_mm=22:26"),)
    study = pd.DataFrame({RUN_COLUMN: ["base", "thickness_mm_low", "thickness_mm_high"], "du_mm": [88.0, 70.0, 95.0],
                          "hinges": "", "wall_s": 0.1})  # fmt: skip
    static = ya.preset("set2").with_overrides({"numerics.engine": "static"})
    table = checks.run_checks(
        static, study, factors, 1, tmp_path, None, settings={"numerics.support_path_states": "static"}
    )
    assert made[0].numerics.engine == "dem" and made[0].numerics.support_path_states == "static"
    assert table[RUN_COLUMN].tolist() == ["thickness_mm_low"] and table["dem_du_mm"].tolist() == [60.0]
    with pytest.raises(YadearchError, match="check_settings expects numerics.KEY=VALUE .* got 'numerics.engine'"):
        ya.sensitivity("set2", tmp_path / "unused", check_runs=1, check_settings={"numerics.engine": "static"})
    assert not (tmp_path / "unused").exists()


def test_blocks_with_a_failed_run_are_left_out_of_the_estimate():
    rows = sobol_rows(ISHIGAMI, 64)
    du = np.array([_ishigami(r) for r in rows])
    du[[0, 7, 12]] = np.nan  # blocks 0, 1 and 2 (5 runs a block)
    assert sobol_indices(ISHIGAMI, du, 64)["used_points"].iloc[0] == 61


def test_bad_designs_are_refused_in_one_line_naming_the_value():
    with pytest.raises(CampaignError, match="base_points must be a power of two >= 8, got 100"):
        check_base_points(100)
    with pytest.raises(CampaignError, match="NAME=LOW:HIGH"):
        parse_factor("kn_N_per_mm3=0.25")
    with pytest.raises(CaseError, match="unknown parameter 'stiffness'"):
        parse_factor("stiffness=1:2")
    with pytest.raises(CampaignError, match="low 3 must be below high 2"):
        check_factors(ya.preset("set2"), (parse_factor("friction_deg=3:2"),))
    with pytest.raises(CaseError, match="friction_deg"):
        check_factors(ya.preset("set2"), (parse_factor("friction_deg=30:95"),))
    with pytest.raises(CampaignError, match=r"check_runs must be an integer in \[0, 50\], got -1"):
        ya.sensitivity("set2", "unused", check_runs=-1)
    assert parse_factor("kn_N_per_mm3=0.25:100:log") == Factor(
        "interface.kn_N_per_mm3", "kn_N_per_mm3", 0.25, 100.0, log=True
    )


def test_factors_that_miss_the_arch_and_a_sample_without_variance_are_one_line():
    """The paper's default ranges on another arch (a 40 mm ring outside 23-25 mm) are refused before
    anything runs; a sample whose du never varies (no arch stands: 0 everywhere) has no indices."""
    with pytest.raises(CampaignError, match=r"geometry.thickness_mm: its range 23-25 does not contain the case's 40"):
        check_factors(ya.preset("set2").replace(thickness_mm=40.0), PAPER_FACTORS)
    with pytest.raises(CampaignError, match=r"du is 0 mm in every run of the sample"):
        sobol_indices(ISHIGAMI, np.zeros(64 * (len(ISHIGAMI) + 2)), 64)


def test_static_sensitivity_of_a_small_arch_puts_thickness_before_friction(tmp_path):
    """9 voussoirs at set 2's kn: du grows with the ring's thickness; friction above 38° leaves the
    joints sticking (no slip in these mechanisms), so it hardly matters."""
    case = ya.preset("set2").with_overrides({"n_voussoirs": 9})
    factors = (parse_factor("thickness_mm=22:26"), parse_factor("friction_deg=38:44"))
    result = ya.sensitivity(case, tmp_path, base_points=8, factors=factors, engine="static", jobs=2)
    tornado = result.tornado.set_index("factor")
    assert tornado.loc["thickness_mm", "du_high_mm"] > tornado.loc["thickness_mm", "du_low_mm"]
    assert tornado.index[0] == "thickness_mm"
    assert tornado.loc["friction_deg", "swing_mm"] < 0.02 * tornado.loc["thickness_mm", "swing_mm"]
    indices = result.indices[result.indices["base_points"] == 8].set_index("factor")
    assert indices["ST"].idxmax() == "thickness_mm"
    assert (result.samples["status"] == "done").all()
    assert not list((tmp_path / "runs").glob("*/summary.json"))  # the sample's static runs keep no folders
    assert list((tmp_path / "runs" / "batches").glob("*.jsonl"))
    assert len(list((tmp_path / "tornado_runs").glob("*/joints.csv"))) == len(result.tornado) * 2 + 1
    assert pd.read_csv(tmp_path / "indices.csv")["base_points"].tolist() == [4, 4, 8, 8]
    for figure in ("tornado", "indices", "convergence"):
        assert (tmp_path / f"{figure}.png").stat().st_size > 0
    assert pd.read_csv(tmp_path / "convergence.csv")["base_points"].tolist() == [8]
    assert "## Sobol indices" in (tmp_path / "sensitivity.md").read_text()
    assert "![tornado](tornado.png)" in (tmp_path / "sensitivity.md").read_text()
    ya.sensitivity(case, tmp_path, base_points=8, factors=factors, engine="static", jobs=2, figures=False)
    assert "![" not in (tmp_path / "sensitivity.md").read_text()  # resumed without figures: no links to old ones


def test_the_figures_are_drawn_again_from_the_tables_a_study_wrote(tmp_path):
    """`scripts/sensitivity_figures.py`: the committed study's tables alone give its three figures."""
    import shutil

    from conftest import REPO

    from yadearch.studies.sensitivity.study import CONVERGENCE_TABLE, INDICES_TABLE, TORNADO_TABLE, redraw_figures

    for name in (TORNADO_TABLE, INDICES_TABLE, CONVERGENCE_TABLE):
        shutil.copy(REPO / "reports" / "sensitivity" / name, tmp_path / name)
    redraw_figures(tmp_path)
    assert all((tmp_path / f"{name}.png").stat().st_size > 1000 for name in ("tornado", "indices", "convergence"))


def test_a_tornado_end_where_the_arch_cannot_stand_is_du_zero_and_swings_most():
    """A ring 50 mm thick stands, 30 mm does not (fourth user trial: its bar was missing and sorted
    last, though its total index was the largest): du 0 there, its swing the base's du."""
    from yadearch.errors import CANNOT_STAND

    thickness = Factor("geometry.thickness_mm", "thickness_mm", 30.0, 50.0)
    friction = Factor("material.friction_deg", "friction_deg", 35.0, 45.0)
    results = pd.DataFrame(
        {
            RUN_COLUMN: ["base", "thickness_mm_low", "thickness_mm_high", "friction_deg_low", "friction_deg_high"],
            "status": ["done", "failed", "done", "done", "done"],
            "collapsed": [True, None, True, True, True],
            "reason": ["", f"run failed: {CANNOT_STAND}", "", "", ""],
            "du_mm": [40.0, np.nan, 55.0, 38.0, 41.0],
        }
    )
    table = tornado_table(ya.preset("set2"), (thickness, friction), results)
    assert table["factor"].tolist() == ["thickness_mm", "friction_deg"]
    assert table.loc[0, "du_low_mm"] == 0.0 and table.loc[0, "swing_mm"] == 55.0


def test_factors_are_taken_as_the_command_line_writes_them_or_by_a_paper_factors_name():
    """ya.sensitivity(..., factors=("kn_N_per_mm3",)) was an AttributeError from inside the library."""
    from yadearch.studies.sensitivity.indices import as_factor

    assert as_factor("thickness_mm=22:26") == parse_factor("thickness_mm=22:26")
    assert as_factor("kn_N_per_mm3") is next(f for f in PAPER_FACTORS if f.name == "kn_N_per_mm3")
    assert as_factor(PAPER_FACTORS[0]) is PAPER_FACTORS[0] and ya.Factor is Factor and "sensitivity" in dir(ya)
    with pytest.raises(CampaignError, match=r"factor 'bogus' must be a Factor, 'NAME=LOW:HIGH"):
        as_factor("bogus")
