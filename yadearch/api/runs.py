"""Cases, single runs, the paper's reproduction, reports and the rigid-block limit analysis as
functions; the command line calls the same functions."""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from yadearch.api.arguments import check_arguments
from yadearch.api.results import RunResult, open_run
from yadearch.case.config import ArchCase, load_case
from yadearch.case.config import preset as _preset
from yadearch.case.names import check_name, output_path
from yadearch.case.numerics_section import NO_INCREMENTS_CHECK
from yadearch.case.plan import static_only_refusal
from yadearch.errors import ArgumentTypeError, CaseError, RunFolderError
from yadearch.results.reuse import case_differences, is_current

if TYPE_CHECKING:
    from yadearch.solve.limit_result import LimitResult

DEFAULT_RUNS_DIR = Path("runs")
PAPER_SETS = ("set1", "set2")


def preset(name: str) -> ArchCase:
    """The paper's arch with the kn of voussoir set 1 or set 2 ("set1", "set2")."""
    return _preset(name)


def movement(name: str) -> dict:
    """The [loading] parameters of a named support movement, for `case.with_overrides(...)`:
    settlement, spreading, closing, inclined, symmetric_spreading, abutment_tilt, settle_then_spread
    (docs/movements.md)."""
    from yadearch.case.support import movement_overrides

    return movement_overrides(name)


ENGINES = ("dem", "static")


def as_case(case: ArchCase | str) -> ArchCase:
    """An ArchCase, a preset's name ('set1', 'set2') taken as that preset, or a case file's path (TOML)
    read; TypeError naming the argument for anything else."""
    if isinstance(case, ArchCase):
        return case
    if isinstance(case, (str, Path)) and (Path(case).suffix == ".toml" or Path(case).is_file()):
        return load_case(Path(case))
    if isinstance(case, str):
        return _preset(case)
    raise ArgumentTypeError(
        f"case must be an ArchCase (ya.preset), a preset name ('set1', 'set2') or a case file's path (TOML), "
        f"got {type(case).__name__}"
    )


def with_engine(case: ArchCase | str, engine: str | None) -> ArchCase:
    """`case` (or a preset's name) solved by `engine` ('dem': YADE, 'static': Newton's method; None: the
    case's own numerics.engine); CaseError naming the argument for another value, or for a static-only
    setting with the DEM."""
    case = as_case(case)
    if engine is not None:
        if engine not in ENGINES:
            raise CaseError(f"engine must be one of {', '.join(ENGINES)}, got {engine!r}")
        case = case.with_overrides({"numerics.engine": engine})
    refused = static_only_refusal(case.numerics)
    if refused:
        raise CaseError(refused)
    return case


def _lacks_its_check(folder: Path, case: ArchCase) -> bool:
    """Whether `case` asks for the increments check and the finished run in `folder` did not make one
    (it is run again rather than reused without it)."""
    return case.numerics.increments_check != NO_INCREMENTS_CHECK and open_run(folder).summary.increments_check is None


