"""Field metadata of a case's parameters: the accepted range of a number and its one-line
description, which `yadearch params` prints and validation reads."""

from __future__ import annotations

from typing import Any


def number_meta(
    low: float | None = None,
    high: float | None = None,
    *,
    low_open: bool = False,
    high_open: bool = False,
    doc: str = "",
    predates: float | None = None,
) -> dict[str, Any]:
    """Field metadata: the accepted range of a number and a one-line description (and the value a case
    written before the parameter existed takes, where it has one)."""
    found = {"low": low, "high": high, "low_open": low_open, "high_open": high_open, "doc": doc}
    return found | ({"predates": predates} if predates is not None else {})


def choice_meta(choices: tuple[str, ...], doc: str, predates: str | None = None) -> dict[str, Any]:
    """Field metadata: the accepted words and a one-line description (and the value a case written
    before the parameter existed takes, where it has one)."""
    return {"choices": choices, "doc": doc, **({"predates": predates} if predates is not None else {})}


def table_meta(columns: tuple[str, ...], doc: str) -> dict[str, Any]:
    """Field metadata: a table parameter's columns (rows of numbers) and a one-line description; a case
    written before it existed has no rows."""
    return {"table_columns": columns, "predates": [], "doc": doc}
