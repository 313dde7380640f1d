"""The `yadearch` command line: run cases, reproduce the paper, list parameters."""

from __future__ import annotations

import signal
import sys
from pathlib import Path
from typing import TYPE_CHECKING

import click

from yadearch.cli.check import check_option, with_increments_check
from yadearch.cli.lazy import LAZY_COMMANDS, LazyGroup
from yadearch.cli.options import ENGINES, case_options, figures_option, resolve_case, stood_text
from yadearch.cli.param_types import OUT_FOLDER, argument_type
from yadearch.errors import YadearchError
from yadearch.markdown import seconds_text

if TYPE_CHECKING:
    from yadearch.results.summary import RunSummary

FIGURE_JOBS = 2  # a single run's figures are drawn in two processes (where the platform forks)


def _report_summary(out: Path, logged: bool = False) -> None:
    """A finished run's answer in a line and its warnings; the 1:10 model's values not again where the
    run was just made (`logged`: its log said them at its start)."""
    from yadearch.analysis.mechanism import run_warnings
    from yadearch.case.config import load_case
    from yadearch.case.paper import model_values_text
    from yadearch.model.hinges import SAME_MECHANISM, hinge_change
    from yadearch.results.rundir import CASE_FILE, read_summary

    summary: RunSummary = read_summary(out)
    du = summary.du_mm
    loading = summary.loading
    reach = stood_text(loading.max_displacement_mm, loading.motion) if loading else "no collapse"
    mode = " ".join(summary.collapse_mode_hinges or [])
    fold = (  # the fold's own motion where the joints open after the runaway make another mechanism
        f" (the fold's mode: {mode}, {summary.collapse_kind})"
        if mode
        and summary.hinge_labels
        and hinge_change(summary.hinge_labels, mode, load_case(out / CASE_FILE).geometry.n_voussoirs + 1)
        not in SAME_MECHANISM
        else ""
    )
    click.echo(
        f"{summary.name}: du = {reach if du is None else f'{du:.2f} mm'}, "
        f"hinges at collapse {summary.hinge_text or '-'}{fold}, {summary.cost}, "
        f"{seconds_text(summary.wall_s)} -> {out}"
    )
    if summary.increments_check:
        from yadearch.results.check_text import check_line, unresolved_warning

        if unresolved_warning(summary.increments_check) is None:  # else a warning says it
            click.echo(check_line(summary.increments_check))
    taken = summary.paper_model_values
    said = model_values_text(taken) if taken and logged else None
    for warning in run_warnings(summary):
        if warning != said:
            click.echo(f"warning: {warning}")


