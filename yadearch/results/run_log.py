"""A run's log: each line stamped with the time, printed and written to the run's log file at once
(a run that dies leaves its log up to its last line)."""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import TextIO


def stamped_log(log_file: TextIO) -> Callable[[str], None]:
    """A `log(line)` that prints `line` stamped with the time and appends it to `log_file`, flushed."""

    def log(line: str) -> None:
        stamped = f"{time.strftime('%H:%M:%S')} {line}"
        print(stamped, flush=True)
        log_file.write(stamped + "\n")
        log_file.flush()

    return log
