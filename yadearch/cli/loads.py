"""`yadearch loads`: the live load an arch carries at collapse by the rigid-block limit analysis (a thin
client of `ya.loads`)."""

from __future__ import annotations

import math

import click

from yadearch import api
from yadearch.api.live_loads import loads_file
from yadearch.cli.options import OUT_FOLDER, case_options, resolve_case


@click.command()
@case_options(with_kn=False, with_engine=False)
@click.option(
    "--out", type=OUT_FOLDER, default="runs/loads", show_default=True, help="folder that receives NAME_loads.json"
)
@click.option(
    "--positions",
    type=int,
    default=None,
    help="also the influence line: a concentrated load's capacity at this many points across the span "
    "(2-200), written as NAME_influence.csv and its figure",
)
def loads(
    preset_name: str | None, case_file: str | None, settings: tuple[str, ...], out: str, positions: int | None
) -> None:
    """Rigid-block limit analysis of a live load, no YADE: the load (N) or acceleration (g) at
    collapse with the self-weight held, and its mechanism ([loads] of the case, or --set live_load=...)."""
    case = resolve_case(preset_name, case_file, None, settings)
    if positions is not None:
        table = api.load_influence(case, positions, out=out)
        weakest = table.loc[table["collapse_load_N"].idxmin()]
        click.echo(
            f"{case.name}: influence line at {positions} positions: least {weakest.collapse_load_N:.4g} N at "
            f"{weakest.position_over_span:.3g} of the span ({weakest.hinges}) -> {out}/{case.name}_influence.csv"
        )
        if case.loads.live_load == "none":
            return
    result = api.loads(case, out=out)
    what = case.loads.live_load.replace("_", " ")
    if case.loads.live_load == "vertical":
        width = f", spread over {case.loads.load_width_mm:g} mm" if case.loads.load_width_mm else ""
        what += f" load at {case.loads.load_position_over_span:g} of the span{width}"
    else:
        what += f" toward the {case.loads.acceleration_toward}"
    if math.isnan(result.multiplier):
        outcome = "the arch does not stand under its own weight"
    elif math.isinf(result.multiplier):
        outcome = "no collapse however large (its thrust line stays within the ring; rigid blocks do not crush)"
    else:
        share = f" ({result.multiplier / result.arch_weight_N:.3f} of the arch's weight)" if result.unit == "N" else ""
        outcome = f"collapse at {result.multiplier:.4g} {result.unit}{share} on {result.hinge_labels}"
    click.echo(f"{case.name}: {what}: {outcome} -> {loads_file(case, out)}")
