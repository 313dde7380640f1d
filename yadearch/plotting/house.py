"""The house style every figure shares: print sizes (8.5 cm a journal column), 8 pt text, the
colours of the hinge letters and the thrust line, the room labels take, and how a figure is
written (vector PDF and 300 dpi PNG, atomically). Figures use matplotlib's Figure directly (no
pyplot), so they never touch an interactive backend."""

from __future__ import annotations

from pathlib import Path

from matplotlib.figure import Figure

from yadearch.atomic import write_atomically
from yadearch.model.hinges import PAPER_LABELS
from yadearch.plotting.pdf_fonts import lean_pdf_fonts

CM = 1 / 2.54  # inches
ENGINE_NAMES = {"static": "static engine", "dem": "DEM (YADE)"}  # an engine as a figure's legend or title names it
COLUMN_CM = 8.5
PNG_DPI = 300
MIN_TEXT_PT = 7  # the smallest text at print size: the smallest a journal prints legibly
STYLE = {
    "font.size": 8,
    "axes.labelsize": 8,
    "axes.titlesize": 8,
    "legend.fontsize": MIN_TEXT_PT,
    "xtick.labelsize": MIN_TEXT_PT,
    "ytick.labelsize": MIN_TEXT_PT,
    "lines.linewidth": 1.0,
    "axes.linewidth": 0.6,
    "xtick.major.width": 0.6,
    "ytick.major.width": 0.6,
    "legend.frameon": False,
    "pdf.fonttype": 42,
    "ps.fonttype": 42,
    "savefig.dpi": PNG_DPI,
}
HINGE_COLOURS = ["#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9"]  # Okabe-Ito
THRUST_COLOUR = "#B2182B"  # the thrust line: a red no hinge letter takes
LABEL_ROOM = 0.15  # fraction of the arch's width left free on each side for hinge labels at the supports
AXIS_MARGINS_CM = (1.3, 1.1)  # room the axis labels and ticks take across and down an equal-aspect plot


def hinge_colour(letter: str, extra: int = 0) -> str:
    """The colour of a hinge in every figure and movie: one per paper letter A-D, the next colours
    for hinges without a letter (the `extra`-th of them)."""
    if letter in PAPER_LABELS:
        return HINGE_COLOURS[PAPER_LABELS.index(letter)]
    return HINGE_COLOURS[len(PAPER_LABELS) + extra % (len(HINGE_COLOURS) - len(PAPER_LABELS))]


def mechanism_colour(k: int) -> str:
    """The colour of the `k`-th hinge (left to right) of a mechanism without the paper's letters (a live
    load's): each of up to six hinges its own, none of them the thrust line's."""
    return HINGE_COLOURS[k % len(HINGE_COLOURS)]


def new_figure(height_cm: float, width_cm: float = COLUMN_CM) -> Figure:
    """A figure in the house style at its print size."""
    fig = Figure(figsize=(width_cm * CM, height_cm * CM), layout="constrained")
    fig.get_layout_engine().set(w_pad=0.02, h_pad=0.02)
    return fig


def save_figure(fig: Figure, stem: Path) -> tuple[Path, Path]:
    """Write `stem`.pdf (vector, without a creation date, so that regenerated evidence differs only
    where its content does; fonts without their layout tables, `plotting.pdf_fonts`) and `stem`.png
    (300 dpi); returns both paths."""
    stem.parent.mkdir(parents=True, exist_ok=True)
    pdf, png = stem.with_name(f"{stem.name}.pdf"), stem.with_name(f"{stem.name}.png")  # a stem may hold dots
    with lean_pdf_fonts():
        write_atomically(pdf, lambda tmp: fig.savefig(tmp, format="pdf", metadata={"CreationDate": None}))
    write_atomically(png, lambda tmp: fig.savefig(tmp, format="png", dpi=PNG_DPI))
    return pdf, png


def house_style(draw):
    """Run a figure builder under the house rcParams."""
    import matplotlib

    def wrapper(*args, **kwargs):
        with matplotlib.rc_context(STYLE):
            return draw(*args, **kwargs)

    wrapper.__name__, wrapper.__doc__ = draw.__name__, draw.__doc__
    return wrapper
