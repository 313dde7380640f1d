"""`yadearch montecarlo`: seeded samples of an imperfect arch (optionally at several amplitude
levels), resumable, with the distribution of du and of the hinges as a table, Markdown and figures."""

from __future__ import annotations

import math
from pathlib import Path

import click

from yadearch import api
from yadearch.analysis.samples import collapse_displacement, du_statistics
from yadearch.cli.campaigns import note, parse_axes
from yadearch.cli.options import case_options, drawing_pool_options, resolve_case, timeout_s
from yadearch.cli.param_types import OUT_FOLDER, argument_type
from yadearch.errors import YadearchError
from yadearch.studies.montecarlo import MONTECARLO_FILE, SUMMARY_FILE, outcomes_text


@click.command()
@case_options(with_kn=True)
@click.option("--samples", type=argument_type("samples"), required=True, help="samples (seeds) per amplitude level")
@click.option(
    "--seed",
    type=argument_type("seed"),
    default=1,
    show_default=True,
    help="seed of the first sample; sample i uses seed + i",
)
@click.option(
    "--param",
    "param_specs",
    multiple=True,
    metavar="NAME=VALUES",
    help="an amplitude to sweep, e.g. --param edge_radius_mm=0.5,1,2 (samples at each level)",
)
@click.option(
    "--out",
    required=True,
    type=OUT_FOLDER,
    help="campaign folder: run folders, results.csv, montecarlo.csv, montecarlo.md, figures",
)
@drawing_pool_options("the distribution of du, the hinge positions and du against each amplitude")
def montecarlo(
    preset_name: str | None,
    case_file: str | None,
    kn: float | None,
    settings: tuple[str, ...],
    samples: int,
    seed: int,
    param_specs: tuple[str, ...],
    out: str,
    jobs: int | None,
    scheduler: str | None,
    timeout_min: float | None,
    figures: bool,
) -> None:
    """Run (or resume) seeded samples of the case's imperfections; write the distribution of du and
    of the hinges (montecarlo.csv, montecarlo.md, figures)."""
    base = resolve_case(preset_name, case_file, kn, settings)
    axes = parse_axes(param_specs)
    folder = Path(out)
    table = api.montecarlo(
        base,
        folder,
        samples,
        seed=seed,
        jobs=jobs,
        scheduler=scheduler,
        timeout_s=timeout_s(timeout_min),
        log=note,
        figures=figures,
        **axes,
    )
    du = collapse_displacement(table)  # an arch that cannot stand: 0
    stats = du_statistics(du)
    interval = (
        f"95 % interval {stats['median_low']:.2f}-{stats['median_high']:.2f}"
        if math.isfinite(stats["median_low"])
        else "too few samples for its 95 % interval"
    )
    click.echo(
        f"{outcomes_text(du)}; median du {stats['median']:.2f} mm ({interval}), "
        f"5-95 % {stats['low']:.2f}-{stats['high']:.2f} mm -> {folder / MONTECARLO_FILE}, "
        f"{folder / SUMMARY_FILE}"
    )
    failed = int((table["status"] == "failed").sum())
    if failed:
        raise YadearchError(f"{failed} of {len(table)} samples failed; reasons in {folder / MONTECARLO_FILE}")
