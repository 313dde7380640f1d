"""Time spent in each YADE engine over a whole run (YADE layer).

YADE's `O.timingEnabled` makes every engine accumulate its own `execTime`. The profile splits a
run's wall time into the scene's engines (the physics: YADE's C++ engines and the contact model's
Python engine), the driver's callbacks inside the engine loop (the support driver), and the rest
(the driver's own checks, records and state snapshots).
"""

from __future__ import annotations

from yadearch.dem.stepping import GATE_LABEL

PYTHON_ENGINES = ("PyRunner",)


class EngineClock:
    """Accumulated nanoseconds per engine label over the run; Python engines whose command starts
    with one of `driver_callbacks` count as the driver's, every other engine as the scene's."""

    def __init__(self, driver_callbacks: tuple[str, ...]) -> None:
        from yade import O

        O.timingEnabled = True
        self.driver_labels = tuple(f"{name}({callback}" for name in PYTHON_ENGINES for callback in driver_callbacks)
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
        """Seconds per engine, the scene's and the driver's shares, and wall time / scene time."""
        self.harvest()
        seconds = {label: ns * 1e-9 for label, ns in self.totals_ns.items()}
        driver_s = sum(s for label, s in seconds.items() if label.startswith(self.driver_labels))
        scene_s = sum(seconds.values()) - driver_s
        return {
            "engine_s": seconds,
            "scene_engines_s": scene_s,
            "driver_callbacks_s": driver_s,
            "driver_rest_s": wall_s - scene_s - driver_s,
            "driver_overhead_ratio": wall_s / scene_s if scene_s > 0 else None,
        }
