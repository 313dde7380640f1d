"""Calling a compiled kernel that takes a large tuple of arrays without numba typing it at every call.

numba 0.56 remembers an argument's type by a fingerprint of at most 40 bytes; a tuple of more than
about four arrays (the static engine's joint table and problem) is typed again in Python at every
call, 0.26 ms, about a sixth of a campaign run's solver time. `KernelCall` remembers the types of its
calls under a key of its own (what numba's typeof reads of each value) and calls the compiled
overload that numba's dispatcher would call: the same machine code, the same answers."""

from __future__ import annotations

from collections.abc import Callable, Hashable
from typing import Any

import numpy as np

INT64_RANGE = (-(2**63), 2**63)  # numba types a Python int in it as int64


class Unkeyed(TypeError):
    """A value whose type this module does not key (it goes through numba's own dispatch)."""


def type_key(value: Any) -> Hashable:
    """What numba's typeof reads of `value`: an array's dtype, dimensions, layout, writability and
    alignment; a Python scalar's type (an int's range); a tuple's items in turn."""
    kind = type(value)
    if kind is np.ndarray:
        flags = value.flags
        layout = "C" if flags.c_contiguous else "F" if flags.f_contiguous else "A"
        return (value.dtype, value.ndim, layout, flags.writeable, flags.aligned)
    if kind is tuple:
        return tuple(type_key(item) for item in value)
    if kind is float or kind is bool:
        return kind.__name__
    if kind is int:
        return ("int", INT64_RANGE[0] <= value < INT64_RANGE[1])
    raise Unkeyed(kind.__name__)


class KernelCall:
    """A numba dispatcher's function called through the overload its arguments' key selected before
    (the dispatcher itself the first time a key is seen, and for values without a key)."""

    def __init__(self, dispatcher: Any) -> None:
        self.dispatcher = dispatcher
        self.entries: dict[Hashable, Callable[..., Any]] = {}

    def __call__(self, *args: Any) -> Any:
        try:
            key = tuple(type_key(arg) for arg in args)
        except Unkeyed:
            return self.dispatcher(*args)
        entry = self.entries.get(key)
        if entry is not None:
            return entry(*args)
        result = self.dispatcher(*args)  # typed, compiled or loaded from numba's cache
        compiled = self.dispatcher.overloads.get(tuple(self.dispatcher.typeof_pyval(arg) for arg in args))
        if compiled is not None:
            self.entries[key] = compiled.entry_point
        return result
