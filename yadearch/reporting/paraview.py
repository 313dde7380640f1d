"""A run for ParaView: every recorded state of its loading path as a time series (NAME.pvd) of VTK
XML unstructured grids written by VTK itself, in metres: part 0 the blocks as hexahedra (cell data:
block id, support flag, displacement, rotation), part 1 the joints as points at their centres
(point data: interface, normal and shear force, openings, hinge flag). ParaView's time is the
support displacement delta in mm; the file names carry the state's index and delta. On a live load's
path the time is the state's index along it (its load rises, then falls past the peak), the load in
the file names and in the blocks' `live_load_N` (or `_g`)."""

from __future__ import annotations

import xml.etree.ElementTree as ElementTree
from pathlib import Path
from typing import Any

import numpy as np

from yadearch.analysis.blocks import block_centroids, case_geometry, joint_points
from yadearch.atomic import write_atomically
from yadearch.errors import YadearchError
from yadearch.model.geometry import ArchGeometry
from yadearch.plotting.states import run_states, state_hinges, state_joints
from yadearch.results.rundir import RunFolder
from yadearch.results.states import LOAD_COLUMN, LOAD_DIGITS, RunStates

PARTS = ("blocks", "joints")
HEX_CORNERS = 8  # a block is a prism on a quadrilateral: 4 front and 4 back corners


def placed_corners(geometry: ArchGeometry, pos: np.ndarray, rot: np.ndarray) -> np.ndarray:
    """(n_blocks, 8, 3) block corners (m) as placed: each prism turned by its rotation about z and moved
    from its undeformed centroid to `pos`; ordered as a VTK hexahedron (the first face's normal,
    right-handed, toward the second face)."""
    centroids = block_centroids(geometry)
    corners = []
    for b, prism in enumerate(geometry.blocks):
        if len(prism) != HEX_CORNERS:
            raise ValueError(f"block {b} has {len(prism)} corners; the export takes quadrilateral prisms")
        c, s = np.cos(rot[b]), np.sin(rot[b])
        d = prism[:, :2] - centroids[b]
        xy = pos[b] + np.column_stack([c * d[:, 0] - s * d[:, 1], s * d[:, 0] + c * d[:, 1]])
        placed = np.column_stack([xy, prism[:, 2]])
        front, back = placed[:4], placed[4:]
        normal = np.cross(front[1] - front[0], front[2] - front[0])
        if normal @ (back[0] - front[0]) < 0:  # the front face turns the other way: reverse both faces
            front, back = front[::-1], back[::-1]
        corners.append(np.vstack([front, back]))
    return np.array(corners)


def _grid(points: np.ndarray, cell_type: int, cells: np.ndarray, data: dict[str, np.ndarray], on_cells: bool) -> Any:
    """A vtkUnstructuredGrid of `cells` (rows of point indices) with `data` arrays on its cells or points."""
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkUnstructuredGrid

    grid = vtkUnstructuredGrid()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(np.ascontiguousarray(points, dtype=float), deep=True))
    grid.SetPoints(vtk_points)
    connectivity = np.hstack([np.full((len(cells), 1), cells.shape[1]), cells]).ravel()
    cell_array = vtkCellArray()
    cell_array.SetCells(len(cells), numpy_to_vtkIdTypeArray(connectivity.astype(np.int64), deep=True))
    grid.SetCells(cell_type, cell_array)
    target = grid.GetCellData() if on_cells else grid.GetPointData()
    for name, values in data.items():
        array = numpy_to_vtk(np.ascontiguousarray(values), deep=True)
        array.SetName(name)
        target.AddArray(array)
    return grid


def _write(grid: Any, path: Path) -> Path:
    """Write `grid` as a compressed binary .vtu file with VTK's XML writer, atomically."""
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter

    def save(temporary: Path) -> None:
        writer = vtkXMLUnstructuredGridWriter()
        writer.SetFileName(str(temporary))
        writer.SetInputData(grid)
        writer.SetDataModeToAppended()
        if not writer.Write():
            raise OSError(f"VTK could not write {path}")

    return write_atomically(path, save)


