"""`yadearch survey`: a case TOML of a surveyed arch from its joints' corners in a CSV, or its blocks'
corners in a JSON survey (a thin client of `ya.measured_case`); `yadearch piers`: any arch on its
piers (of `ya.on_piers`)."""

from __future__ import annotations

import click

from yadearch import api
from yadearch.atomic import write_text_atomically
from yadearch.case.names import FILE, output_path
from yadearch.cli.check import case_file_text
from yadearch.cli.options import case_options, resolve_case
from yadearch.cli.param_types import OUT_FILE, argument_type


@click.command()
@click.argument("joints", type=click.Path(exists=True, dir_okay=False))
@case_options(with_kn=True, with_engine=False)
@click.option("--out", type=OUT_FILE, required=True, help="the case TOML to write (e.g. my_arch.toml)")
@click.option("--name", default=None, help="the case's name (default: the base case's)")
def survey(
    joints: str,
    preset_name: str | None,
    case_file: str | None,
    kn: float | None,
    settings: tuple[str, ...],
    out: str,
    name: str | None,
) -> None:
    """Write a case of the surveyed arch in JOINTS (a CSV with the columns x_intrados_mm, y_intrados_mm,
    x_extrados_mm, y_extrados_mm, one row a joint, left to right; or a CSV of the blocks' corners, the
    columns block, x_mm, y_mm and support ('left'/'right' on the abutments), one row a corner; or a .json
    survey of the blocks:
    {"blocks": [{"corners": [[x, y], ...]}, ..., {"corners": ..., "support": "left"}, ...]}, in mm, each
    voussoir's corners in order round it, two on each joint and any more on its faces) on the material,
    joints, loading and numerics of --preset/--case/--set; run it with `yadearch run --case OUT`."""
    case = api.measured_case(joints, base=resolve_case(preset_name, case_file, kn, settings), name=name)
    path = output_path(out, "--out", FILE)
    write_text_atomically(path, case_file_text(case, case_file, settings))
    geometry = case.geometry
    faces = {int(row[0]) for row in geometry.intrados_points_mm + geometry.extrados_points_mm}
    polygons = f", {len(faces)} of more than four corners" if faces else ""
    click.echo(
        f"{case.name}: {geometry.n_voussoirs} voussoirs between {len(geometry.joint_points_mm)} measured joints"
        f"{polygons}, mean joint length {geometry.thickness_mm:.2f} mm -> {path}"
    )


@click.command()
@case_options(with_kn=True, with_engine=False)
@click.option("--height-mm", "height_mm", type=argument_type("pier_height_mm"), required=True, help="pier height (mm)")
@click.option("--width-mm", "width_mm", type=argument_type("pier_width_mm"), required=True, help="pier base width (mm)")
@click.option("--out", type=OUT_FILE, required=True, help="the case TOML to write (e.g. on_piers.toml)")
@click.option("--name", default=None, help="the case's name (default: the base case's)")
def piers(
    preset_name: str | None,
    case_file: str | None,
    kn: float | None,
    settings: tuple[str, ...],
    height_mm: float,
    width_mm: float,
    out: str,
    name: str | None,
) -> None:
    """Write a case of the arch of --preset/--case/--set on two piers (real abutments that can slide or
    overturn on their base joints, the supports moving the ground under them): each pier --height-mm
    tall below its springing, --width-mm wide at its base; run it with `yadearch run --case OUT`."""
    case = api.on_piers(resolve_case(preset_name, case_file, kn, settings), height_mm, width_mm, name=name)
    path = output_path(out, "--out", FILE)
    write_text_atomically(path, case_file_text(case, case_file, settings))
    click.echo(
        f"{case.name}: {case.geometry.n_voussoirs - 2} voussoirs on two piers {height_mm:g} x {width_mm:g} mm -> {path}"
    )
