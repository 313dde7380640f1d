"""A run's figures drawn in two processes where the platform forks cheaply (Linux): they are
independent files, and drawing them is most of a single static run's wall time (docs/speed.md)."""

from __future__ import annotations

import multiprocessing
import sys
import threading
from collections.abc import Callable, Sequence
from dataclasses import dataclass

FORKING_PLATFORMS = ("linux",)  # where a forked child shares the parent's imports; elsewhere: one process
JOBS = (1, 2)  # one process, or this one and a forked child
CHILD_WAIT_S = 120.0  # a child not done this long after this process's share (stuck): stopped, its share redrawn


@dataclass(frozen=True)
class Drawing:
    """One figure to draw: its name, its relative cost (what splits the work) and the call."""

    name: str
    cost: float
    draw: Callable[[], object]


def draw_all(drawings: Sequence[Drawing], jobs: int = 1) -> None:
    """Call every drawing. With `jobs` 2 on a forking platform, in a process running no other thread
    (a fork copies no thread, and a lock another holds would stay locked in the child), a forked child
    draws about half the cost while this process draws the rest; whatever the child did not finish
    (it failed, or was stopped after CHILD_WAIT_S) is drawn here again: figures are written
    atomically, so a half-drawn one is never left."""
    if jobs not in JOBS:
        raise ValueError(f"jobs must be 1 or 2 (processes that draw the figures), got {jobs!r}")
    forks = sys.platform.startswith(FORKING_PLATFORMS) and threading.active_count() == 1
    if jobs == 1 or len(drawings) < 2 or not forks:
        for drawing in drawings:
            drawing.draw()
        return
    here, there = _split(drawings)
    child = multiprocessing.get_context("fork").Process(target=_draw, args=(there,))
    child.start()
    try:
        for drawing in here:
            drawing.draw()
    finally:
        child.join(CHILD_WAIT_S)
        if child.is_alive():
            child.terminate()
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


def _draw(drawings: list[Drawing]) -> None:
    """The child's share."""
    for drawing in drawings:
        drawing.draw()