def run(
    case: ArchCase | str,
    out: str | Path | None = None,
    timeout_s: float | None = None,
    figures: bool = True,
    rerun: bool = False,
    overwrite: bool = False,
    engine: str | None = None,
    quiet: bool = False,
    figure_jobs: int = 1,
) -> RunResult:
    """Run `case` to collapse in a child process (YADE, or the static engine with `engine="static"`),
    writing the run folder `out` (default runs/NAME) and its figures; returns the result read back.
    A finished run of the same case in `out` is reused (unless `rerun`); one of another case is kept
    unless `overwrite`. The run's progress lines are printed unless `quiet` (run.log keeps them);
    `figure_jobs` 2 draws the figures in two processes (`RunResult.write_figures`)."""
    from yadearch.launch.process import run_case_process

    check_arguments(
        timeout_s=timeout_s, figures=figures, rerun=rerun, overwrite=overwrite, quiet=quiet, figure_jobs=figure_jobs
    )
    case = with_engine(case, engine)
    check_name(case.name, "case.name")
    folder = output_path(out, "out") if out is not None else DEFAULT_RUNS_DIR / case.name
    if not case.numerics.keeps_tables:
        raise CaseError(
            f"numerics.run_files = {case.numerics.run_files!r} keeps no tables for a single run's result "
            "and figures; it is for campaigns (sweep, montecarlo, sensitivity, ...): use 'full' here"
        )
    if is_current(folder) and not rerun:
        differences = case_differences(folder, case)
        if not differences and not _lacks_its_check(folder, case):
            reused = open_run(folder)
            reused.reused = True
            return reused
        if differences and not overwrite:  # the same case without its check is run again
            raise RunFolderError(
                f"{folder} holds a finished run of another case ({differences[0]}"
                f"{', ...' if len(differences) > 1 else ''}); choose another output "
                "folder (--out, out=) or replace it (--overwrite, overwrite=True)"
            )
    run_case_process(case, folder, timeout_s=timeout_s, quiet=quiet, single=True)
    result = open_run(folder)
    if figures:
        if not quiet:  # a few seconds with nothing said otherwise
            print(f"drawing the figures of {folder} ...", flush=True)
        result.write_figures(jobs=figure_jobs)
    return result


def reproduce(
    out: str | Path = "runs/reproduce",
    jobs: int = 2,
    rerun: bool = False,
    on_reuse: Callable[[Path], None] | None = None,
    engine: str = "dem",
) -> tuple[list[RunResult], Path]:
    """The paper's two cases (OUT/set1, OUT/set2, `jobs` at once) by `engine` (the DEM, YADE; or
    'static': the same blocks and joints by Newton's method, seconds, no YADE) and OUT/report.md with
    figures; a finished run of exactly the same case in OUT is reused (`on_reuse` is told), unless
    `rerun`. Returns both results and the report's path."""
    from concurrent.futures import ThreadPoolExecutor

    from yadearch.launch.process import run_case_process
    from yadearch.results.reuse import holds_case

    check_arguments(jobs=jobs, rerun=rerun)
    cases = {name: with_engine(name, engine) for name in PAPER_SETS}
    folders = [output_path(out, "out") / name for name in PAPER_SETS]
    todo = [f for f in folders if rerun or not holds_case(f, cases[f.name])]
    for folder in set(folders) - set(todo):
        if on_reuse is not None:
            on_reuse(folder)
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        list(pool.map(lambda folder: run_case_process(cases[folder.name], folder), todo))
    return [open_run(f) for f in folders], report(folders, out)


def report(runs: Sequence[str | Path], out: str | Path) -> Path:
    """OUT/report.md for the run folders `runs`: comparison with the paper where a run is the
    paper's case, hinges and how they formed, figures; returns its path."""
    from yadearch.reporting.report import write_report

    if isinstance(runs, (str, Path)):
        raise ArgumentTypeError(f"runs must be a list of run folders, got {type(runs).__name__} {str(runs)!r:.40}")
    if not runs:
        raise RunFolderError("runs must list at least one run folder, got none")
    seen: set[Path] = set()
    for run in runs:
        if Path(run).resolve() in seen:  # the same run's section twice, and its figures copied twice
            raise RunFolderError(f"runs lists {str(run)!r} twice; give each run folder once")
        seen.add(Path(run).resolve())
    return write_report(list(runs), output_path(out, "out"))


