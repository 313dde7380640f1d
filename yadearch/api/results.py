"""A finished run read back for notebooks and scripts: its typed summary, its hinges with the
paper's letters, its tables and figures."""

from __future__ import annotations

import math
import os
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path
from typing import TYPE_CHECKING

from yadearch.case.names import FILE, output_path, writable_folder
from yadearch.errors import ArgumentTypeError, CaseError
from yadearch.results.rundir import FIGURES_DIR, VTK_DIR, RunFolder, is_load_path_folder, read_run
from yadearch.results.states import RunStates
from yadearch.results.summary import DEM, HingeRef, RunSummary

if TYPE_CHECKING:
    import pandas as pd

MOVIE_FORMATS = ("mp4", "gif")


@dataclass(frozen=True)
class HingeAtCollapse(HingeRef):
    """One hinge of the collapse mechanism: the run summary's hinge (interface, 1 = left support; side,
    I intrados or E extrados; `label` "30E") with its letter in the paper's positional convention (A
    the intrados hinge, B the other extrados hinge, C at the right support, D at the left one; None if
    it has none) and its rotation."""

    paper_label: str | None
    rotation_mrad: float | None


class RunResult:
    """A finished run folder read back: its summary as attributes, its tables as DataFrames."""

    def __init__(self, folder: RunFolder):
        self.folder = folder
        self.reused = False  # `run` found this run finished in its folder and made none (its log said nothing)

    @property
    def path(self) -> Path:
        return self.folder.path

    @property
    def summary(self) -> RunSummary:
        """summary.json, typed: du, its bracket, the hinges, the loading, the cost (docs/usage.md)."""
        return self.folder.summary

    @property
    def du_mm(self) -> float | None:
        """Collapse displacement of the support (mm); None if the arch did not collapse."""
        return self.summary.du_mm

    @property
    def du_first_mm(self) -> float | None:
        """Where the path first lost stability (mm; a fold, or a snap past the snap floor): du where the
        path made no snap; an arch that survives its snaps and stands has one too; None where the path
        neither snapped nor collapsed (docs/numerics.md)."""
        return self.summary.du_first_mm

    @property
    def engine(self) -> str:
        """The engine that made this run: 'dem' (YADE) or 'static' (Newton's method)."""
        return self.summary.engine

    @property
    def collapsed(self) -> bool:
        return self.summary.collapsed

    @property
    def capacity(self) -> tuple[float, str] | None:
        """A live load's path folder: its collapse multiplier and unit ((7.39, 'N'); NaN: no collapse);
        None for a support-movement run, whose answer is `du_mm`."""
        answer = self.folder.load_path
        if answer is None:
            return None
        value = answer["collapse_multiplier"]
        return (math.nan if value is None else float(value), str(answer["unit"]))

    @property
    def series(self) -> pd.DataFrame:
        """series.csv: one row every few steps, labelled by stage (docs/numerics.md)."""
        return self.folder.series

    @property
    def joints(self) -> pd.DataFrame:
        """joints.csv: every interface at every equilibrium state and at collapse."""
        return self.folder.joints

    @cached_property
    def hinges(self) -> list[HingeAtCollapse]:
        """The hinges at collapse, left to right, with the paper's positional labels."""
        rotation = self.summary.hinge_rotations_mrad
        labels = self.summary.paper_labels(self.folder.case["geometry"]["n_voussoirs"] + 1)
        return [HingeAtCollapse(h.interface, h.side, label, rotation.get(h)) for h, label in labels.items()]

    def loading_curve(self) -> pd.DataFrame:
        """The equilibrium points of the loading only (self-weight state, then each accepted
        equilibrium), in increasing support displacement."""
        from yadearch.plotting.run_figures import loading_path

        return loading_path(self.series)

    def plot_collapse(self, ax=None, snapshot: str = "collapse"):
        """The arch at collapse with its hinges (the paper's Fig. 9) into a matplotlib `ax`, or a new
        figure at print size; returns the figure."""
        from yadearch.analysis.run import analyse_run
        from yadearch.plotting.run_figures import collapse_figure

        return collapse_figure(self.folder, analyse_run(self.folder), ax=ax, snapshot=snapshot)

    @property
    def references(self) -> list[str]:
        """What this result stands on: the DEM engine (for a DEM run) and, for the paper's case, the paper."""
        from yadearch.case.paper import paper_mismatch
        from yadearch.case.reference import references_for

        return references_for(dem=self.engine == DEM, paper_case=paper_mismatch(self.folder.case) is None)

    @property
    def states(self) -> RunStates:
        """Every recorded state (states.npz) as arrays: support displacement, stage, step, block
        positions and rotations; RunFolderError for a run written before states were kept."""
        from yadearch.plotting.states import run_states

        return run_states(self.folder)

    def animate(self, out: str | Path | None = None, fmt: str = "mp4") -> Path:
        """The run as a movie (MP4 through ffmpeg, or GIF) along its loading path to collapse, written
        to `out` (default: the run folder's figures/NAME.FMT); returns its path."""
        from yadearch.analysis.run import analyse_run
        from yadearch.plotting.animation import animate_run

        if fmt not in MOVIE_FORMATS:
            raise CaseError(f"fmt must be one of {', '.join(MOVIE_FORMATS)}, got {fmt!r}")
        path = output_path(out, "out", FILE) if out is not None else self.path / FIGURES_DIR / f"{self.path.name}.{fmt}"
        if path.suffix.lower() != f".{fmt}":
            raise CaseError(f"out must end in .{fmt} for a {fmt} movie, got {str(path)!r}")
        writable_folder(path.parent, "out")  # refused before minutes of drawing, not after
        return animate_run(self.folder, analyse_run(self.folder), path, fmt)

    def export_vtk(self, out: str | Path | None = None) -> Path:
        """Every state as a ParaView time series (a .pvd of .vtu files: the voussoirs as 3D cells, the
        joints as points with their forces) in `out` (default: the run folder's vtk/); returns the .pvd."""
        from yadearch.reporting.paraview import export_run

        return export_run(self.folder, output_path(out, "out") if out is not None else self.path / VTK_DIR)

    def write_figures(self, out: str | Path | None = None, jobs: int = 1) -> dict[str, tuple[Path, Path]]:
        """Write the run's figures (PDF and PNG) into `out` (default: the run folder's `figures/`); `jobs`
        2 draws them in two processes where the platform forks (Linux). The garbage collector is paused
        from the imports on (`plotting.parallel.collector_paused`)."""
        from yadearch.api.arguments import check_arguments
        from yadearch.plotting.parallel import collector_paused

        check_arguments(figure_jobs=jobs)
        if self.folder.load_path is not None:  # a run's figures are drawn against a displacement it holds
            raise CaseError(
                f"{self.path} is a live load's path: its figure is {self.path}.pdf/.png; its folder serves "
                "animate and export_vtk"
            )
        folder = output_path(out, "out") if out is not None else self.path / FIGURES_DIR
        with collector_paused():
            from yadearch.analysis.run import analyse_run
            from yadearch.plotting.run_figures import write_figures

            return write_figures(self.folder, analyse_run(self.folder), folder, jobs)

    def __repr__(self) -> str:
        if self.folder.load_path is not None:
            answer = f"live load: {self.summary.outcome}"
        else:
            answer = "no collapse" if self.du_mm is None else f"du={self.du_mm:.2f} mm"
        return f"RunResult({self.path}, {answer}, hinges {' '.join(map(str, self.hinges)) or '-'})"


def open_run(path: str | Path) -> RunResult:
    """Read a finished run folder, or a live load's path folder (OUT/NAME_load_path/ of `load_path`
    on the static engine: its states, `animate`, `export_vtk`); RunFolderError in one line for one
    that is not complete or damaged."""
    if isinstance(path, bytes) or not isinstance(path, (str, os.PathLike)):
        raise ArgumentTypeError(
            f"path must be a run folder (str or pathlib.Path), got {type(path).__name__} {path!r:.40}"
        )
    if not is_load_path_folder(Path(path)):
        return RunResult(read_run(path))
    from yadearch.results.load_path import read_load_path_folder  # a live load's solver, imported for one only

    return RunResult(read_load_path_folder(Path(path)))
