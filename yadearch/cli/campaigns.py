"""`yadearch sweep` (parametric campaigns, the kn sweep), `yadearch calibrate` (kn from a measured
du) and `yadearch robustness` (du against the numerics), as click commands for the main group."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import click

from yadearch import api
from yadearch.case import reference
from yadearch.case.config import ArchCase
from yadearch.cli.options import case_options, drawing_pool_options, pool_options, resolve_case, timeout_s
from yadearch.cli.param_types import OUT_FILE, OUT_FOLDER, argument_type
from yadearch.errors import YadearchError
from yadearch.solve.stages import Outcome
from yadearch.studies.campaigns.grid import check_parameter, parse_values, qualified_name
from yadearch.studies.campaigns.runner import RESULTS_FILE
from yadearch.studies.robustness import KN_VALUES, VARIANTS
from yadearch.studies.sweep_figures import KN_KEY


def _base_case(preset_name: str | None, case_file: str | None, settings: tuple[str, ...]) -> ArchCase:
    return resolve_case(preset_name, case_file, None, settings)


@click.command()
@case_options(with_kn=False)
@click.option(
    "--kn", "kn_spec", metavar="VALUES", help="kn values (N/mm3): 0.25,5.2 or start:stop:log:n, e.g. 0.1:100:log:13"
)
@click.option(
    "--param",
    "param_specs",
    multiple=True,
    metavar="NAME=VALUES",
    help="another grid axis, e.g. --param n_voussoirs=15,31,55 or damping=0.1:0.3:lin:3",
)
@click.option(
    "--table",
    "table_file",
    type=click.Path(dir_okay=False),
    help="explicit CSV table of runs instead of a grid (one column per parameter)",
)
@click.option(
    "--out",
    required=True,
    type=OUT_FOLDER,
    help="campaign folder: one run folder per run, runs.csv, results.csv",
)
@drawing_pool_options("du against each swept parameter (with the hinges when kn alone is swept)")
@click.option(
    "--retry-failed/--keep-failed",
    default=True,
    show_default=True,
    help="redo runs recorded as failed, or keep them (and their reasons) as they are",
)
def sweep(
    preset_name: str | None,
    case_file: str | None,
    settings: tuple[str, ...],
    kn_spec: str | None,
    param_specs: tuple[str, ...],
    table_file: str | None,
    out: str,
    jobs: int | None,
    scheduler: str | None,
    timeout_min: float | None,
    figures: bool,
    retry_failed: bool,
) -> None:
    """Run a campaign (a grid or a table of cases), resuming a previous one in OUT."""
    base = _base_case(preset_name, case_file, settings)
    if table_file and (kn_spec or param_specs):
        raise click.UsageError("give either --table or --kn/--param, not both")
    axes: dict[str, Any] = {}  # grid axes, passed to the API as keyword arguments
    if kn_spec:
        axes[KN_KEY] = parse_values(kn_spec)
        bad = [v for v in axes[KN_KEY] if isinstance(v, (bool, str))]
        if bad:
            raise click.UsageError(f"--kn values must be numbers, got {bad[0]!r}")
    params = parse_axes(param_specs)
    if kn_spec and any(qualified_name(key) == qualified_name(KN_KEY) for key in params):
        raise click.UsageError("--kn and --param kn_N_per_mm3 give kn twice; keep one")
    axes.update(params)
    if not axes and not table_file:
        raise click.UsageError("nothing to sweep: give --kn, --param or --table")
    folder = Path(out)
    table = api.sweep(
        base,
        folder,
        jobs=jobs,
        scheduler=scheduler,
        timeout_s=timeout_s(timeout_min),
        table=table_file,
        retry_failed=retry_failed,
        figures=figures,
        log=note,
        **axes,
    )
    counts = table["status"].value_counts().to_dict()
    fell = int(((table["status"] == "failed") & (table.get("outcome") == Outcome.CANNOT_STAND)).sum())
    standing = f" ({fell} of them cannot stand: an answer, du 0)" if fell else ""
    click.echo(
        f"{len(table)} runs: {counts.get('done', 0)} done, {counts.get('failed', 0)} failed{standing}, "
        f"{counts.get('pending', 0)} pending -> {folder / RESULTS_FILE}"
    )
    if counts.get("failed", 0) > fell:  # an arch that cannot stand is the arch's answer, not the tool's failure
        failed = counts["failed"] - fell
        raise YadearchError(f"{failed} of {len(table)} runs failed; reasons in {folder / RESULTS_FILE}")


def note(line: str) -> None:
    """The API's messages: notes of what could not be drawn to standard error, the rest to standard output."""
    click.echo(line, err=line.startswith("no "))


def parse_axes(param_specs: tuple[str, ...]) -> dict[str, Any]:
    """--param NAME=VALUES options as grid axes."""
    axes: dict[str, Any] = {}
    for spec in param_specs:
        if "=" not in spec:
            raise click.UsageError(f"--param expects NAME=VALUES, got {spec!r}")
        name, values = spec.split("=", 1)
        check_parameter(name.strip())
        twice = [key for key in axes if qualified_name(key) == qualified_name(name.strip())]
        if twice:
            raise click.UsageError(
                f"--param gives {qualified_name(twice[0])} twice ({twice[0]} and {name.strip()}); keep one"
            )
        axes[name.strip()] = parse_values(values)
    return axes


