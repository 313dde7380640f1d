"""Step a YADE scene in batches inside one uninterrupted simulation thread (YADE layer).

YADE 2023.02a does not reproduce a polyhedra scene across `O.run` restarts: a restart changes the
trajectory in its last bits, differently in each process (9-voussoir arch, 700 steps: one `O.run`
gives one state in every process, 14 runs of 50 steps gave two different states in two processes),
and near collapse those bits decide a hold's verdict. So the simulation thread is started once; a
gate engine, first in the engine list, parks it between batches, and the runner reads and changes
the scene while it is parked, as it would between two steps.
"""

from __future__ import annotations

import atexit
import threading
import time
from typing import Any

import __main__
from yadearch.errors import RunFailedError

GATE_LABEL = "yadearch_stepping_gate"
GATE_NAME = "_yadearch_gate"  # where the gate engine's command finds the gate
STALL_S = 120.0  # wall seconds without a single step before a run is declared stalled
POLL_S = 0.5  # how often a waiting runner checks that the simulation thread is alive
CLOSE_S = 10.0  # wall seconds a closing gate waits for the thread to end its last step
CHECK_EVERY_STEPS = 50  # steps between a runner's checks (speed, equilibrium, records)

_active: list[SteppingGate] = []  # the gate whose simulation thread is running (started), if any


class SteppingGate:
    """Runs the scene `n` steps at a time without ever stopping YADE's simulation thread."""

    def __init__(self) -> None:
        self._parked = threading.Event()
        self._resume = threading.Event()
        self._closing = False
        self._engine: Any = None  # the gate's PyRunner, once installed

    def install(self) -> None:
        """Put the gate engine first in `O.engines` (before the forces are reset: a parked scene is
        between two steps)."""
        from yade import O
        from yade.wrapper import PyRunner

        setattr(__main__, GATE_NAME, self)
        gate = PyRunner(command=f"{GATE_NAME}.park()", iterPeriod=1, initRun=True, label=GATE_LABEL)
        O.engines = [gate, *O.engines]
        self._engine = O.engines[0]

    def park(self) -> None:
        """Called by the gate engine in the simulation thread: wait until the runner asks for more
        steps, or stop the thread for good (it finishes the step it is in) when the gate closes."""
        from yade import O

        if not self._closing:
            self._parked.set()
            self._resume.wait()
            self._resume.clear()
        if self._closing:
            self._engine.dead = True
            O.pause()

    def advance(self, n: int) -> None:
        """Run exactly `n` more steps and return with the thread parked."""
        from yade import O

        if self not in _active:  # first batch: start the thread
            close_active()
            self._parked.clear()
            O.run()
            _active.append(self)
            self._wait_parked(O.iter)
        self._engine.iterPeriod = n
        self._parked.clear()
        self._resume.set()
        self._wait_parked(O.iter + n)

    def _wait_parked(self, target: int) -> None:
        """Wait for the thread to park at step `target`; a dead or stalled thread fails the run."""
        from yade import O

        last_iter, last_change = O.iter, time.time()
        while not self._parked.wait(POLL_S):
            if not O.running:
                raise RunFailedError(
                    f"YADE stopped stepping at step {O.iter} (target {target}); an engine probably raised, see stderr"
                )
            if O.iter != last_iter:
                last_iter, last_change = O.iter, time.time()
            elif time.time() - last_change > STALL_S:
                raise RunFailedError(f"YADE made no step for {STALL_S:.0f} s at step {O.iter}")

    def close(self) -> None:
        """Let the thread finish its step and stop; the scene can then be reset or run directly."""
        from yade import O

        if self not in _active:
            return
        parked_at = O.iter if self._parked.is_set() else None
        self._closing = True
        self._resume.set()
        # the thread's last step runs Python engines: wait for it to end, or a caller holding the
        # GIL (O.reset) would wait for the thread forever
        deadline = time.time() + CLOSE_S  # a thread lost in an engine error never ends its step
        while (O.running or (parked_at is not None and O.iter == parked_at)) and time.time() < deadline:
            time.sleep(0.001)
        _active.remove(self)


def close_active() -> None:
    """Stop the simulation thread a gate keeps parked (before `O.reset()` or a bare `O.run`)."""
    for gate in list(_active):
        gate.close()


atexit.register(close_active)
