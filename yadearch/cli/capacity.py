"""`yadearch capacity`: du against the direction of the support movement, every few degrees, beside
the rigid-block limit (a thin client of `ya.capacity`)."""

from __future__ import annotations

from pathlib import Path

import click

from yadearch import api
from yadearch.cli.options import case_options, drawing_pool_options, resolve_case, timeout_s
from yadearch.cli.param_types import OUT_FOLDER, argument_type
from yadearch.studies.capacity.campaign import FIGURE, REPORT, TABLE


@click.command()
@case_options(with_kn=True)
@click.option(
    "--step-deg",
    type=argument_type("step_deg"),
    default=15.0,
    show_default=True,
    help="directions every STEP degrees from spreading (0) to closing (-180); must divide 180",
)
@click.option("--no-rigid", is_flag=True, help="skip the rigid-block limit of each direction")
@click.option(
    "--out",
    required=True,
    type=OUT_FOLDER,
    help="folder: runs/ (the campaign), capacity.csv, capacity.md, capacity_map.pdf/.png",
)
@drawing_pool_options("the polar capacity map")
def capacity(
    preset_name: str | None,
    case_file: str | None,
    kn: float | None,
    settings: tuple[str, ...],
    step_deg: float,
    no_rigid: bool,
    out: str,
    jobs: int | None,
    scheduler: str | None,
    timeout_min: float | None,
    figures: bool,
) -> None:
    """Run (or resume) the capacity map of a case: du for movements of its support in every direction
    of the half-plane below the horizontal, with the rigid-block limit of each."""
    case = resolve_case(preset_name, case_file, kn, settings)
    try:
        table = api.capacity(
            case,
            out,
            step_deg=step_deg,
            jobs=jobs,
            scheduler=scheduler,
            timeout_s=timeout_s(timeout_min),
            rigid=not no_rigid,
            figures=figures,
        )
    except ValueError as exc:
        raise click.BadParameter(str(exc), param_hint="--step-deg") from None
    folder = Path(out)
    done = table[table["status"] == "done"]
    weakest = done.loc[done["du_mm"].idxmin()] if not done.empty else None
    click.echo(
        f"{len(done)} of {len(table)} directions done"
        + (f"; the weakest {weakest.direction_deg:g} deg, du {weakest.du_mm:.2f} mm" if weakest is not None else "")
        + f" -> {folder / TABLE}, {folder / REPORT}"
        + (f", {folder / FIGURE}.pdf" if figures else "")
    )