def limit(
    case: ArchCase | str,
    compliant: bool = False,
    max_snap_mm: float | None = None,
    out: str | Path | None = None,
    start_hinges: str | Sequence[str] | None = None,
    start_mm: float = 0.0,
    figures: bool = True,
    quiet: bool = False,
    static_beside: bool = True,
) -> LimitResult:
    """Rigid-block limit analysis of `case` (no YADE, seconds): du_rigid and the hinge history;
    `compliant`: with the joints folding at the margin the case's kn allows (what a DEM run of that
    stiffness should find; docs/validation.md); `max_snap_mm`: a hinge snap moving a block further
    is collapse, as in a run; `start_hinges` ("1E 35I 56E"): leave rest on that linkage (another
    engine's) instead of the LP's, placed `start_mm` along it. With `out`, writes OUT/NAME.json and
    (with `figures`) the thrust-line figure (NAME_compliant-knKN.* when compliant, NAME_start-1E-35I-56E.*
    from a named linkage). Unless `quiet`, a march longer than a few seconds prints where it is. A
    compliant march carries the static engine's answer on the same joints beside it (`static_beside`)
    and what its reader must know in `warnings` (`api.limit_notes`), shown when the result is printed."""
    from yadearch.api.limit_notes import failed_march, with_static_answer, with_warnings
    from yadearch.plotting.thrust_line import save_thrust_line
    from yadearch.solve.limit import limit_analysis
    from yadearch.solve.limit_result import write_result_json
    from yadearch.solve.rigid import MarchStopped

    check_arguments(compliant=compliant, figures=figures, quiet=quiet, static_beside=static_beside)
    check_arguments(max_snap_mm=max_snap_mm, start_mm=start_mm)
    case = as_case(case)
    check_name(case.name, "case.name")
    folder = output_path(out, "out") if out is not None else None
    try:
        result = limit_analysis(
            case,
            max_snap_mm=max_snap_mm,
            compliant=compliant,
            start_hinges=start_hinges,
            start_mm=start_mm,
            progress=None if quiet else position_lines(case.name, case.loading.max_support_displacement_mm),
            mirror_progress=None
            if quiet
            else position_lines(case.name, case.loading.max_support_displacement_mm, True),
        )
    except MarchStopped as exc:  # a compliant march that fails says the static engine's answer on the same joints
        if not (compliant and static_beside):
            raise
        raise failed_march(exc, case) from None
    if compliant:
        result = with_warnings(with_static_answer(result, case) if static_beside else result, case)
    if folder is not None:
        json_path, figure_stem = limit_files(case, compliant, folder, result.start_hinges, result.start_mm)
        write_result_json(result, case, json_path)
        if figures:
            save_thrust_line(result, case, figure_stem)
    return result


def limit_files(
    case: ArchCase,
    compliant: bool,
    out: str | Path,
    start_hinges: Sequence[str] | None = None,
    start_mm: float | None = None,
) -> tuple[Path, Path]:
    """Where `limit(..., out=out)` writes: OUT/NAME.json and the figure's stem OUT/NAME (NAME_compliant-kn100
    when compliant at kn 100, so that two stiffnesses keep two files, then _start-1E-35I-56E from a named
    linkage, -at2.5mm placed along it; a name may hold dots, as kn5.2)."""
    name = f"{case.name}_compliant-kn{case.interface.kn_N_per_mm3:g}" if compliant else case.name
    if start_hinges:
        name += "_start-" + "-".join(start_hinges) + (f"-at{start_mm:g}mm" if start_mm else "")
    return Path(out) / f"{name}.json", Path(out) / name


PROGRESS_EVERY_S = 2.0  # a progress line at most this often, the first after as long


def position_lines(name: str, limit_mm: float, mirrored: bool = False) -> Callable[[float], None]:
    """A march's progress: its support position (mm), at most every PROGRESS_EVERY_S; the `mirrored`
    branch's (which `limit` solves after the case's) named so."""
    started = last = time.perf_counter()
    branch = " (the mirror image)" if mirrored else ""

    def tell(delta_mm: float) -> None:
        nonlocal last
        now = time.perf_counter()
        if now - last >= PROGRESS_EVERY_S:
            last = now
            at = f"at {delta_mm:.2f} mm of at most {limit_mm:g} mm{branch}"
            print(f"{name}: {at}, {now - started:.0f} s", flush=True)

    return tell