@click.group(cls=LazyGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(package_name="yadearch")
def cli() -> None:
    """Masonry arches on moving supports, simulated with YADE (polyhedral blocks, dry joints)."""


@cli.command()
@case_options(with_kn=True)
@click.option("--name", help="run name (default: the preset's or case's)")
@click.option("--out", type=OUT_FOLDER, help="run folder (default runs/NAME)")
@click.option("--rerun", is_flag=True, help="run again even if OUT holds a finished run of this case")
@click.option("--overwrite", is_flag=True, help="replace a finished run of another case in OUT")
@figures_option("the run's figures (a static run's solver takes a fraction of their seconds)")
@check_option
def run(
    preset_name: str | None,
    case_file: str | None,
    kn: float | None,
    settings: tuple[str, ...],
    name: str | None,
    out: str | None,
    rerun: bool,
    overwrite: bool,
    figures: bool,
    check: bool | None,
) -> None:
    """Run one case to collapse and write its run folder (a finished run of the same case is reused)."""
    from yadearch.api.runs import run as run_case
    from yadearch.case.names import check_name

    case = resolve_case(preset_name, case_file, kn, settings)
    if name is not None:
        case = case.with_overrides({"name": check_name(name, "--name")})
    case = with_increments_check(case, check, case_file, settings)
    result = run_case(case, out=out, rerun=rerun, overwrite=overwrite, figures=figures, figure_jobs=FIGURE_JOBS)
    _report_summary(result.path, logged=not result.reused)
    if figures:
        click.echo(f"figures -> {result.path / 'figures'}")


@cli.command()
@click.option(
    "--out",
    type=OUT_FOLDER,
    default="runs/reproduce",
    show_default=True,
    help="folder that receives set1/ and set2/ (the committed evidence: --out reports)",
)
@click.option(
    "--jobs", type=argument_type("jobs"), default=2, show_default=True, help="cases run at once (one core each)"
)
@click.option("--rerun", is_flag=True, help="run both cases again even if OUT holds finished runs of them")
@click.option(
    "--engine",
    type=click.Choice(ENGINES),
    default="dem",
    show_default=True,
    help="dem: YADE, minutes; static: the same blocks and joints solved by Newton's method, seconds, no YADE",
)
def reproduce(out: str, jobs: int, rerun: bool, engine: str) -> None:
    """Run both paper cases into OUT/set1 and OUT/set2, then write OUT/report.md with figures.

    A finished run of exactly the same case already in OUT is reused (an interrupted reproduction
    resumes), unless --rerun."""
    from yadearch.api.runs import reproduce as reproduce_cases

    def reused(folder: Path) -> None:
        click.echo(f"{folder.name}: reusing the finished run in {folder} (--rerun to run it again)")

    results, path = reproduce_cases(out, jobs=jobs, rerun=rerun, on_reuse=reused, engine=engine)
    for result in results:
        _report_summary(result.path)
    click.echo(f"report: {path}")


@cli.command()
def params() -> None:
    """List every case parameter with its default, what it accepts and its meaning."""
    from yadearch.case.sections import parameter_accepted, parameter_docs

    accepted = parameter_accepted()
    for qualified, default, doc in parameter_docs():
        says = f" [{accepted[qualified]}]" if accepted[qualified] else ""
        click.echo(f"{qualified:40s} {default:>10s}  {doc}{says}")


@cli.command("report")
@click.argument("runs", nargs=-1, required=True, type=click.Path())
@click.option("--out", required=True, type=OUT_FOLDER, help="folder that receives report.md and the figures")
def report(runs: tuple[str, ...], out: str) -> None:
    """Write OUT/report.md for the run folders RUNS: comparison with the paper, hinges, figures."""
    from yadearch.api.runs import report as write_report

    click.echo(f"report -> {write_report(runs, out)}")


def main(argv: list[str] | None = None) -> int:
    """Entry point: user mistakes and failed runs end in one line and a non-zero exit code."""
    signal.signal(signal.SIGTERM, _terminate_as_interrupt)
    try:
        cli.main(args=argv, standalone_mode=False)
    except click.exceptions.Abort:
        click.echo("aborted", err=True)
        return 130
    except click.ClickException as exc:  # usage mistakes too: one line, exit 1, as any user error
        click.echo(f"error: {exc.format_message()} (see `yadearch {_command(argv)}--help`)", err=True)
        return 1
    except YadearchError as exc:
        click.echo(f"error: {exc}", err=True)
        return 1
    except OSError as exc:  # an output folder that cannot be written, a full disk
        click.echo(f"error: {exc.strerror or exc}: {exc.filename or ''}".rstrip(": "), err=True)
        return 1
    return 0


def _terminate_as_interrupt(signum: int, frame: object) -> None:
    """SIGTERM stops a command as Ctrl-C does: campaigns write their results table on the way out."""
    raise KeyboardInterrupt


def _command(argv: list[str] | None) -> str:
    """The sub-command a command line names (with a trailing space), for the help hint."""
    words = sys.argv[1:] if argv is None else argv
    names = set(cli.commands) | set(LAZY_COMMANDS)
    return next((f"{w} " for w in words if w in names), "")


if __name__ == "__main__":
    sys.exit(main())
