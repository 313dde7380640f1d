"""DEM numerics a study gives each of its DEM runs (`--dem-set numerics.KEY=VALUE` of the study scripts):
how a report's command names the DEM settings it was made with, e.g. its path reading (docs/numerics.md)."""

from __future__ import annotations

import argparse
from collections.abc import Iterable, Mapping
from types import MappingProxyType
from typing import Any

from yadearch.case.config import ArchCase
from yadearch.errors import YadearchError
from yadearch.studies.campaigns.grid import parse_scalar

NUMERICS_PREFIX = "numerics."  # the only section a study's DEM settings may name
ENGINE_KEY = "numerics.engine"  # the study picks each run's engine itself
NO_DEM_SETTINGS: Mapping[str, Any] = MappingProxyType({})  # a study's DEM runs at the case's own numerics


def parse_dem_settings(items: Iterable[str], option: str = "--dem-set") -> dict[str, Any]:
    """`numerics.KEY=VALUE` items (of `option`) as overrides of a run's numerics (`checked_settings`)."""
    settings: dict[str, Any] = {}
    for item in items:
        key, equals, value = (part.strip() for part in item.partition("="))
        if not equals:
            raise YadearchError(f"{option} expects numerics.KEY=VALUE, got {item!r}")
        settings[key] = parse_scalar(value)
    return checked_settings(settings, option)


def checked_settings(settings: Mapping[str, Any], option: str) -> dict[str, Any]:
    """`settings` ({"numerics.KEY": value}), each checked on the default case; YadearchError in one line
    naming `option` for a key outside the numerics, the engine, or a value out of range."""
    for key in settings:
        if not key.startswith(NUMERICS_PREFIX) or key == ENGINE_KEY:
            raise YadearchError(
                f"{option} expects numerics.KEY=VALUE (a numerical setting other than the engine), got {key!r}"
            )
    ArchCase().with_overrides(dict(settings))  # a bad key or value says so here, before any run
    return dict(settings)


def with_dem_settings(case: ArchCase, settings: Mapping[str, Any]) -> ArchCase:
    """`case` with the study's DEM `settings` (the case itself when there are none)."""
    return case.with_overrides(dict(settings)) if settings else case


def dem_arguments(settings: Mapping[str, Any]) -> str:
    """The `--dem-set` arguments that name `settings` in a report's command ('' for none)."""
    return "".join(
        f" --dem-set {key}={str(value).lower() if isinstance(value, bool) else value}"
        for key, value in settings.items()
    )


def add_dem_set_option(parser: argparse.ArgumentParser) -> None:
    """A study script's repeatable `--dem-set numerics.KEY=VALUE` option."""
    parser.add_argument(
        "--dem-set",
        action="append",
        default=[],
        metavar="numerics.KEY=VALUE",
        help="a DEM setting for every DEM run, e.g. numerics.support_path_states=static (named in the report)",
    )


def dem_settings_of(parser: argparse.ArgumentParser, arguments: argparse.Namespace) -> dict[str, Any]:
    """The settings of the parsed `--dem-set` options; a bad one ends the script with a one-line usage error."""
    try:
        return parse_dem_settings(arguments.dem_set)
    except YadearchError as exc:
        parser.error(str(exc))
