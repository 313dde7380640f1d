"""The Python API: cases, runs, campaigns and the rigid-block limit analysis as functions returning
typed results, for notebooks and scripts; the command line calls the same functions.

    import yadearch as ya
    case = ya.preset("set2").replace(kn_N_per_mm3=10)
    res = ya.run(case, out="runs/k10")
    res.du_mm, res.hinges, res.loading_curve(), res.write_figures()
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.case.config import ArchCase
from yadearch.case.config import preset as _preset
from yadearch.errors import RunFolderError
from yadearch.results.rundir import FIGURES_DIR, RunFolder, case_differences, is_complete, read_run
from yadearch.results.summary import DEM, RunSummary

DEFAULT_RUNS_DIR = Path("runs")


@dataclass(frozen=True)
class HingeAtCollapse:
    """One hinge of the collapse mechanism: interface (1 = left support), side (I intrados, E
    extrados), its letter in the paper's positional convention (A the intrados hinge, B the other
    extrados hinge, C at the right support, D at the left one; None if it has none) and its rotation.
    As everywhere in yadearch (run summaries, limit analyses), `label` is "30E"."""

    interface: int
    side: str
    paper_label: str | None
    rotation_mrad: float | None

    @property
    def label(self) -> str:
        return f"{self.interface}{self.side}"

    def __str__(self) -> str:
        return self.label


class RunResult:
    """A finished run folder read back: its summary as attributes, its tables as DataFrames."""

    def __init__(self, folder: RunFolder):
        self.folder = folder

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
    def engine(self) -> str:
        """The engine that made this run: 'dem' (YADE) or 'static' (Newton's method)."""
        return self.summary.engine

    @property
    def collapsed(self) -> bool:
        return self.summary.collapsed

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
        from yadearch.analysis import analyse_run
        from yadearch.plotting.run_figures import collapse_figure

        return collapse_figure(self.folder, analyse_run(self.folder), ax=ax, snapshot=snapshot)

    @property
    def references(self) -> list[str]:
        """What this result stands on: the DEM engine (for a DEM run) and, for the paper's case, the paper."""
        from yadearch.case.reference import references_for
        from yadearch.reporting.report import case_mismatch

        return references_for(dem=self.engine == DEM, paper_case=case_mismatch(self.folder.case) is None)

    def write_figures(self, out: str | Path | None = None) -> dict[str, tuple[Path, Path]]:
        """Write the run's figures (PDF and PNG) into `out` (default: the run folder's `figures/`)."""
        from yadearch.analysis import analyse_run
        from yadearch.plotting.run_figures import write_figures

        folder = Path(out) if out is not None else self.path / FIGURES_DIR
        return write_figures(self.folder, analyse_run(self.folder), folder)

    def __repr__(self) -> str:
        du = "no collapse" if self.du_mm is None else f"du={self.du_mm:.2f} mm"
        return f"RunResult({self.path}, {du}, hinges {' '.join(map(str, self.hinges)) or '-'})"


def preset(name: str) -> ArchCase:
    """The paper's arch with the kn of voussoir set 1 or set 2 ("set1", "set2")."""
    return _preset(name)


def movement(name: str) -> dict:
    """The [loading] parameters of a named support movement, for `case.with_overrides(...)`:
    settlement, spreading, closing, inclined, symmetric_spreading, abutment_tilt, settle_then_spread
    (docs/movements.md)."""
    from yadearch.case.movement import movement_overrides

    return movement_overrides(name)


def open_run(path: str | Path) -> RunResult:
    """Read a finished run folder."""
    return RunResult(read_run(path))


ENGINES = ("dem", "static")


def as_case(case: ArchCase | str) -> ArchCase:
    """An ArchCase, or a preset's name ('set1', 'set2') taken as that preset; TypeError naming the
    argument for anything else."""
    if isinstance(case, ArchCase):
        return case
    if isinstance(case, str):
        return _preset(case)
    raise TypeError(f"case must be an ArchCase (ya.preset, ya.load_case) or a preset name ('set1', 'set2'), "
                    f"got {type(case).__name__}")


def with_engine(case: ArchCase | str, engine: str | None) -> ArchCase:
    """`case` (or a preset's name) solved by `engine` ('dem': YADE, 'static': Newton's method; None:
    the case's own numerics.engine); ValueError naming the argument for another value."""
    case = as_case(case)
    if engine is None:
        return case
    if engine not in ENGINES:
        raise ValueError(f"engine must be one of {', '.join(ENGINES)}, got {engine!r}")
    return case.with_overrides({"numerics.engine": engine})


def run(case: ArchCase | str, out: str | Path | None = None, timeout_s: float | None = None,
        figures: bool = True, rerun: bool = False, overwrite: bool = False, engine: str | None = None) -> RunResult:
    """Run `case` to collapse in a child process (YADE, or the static engine with `engine="static"`),
    writing the run folder `out` (default runs/NAME) and its figures; returns the result read back.
    A finished run of the same case in `out` is reused (unless `rerun`); one of another case is kept
    unless `overwrite`."""
    from yadearch.engine.process import run_case_process

    case = with_engine(case, engine)
    folder = Path(out) if out is not None else DEFAULT_RUNS_DIR / case.name
    if is_complete(folder) and not rerun:
        differences = case_differences(folder, case)
        if not differences:
            return open_run(folder)
        if not overwrite:
            raise RunFolderError(f"{folder} holds a finished run of another case ({differences[0]}"
                                 f"{', ...' if len(differences) > 1 else ''}); choose another output "
                                 "folder or overwrite it")
    run_case_process(case, folder, timeout_s=timeout_s)
    result = open_run(folder)
    if figures:
        result.write_figures()
    return result


def sweep(case: ArchCase | str, out: str | Path, jobs: int | None = None, scheduler: str | None = None,
          timeout_s: float | None = None, engine: str | None = None, **values: list[Any]) -> pd.DataFrame:
    """Run `case` over the grid of parameter `values` (e.g. `kn_N_per_mm3=[0.25, 1, 5.2]`) as a
    resumable campaign in `out`; returns its results table (one row a run)."""
    from yadearch.studies.campaign import run_campaign
    from yadearch.studies.executors import open_pool
    from yadearch.studies.grid import grid

    with open_pool(jobs, scheduler) as pool:
        return run_campaign(with_engine(case, engine), grid(values), Path(out), pool, timeout_s=timeout_s)


def montecarlo(case: ArchCase | str, out: str | Path, samples: int, seed: int = 1, jobs: int | None = None,
               scheduler: str | None = None, timeout_s: float | None = None, engine: str | None = None,
               **levels: list[Any]) -> pd.DataFrame:
    """`samples` seeded draws of `case`'s imperfections (at every combination of the amplitude
    `levels`, e.g. `edge_radius_mm=[0.5, 1]`) as a resumable campaign in `out`; returns the table
    of montecarlo.csv (du, hinges and each sample's imperfection summary)."""
    from yadearch.studies.executors import open_pool
    from yadearch.studies.montecarlo import run_montecarlo

    with open_pool(jobs, scheduler) as pool:
        return run_montecarlo(with_engine(case, engine), Path(out), pool, samples, seed, levels or None,
                              timeout_s=timeout_s)


def calibrate(case: ArchCase | str, target_du_mm: float, out: str | Path, kn_min: float = 0.1,
              kn_max: float = 100.0, tolerance_mm: float = 0.5, jobs: int | None = None,
              engine: str | None = None, scheduler: str | None = None, timeout_s: float | None = None):
    """The kn at which `case` collapses at `target_du_mm` (within `tolerance_mm`), by bracketing
    root finding over runs kept in `out` (local processes, or the dask `scheduler`); returns the
    `Calibration`."""
    from yadearch.studies.calibration import calibrate as calibrate_kn
    from yadearch.studies.calibration import campaign_evaluator
    from yadearch.studies.executors import open_pool

    with open_pool(jobs, scheduler) as pool:
        return calibrate_kn(campaign_evaluator(with_engine(case, engine), Path(out), pool, timeout_s), target_du_mm,
                            tolerance_mm, kn_min, kn_max)


def capacity(case: ArchCase | str, out: str | Path, step_deg: float = 15.0, engine: str | None = None,
             jobs: int | None = None, scheduler: str | None = None, timeout_s: float | None = None,
             rigid: bool = True) -> pd.DataFrame:
    """The capacity map of `case`: du against the direction of the support movement every `step_deg`
    from spreading (0) to closing (-180), a resumable campaign in OUT/runs, with the rigid limit of
    each direction (unless not `rigid`); writes OUT/capacity.csv, capacity.md and the polar figure
    and returns the table."""
    from yadearch.studies.capacity import directions
    from yadearch.studies.capacity_map import run_capacity
    from yadearch.studies.executors import open_pool

    case = with_engine(case, engine)
    directions(step_deg)  # refuses a bad step before anything starts
    with open_pool(jobs, scheduler) as pool:
        return run_capacity(case, Path(out), pool, step_deg, rigid=rigid, timeout_s=timeout_s)


def sensitivity(case: ArchCase | str, out: str | Path, base_points: int = 256, factors: tuple | None = None,
                engine: str | None = None, jobs: int | None = None, scheduler: str | None = None,
                timeout_s: float | None = None):
    """What du of `case` is sensitive to: each factor alone at the ends of its range (a tornado) and
    Sobol indices from Saltelli's sample of `base_points` (a power of two), both resumable campaigns in
    `out`; `factors` (`yadearch.studies.sensitivity.Factor`s) default to the paper arch's plausible
    ranges. Writes the tables, figures and sensitivity.md; returns the `SensitivityResult`."""
    from yadearch.studies.executors import open_pool
    from yadearch.studies.sensitivity import PAPER_FACTORS, check_base_points, check_factors
    from yadearch.studies.sensitivity_campaign import run_sensitivity

    case = with_engine(case, engine)
    chosen = tuple(factors) if factors else PAPER_FACTORS
    check_base_points(base_points)  # refused before a pool starts
    check_factors(case, chosen)
    with open_pool(jobs, scheduler) as pool:
        return run_sensitivity(case, Path(out), pool, base_points, chosen, timeout_s=timeout_s)


def limit(case: ArchCase | str, compliant: bool = False):
    """Rigid-block limit analysis of `case` (no YADE, seconds): du_rigid and the hinge history;
    `compliant`: with the joints folding at the margin the case's kn allows (what a DEM run of that
    stiffness should find; docs/validation.md)."""
    from yadearch.solve.limit import limit_analysis

    return limit_analysis(as_case(case), compliant=compliant)
