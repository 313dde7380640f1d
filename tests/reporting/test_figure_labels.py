"""Labels a journal prints: in the strip of four states and in a movie frame of the committed paper
runs, every text is at least 7 pt and clears the blocks, the other texts and its axes' edge
(plotting.labels.label_clashes), and the clash finder does find a label put on a block."""

from __future__ import annotations

from pathlib import Path

import matplotlib
import pandas as pd
import pytest

matplotlib.use("Agg")

from yadearch.analysis.blocks import case_geometry  # noqa: E402
from yadearch.analysis.run import analyse_run  # noqa: E402
from yadearch.api.results import open_run  # noqa: E402
from yadearch.plotting.animation import FRAME_CM  # noqa: E402
from yadearch.plotting.blocks import BLOCKS_GID  # noqa: E402
from yadearch.plotting.house import MIN_TEXT_PT, new_figure  # noqa: E402
from yadearch.plotting.labels import label_clashes  # noqa: E402
from yadearch.plotting.states import (  # noqa: E402
    draw_state,
    drawing_limits,
    place_texts,
    run_states,
    state_view,
    strip_figure,
)
from yadearch.results.rundir import read_run  # noqa: E402

REPORTS = Path(__file__).resolve().parents[2] / "reports"
RUNS = ("set1", "set2")


def texts(fig):
    return [t for ax in fig.axes for t in ax.texts if t.get_text().strip()]


@pytest.mark.parametrize("name", RUNS)
def test_the_strips_labels_are_readable_and_clear(name):
    run = read_run(REPORTS / name)
    fig = strip_figure(run, analyse_run(run))
    assert all(t.get_fontsize() >= MIN_TEXT_PT for t in texts(fig))
    assert label_clashes(fig) == []


@pytest.mark.parametrize("name", RUNS)
def test_a_movie_frame_at_collapse_has_its_labels_clear(name):
    run = read_run(REPORTS / name)
    analysis, geometry = analyse_run(run), case_geometry(run.case)
    fig = new_figure(height_cm=FRAME_CM[1], width_cm=FRAME_CM[0])
    ax = fig.add_subplot()
    last = int(run_states(run).path()[-1])
    draw_state(ax, state_view(run, geometry, analysis, last), geometry, drawing_limits(geometry))
    place_texts(fig)
    assert len(texts(fig)) >= 4  # the four hinges at collapse and the corner text
    assert label_clashes(fig) == []


def test_a_hinge_keeps_its_letter_before_it_moves():
    """Set 1's hinges A and B move along the path (10I -> 12I, 30E -> 29E): each state on it letters them
    where they stood then, each letter once, not only where they end."""
    run = read_run(REPORTS / "set1")
    analysis, geometry = analyse_run(run), case_geometry(run.case)
    final = {t.paper_label: (t.final.interface, t.side) for t in analysis.tracks if t.paper_label}
    away = set()
    for index in run_states(run).path():
        lettered = [
            (letter, (k, side))
            for k, side, _, letter, _ in state_view(run, geometry, analysis, int(index)).hinges
            if letter
        ]
        letters = [letter for letter, _ in lettered]
        assert len(letters) == len(set(letters))
        away |= {letter for letter, where in lettered if where != final[letter]}
    assert {"A", "B"} <= away


def test_a_state_sharing_its_step_with_the_collapse_takes_its_own_letters():
    """A live load's last equilibrium and its collapse share the DEM's step: the equilibrium is lettered
    from its own record (A at 42I), not from the collapse's (A at 41I, where it drew A unlettered)."""
    run = open_run(REPORTS / "loads/descent/load_paths/spring10_step0.01_to0.5/paper_quarter_span_load_path").folder
    analysis, geometry, states = analyse_run(run), case_geometry(run.case), run_states(run)
    last, collapse = (int(i) for i in states.path()[-2:])
    assert states.step[last] == states.step[collapse] and states.stage[last] != states.stage[collapse]
    drawn = {letter: (k, side) for k, side, _, letter, _ in state_view(run, geometry, analysis, last).hinges if letter}
    assert drawn["A"] == (42, "I")


