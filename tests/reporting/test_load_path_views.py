"""A live load's path seen as a run is (no YADE: the static engine on a 9-voussoir arch): its states
kept in OUT/NAME_load_path/ with their loads and the solver's poses, the movie labelled by the load,
the ParaView series with a file per state, and one-line refusals of a folder without states."""

from __future__ import annotations

import xml.etree.ElementTree as ElementTree

import matplotlib
import numpy as np
import pandas as pd
import pytest
from PIL import Image, ImageSequence
from synthetic_runs import make_run

matplotlib.use("Agg")

import yadearch as ya  # noqa: E402
from yadearch.analysis.blocks import case_geometry  # noqa: E402
from yadearch.analysis.run import analyse_run  # noqa: E402
from yadearch.cli.commands import main  # noqa: E402
from yadearch.errors import CaseError  # noqa: E402
from yadearch.plotting.animation import FRAME_CM, movie_title  # noqa: E402
from yadearch.plotting.house import new_figure  # noqa: E402
from yadearch.plotting.states import draw_state, drawing_limits, state_view  # noqa: E402
from yadearch.solve.load_path import ASCENDING, BRANCH  # noqa: E402
from yadearch.solve.statics import static_arch  # noqa: E402

CASE = ya.preset("set2").with_overrides({"live_load": "vertical", "n_voussoirs": 9})
FOLDER_FILES = {"case.toml", "series.csv", "joints.csv", "snapshots.json", "states.npz", "load_path.json"}
CSV_PRECISION = 1e-7  # the tables' eight significant figures
BALANCE_TOLERANCE = 1e-6  # relative to the arch's weight: every recorded state is an equilibrium


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    """The load path (the solver's answer with its states) and its folder read back."""
    out = tmp_path_factory.mktemp("load_path")
    result = ya.load_path(CASE, out=out)
    return result, ya.open_run(out / "set2_load_path")


def test_the_folder_keeps_every_state_of_the_path_beside_the_files_it_had(written):
    """One state per row of the curve (the start, the ascending and descending branches) and the
    collapse; each state's load is the curve's multiplier, rising along the ascending branch; the
    support displacement is the one the path holds (none)."""
    result, run = written
    assert {p.name for p in run.path.iterdir()} == FOLDER_FILES
    assert {p.name for p in run.path.parent.glob("set2_load_path.*")} == {
        f"set2_load_path.{s}" for s in ("json", "csv", "pdf", "png")
    }
    states, curve = run.states, result.curve
    assert result.outcome == "collapse" and (curve[BRANCH] == "descending").sum() >= 3
    assert len(states) == len(curve) + 1 == len(result.states)
    assert states.stage[0] == "selfweight" and states.stage[-1] == "collapse" and states.load_unit == "N"
    assert np.array_equal(states.load[:-1], curve["multiplier"].to_numpy())
    ascending = (curve[BRANCH] == ASCENDING).to_numpy()
    assert (np.diff(states.load[:-1][ascending]) > 0).all() and states.load[0] == 0.0
    assert (states.delta_mm == 0.0).all() and (np.diff(states.step) > 0).all()


def test_the_poses_are_the_solvers(written):
    """Every state's block poses, the last (the collapse) included, as the solver left them."""
    result, run = written
    arch = static_arch(CASE)
    for index, state in enumerate(result.states):
        pos, rot = arch.poses(state.u)
        assert np.array_equal(run.states.pos_m[index], pos) and np.array_equal(run.states.rot_rad[index], rot)


def test_the_tables_hold_each_state_with_its_load_in_equilibrium(written):
    """series.csv: the supports carry the weight and each state's load, and the residual counts the
    load (the collapse, a runaway, is no equilibrium); joints.csv: every joint of every state."""
    result, run = written
    series = run.series
    weight = float(static_arch(CASE).weight[1:-1].sum())
    balanced = series[series["stage"] != "collapse"]
    assert series["live_load_N"].to_numpy() == pytest.approx(run.states.load, rel=CSV_PRECISION)
    carried = balanced["left_Ry_N"] + balanced["right_Ry_N"] - weight - balanced["live_load_N"]
    assert np.abs(carried).max() < BALANCE_TOLERANCE * weight
    assert balanced["unbalanced"].max() < BALANCE_TOLERANCE
    assert len(run.joints) == len(run.states) * len(case_geometry(run.folder.case).joints)


