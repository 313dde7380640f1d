"""Axis labels of case parameters in the paper's style (issue 43): a readable name and the unit in
parentheses, never the raw parameter name, in the sweep and Monte Carlo figures."""

from __future__ import annotations

import matplotlib
import pandas as pd
import pytest

matplotlib.use("Agg")

from yadearch.plotting import sweep  # noqa: E402
from yadearch.plotting.parameter_labels import parameter_label, parameter_setting  # noqa: E402


@pytest.mark.parametrize(
    ("column", "label"),
    [
        ("interface.kn_N_per_mm3", "$k_n$ (N/mm³)"),
        ("face_bump_sd_mm", "face bump s.d. (mm)"),
        ("material.density_g_per_cm3", "density (g/cm³)"),
        ("support_direction_deg", "support direction (°)"),
        ("n_voussoirs", "voussoirs"),
        ("shape", "shape"),
    ],
)
def test_a_parameter_is_labelled_by_name_and_unit(column, label):
    assert parameter_label(column) == label


def test_a_legend_entry_gives_the_value_with_its_unit():
    assert parameter_setting("kn_N_per_mm3", 5.2) == "$k_n$ = 5.2 N/mm³"
    assert parameter_setting("shape", "pointed") == "shape = pointed"


@pytest.fixture
def figures(monkeypatch) -> list:
    """The figures a sweep draws, kept here instead of saved."""
    drawn: list = []
    monkeypatch.setattr(sweep, "save_figure", lambda fig, stem: drawn.append(fig) or (stem, stem))
    return drawn


def _finished(runs: list[str], **columns: list) -> pd.DataFrame:
    """A campaign's results table of `runs` that finished and collapsed, with `columns`."""
    return pd.DataFrame({"run": runs, "status": ["done"] * len(runs), "collapsed": [True] * len(runs), **columns})


def test_a_sweep_figure_labels_its_axis_and_lines_without_raw_names(figures, tmp_path):
    table = _finished(
        list("abcd"),
        du_mm=[50.0, 60.0, 55.0, 66.0],
        thickness_mm=[24.0, 30.0, 24.0, 30.0],
        kn_N_per_mm3=[1.0, 1.0, 5.2, 5.2],
    )
    sweep.parameter_sweep_figure(table, "thickness_mm", tmp_path / "t", ["thickness_mm", "kn_N_per_mm3"])
    ax = figures[0].axes[0]
    assert ax.get_xlabel() == "thickness (mm)"
    assert [t.get_text() for t in ax.get_legend().get_texts()] == ["$k_n$ = 1 N/mm³", "$k_n$ = 5.2 N/mm³"]


def test_many_lines_of_one_setting_take_a_colour_scale_not_a_legend(figures, tmp_path):
    """40 kn levels against friction drew a 40-entry legend over the data (fourth user trial): more
    than MAX_LEGEND_LINES lines of one numeric setting are shaded on a colour bar named by it."""
    kn = [2.0 * 10 ** (k / 4) for k in range(12)]
    table = _finished(
        [f"r{i}" for i in range(24)],
        du_mm=[30.0 + i for i in range(24)],
        friction_deg=[34.0, 38.0] * 12,
        kn_N_per_mm3=[k for k in kn for _ in range(2)],
    )
    sweep.parameter_sweep_figure(table, "friction_deg", tmp_path / "f", ["friction_deg", "kn_N_per_mm3"])
    ax, bar = figures[0].axes
    assert ax.get_legend() is None and len(ax.lines) == 12 and bar.get_ylabel() == "$k_n$ (N/mm³)"


def test_an_arch_that_cannot_stand_is_drawn_at_du_zero_and_marked(figures, tmp_path):
    """The sweep figures left such runs out silently (fourth user trial); the studies count them as 0."""
    from yadearch.errors import CANNOT_STAND

    table = pd.DataFrame(
        {
            "run": list("abc"),
            "status": ["failed", "done", "done"],
            "collapsed": [None, True, True],
            "reason": [f"run failed: {CANNOT_STAND}", "", ""],
            "du_mm": [float("nan"), 40.0, 55.0],
            "thickness_mm": [20.0, 30.0, 40.0],
        }
    )
    sweep.parameter_sweep_figure(table, "thickness_mm", tmp_path / "t", ["thickness_mm"])
    ax = figures[0].axes[0]
    assert list(ax.lines[0].get_ydata()) == [0.0, 40.0, 55.0]
    assert [t.get_text() for t in ax.get_legend().get_texts()] == ["cannot stand (du 0)"]


def test_a_table_that_is_not_a_grid_draws_one_named_point_a_run_unjoined(figures, tmp_path):
    """A line through runs that differ in other parameters too suggested a trend (fifth user trial):
    such a table's runs are open points, unjoined, and coinciding points share one name label."""
    table = _finished(
        list("abcd"),
        du_mm=[67.1, 88.0, 87.6, 119.8],
        thickness_mm=[20.0, 24.0, 24.0, 30.0],
        n_voussoirs=[41, 55, 41, 71],
    )
    sweep.parameter_sweep_figure(table, "thickness_mm", tmp_path / "t", ["thickness_mm", "n_voussoirs"])
    ax = figures[0].axes[0]
    assert [line.get_linestyle() for line in ax.lines] == ["None"] and len(ax.lines[0].get_xdata()) == 4
    assert sorted(t.get_text() for t in ax.texts) == ["a", "c, b", "d"]
