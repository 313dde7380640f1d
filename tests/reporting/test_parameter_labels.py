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


def test_a_sweep_figure_labels_its_axis_and_lines_without_raw_names(monkeypatch, tmp_path):
    figures: list = []
    monkeypatch.setattr(sweep, "save_figure", lambda fig, stem: figures.append(fig) or (stem, stem))
    table = pd.DataFrame(
        {
            "run": list("abcd"),
            "status": ["done"] * 4,
            "collapsed": [True] * 4,
            "du_mm": [50.0, 60.0, 55.0, 66.0],
            "thickness_mm": [24.0, 30.0, 24.0, 30.0],
            "kn_N_per_mm3": [1.0, 1.0, 5.2, 5.2],
        }
    )
    sweep.parameter_sweep_figure(table, "thickness_mm", tmp_path / "t", ["thickness_mm", "kn_N_per_mm3"])
    ax = figures[0].axes[0]
    assert ax.get_xlabel() == "thickness (mm)"
    assert [t.get_text() for t in ax.get_legend().get_texts()] == ["$k_n$ = 1 N/mm³", "$k_n$ = 5.2 N/mm³"]


def test_many_lines_of_one_setting_take_a_colour_scale_not_a_legend(monkeypatch, tmp_path):
    """40 kn levels against friction drew a 40-entry legend over the data (fourth user trial): more
    than MAX_LEGEND_LINES lines of one numeric setting are shaded on a colour bar named by it."""
    figures: list = []
    monkeypatch.setattr(sweep, "save_figure", lambda fig, stem: figures.append(fig) or (stem, stem))
    kn = [2.0 * 10 ** (k / 4) for k in range(12)]
    table = pd.DataFrame(
        {
            "run": [f"r{i}" for i in range(24)],
            "status": ["done"] * 24,
            "collapsed": [True] * 24,
            "du_mm": [30.0 + i for i in range(24)],
            "friction_deg": [34.0, 38.0] * 12,
            "kn_N_per_mm3": [k for k in kn for _ in range(2)],
        }
    )
    sweep.parameter_sweep_figure(table, "friction_deg", tmp_path / "f", ["friction_deg", "kn_N_per_mm3"])
    ax, bar = figures[0].axes
    assert ax.get_legend() is None and len(ax.lines) == 12 and bar.get_ylabel() == "$k_n$ (N/mm³)"


def test_an_arch_that_cannot_stand_is_drawn_at_du_zero_and_marked(monkeypatch, tmp_path):
    """The sweep figures left such runs out silently (fourth user trial); the studies count them as 0."""
    from yadearch.errors import CANNOT_STAND

    figures: list = []
    monkeypatch.setattr(sweep, "save_figure", lambda fig, stem: figures.append(fig) or (stem, stem))
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