def test_a_frame_says_the_load_and_the_title_the_capacity(written):
    """The corner of each frame names its load, never δ; the title the capacity; the support is not
    called moving."""
    result, run = written
    geometry = case_geometry(run.folder.case)
    analysis = analyse_run(run.folder)
    assert movie_title(run.folder) == f"set2: static engine, live load: collapse at {result.capacity:.4g} N"
    last = len(run.states) - 1
    fig = new_figure(height_cm=FRAME_CM[1], width_cm=FRAME_CM[0])
    ax = fig.add_subplot()
    draw_state(ax, state_view(run.folder, geometry, analysis, last), geometry, drawing_limits(geometry))
    corner = next(t.get_text() for t in ax.texts if "(collapse)" in t.get_text())
    assert corner.startswith(f"load {run.states.load[-1]:.4g} N (collapse)\nright support on the arch:")
    labels = [float(run.states.place(i).split()[1]) for i in range(len(run.states))]
    ascending = (result.curve[BRANCH] == ASCENDING).to_numpy()
    assert all(run.states.place(i).endswith(" N") and "δ" not in run.states.place(i) for i in range(last + 1))
    assert (np.diff(np.array(labels[:-1])[ascending]) >= 0).all() and labels[0] == 0.0
    assert labels[-1] == pytest.approx(result.capacity, rel=1e-3)


def test_the_commands_animate_and_export_the_load_path(written, tmp_path, capsys):
    """`yadearch animate` writes a frame per state (the collapse held); `yadearch export --vtk` a
    blocks and a joints file per state, timed by the state's index, each with its load."""
    pytest.importorskip("vtkmodules")
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

    result, run = written
    assert main(["animate", str(run.path), "--format", "gif", "--out", str(tmp_path / "m.gif")]) == 0
    assert main(["export", str(run.path), "--vtk", "--out", str(tmp_path / "v")]) == 0
    assert "movie -> " in capsys.readouterr().out
    frames = list(ImageSequence.Iterator(Image.open(tmp_path / "m.gif")))
    assert len(frames) == len(run.states)
    datasets = ElementTree.parse(tmp_path / "v" / "set2_load_path.pvd").getroot().find("Collection").findall("DataSet")
    blocks = [d for d in datasets if d.get("part") == "0"]
    assert len(blocks) == len(datasets) / 2 == len(run.states) == len(list((tmp_path / "v").glob("blocks_*.vtu")))
    assert [float(d.get("timestep")) for d in blocks] == list(range(len(run.states)))
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(tmp_path / "v" / blocks[-1].get("file")))
    reader.Update()
    cells = reader.GetOutput().GetCellData()
    assert vtk_to_numpy(cells.GetArray("live_load_N")) == pytest.approx(run.states.load[-1])
    moved = vtk_to_numpy(cells.GetArray("displacement_m"))[:, :2]
    assert moved == pytest.approx(run.states.pos_m[-1] - static_arch(CASE).centroid0, abs=1e-12)


def test_a_settled_arch_path_starts_after_its_movement(tmp_path):
    """After 5 mm of the support's movement: every state holds it, the start is the movement's last
    equilibrium (no load), the moving support's block 5 mm down; no descending branch asked for."""
    result = ya.load_path(CASE, out=tmp_path, after_mm=5.0, descend_to=None)
    states = ya.open_run(tmp_path / "set2_load_path").states
    assert len(states) == len(result.curve) + (result.outcome == "collapse")
    assert (states.delta_mm == 5.0).all() and states.stage[0] == "equilibrium" and states.load[0] == 0.0
    support = states.pos_m[:, -1] - static_arch(CASE).centroid0[-1]
    assert support == pytest.approx(np.tile([0.0, -5e-3], (len(states), 1)), abs=1e-12)


def test_a_folder_without_states_is_one_line_naming_what_is_taken(written, tmp_path, capsys):
    """animate and export refuse a folder that holds no run, a run without states, or the load path's
    JSON, in one line that says RUN_FOLDER takes a run or a load path's folder; a load path's folder
    has no run figures."""
    _, run = written
    make_run(tmp_path / "old")  # a run written before states were kept
    (tmp_path / "empty").mkdir()
    answer = run.path.parent / "set2_load_path.json"
    for folder, words in (("old", "no states.npz"), ("empty", "no summary.json"), (answer, "is a file")):
        for command in (["animate", "--format", "gif"], ["export", "--vtk"]):
            assert main([command[0], str(tmp_path / folder), *command[1:]]) == 1
            err = capsys.readouterr().err.strip()
            assert "\n" not in err and err.startswith("error: Invalid value for 'RUN_FOLDER'") and words in err
            assert "RUN_FOLDER takes a run folder or a live load's path folder" in err
    with pytest.raises(CaseError, match="is a live load's path: its figure is .*set2_load_path.pdf") as error:
        run.write_figures(tmp_path / "figures")
    assert "\n" not in str(error.value) and not (tmp_path / "figures").exists()
    assert pd.read_csv(run.path.parent / "set2_load_path.csv").shape[0] == len(run.states) - 1
