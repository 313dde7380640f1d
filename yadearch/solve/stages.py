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
    RUNAWAY = "runaway"  # a block moved more than the runaway bound (a multiple of the ring's thickness)
    TIMEOUT = "timeout"  # neither, within the time or iterations allowed (after the engine's retries)


class Outcome(StrEnum):
    """How a run's path ended, as summary.json's `outcome` writes it."""

    COLLAPSE = "collapse"  # no equilibrium past du: a block ran away
    STANDS = "stands"  # equilibrium up to the largest support displacement asked for
    UNRESOLVED = "unresolved"  # the solver found neither equilibrium nor runaway: no du, never a collapse
    CANNOT_STAND = "cannot stand"  # no equilibrium under the self-weight alone


PATH_STAGES = (Stage.SELFWEIGHT, Stage.EQUILIBRIUM, Stage.COLLAPSE)  # the quasi-static path, in its order
