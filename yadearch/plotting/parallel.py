"""A run's figures drawn in two processes where the platform forks cheaply (Linux): they are
independent files, and drawing them is most of a single static run's wall time (docs/speed.md)."""

from __future__ import annotations

import gc
import multiprocessing
import sys
import threading
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from itertools import combinations

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
    atomically, so a half-drawn one is never left. The garbage collector is paused throughout
    (`collector_paused`)."""
    if jobs not in JOBS:
        raise ValueError(f"jobs must be 1 or 2 (processes that draw the figures), got {jobs!r}")
    with collector_paused():
        forks = sys.platform.startswith(FORKING_PLATFORMS) and threading.active_count() == 1
        if jobs == 1 or len(drawings) < 2 or not forks:
            _draw(drawings)
        else:
            _draw_in_two(drawings)


@contextmanager
def collector_paused() -> Iterator[None]:
    """Python's cyclic garbage collector off within the block (on again after, if it was): a process
    that holds numpy, pandas, numba and matplotlib tracks some 140 000 objects, and the collections
    that importing and drawing set off cost a tenth of the figures' time (docs/speed.md). The few MB
    of cycles the figures leave are collected after the block."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()


def _draw_in_two(drawings: Sequence[Drawing]) -> None:
    """`draw_all` with a forked child drawing one share."""
    here, there = _split(drawings)
    child = multiprocessing.get_context("fork").Process(target=_draw, args=(there,))
    child.start()
    try:
        _draw(here)
    finally:
        child.join(CHILD_WAIT_S)
        if child.is_alive():
            child.terminate()
            child.join()
    if child.exitcode != 0:
        _draw(there)


def _split(drawings: Sequence[Drawing]) -> tuple[list[Drawing], list[Drawing]]:
    """The two shares whose dearer one costs least, every split tried (a run has six figures at most;
    with set 2's costs a greedy split, dearest first, left one share 17 % above the other, the best 7 %);
    each share in the given order."""
    total = sum(d.cost for d in drawings)
    picks = (set(pick) for n in range(len(drawings) + 1) for pick in combinations(range(len(drawings)), n))

    def dearer(pick: set[int]) -> float:
        cost = sum(drawings[k].cost for k in pick)
        return max(cost, total - cost)

    there = min(picks, key=dearer)
    return [d for k, d in enumerate(drawings) if k not in there], [d for k, d in enumerate(drawings) if k in there]


def _draw(drawings: Sequence[Drawing]) -> None:
    """Draw a share, in order."""
    for drawing in drawings:
        drawing.draw()
