"""The command line's parameter types: numbers as a person writes them, an API argument's option read
and checked as the API checks it, and output paths (one declaration each, shared by the commands)."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING, Any

import click

from yadearch.case.names import FILE, FOLDER, output_path
from yadearch.errors import CaseError

if TYPE_CHECKING:
    from yadearch.api.arguments import Argument

FLOAT_TEXT = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?|[+-]?(nan|inf|infinity)", re.IGNORECASE)
INT_TEXT = re.compile(r"[+-]?\d+")


class Number(click.ParamType):
    """A number as a person writes it: digits, a point, an exponent (not Python's '0_3', which
    float() reads as 3); its range is the case's or the API's to check."""

    name = "number"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> float:
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            return float(value)
        if not FLOAT_TEXT.fullmatch(str(value).strip()):
            self.fail(f"must be a number (e.g. 5.2 or 1e-3), got {value!r}", param, ctx)
        return float(value)


NUMBER = Number()


class ArgumentType(click.ParamType):
    """The option of an API argument (`api.arguments.ARGUMENTS`): read strictly and checked against
    the same range in the option's unit, so that the command line and the API agree. A row given by
    its name is looked up when first needed (the table imports the studies whose limits it holds)."""

    def __init__(self, argument: Argument | str):
        self._argument = argument

    @property
    def argument(self) -> Argument:
        if isinstance(self._argument, str):
            from yadearch.api.arguments import ARGUMENTS

            self._argument = ARGUMENTS[self._argument]
        return self._argument

    @property
    def name(self) -> str:  # type: ignore[override]  # click's name of the type (help's metavar, messages)
        return "integer" if self.argument.kind is int else "number"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        argument = self.argument
        accepted = f"must be {argument.accepted(argument.scale, none=False)}, got {value!r}"
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            pattern = INT_TEXT if argument.kind is int else FLOAT_TEXT
            if not pattern.fullmatch(str(value).strip()):
                self.fail(accepted, param, ctx)
            value = argument.kind(str(value).strip())
        if argument.refusal(value if argument.scale == 1 else value * argument.scale) is not None:
            self.fail(accepted, param, ctx)
        return value


def argument_type(name: str) -> ArgumentType:
    """The click type of the option for the API argument `name`."""
    return ArgumentType(name)


class OutputPath(click.ParamType):
    """An output folder or file, checked where the API checks it (`case.names.output_path`)."""

    def __init__(self, kind: str = FOLDER):
        self.kind = kind
        self.name = "path"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> str:
        option = param.opts[0] if param is not None and param.opts else "--out"
        try:
            output_path(value, option, self.kind)
        except CaseError as exc:
            raise click.UsageError(str(exc), ctx) from None
        return str(value)


OUT_FOLDER, OUT_FILE = OutputPath(FOLDER), OutputPath(FILE)
