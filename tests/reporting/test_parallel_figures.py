"""A run's figures drawn in two processes (plotting.parallel) are the files one process draws, byte
for byte, a drawing the child could not finish is drawn by the parent, the shares are the most even
split of the costs, and the garbage collector is paused while drawing."""

from __future__ import annotations

import gc
import os
import sys
from pathlib import Path

import pytest
from conftest import REPO

from yadearch.analysis.run import analyse_run
from yadearch.plotting.parallel import Drawing, _split, collector_paused, draw_all
from yadearch.plotting.run_figures import write_figures
from yadearch.results.rundir import read_run

forking = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="figures fork only on Linux")


@forking
def test_two_processes_draw_the_same_files_as_one(tmp_path: Path) -> None:
    run = read_run(REPO / "reports/set2")
    analysis = analyse_run(run)
    one = write_figures(run, analysis, tmp_path / "one", jobs=1)
    two = write_figures(run, analysis, tmp_path / "two", jobs=2)
    assert one.keys() == two.keys() and len(one) >= 5
    for name, paths in one.items():
        for drawn_once, drawn_twice in zip(paths, two[name], strict=True):
            assert drawn_once.read_bytes() == drawn_twice.read_bytes(), drawn_once.name


@forking
def test_what_the_child_did_not_draw_is_drawn_here(tmp_path: Path) -> None:
    parent = os.getpid()

    def write(name: str) -> None:
        if os.getpid() != parent:
            raise RuntimeError("the child fails")
        (tmp_path / name).write_text(name)

    drawings = [
        Drawing(name, cost, lambda name=name: write(name)) for name, cost in (("a", 2.0), ("b", 1.0), ("c", 1.0))
    ]
    draw_all(drawings, jobs=2)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a", "b", "c"]


def test_a_process_running_other_threads_draws_alone(tmp_path: Path) -> None:
    """A fork copies no thread (a lock another thread holds would stay locked in the child): with a
    second thread running, every figure is drawn by this process."""
    import threading

    parent, drawn_by = os.getpid(), []
    release = threading.Event()
    other = threading.Thread(target=release.wait)
    other.start()
    try:
        draw_all([Drawing(name, 1.0, lambda: drawn_by.append(os.getpid())) for name in "abc"], jobs=2)
    finally:
        release.set()
        other.join()
    assert drawn_by == [parent] * 3


def test_the_number_of_drawing_processes_is_one_or_two() -> None:
    with pytest.raises(ValueError, match="jobs must be 1 or 2"):
        draw_all([], jobs=3)


def test_the_split_is_the_most_even_one() -> None:
    """Costs 3, 3, 2, 2, 2: a greedy split, dearest first, gives 7 and 5; the best gives 6 and 6."""
    drawings = [Drawing(name, cost, lambda: None) for name, cost in zip("abcde", (3.0, 3.0, 2.0, 2.0, 2.0))]
    here, there = _split(drawings)
    assert sorted(d.name for d in here + there) == list("abcde")
    assert sum(d.cost for d in here) == sum(d.cost for d in there) == 6.0


def test_the_garbage_collector_is_paused_while_drawing_and_restored() -> None:
    enabled = []
    draw_all([Drawing("a", 1.0, lambda: enabled.append(gc.isenabled()))])
    assert enabled == [False] and gc.isenabled()
    gc.disable()
    try:
        with collector_paused():
            pass
        assert not gc.isenabled()  # a collector that was off stays off
    finally:
        gc.enable()
