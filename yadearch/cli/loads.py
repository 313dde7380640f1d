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
def loads(preset_name: str | None, case_file: str | None, settings: tuple[str, ...], out: str) -> None:
    """Rigid-block limit analysis of a live load, no YADE: the load (N) or acceleration (g) at
    collapse with the self-weight held, and its mechanism ([loads] of the case, or --set live_load=...)."""
    case = resolve_case(preset_name, case_file, None, settings)
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
        outcome = "no collapse however large (the load goes straight to the supports)"
    else:
        share = f" ({result.multiplier / result.arch_weight_N:.3f} of the arch's weight)" if result.unit == "N" else ""
        outcome = f"collapse at {result.multiplier:.4g} {result.unit}{share} on {result.hinge_labels}"
    click.echo(f"{case.name}: {what}: {outcome} -> {loads_file(case, out)}")
