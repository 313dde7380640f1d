"""Seeing the collapse (no YADE: the static engine on a 15-voussoir arch writes the same run folder as
the DEM): every state kept in states.npz, the strip of four states, the movie, and the ParaView time
series read back with VTK's own reader and rendered off-screen."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

import numpy as np
import pytest
from PIL import Image, ImageSequence
from synthetic_runs import make_run

import yadearch as ya
from yadearch.analysis.blocks import case_geometry
from yadearch.cli.commands import main
from yadearch.errors import RunFolderError, YadearchError
from yadearch.plotting import animation
from yadearch.solve.stages import Stage

COARSE = {"geometry.n_voussoirs": 15, "numerics.engine": "static"}
VOLUME_TOLERANCE = 1e-9  # relative: the blocks move as rigid bodies


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    folder = tmp_path_factory.mktemp("views") / "coarse"
    return ya.run(ya.preset("set2").with_overrides(COARSE), out=folder)


def test_every_state_of_the_path_is_kept_with_its_block_poses(run):
    """One state per joints.csv state, self-weight first and collapse last; the moving support's block
    sits where the settlement put it (straight down by delta) in every state of the path, and in the
    collapse state within du's tolerance (the static engine's collapse state is the failure nearest
    du's upper end, labelled with that end)."""
    states = run.states
    n_joints = len(case_geometry(run.folder.case).joints)
    assert len(states) * n_joints == len(run.joints) and states.pos_m.shape == (len(states), 17, 2)
    assert states.stage[0] == "selfweight" and states.stage[-1] == Stage.COLLAPSE
    path = states.path()
    assert (np.diff(states.delta_mm[path]) > 0).all()
    support = states.pos_m[:, -1] - states.pos_m[0, -1]
    assert support[:, 0] == pytest.approx(0.0, abs=1e-12)
    assert support[:-1, 1] == pytest.approx(-states.delta_mm[:-1] * 1e-3, abs=1e-12)
    tolerance_m = run.folder.case["numerics"]["du_tolerance_mm"] * 1e-3
    assert support[-1, 1] == pytest.approx(-states.delta_mm[-1] * 1e-3, abs=tolerance_m)
    assert states.delta_mm[-1] == pytest.approx(run.summary.du_bracket_mm[1])


def test_the_strip_of_four_states_is_written_with_the_run_figures(run):
    strip = run.path / "figures" / "strip.png"
    image = np.asarray(Image.open(strip).convert("L"), float)
    assert (run.path / "figures" / "strip.pdf").stat().st_size > 0 and image.std() > 10


def test_the_movie_has_a_frame_per_state_and_holds_the_collapse(run, tmp_path):
    gif = run.animate(tmp_path / "coarse.gif", fmt="gif")
    frames, durations = [], []  # GIF stores the held collapse as one long frame
    for frame in ImageSequence.Iterator(Image.open(gif)):  # one image, seeked: read each as it comes
        frames.append(np.asarray(frame.convert("L"), float))
        durations.append(frame.info["duration"])
    frame_ms = 1000 / animation.FRAMES_PER_S
    assert len(frames) == len(run.states.path()) and np.abs(frames[0] - frames[-1]).max() > 0
    assert durations[-1] == pytest.approx(
        frame_ms * (1 + animation.HOLD_COLLAPSE_S * animation.FRAMES_PER_S), abs=len(frames)
    )
    if shutil.which("ffmpeg"):
        assert run.animate(tmp_path / "coarse.mp4").stat().st_size > 10_000


def test_mp4_without_ffmpeg_and_a_run_without_states_are_one_line_errors(run, tmp_path, monkeypatch):
    monkeypatch.setattr(animation.writers, "is_available", lambda name: False)
    with pytest.raises(YadearchError, match="MP4 needs ffmpeg.*--format gif") as error:
        run.animate(tmp_path / "x.mp4")
    assert "\n" not in str(error.value) and not (tmp_path / "x.mp4").exists()
    make_run(tmp_path / "old")
    with pytest.raises(RunFolderError, match="no states.npz"):
        ya.open_run(tmp_path / "old").export_vtk()


def _read(path):
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    return reader.GetOutput()


