"""`yadearch animate` (a run as a movie) and `yadearch export` (a run for ParaView), clients of
`RunResult.animate` and `RunResult.export_vtk`; both take a run folder or a live load's path folder."""

from __future__ import annotations

from pathlib import Path

import click

from yadearch import api
from yadearch.api.results import RunResult
from yadearch.cli.param_types import OUT_FILE, OUT_FOLDER
from yadearch.errors import RunFolderError
from yadearch.plotting.animation import FORMATS
from yadearch.plotting.states import run_states

ACCEPTED = (
    "RUN_FOLDER takes a run folder or a live load's path folder (OUT/NAME_load_path of "
    "`yadearch loads --engine static --out OUT`) that holds states.npz"
)


def _with_states(run_folder: str) -> RunResult:
    """The run or live load's path in `run_folder`; a file, or a folder without states, is a bad
    RUN_FOLDER (one line)."""
    try:
        if not Path(run_folder).is_dir():  # NAME_load_path.json, say, beside its folder
            raise RunFolderError(f"{run_folder} is a file")
        result = api.open_run(run_folder)
        run_states(result.folder)
    except RunFolderError as exc:
        raise click.BadParameter(f"{exc}; {ACCEPTED}", param_hint="'RUN_FOLDER'") from None
    return result


@click.command()
@click.argument("run_folder", type=click.Path(exists=True))
@click.option(
    "--format", "fmt", type=click.Choice(FORMATS), default="mp4", show_default=True, help="mp4 (needs ffmpeg) or gif"
)
@click.option("--out", type=OUT_FILE, help="movie file [default: RUN/figures/NAME.FORMAT]")
def animate(run_folder: str, fmt: str, out: str | None) -> None:
    """Draw a finished run as a movie along its loading path to collapse: the blocks to scale, hinges
    with the paper's letters, the thrust line, the support displacement and reaction. A live load's
    path folder (NAME_load_path, `yadearch loads --engine static`) is drawn along its load."""
    click.echo(f"movie -> {_with_states(run_folder).animate(out, fmt)}")


@click.command()
@click.argument("run_folder", type=click.Path(exists=True))
@click.option("--vtk", "vtk", is_flag=True, help="a ParaView time series (.pvd of .vtu files)")
@click.option("--out", type=OUT_FOLDER, help="folder [default: RUN/vtk]")
def export(run_folder: str, vtk: bool, out: str | None) -> None:
    """Export every state of a finished run for ParaView: blocks as 3D cells with their displacement
    and rotation, joints as points with their forces, openings and hinge flags; time = delta (mm), or
    on a live load's path (NAME_load_path) the state's index, its load in live_load_N (or _g)."""
    if not vtk:
        raise click.UsageError("say what to export: --vtk")
    click.echo(f"ParaView time series -> {_with_states(run_folder).export_vtk(Path(out) if out else None)}")
