"""Monte Carlo campaigns without YADE: the samples' seeds and names, du's statistics, the hinge
frequencies, the Markdown summary and the figures, from a made-up results table."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

from yadearch.analysis.samples import du_statistics, hinge_frequencies, median_interval
from yadearch.plotting.montecarlo import (
    campaign_figures,
    du_amplitude_figure,
    du_distribution_figure,
    hinge_frequency_figure,
)
from yadearch.studies.montecarlo import SEED_KEY, sample_rows, summary_markdown


def _table(n: int = 40) -> pd.DataFrame:
    rng = np.random.default_rng(0)
    return pd.DataFrame(
        {
            "run": [f"s{i}" for i in range(n)],
            "status": ["done"] * (n - 1) + ["failed"],
            "du_mm": np.r_[rng.normal(60.0, 5.0, n - 1), np.nan],
            "edge_radius_mm": np.repeat([0.5, 1.0], n // 2),
            "hinge_A": pd.array([11 if i % 4 else 12 for i in range(n)], dtype="Int64"),
            "hinge_B": pd.array([30] * n, dtype="Int64"),
            "hinge_C": pd.array([56] * n, dtype="Int64"),
            "hinge_D": pd.array([1] * n, dtype="Int64"),
        }
    )


def test_samples_take_consecutive_seeds_at_every_amplitude_level():
    rows = sample_rows(3, 10)
    assert [r[SEED_KEY] for r in rows] == [10, 11, 12] and [r["run"] for r in rows] == ["s10", "s11", "s12"]
    levels = sample_rows(2, 1, {"edge_radius_mm": [0.5, 1.0]})
    assert [(r["edge_radius_mm"], r[SEED_KEY]) for r in levels] == [(0.5, 1), (0.5, 2), (1.0, 1), (1.0, 2)]
    assert len({r["run"] for r in levels}) == 4
    assert sample_rows(5, 0)[:3] == sample_rows(3, 0)  # more samples keep the first ones
    with pytest.raises(ValueError, match="samples"):
        sample_rows(0, 1)


def test_du_statistics_are_the_median_and_the_5_95_band_of_the_finished_samples():
    stats = du_statistics(pd.Series([1.0, 2.0, 3.0, np.nan, 4.0, 5.0]))
    assert stats["n"] == 5 and stats["median"] == 3.0
    assert stats["low"] == pytest.approx(1.2) and stats["high"] == pytest.approx(4.8)


def test_hinge_frequencies_count_each_label_per_interface_over_finished_samples():
    frequencies = hinge_frequencies(_table())
    a = frequencies[frequencies["hinge"] == "A"].set_index("interface")["count"]
    assert a.to_dict() == {11: 29, 12: 10}  # 39 finished: every fourth (0, 4, ..., 36) at 12
    assert frequencies.groupby("hinge")["share"].sum().round(9).eq(1.0).all()


def test_the_summary_and_the_figures_describe_the_campaign(tmp_path):
    table = _table()
    text = summary_markdown(table, ["edge_radius_mm"])
    assert "40 samples: 39 collapsed, 0 cannot stand under their own weight (du 0 in the statistics), 1 without" in text
    assert "| 0.5 | 20 |" in text and "| 1 | 19 |" in text
    assert "- A: 11: 74%, 12: 26%" in text
    for paths in (
        du_distribution_figure(table, tmp_path / "du", [(70.0, "perfect arch"), (48.9, "experiment")]),
        hinge_frequency_figure(table, tmp_path / "hinges"),
        du_amplitude_figure(table, "edge_radius_mm", tmp_path / "amp"),
    ):
        assert all(p.is_file() and p.stat().st_size > 1000 for p in paths)


def test_du_is_drawn_against_an_amplitude_only_where_it_takes_two_levels_or_more(tmp_path):
    table = _table().assign(face_bump_sd_mm=0.18)  # one level: no curve to draw
    campaign_figures(table, tmp_path, ["edge_radius_mm", "face_bump_sd_mm"])
    assert (tmp_path / "du_vs_edge_radius_mm.png").is_file()
    assert not (tmp_path / "du_vs_face_bump_sd_mm.png").exists()


def test_the_median_interval_holds_the_true_median_at_its_confidence():
    """Order statistics around the middle hold the median of any continuous law with at least 95 %
    probability: 4000 draws of 70 normal samples hold 0 in 94-97 % of cases; too few samples give
    no interval."""
    rng = np.random.default_rng(20261124)
    held = [low <= 0.0 <= high for low, high in (median_interval(rng.normal(size=70)) for _ in range(4000))]
    assert 0.94 <= np.mean(held) <= 0.97
    assert all(math.isnan(v) for v in median_interval(np.arange(5.0)))
    assert median_interval(np.arange(20.0)) == (5.0, 14.0)


def test_samples_that_cannot_stand_count_as_du_zero_as_in_the_sensitivity_study():
    """21 of 40 arches fell under their own weight: the median is theirs too (it was the 19 standing
    samples' alone, overstating the capacity; fourth user trial), and the summary says how many."""
    from yadearch.errors import CANNOT_STAND

    table = _table().assign(collapsed=True, reason="")
    fell = table.index < 21
    table.loc[fell, ["status", "du_mm", "reason"]] = ["failed", np.nan, f"run failed: {CANNOT_STAND} (...)"]
    text = summary_markdown(table, [])
    assert "40 samples: 18 collapsed, 21 cannot stand under their own weight" in text
    assert "| 39 | 0.00 |" in text  # the median of 21 zeros and 18 collapses (one sample has no du)
    assert "share of the 18 samples that collapsed" in text


def test_a_hinge_without_a_paper_letter_is_counted_too(tmp_path):
    """Found in a user trial: a spreading mechanism 1E 5I 12E 18I 22E has two intrados hinges, A the
    more turned one; the other was in no statistic. Every hinge counts, the unlettered ones apart."""
    n = 10
    table = pd.DataFrame(
        {
            "run": [f"s{i}" for i in range(n)],
            "status": ["done"] * n,
            "du_mm": np.linspace(500.0, 520.0, n),
            "hinges": ["1E 5I 12E 18I 22E"] * n,
            "hinge_A": pd.array([18 if i == 0 else 5 for i in range(n)], dtype="Int64"),
            "hinge_B": pd.array([12] * n, dtype="Int64"),
            "hinge_C": pd.array([22] * n, dtype="Int64"),
            "hinge_D": pd.array([1] * n, dtype="Int64"),
        }
    )
    text = summary_markdown(table, [])
    assert "- A: 5: 90%, 18: 10%" in text
    assert (
        "- without a letter (a second intrados hinge, a fifth hinge): 18I: 90%; 1 other position, each in under 50%"
        in text
    )
    assert all(p.stat().st_size > 0 for p in hinge_frequency_figure(table, tmp_path / "hinges"))