def _cell_array(grid, name):
    from vtkmodules.util.numpy_support import vtk_to_numpy

    return vtk_to_numpy(grid.GetCellData().GetArray(name))


def test_the_paraview_export_without_vtk_is_a_one_line_error(run, tmp_path, monkeypatch):
    import sys

    monkeypatch.setitem(sys.modules, "vtkmodules.vtkCommonDataModel", None)  # as on a pip install without VTK
    with pytest.raises(YadearchError, match="needs VTK") as error:
        run.export_vtk(tmp_path / "vtk")
    assert "\n" not in str(error.value)


def test_the_paraview_series_reads_back_with_vtk(run, tmp_path):
    pytest.importorskip("vtkmodules")
    """Every path state at its delta, both parts; the blocks' volumes are the prisms' (rigid motion,
    positive: well-ordered hexahedra); the moving support's displacement is the settlement; four
    joints flagged as hinges at collapse."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter

    pvd = run.export_vtk(tmp_path / "vtk")
    datasets = ElementTree.parse(pvd).getroot().find("Collection").findall("DataSet")
    states = run.states
    assert len(datasets) == 2 * len(states.path())
    times = [float(d.get("timestep")) for d in datasets if d.get("part") == "0"]
    assert times == pytest.approx(states.delta_mm[states.path()].tolist())
    geometry = case_geometry(run.folder.case)
    prisms = np.array([abs(_area(b[:4, :2])) * np.ptp(b[:, 2]) for b in geometry.blocks])
    last_blocks = _read(tmp_path / "vtk" / datasets[-2].get("file"))
    sizes = vtkCellSizeFilter()
    sizes.SetInputData(last_blocks)
    sizes.Update()
    volumes = vtk_to_numpy(sizes.GetOutput().GetCellData().GetArray("Volume"))
    assert last_blocks.GetNumberOfCells() == len(geometry.blocks) == 17
    assert volumes == pytest.approx(prisms, rel=VOLUME_TOLERANCE)
    settled = _read(tmp_path / "vtk" / datasets[-4].get("file"))  # the last equilibrium
    moved = _cell_array(settled, "displacement_m")[-1]
    assert moved == pytest.approx([0.0, -states.delta_mm[states.path()[-2]] * 1e-3, 0.0], abs=1e-9)
    joints = _read(tmp_path / "vtk" / datasets[-1].get("file"))
    hinge = vtk_to_numpy(joints.GetPointData().GetArray("hinge"))
    assert joints.GetNumberOfPoints() == len(geometry.joints) and hinge.sum() == len(run.hinges) == 4


def test_polygon_blocks_export_as_polyhedra_of_their_volume(tmp_path):
    """Voussoirs of seven corners (a curved extrados, tests/surveys.py) export as VTK polyhedra: every
    block's volume, as VTK measures it after the collapse, is its prism's (rigid motion, outward faces);
    the supports stay hexahedra."""
    pytest.importorskip("vtkmodules")
    from surveys import curved_extrados
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkCommonDataModel import VTK_HEXAHEDRON, VTK_POLYHEDRON
    from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter

    base = ya.preset("set2").with_overrides(COARSE)
    polygon_run = ya.run(ya.measured_case(curved_extrados(base, 3), base=base), out=tmp_path / "run")
    pvd = polygon_run.export_vtk(tmp_path / "vtk")
    datasets = ElementTree.parse(pvd).getroot().find("Collection").findall("DataSet")
    last = _read(tmp_path / "vtk" / datasets[-2].get("file"))
    types = [last.GetCellType(k) for k in range(last.GetNumberOfCells())]
    assert types == [VTK_HEXAHEDRON] + [VTK_POLYHEDRON] * 15 + [VTK_HEXAHEDRON]
    sizes = vtkCellSizeFilter()
    sizes.SetInputData(last)
    sizes.Update()
    volumes = vtk_to_numpy(sizes.GetOutput().GetCellData().GetArray("Volume"))
    geometry = case_geometry(polygon_run.folder.case)
    prisms = [abs(_area(b[: len(b) // 2, :2])) * np.ptp(b[:, 2]) for b in geometry.blocks]
    assert volumes == pytest.approx(prisms, rel=VOLUME_TOLERANCE)


def _area(xy):
    """Signed area of a polygon (shoelace)."""
    return 0.5 * np.sum(xy[:, 0] * np.roll(xy[:, 1], -1) - np.roll(xy[:, 0], -1) * xy[:, 1])


RENDER = """
import sys
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.vtkFiltersGeometry import vtkGeometryFilter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow,
                                         vtkWindowToImageFilter)