def _time_and_tag(states: RunStates, index: int) -> tuple[float, str]:
    """ParaView's time of state `index` and its files' tag: its support displacement, or on a live
    load's path its index, the load in the tag."""
    if states.load is None:
        return float(states.delta_mm[index]), f"delta{states.delta_mm[index]:.3f}mm"
    return float(index), f"load{states.load[index]:.{LOAD_DIGITS}g}{states.load_unit}"


def _load_data(states: RunStates, index: int, n_blocks: int) -> dict[str, np.ndarray]:
    """The blocks' cell array of a live load's path state: its load (none on a support's path)."""
    if states.load is None:
        return {}
    return {f"{LOAD_COLUMN}_{states.load_unit}": np.full(n_blocks, states.load[index])}


def export_run(run: RunFolder, out: Path) -> Path:
    """Write every state of the run's loading path into `out` (one .vtu per part and state) and
    `out`/RUN.pvd (RUN: the run folder's name) that lists them by time; returns the .pvd's path."""
    states = run_states(run)
    try:
        from vtkmodules.vtkCommonDataModel import VTK_HEXAHEDRON, VTK_VERTEX
    except ImportError:
        raise YadearchError(
            "the ParaView export needs VTK: Debian's python3-vtk9 (scripts/setup.sh) or `pip install vtk`"
        ) from None
    geometry = case_geometry(run.case)
    n_blocks, n_joints = len(geometry.blocks), len(geometry.joints)
    depth_mid = float(np.mean([prism[:, 2].mean() for prism in geometry.blocks]))
    centroids = block_centroids(geometry)
    ids = np.arange(n_blocks)
    collection = ElementTree.Element("Collection")
    for index in states.path():
        pos, rot = states.pos_m[index], states.rot_rad[index]
        snapshot = states.snapshot(index)
        time, tag = _time_and_tag(states, index)
        stem = f"{index:04d}_{tag}"
        displacement = np.column_stack([pos - centroids, np.zeros(n_blocks)])  # from the unloaded arch
        blocks = _grid(
            placed_corners(geometry, pos, rot).reshape(-1, 3),
            VTK_HEXAHEDRON,
            np.arange(n_blocks * HEX_CORNERS).reshape(n_blocks, HEX_CORNERS),
            {
                "block_id": ids,
                "support": np.isin(ids, (0, n_blocks - 1)).astype(np.int8),
                "displacement_m": displacement,
                "rotation_rad": rot,
                **_load_data(states, index, n_blocks),
            },
            on_cells=True,
        )
        rows = state_joints(run, geometry, index)
        intrados, extrados = rows["opening_intrados_mm"].to_numpy(), rows["opening_extrados_mm"].to_numpy()
        hinged = np.zeros(n_joints, np.int8)
        for h in state_hinges(run, geometry, rows):
            hinged[h.interface - 1] = 1
        centres = (joint_points(geometry, snapshot, "I") + joint_points(geometry, snapshot, "E")) / 2
        joint_grid = _grid(
            np.column_stack([centres, np.full(n_joints, depth_mid)]),
            VTK_VERTEX,
            np.arange(n_joints).reshape(-1, 1),
            {
                "interface": np.arange(1, n_joints + 1),
                "normal_force_N": rows["normal_force_N"].to_numpy(),
                "shear_force_N": rows["shear_force_N"].to_numpy(),
                "opening_intrados_m": intrados * 1e-3,
                "opening_extrados_m": extrados * 1e-3,
                "hinge": hinged,
            },
            on_cells=False,
        )
        for part, grid in enumerate((blocks, joint_grid)):
            name = f"{PARTS[part]}_{stem}.vtu"
            _write(grid, out / name)
            ElementTree.SubElement(collection, "DataSet", timestep=f"{time:.6g}", part=str(part), file=name)
    root = ElementTree.Element("VTKFile", type="Collection", version="0.1")
    root.append(collection)
    ElementTree.indent(root)
    pvd = out / f"{run.path.name}.pvd"
    tree = ElementTree.ElementTree(root)
    return write_atomically(pvd, lambda temporary: tree.write(temporary, encoding="utf-8", xml_declaration=True))
