"""The report's part for a live load's path folder (OUT/NAME_load_path/ of `yadearch loads --engine
static|dem`): what the load path answers (the load at the first loss of stability and at collapse,
the mechanism, the rigid blocks' load beside it) and its load-displacement figure, so that `yadearch
report` takes a load run as it takes a support movement's."""

from __future__ import annotations

import json
import math
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from yadearch.errors import RunFolderError
from yadearch.markdown import markdown_table
from yadearch.plotting.loads import plot_load_path
from yadearch.results.load_path import LOAD_PATH_SUFFIX, read_load_path
from yadearch.results.rundir import FIGURES_DIR, LOAD_PATH_FILE


@dataclass
class ReportedLoad:
    """A load path folder as the report shows it: its answer, and its figure's folder in the report."""

    path: Path
    answer: dict[str, Any]
    folder: str
    figure: Path | None


def is_load_path_folder(path: str | Path) -> bool:
    """Whether `path` is a live load's path folder (it holds the load path's answer)."""
    return (Path(path) / LOAD_PATH_FILE).is_file()


def checked_load_paths(paths: Sequence[str | Path]) -> list[Path]:
    """The live load's path folders among `paths`, each answer checked readable (before anything is written)."""
    found = [Path(p) for p in paths if is_load_path_folder(p)]
    for path in found:
        read_answer(path)
    return found


def read_answer(path: Path) -> dict[str, Any]:
    """The load path's answer in `path`; RunFolderError naming the file when it cannot be read."""
    file = path / LOAD_PATH_FILE
    try:
        answer = json.loads(file.read_text())
        if not isinstance(answer, dict) or "name" not in answer:
            raise ValueError("no load path's answer")
        return answer
    except (OSError, ValueError) as exc:
        raise RunFolderError(f"{file} cannot be read as a load path's answer ({exc})") from None


def report_load(path: Path, out: Path, folder: str) -> ReportedLoad:
    """The answer of the load path folder `path` and its load-displacement figure under OUT/`folder`
    (drawn from the curve written beside the folder, NAME_load_path.csv; none if it is not there)."""
    answer = read_answer(path)
    figure = None
    name = str(answer["name"])
    if (path.parent / f"{name}{LOAD_PATH_SUFFIX}.csv").is_file():
        pdf, _ = plot_load_path(read_load_path(path.parent, name), out / folder / FIGURES_DIR / "load_path")
        figure = pdf.with_suffix(".png").relative_to(out)
    return ReportedLoad(path, answer, folder, figure)


def _load(value: Any, unit: str) -> str:
    return "—" if value is None or (isinstance(value, float) and math.isnan(value)) else f"{value:.4g} {unit}"


def load_overview(loads: list[ReportedLoad]) -> list[str]:
    """One line per load path: the load, where it started, the load at the first loss and at collapse,
    the mechanism and the rigid blocks' load."""
    columns = ["run", "engine", "live load", "after (mm)", "first loss", "collapse", "hinges", "rigid blocks"]
    return markdown_table(columns, (_overview_cells(r) for r in loads))


def _overview_cells(r: ReportedLoad) -> list[str]:
    a, unit = r.answer, r.answer["unit"]
    rigid = f"{_load(a['rigid_multiplier'], unit)} on {' '.join(a['rigid_hinges']) or '—'}"
    return [
        f"{a['name']} ({r.folder})",
        a["engine"],
        a["live_load"].replace("_", " "),
        f"{a['after_mm']:g}",
        _load(a["first_loss_multiplier"], unit),
        _load(a["collapse_multiplier"], unit),
        " ".join(a["hinges_at_collapse"]) or "—",
        rigid,
    ]


def load_section(r: ReportedLoad) -> list[str]:
    """A load path's section: its answer in words and its load-displacement figure."""
    a, unit = r.answer, r.answer["unit"]
    lines = [
        f"## {a['name']}: {a['live_load'].replace('_', ' ')} ({a['engine']}, `{r.path}`)",
        "",
        f"Outcome: {a['outcome']} ({a['collapse_kind'] or 'no mechanism'}); the load first loses stability at "
        f"{_load(a['first_loss_multiplier'], unit)} and collapses at {_load(a['collapse_multiplier'], unit)} "
        f"on {' '.join(a['hinges_at_collapse']) or '—'}, after {a['after_mm']:g} mm of support movement. Rigid "
        f"blocks in the same state: {_load(a['rigid_multiplier'], unit)}"
        + (f" ({a['rigid_note']})" if a.get("rigid_note") else "")
        + ".",
        "",
    ]
    if r.figure is not None:
        lines += [f"![load path]({r.figure})", ""]
    return lines