from vtkmodules.vtkIOImage import vtkPNGWriter
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  the rendering backend
reader = vtkXMLUnstructuredGridReader(); reader.SetFileName(sys.argv[1])
surface = vtkGeometryFilter(); surface.SetInputConnection(reader.GetOutputPort())
mapper = vtkPolyDataMapper(); mapper.SetInputConnection(surface.GetOutputPort())
actor = vtkActor(); actor.SetMapper(mapper)
renderer = vtkRenderer(); renderer.AddActor(actor); renderer.SetBackground(1, 1, 1); renderer.ResetCamera()
window = vtkRenderWindow(); window.SetOffScreenRendering(1); window.AddRenderer(renderer); window.SetSize(400, 300)
window.Render()
image = vtkWindowToImageFilter(); image.SetInput(window); image.Update()
writer = vtkPNGWriter(); writer.SetFileName(sys.argv[2]); writer.SetInputConnection(image.GetOutputPort())
writer.Write()
"""


def test_a_state_renders_off_screen(run, tmp_path):
    """ParaView's engine draws the exported blocks: the picture is not blank (X-less machines render
    through Xvfb, as ParaView's batch tools do)."""
    pytest.importorskip("vtkmodules")
    pvd = run.export_vtk(tmp_path / "vtk")
    blocks = tmp_path / "vtk" / ElementTree.parse(pvd).getroot().find("Collection").find("DataSet").get("file")
    command = [sys.executable, "-c", RENDER, str(blocks), str(tmp_path / "state.png")]
    if not os.environ.get("DISPLAY"):
        if not shutil.which("xvfb-run"):
            pytest.skip("no display and no xvfb-run (scripts/setup.sh installs xvfb)")
        command = ["xvfb-run", "-a", *command]
    subprocess.run(command, check=True, capture_output=True, timeout=120)
    image = np.asarray(Image.open(tmp_path / "state.png").convert("L"), float)
    assert image.shape == (300, 400) and (image < 250).mean() > 0.01  # some of it is drawn, not white


def test_the_commands_write_the_movie_and_the_series(run, tmp_path, capsys):
    pytest.importorskip("vtkmodules")
    assert main(["animate", str(run.path), "--format", "gif", "--out", str(tmp_path / "m.gif")]) == 0
    assert main(["export", str(run.path), "--vtk", "--out", str(tmp_path / "v")]) == 0
    out = capsys.readouterr().out
    assert (tmp_path / "m.gif").is_file() and "movie -> " in out and (tmp_path / "v" / "coarse.pvd").is_file()


@pytest.mark.parametrize(
    "out, fmt, message",
    [
        ("movie.txt", "mp4", r"out must end in \.mp4 for a mp4 movie"),
        ("movie.gif", "avi", "fmt must be one of mp4, gif, got 'avi'"),
        ("/proc/movie.gif", "gif", "out: cannot write in the folder '/proc'"),
    ],
)
def test_a_movie_that_cannot_be_written_is_refused_before_drawing(run, tmp_path, out, fmt, message):
    """A wrong suffix or format, or a folder no file can be written in: one line, nothing drawn."""
    target = out if out.startswith("/") else tmp_path / out
    with pytest.raises(YadearchError, match=message) as error:
        run.animate(target, fmt=fmt)
    assert "\n" not in str(error.value)


def test_a_long_path_is_drawn_at_every_kth_state_ending_on_the_collapse():
    """Found in a user trial: a static run's 636 states made a 13.5 MB GIF in 2.5 minutes."""
    kept = animation.every_kth(list(range(636)), animation.MAX_PATH_FRAMES)
    assert len(kept) <= animation.MAX_PATH_FRAMES and kept[0] == 0 and kept[-1] == 635
    assert animation.every_kth(list(range(10)), animation.MAX_PATH_FRAMES) == list(range(10))
