"""A run's figures drawn in two processes where the platform forks cheaply (Linux): they are
independent files, and drawing them is most of a single static run's wall time (docs/speed.md)."""

from __future__ import annotations

import multiprocessing
import os
import sys
from collections.abc import Callable, Sequence
from dataclasses import dataclass

FORKING_PLATFORMS = ("linux",)  # where a forked child shares the parent's imports; elsewhere: one process


@dataclass(frozen=True)
class Drawing:
    """One figure to draw: its name, its relative cost (what splits the work) and the call."""

    name: str
    cost: float
    draw: Callable[[], object]


def draw_all(drawings: Sequence[Drawing], jobs: int = 1) -> None:
    """Call every drawing. With `jobs` > 1 on a forking platform a forked child draws about half the
    cost while this process draws the rest; whatever the child did not finish is drawn here again
    (a figure is written atomically, so a half-drawn one is never left)."""
    if jobs <= 1 or len(drawings) < 2 or not sys.platform.startswith(FORKING_PLATFORMS):
        for drawing in drawings:
            drawing.draw()
        return
    here, there = _split(drawings)
    child = multiprocessing.get_context("fork").Process(target=_draw_and_exit, args=(there,))
    child.start()
    for drawing in here:
        drawing.draw()
    child.join()
    if child.exitcode != 0:
        for drawing in there:
            drawing.draw()


def _split(drawings: Sequence[Drawing]) -> tuple[list[Drawing], list[Drawing]]:
    """Two shares of about equal cost, the dearest drawings placed first (greedy)."""
    shares: tuple[list[Drawing], list[Drawing]] = ([], [])
    for drawing in sorted(drawings, key=lambda d: -d.cost):
        min(shares, key=lambda share: sum(d.cost for d in share)).append(drawing)
    return shares


def _draw_and_exit(drawings: list[Drawing]) -> None:
    """The child's work: its drawings, then an exit that skips the parent's clean-up handlers."""
    for drawing in drawings:
        drawing.draw()
    sys.stdout.flush()
    os._exit(0)
