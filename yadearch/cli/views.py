"""`yadearch animate` (a run as a movie) and `yadearch export` (a run for ParaView), clients of
`RunResult.animate` and `RunResult.export_vtk`."""

from __future__ import annotations

from pathlib import Path

import click

from yadearch import api
from yadearch.cli.options import OUT_FILE, OUT_FOLDER
from yadearch.plotting.animation import FORMATS


@click.command()
@click.argument("run_folder", type=click.Path(exists=True, file_okay=False))
@click.option(
    "--format", "fmt", type=click.Choice(FORMATS), default="mp4", show_default=True, help="mp4 (needs ffmpeg) or gif"
)
@click.option("--out", type=OUT_FILE, help="movie file [default: RUN/figures/NAME.FORMAT]")
def animate(run_folder: str, fmt: str, out: str | None) -> None:
    """Draw a finished run as a movie along its loading path to collapse: the blocks to scale, hinges
    with the paper's letters, the thrust line, the support displacement and reaction."""
    click.echo(f"movie -> {api.open_run(run_folder).animate(out, fmt)}")


@click.command()
@click.argument("run_folder", type=click.Path(exists=True, file_okay=False))
@click.option("--vtk", "vtk", is_flag=True, help="a ParaView time series (.pvd of .vtu files)")
@click.option("--out", type=OUT_FOLDER, help="folder [default: RUN/vtk]")
def export(run_folder: str, vtk: bool, out: str | None) -> None:
    """Export every state of a finished run for ParaView: blocks as 3D cells with their displacement
    and rotation, joints as points with their forces, openings and hinge flags; time = delta (mm)."""
    if not vtk:
        raise click.UsageError("say what to export: --vtk")
    click.echo(f"ParaView time series -> {api.open_run(run_folder).export_vtk(Path(out) if out else None)}")
