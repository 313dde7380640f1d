"""A run for ParaView: every recorded state of its loading path as a time series (NAME.pvd) of VTK
XML unstructured grids written by VTK itself, in metres: part 0 the blocks as hexahedra (polyhedra
where a block is a prism on another polygon; cell data: block id, support flag, displacement,
rotation), part 1 the joints as points at their centres
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
from yadearch.model.geometry import QUADRILATERAL_PRISM, ArchGeometry
from yadearch.plotting.states import run_states, state_hinges, state_joints
from yadearch.results.rundir import RunFolder
from yadearch.results.states import LOAD_COLUMN, LOAD_DIGITS, RunStates

PARTS = ("blocks", "joints")


def placed_corners(geometry: ArchGeometry, pos: np.ndarray, rot: np.ndarray) -> list[np.ndarray]:
    """Each block's (2k, 3) corners (m) as placed: its prism turned by its rotation about z and moved
    from its undeformed centroid to `pos`; its front face first, ordered so that its normal (right-handed)
    points toward the back face, as a VTK hexahedron's (and a polyhedron's faces) want."""
    centroids = block_centroids(geometry)
    corners = []
    for b, prism in enumerate(geometry.blocks):
        c, s = np.cos(rot[b]), np.sin(rot[b])
        d = prism[:, :2] - centroids[b]
        xy = pos[b] + np.column_stack([c * d[:, 0] - s * d[:, 1], s * d[:, 0] + c * d[:, 1]])
        placed = np.column_stack([xy, prism[:, 2]])
        half = len(placed) // 2
        front, back = placed[:half], placed[half:]
        normal = np.cross(front[1] - front[0], front[2] - front[0])
        if normal @ (back[0] - front[0]) < 0:  # the front face turns the other way: reverse both faces
            front, back = front[::-1], back[::-1]
        corners.append(np.vstack([front, back]))
    return corners


def _block_cells(corners: list[np.ndarray]) -> list[tuple[int, list[int]]]:
    """The blocks as VTK cells over their stacked corners: a hexahedron for a prism on a quadrilateral,
    a polyhedron (its face stream: front, back and side faces, each outward) on any other polygon."""
    from vtkmodules.vtkCommonDataModel import VTK_HEXAHEDRON, VTK_POLYHEDRON

    cells, first = [], 0
    for block in corners:
        half = len(block) // 2
        front = list(range(first, first + half))
        back = [i + half for i in front]
        if len(block) == QUADRILATERAL_PRISM:
            cells.append((VTK_HEXAHEDRON, front + back))
        else:
            sides = [[front[i], front[(i + 1) % half], back[(i + 1) % half], back[i]] for i in range(half)]
            faces = [front[::-1], back, *sides]  # the front face's normal points inward: reversed
            cells.append((VTK_POLYHEDRON, [len(faces)] + [v for face in faces for v in (len(face), *face)]))
        first += len(block)
    return cells


def _grid(points: np.ndarray, cells: list[tuple[int, list[int]]], data: dict[str, np.ndarray], on_cells: bool) -> Any:
    """A vtkUnstructuredGrid of `cells` (a VTK cell type and its point ids, or a polyhedron's face
    stream, a cell) with `data` arrays on its cells or points."""
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonCore import vtkIdList, vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid

    grid = vtkUnstructuredGrid()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(np.ascontiguousarray(points, dtype=float), deep=True))
    grid.SetPoints(vtk_points)
    grid.Allocate(len(cells))
    for cell_type, stream in cells:
        ids = vtkIdList()
        for v in stream:
            ids.InsertNextId(v)
        grid.InsertNextCell(cell_type, ids)
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
        from vtkmodules.vtkCommonDataModel import VTK_VERTEX
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
        corners = placed_corners(geometry, pos, rot)
        blocks = _grid(
            np.vstack(corners),
            _block_cells(corners),
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
            [(VTK_VERTEX, [k]) for k in range(n_joints)],
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
