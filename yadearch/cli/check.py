"""--check/--no-check: the static engine's increments check on a command line (`run`, `loads --engine
static`): on unless the case file or a --set names numerics.increments_check (docs/numerics.md)."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

import click

if TYPE_CHECKING:
    from yadearch.case.config import ArchCase

CHECK_HELP = (
    "static engine: solve the path again with the increments halved and say whether the answer moves by "
    "more than 1 % (numerics.increments_check; twice the solver's time)  [default: check, unless the case "
    "file or --set says numerics.increments_check]"
)


def check_option(function: Callable) -> Callable:
    """--check/--no-check: the static engine's increments check (`with_increments_check`)."""
    return click.option("--check/--no-check", default=None, help=CHECK_HELP)(function)


def with_increments_check(
    case: ArchCase, check: bool | None, case_file: str | None, settings: tuple[str, ...]
) -> ArchCase:
    """`case` with the static engine's increments check as --check/--no-check asks; without either, on
    unless the case file or a --set names numerics.increments_check (its value is kept). Other engines:
    `case` as it is."""
    from yadearch.case.numerics_section import HALVED_INCREMENTS_CHECK, NO_INCREMENTS_CHECK, STATIC_ENGINE

    if case.numerics.engine != STATIC_ENGINE:
        return case
    if check is None:
        if _states_the_check(case_file, settings):
            if case.numerics.increments_check == NO_INCREMENTS_CHECK:
                source = "a --set" if _states_the_check(None, settings) else case_file
                click.echo(f"increments check off: {source} says numerics.increments_check = 'none' (--check to check)")
            return case
        check = True
    elif _states_the_check(None, settings):
        flag = "--check" if check else "--no-check"
        raise click.UsageError(f"{flag} and --set numerics.increments_check both say whether to check; keep one")
    return case.with_overrides({"numerics.increments_check": HALVED_INCREMENTS_CHECK if check else NO_INCREMENTS_CHECK})


def _states_the_check(case_file: str | None, settings: tuple[str, ...]) -> bool:
    """Whether the case file or a --set names numerics.increments_check (then `run` keeps its value)."""
    import tomllib

    if any(setting.split("=", 1)[0].split(".")[-1] == "increments_check" for setting in settings):
        return True
    if case_file is None:
        return False
    return "increments_check" in tomllib.loads(Path(case_file).read_text()).get("numerics", {})


def case_file_text(case: ArchCase, case_file: str | None, settings: tuple[str, ...]) -> str:
    """`case` as the TOML a command writes for a later `run --case`: without numerics.increments_check
    unless the case file or a --set it came from names it, so that `run` checks by default."""
    import tomli_w

    data = case.to_dict()
    if not _states_the_check(case_file, settings):
        data["numerics"].pop("increments_check", None)
    return tomli_w.dumps(data)
