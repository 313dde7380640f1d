"""One colour per hinge letter in every figure that draws hinges (issue 43): the run's collapse
figure, a kn sweep's hinge panel, the kn curve's and a Monte Carlo campaign's hinge positions all
take house.hinge_colour's colour for A, B, C and D."""

from __future__ import annotations

from pathlib import Path

import matplotlib
import pandas as pd

matplotlib.use("Agg")

from matplotlib.colors import to_hex  # noqa: E402

from yadearch.analysis.run import analyse_run  # noqa: E402
from yadearch.plotting import kn_curve, montecarlo, sweep  # noqa: E402
from yadearch.plotting.house import hinge_colour as house_colour  # noqa: E402
from yadearch.plotting.run_figures import collapse_figure  # noqa: E402
from yadearch.results.rundir import read_run  # noqa: E402

REPORTS = Path(__file__).resolve().parents[2] / "reports"


def hinge_colour(letter: str) -> str:
    """The house's colour of a hinge letter, as matplotlib reports a drawn colour."""
    return to_hex(house_colour(letter))


def captured(monkeypatch, module) -> list:
    """The figures `module` saves, kept instead of written."""
    figures: list = []
    monkeypatch.setattr(module, "save_figure", lambda fig, stem: figures.append(fig) or (stem, stem))
    return figures


def sweep_table() -> pd.DataFrame:
    return pd.DataFrame(
        {
            "run": ["a", "b", "c"],
            "status": ["done"] * 3,
            "collapsed": [True] * 3,
            "kn_N_per_mm3": [0.5, 5.0, 50.0],
            "du_mm": [50.0, 80.0, 100.0],
            "mechanism": ["E-I-E-E"] * 3,
            "n_voussoirs": [55] * 3,
            "hinge_A": [12, 10, 9],
            "hinge_B": [30, 29, 29],
            "hinge_C": [56, 56, 56],
            "hinge_D": [1, 1, 1],
        }
    )


def line_colours(ax) -> dict[str, str]:
    return {line.get_label(): to_hex(line.get_color()) for line in ax.get_lines()}


def test_the_collapse_figure_draws_each_hinge_in_its_letters_colour():
    run = read_run(REPORTS / "set2")
    analysis = analyse_run(run)
    fig = collapse_figure(run, analysis)
    label_colours = {t.get_text()[0]: to_hex(t.get_color()) for t in fig.axes[0].texts}
    assert label_colours == {letter: hinge_colour(letter) for letter in "ABCD"}


def test_a_kn_sweeps_hinge_panel_takes_the_letters_colours(monkeypatch, tmp_path):
    figures = captured(monkeypatch, sweep)
    sweep.kn_sweep_figure(sweep_table(), tmp_path / "du_vs_kn")
    colours = line_colours(figures[0].axes[1])
    for letter, _, label in sweep.HINGE_STYLE.values():
        assert colours[label] == hinge_colour(letter)


def test_the_kn_curves_hinge_panel_takes_the_letters_colours(monkeypatch, tmp_path):
    figures = captured(monkeypatch, kn_curve)
    table = sweep_table()
    kn_curve.kn_curve_figure(table, None, pd.DataFrame(), 113.5, tmp_path / "kn_curve")
    colours = line_colours(figures[0].axes[1])
    assert colours["hinge A (intrados)"] == hinge_colour("A") and colours["hinge B (extrados)"] == hinge_colour("B")


def test_the_hinge_positions_of_a_campaign_take_the_letters_colours(monkeypatch, tmp_path):
    figures = captured(monkeypatch, montecarlo)
    montecarlo.hinge_frequency_figure(sweep_table(), tmp_path / "hinges")
    bars = {c.get_label()[0]: to_hex(c.patches[0].get_facecolor()) for c in figures[0].axes[0].containers}
    assert bars == {letter: hinge_colour(letter) for letter in "ABCD"}


def test_a_load_collapse_draws_each_hinge_of_its_mechanism_in_a_colour_of_its_own(monkeypatch, tmp_path):
    """A live load's mechanism has no paper letters: its hinges, left to right, take the house's colours
    in turn, none shared (the quarter-span load on set 2: four hinges)."""
    from yadearch.case.config import preset
    from yadearch.case.mechanics import arch_geometry
    from yadearch.plotting import load_figure
    from yadearch.solve.load_lp import load_analysis

    case = preset("set2").with_overrides({"live_load": "vertical"})
    result = load_analysis(case)
    figures = captured(monkeypatch, load_figure)
    load_figure.plot_load_collapse(case, arch_geometry(case), result, tmp_path / "collapse")
    colours = {t.get_text(): to_hex(t.get_color()) for t in figures[0].axes[0].texts if t.get_text()[-1] in "IE"}
    assert len(colours) == len(result.pivots) == 4
    assert len(set(colours.values())) == len(colours)
