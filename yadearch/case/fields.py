"""Field metadata of a case's parameters: the accepted range of a number and its one-line
description, which `yadearch params` prints and validation reads."""

from __future__ import annotations

from collections.abc import Mapping
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


def range_text(meta: Mapping[str, Any]) -> str:
    """A number's accepted range in words ("in (0, 100]", ">= 1")."""
    low, high = meta.get("low"), meta.get("high")
    if high is None:
        return f"{'>' if meta['low_open'] else '>='} {_bound(low)}"
    if low is None:
        return f"{'<' if meta['high_open'] else '<='} {_bound(high)}"
    left = "(" if meta["low_open"] else "["
    right = ")" if meta["high_open"] else "]"
    return f"in {left}{_bound(low)}, {_bound(high)}{right}"


def _bound(value: Any) -> str:
    """A range's end as the user would type it: a whole number in full (a seed's 4294967295, not
    4.29497e+09), others to 6 significant figures."""
    return str(int(value)) if float(value).is_integer() and abs(value) < 1e15 else f"{value:g}"


def accepted_text(meta: Mapping[str, Any]) -> str:
    """What a parameter accepts, in words: its choices, its range, its table's columns; "" where its
    metadata says nothing (a flag, a name)."""
    if "choices" in meta:
        return "one of " + ", ".join(meta["choices"])
    if "table_columns" in meta:
        return f"rows of [{', '.join(meta['table_columns'])}]"
    if meta.get("low") is not None or meta.get("high") is not None:
        return range_text(meta)
    return ""
