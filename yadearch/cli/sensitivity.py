"""`yadearch sensitivity`: what du is sensitive to, one factor at a time and as Sobol indices (a thin
client of `ya.sensitivity`)."""

from __future__ import annotations

from pathlib import Path

import click

from yadearch import api
from yadearch.cli.options import case_options, drawing_pool_options, resolve_case, timeout_s
from yadearch.cli.param_types import OUT_FOLDER, argument_type
from yadearch.studies.dem_settings import parse_dem_settings
from yadearch.studies.sensitivity.indices import STABLE_TO, parse_factor
from yadearch.studies.sensitivity.study import DEFAULT_BASE_POINTS, INDICES_TABLE, REPORT, TORNADO_TABLE


@click.command()
@case_options(with_kn=True)
@click.option(
    "--base-points",
    type=argument_type("base_points"),
    default=DEFAULT_BASE_POINTS,
    show_default=True,
    help="Sobol base points N (a power of two): N x (factors + 2) runs; indices also on each halving (convergence)",
)
@click.option(
    "--factor",
    "factor_specs",
    multiple=True,
    metavar="NAME=LOW:HIGH[:log|:int]",
    help="a factor and its range, e.g. --factor kn_N_per_mm3=0.25:100:log (repeat; replaces the "
    "paper arch's twelve factors)",
)
@click.option(
    "--check-runs",
    type=argument_type("check_runs"),
    default=0,
    show_default=True,
    help="make the N one-at-a-time runs that move du most again on the other engine (the DEM for a "
    "static study) and report both answers",
)
@click.option(
    "--check-set",
    "check_set",
    multiple=True,
    metavar="numerics.KEY=VALUE",
    help="a numerical setting of the check runs' engine, e.g. numerics.support_path_states=static for the "
    "DEM's checks of a static study (repeat)",
)
@click.option(
    "--out",
    required=True,
    type=OUT_FOLDER,
    help="folder: tornado_runs/, runs/, check_runs/, tornado.csv, indices.csv, convergence.csv, samples.csv, "
    "checks.csv, figures, sensitivity.md",
)
@drawing_pool_options("the tornado, the indices and their convergence")
def sensitivity(
    preset_name: str | None,
    case_file: str | None,
    kn: float | None,
    settings: tuple[str, ...],
    base_points: int,
    factor_specs: tuple[str, ...],
    check_runs: int,
    check_set: tuple[str, ...],
    out: str,
    jobs: int | None,
    scheduler: str | None,
    timeout_min: float | None,
    figures: bool,
) -> None:
    """Run (or resume) the sensitivity study of a case: du with each factor at the ends of its range,
    and Sobol's first-order and total indices over all ranges at once (SALib)."""
    case = resolve_case(preset_name, case_file, kn, settings)
    factors = tuple(parse_factor(spec) for spec in factor_specs) or None
    check_settings = parse_dem_settings(check_set, "--check-set")
    result = api.sensitivity(
        case,
        out,
        base_points=base_points,
        factors=factors,
        jobs=jobs,
        scheduler=scheduler,
        timeout_s=timeout_s(timeout_min),
        check_runs=check_runs,
        figures=figures,
        check_settings=check_settings,
    )
    top = result.indices[result.indices["base_points"] == base_points].sort_values("ST", ascending=False).iloc[0]
    folder = Path(out)
    needed = result.stable_base_points
    verdict = "stable" if result.stable else f"not stable to {STABLE_TO}; ~{needed} base points would be"
    click.echo(
        f"largest total index: {top.factor} (ST {top.ST:.2f}); indices move {result.shift:.3f} as the "
        f"sample doubles ({verdict}) -> "
        f"{folder / TORNADO_TABLE}, {folder / INDICES_TABLE}, {folder / REPORT}"
    )