@click.command()
@case_options(with_kn=False)
@click.option(
    "--target-du",
    "target_du",
    type=argument_type("target_du_mm"),
    required=True,
    help="measured collapse displacement to match (mm)",
)
@click.option(
    "--tolerance-mm",
    type=argument_type("tolerance_mm"),
    default=0.5,
    show_default=True,
    help="accepted |du - target| (mm)",
)
@click.option(
    "--kn-min",
    type=argument_type("kn_min"),
    default=reference.KN_SENSITIVITY_RANGE_N_PER_MM3[0],
    show_default=True,
    help="lower end of the kn bracket (N/mm3)",
)
@click.option(
    "--kn-max",
    type=argument_type("kn_max"),
    default=reference.KN_SENSITIVITY_RANGE_N_PER_MM3[1],
    show_default=True,
    help="upper end of the kn bracket (N/mm3)",
)
@click.option(
    "--max-runs", type=argument_type("max_runs"), default=12, show_default=True, help="give up after this many runs"
)
@click.option("--out", required=True, type=OUT_FILE, help="result JSON, e.g. reports/calibration/set1.json")
@click.option("--runs-dir", type=OUT_FOLDER, help="run folders [default: OUT without .json]")
@pool_options
def calibrate(
    preset_name: str | None,
    case_file: str | None,
    settings: tuple[str, ...],
    target_du: float,
    tolerance_mm: float,
    kn_min: float,
    kn_max: float,
    max_runs: int,
    out: str,
    runs_dir: str | None,
    jobs: int | None,
    scheduler: str | None,
    timeout_min: float | None,
) -> None:
    """Find the kn whose du matches a measured du (bracketing search on log kn)."""
    base = _base_case(preset_name, case_file, settings)
    out_path = Path(out)
    runs = Path(runs_dir) if runs_dir else out_path.with_suffix("")
    click.echo(
        f"calibrating kn of {base.name} ({base.numerics.engine} engine) to du = {target_du:g} +- {tolerance_mm:g} mm, "
        f"kn in [{kn_min:g}, {kn_max:g}] N/mm3; runs in {runs}"
    )
    result = api.calibrate(
        base,
        target_du,
        runs,
        kn_min=kn_min,
        kn_max=kn_max,
        tolerance_mm=tolerance_mm,
        max_runs=max_runs,
        jobs=jobs,
        scheduler=scheduler,
        timeout_s=timeout_s(timeout_min),
        log=click.echo,
    )
    result.write(out_path)
    click.echo(
        f"kn = {result.kn_N_per_mm3:.4g} N/mm3 gives du = {result.du_mm:.2f} mm "
        f"(target {target_du:g} +- {tolerance_mm:g}) after {result.runs} runs "
        f"({result.new_runs} new), hinges {result.hinges or '-'} -> {out_path}"
    )
    if not result.converged:
        raise YadearchError(
            f"no kn within {tolerance_mm:g} mm of the target after {result.runs} "
            f"runs (du jumps, or too few runs); the closest run is in {out_path}"
        )


@click.command()
@case_options(with_kn=False)
@click.option(
    "--kn",
    "kn_spec",
    metavar="VALUES",
    default=",".join(f"{k:g}" for k in KN_VALUES),
    show_default=True,
    help="kn values (N/mm3)",
)
@click.option(
    "--variant",
    "variant_names",
    multiple=True,
    type=click.Choice(list(VARIANTS)),
    help="run only these variants [default: all]",
)
@click.option(
    "--out",
    default="runs/robustness",
    show_default=True,
    type=OUT_FOLDER,
    help="study folder: run folders, robustness.csv, robustness.md",
)
@pool_options
def robustness(
    preset_name: str | None,
    case_file: str | None,
    settings: tuple[str, ...],
    kn_spec: str,
    variant_names: tuple[str, ...],
    out: str,
    jobs: int | None,
    scheduler: str | None,
    timeout_min: float | None,
) -> None:
    """Run every kn with each numerical variant and with higher friction (resumable); write
    OUT/robustness.csv and OUT/robustness.md with a verdict per kn."""
    base = _base_case(preset_name or "set2", case_file, settings)
    kn_values = tuple(parse_values(kn_spec))
    if not all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in kn_values):
        raise click.BadParameter(f"kn values must be numbers, got {kn_spec!r}", param_hint="--kn")
    folder = Path(out)
    for _, row in api.robustness(
        base, folder, kn_values, variant_names or None, jobs=jobs, scheduler=scheduler, timeout_s=timeout_s(timeout_min)
    ).iterrows():
        click.echo(
            f"kn {row.kn_N_per_mm3:g}: base du {row.base_du_mm:.2f} mm ({row.base_hinges}), numerics "
            f"spread {row.numerics_spread:.2%} (du_first {row.du_first_spread:.2%}), "
            f"hinges {'kept' if row.hinges_kept else 'moved'}, "
            + (
                f"friction moves du {row.friction_move:.2%}"
                if not math.isnan(row.friction_move)
                else "friction not run"
            )
            + f": {row.verdict}"
        )
    click.echo(f"-> {folder / 'robustness.csv'}, {folder / 'robustness.md'}")
