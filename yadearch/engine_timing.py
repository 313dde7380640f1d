"""Time spent in each YADE engine over a whole run (YADE layer).

YADE's `O.timingEnabled` makes every engine accumulate its own `execTime`. The profile splits a
run's wall time into YADE's C++ engines, the Python callbacks that run inside the engine loop, and
the rest (the driver's own checks, records and state snapshots).
"""

from __future__ import annotations

from .stepping import GATE_LABEL

PYTHON_ENGINES = ("PyRunner",)


class EngineClock:
    """Accumulated nanoseconds per engine label over the run."""

    def __init__(self) -> None:
        from yade import O

        O.timingEnabled = True
        self.totals_ns: dict[str, int] = {}

    @staticmethod
    def _label(engine) -> str:
        name = type(engine).__name__
        if name in PYTHON_ENGINES:
            return f"{name}({engine.command.split('(')[0]})"
        return name

    def harvest(self) -> None:
        """Add the engines' counters to the totals and zero them."""
        from yade import O

        for engine in O.engines:
            if getattr(engine, "label", "") == GATE_LABEL:  # its time is the runner's, between steps
                continue
            label = self._label(engine)
            self.totals_ns[label] = self.totals_ns.get(label, 0) + engine.execTime
            engine.execTime = 0
            engine.execCount = 0

    def profile(self, wall_s: float) -> dict:
        """Seconds per engine, the C++ and Python shares, and wall time / C++ engine time."""
        self.harvest()
        seconds = {label: ns * 1e-9 for label, ns in self.totals_ns.items()}
        python_s = sum(s for label, s in seconds.items() if label.startswith(PYTHON_ENGINES))
        cpp_s = sum(seconds.values()) - python_s
        return {
            "engine_s": seconds, "yade_cpp_engines_s": cpp_s, "python_callbacks_s": python_s,
            "driver_rest_s": wall_s - cpp_s - python_s,
            "driver_overhead_ratio": wall_s / cpp_s if cpp_s > 0 else None,
        }