def test_a_label_on_a_block_is_found():
    run = read_run(REPORTS / "set2")
    fig = strip_figure(run, analyse_run(run))
    ax = fig.axes[0]
    (blocks,) = [c for c in ax.collections if c.get_gid() == BLOCKS_GID]  # the deformed arch's blocks
    block = blocks.get_paths()[len(blocks.get_paths()) // 2].vertices
    ax.annotate("on a block", block.mean(axis=0), fontsize=MIN_TEXT_PT)
    assert any("on a block" in clash for clash in label_clashes(fig))


FILL = {"fill_depth_mm": 50.0, "fill_density_g_per_cm3": 2.0, "load_dispersal": "boussinesq"}


@pytest.mark.parametrize("fill", [{}, FILL], ids=["on the extrados", "through a fill"])
def test_the_load_collapse_figure_labels_its_hinges_clear_of_the_blocks(tmp_path, monkeypatch, fill):
    """... and of the load's dispersal through a fill (its line crossed 19E)."""
    import yadearch as ya
    from yadearch.plotting import load_figure

    drawn = []
    monkeypatch.setattr(load_figure, "save_figure", lambda fig, stem: drawn.append(fig) or (stem, stem))
    result = ya.loads(ya.preset("set2").replace(live_load="vertical", **fill), out=tmp_path)
    (fig,) = drawn
    hinge_labels = {t.get_text() for t in fig.axes[0].texts}
    assert {p.label for p in result.pivots} <= hinge_labels
    assert label_clashes(fig) == []
    assert (tmp_path / "set2_loads.json").is_file()


@pytest.mark.parametrize("name", RUNS)
def test_the_collapse_figure_labels_its_hinges_clear(name):
    from yadearch.plotting.run_figures import collapse_figure

    run = read_run(REPORTS / name)
    analysis = analyse_run(run)
    fig = collapse_figure(run, analysis)
    assert len(texts(fig)) == len(analysis.tracks) >= 4
    assert all(t.get_fontsize() >= MIN_TEXT_PT for t in texts(fig))
    assert label_clashes(fig) == []


@pytest.mark.parametrize("name", RUNS)
def test_the_thrust_line_figure_labels_its_hinges_clear(name, tmp_path):
    import yadearch as ya
    from yadearch.plotting.thrust_line import plot_thrust_line

    case = ya.preset(name)
    result = ya.limit(case, out=tmp_path)
    fig = plot_thrust_line(result, case)
    assert len(texts(fig)) >= 4  # the four hinges of the mechanism
    assert label_clashes(fig) == []


def every_text(fig) -> list:
    """Every text a drawn figure prints: labels, titles, tick labels, legends, annotations."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    FigureCanvasAgg(fig).draw()
    found = fig.findobj(lambda artist: hasattr(artist, "get_fontsize") and hasattr(artist, "get_text"))
    return [t for t in found if t.get_text().strip() and t.get_visible()]


def test_the_sweep_figures_print_no_text_below_the_house_minimum(monkeypatch, tmp_path):
    """A kn sweep, the kn curve and a campaign's hinge positions (the sweep style): every text at least
    MIN_TEXT_PT at print size (their legends were 6.5 pt)."""
    from test_figure_colours import captured, sweep_table

    from yadearch.plotting import kn_curve, montecarlo, sweep

    drawn = [captured(monkeypatch, module) for module in (sweep, kn_curve, montecarlo)]
    sweep.kn_sweep_figure(sweep_table(), tmp_path / "du_vs_kn")
    kn_curve.kn_curve_figure(sweep_table(), None, pd.DataFrame(), 113.5, tmp_path / "curve")
    montecarlo.hinge_frequency_figure(sweep_table(), tmp_path / "hinges")
    figures = [fig for figs in drawn for fig in figs]
    assert len(figures) == 3
    for fig in figures:
        small = [(t.get_text(), t.get_fontsize()) for t in every_text(fig) if t.get_fontsize() < MIN_TEXT_PT]
        assert small == []


def test_a_tall_arch_strip_keeps_its_texts_and_key_clear(tmp_path):
    """A pointed arch taller than its span (the strip's panels were narrower than their corner texts,
    and the thrust line's key lay over the first one): every text and the legend clear."""
    from yadearch.api.runs import run

    case_overrides = {"geometry.shape": "pointed", "geometry.thickness_mm": 40.0, "geometry.n_voussoirs": 21}
    from yadearch.case.config import preset

    case = preset("set2").with_overrides({**case_overrides, "numerics.engine": "static"})
    result = run(case, out=tmp_path / "tall", figures=False, quiet=True)
    folder = read_run(result.path)
    fig = strip_figure(folder, analyse_run(folder))
    assert fig.legends and label_clashes(fig) == []
