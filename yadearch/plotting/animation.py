"""A run as a movie: the arch along its loading path to collapse (a support's movement, or a live
load's path), one frame a recorded state, drawn to scale as `plotting.states` draws a state, the
collapse held at the end. MP4 through ffmpeg, GIF through Pillow (no ffmpeg needed)."""

from __future__ import annotations

from pathlib import Path

from matplotlib.animation import FFMpegWriter, FuncAnimation, PillowWriter, writers
from tqdm import tqdm

from yadearch.analysis.blocks import case_geometry
from yadearch.analysis.run import RunAnalysis
from yadearch.atomic import write_atomically
from yadearch.errors import CaseError, YadearchError
from yadearch.plotting.house import ENGINE_NAMES, house_style, new_figure
from yadearch.plotting.states import draw_state, drawing_limits, place_texts, run_states, state_view
from yadearch.results.load_path import last_stable_multiplier
from yadearch.results.rundir import RunFolder
from yadearch.results.states import LOAD_DIGITS

FORMATS = ("mp4", "gif")
FRAMES_PER_S = 8
HOLD_COLLAPSE_S = 2.0  # the last state stays on screen this long: the mechanism at collapse
MAX_PATH_FRAMES = 240  # a path of more states is drawn at every k-th (30 s at 8 frames a second), its last kept
FRAME_CM = (17.0, 9.5)
FRAME_DPI = 150


def check_format(fmt: str) -> None:
    """A clear one-line error for an unknown format, or for MP4 without ffmpeg."""
    if fmt not in FORMATS:
        raise CaseError(f"format must be one of {', '.join(FORMATS)}, got {fmt!r}")
    if fmt == "mp4" and not writers.is_available("ffmpeg"):
        raise YadearchError(
            "MP4 needs ffmpeg, which is not installed (Debian: apt-get install ffmpeg); "
            "or write a GIF with --format gif"
        )


def movie_title(run: RunFolder) -> str:
    """The run's name and engine and its answer: du, or on a live load's path the load at collapse."""
    engine = ENGINE_NAMES.get(run.summary.engine, f"{run.summary.engine} engine")
    title = f"{run.summary.name or run.path.name}: {engine}"
    answer = run.load_path
    if answer is None:
        return title + (f", du = {run.summary.du_mm:.2f} mm" if run.summary.du_mm is not None else ", no collapse")
    unit, capacity = answer["unit"], answer["collapse_multiplier"]
    if capacity is not None:
        return f"{title}, live load: collapse at {capacity:.{LOAD_DIGITS}g} {unit}"
    return f"{title}, live load: {answer['outcome']} up to {last_stable_multiplier(answer):.{LOAD_DIGITS}g} {unit}"


def every_kth(states: list[int], most: int) -> list[int]:
    """`states` thinned evenly to at most `most`, the last kept (the collapse): a static run records
    hundreds of states, and a movie of each would run minutes and weigh tens of megabytes."""
    if len(states) <= most:
        return states
    kept = states[:: -(-len(states) // most)]  # every ceil(n / most)-th
    kept[-1] = states[-1]  # the collapse, in place of the state kept nearest it
    return kept


@house_style
def animate_run(
    run: RunFolder, analysis: RunAnalysis, out: Path, fmt: str = "mp4", fps: int = FRAMES_PER_S, progress: bool = True
) -> Path:
    """Write the run's movie to `out` (atomically): the states of the loading path, self-weight to
    collapse (at most MAX_PATH_FRAMES, `every_kth`), then the collapse held for HOLD_COLLAPSE_S;
    returns `out`. `progress`: bars over the states read and the frames drawn (a long run's movie
    takes a minute)."""
    check_format(fmt)
    states = run_states(run)
    geometry = case_geometry(run.case)
    limits = drawing_limits(geometry)
    path = every_kth(list(states.path()), MAX_PATH_FRAMES)
    frames = path + [path[-1]] * int(HOLD_COLLAPSE_S * fps)
    views = {
        i: state_view(run, geometry, analysis, i) for i in tqdm(path, desc="states", unit="state", disable=not progress)
    }
    fig = new_figure(height_cm=FRAME_CM[1], width_cm=FRAME_CM[0])
    ax = fig.add_subplot()
    title = movie_title(run)

    def draw(index: int) -> list:
        ax.clear()
        draw_state(ax, views[index], geometry, limits)
        ax.set_title(title)
        place_texts(fig)
        return []

    movie = FuncAnimation(fig, draw, frames=frames, blit=False)
    writer = FFMpegWriter(fps=fps) if fmt == "mp4" else PillowWriter(fps=fps)

    def save(temporary: Path) -> None:
        named = temporary.with_name(f"{temporary.stem}.{fmt}")  # the writers pick the container by suffix
        with tqdm(total=len(frames), desc="frames", unit="frame", disable=not progress) as bar:
            try:
                movie.save(str(named), writer=writer, dpi=FRAME_DPI, progress_callback=lambda i, n: bar.update(1))
                named.replace(temporary)
            finally:
                named.unlink(missing_ok=True)

    return write_atomically(Path(out), save)
