"""The names of a run's stages and of its holds' verdicts, one enum each, as both engines write them
into series.csv, joints.csv, states.npz and summary.json (string enums: they compare and print as
their values)."""

from __future__ import annotations

from enum import StrEnum


class Stage(StrEnum):
    """What a run is doing when it records a row or a state."""

    SELFWEIGHT = "selfweight"  # gravity applied, supports fixed
    INCREMENT = "increment"  # the support moving (DEM)
    RELAX = "relax"  # the support held while the arch relaxes (DEM)
    EQUILIBRIUM = "equilibrium"  # an accepted state of the loading path
    SETTLE = "settle"  # the lower end of du's bracket relaxing further (DEM)
    COLLAPSE = "collapse"  # the runaway from the first state past du
    END = "end"  # the end of a path that did not collapse


class Verdict(StrEnum):
    """How a hold at a fixed support ended."""

    STABLE = "stable"  # an equilibrium
    RUNAWAY = "runaway"  # a block moved more than runaway_mm
    TIMEOUT = "timeout"  # neither, within the time allowed


PATH_STAGES = (Stage.SELFWEIGHT, Stage.EQUILIBRIUM, Stage.COLLAPSE)  # the quasi-static path, in its order
