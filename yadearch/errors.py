"""Errors that mean a user mistake or an unusable environment: the CLI prints them as one line."""

CANNOT_STAND = "the arch does not stand under its own weight"  # both engines' words; campaigns read them
UNRESOLVED = "unresolved"  # a run's failure that is the solver's, not the arch's (never a collapse)


class YadearchError(Exception):
    """Base of the errors the CLI reports as one line, without a traceback."""


class CaseError(YadearchError, ValueError):
    """A case parameter is unknown or outside its accepted range."""


class CampaignError(YadearchError, ValueError):
    """A campaign's grid, table or size is unusable (refused before anything runs)."""


class YadeMissingError(YadearchError):
    """YADE cannot be imported in this Python."""


class RunFailedError(YadearchError):
    """A simulation process failed (crash, NaN, timeout)."""


class RunInterruptedError(RunFailedError):
    """A simulation process stopped by SIGINT or SIGTERM: not a failure of the case."""


class RunFolderError(YadearchError):
    """A run folder that does not hold a complete, readable run."""


class ArgumentTypeError(YadearchError, TypeError):
    """An API argument of the wrong type (a str where a number is wanted): named, in one line."""
