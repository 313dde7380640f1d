"""Writing files so that a reader never sees half of one: a temporary file in the same folder,
renamed over the target when complete (an interrupted write leaves the old file, or none)."""

from __future__ import annotations

import csv
import math
import numbers
import os
import tempfile
from collections.abc import Callable, Sequence
from pathlib import Path

_UMASK = os.umask(0o022)
os.umask(_UMASK)  # read the process umask (set and restored at import)


def write_atomically(path: Path, write: Callable[[Path], object]) -> Path:
    """Write `path` by `write(temporary)` to a temporary file in the same folder, then rename it over
    `path`."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    handle, temporary = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    os.close(handle)
    try:
        write(Path(temporary))
        os.chmod(temporary, 0o666 & ~_UMASK)  # mkstemp's 0600 -> what open() would have given
        os.replace(temporary, path)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise
    return path


def write_text_atomically(path: Path, text: str) -> Path:
    """`write_atomically` for a text file."""
    return write_atomically(path, lambda temporary: temporary.write_text(text))


CSV_FLOAT_FORMAT = "%.6g"  # six significant figures: tables stay readable and diff cleanly


def write_csv_atomically(path: Path, table) -> Path:
    """`write_atomically` for a pandas table as CSV (no index, floats to six significant figures)."""
    return write_atomically(path, lambda temporary: table.to_csv(temporary, index=False, float_format=CSV_FLOAT_FORMAT))


def _cell(value: object, float_format: str) -> object:
    """A CSV cell as pandas writes it: floats by `float_format`, NaN and None empty, the rest as text."""
    if value is None:
        return ""
    if isinstance(value, numbers.Real) and not isinstance(value, numbers.Integral):
        value = float(value)
        return "" if math.isnan(value) else float_format % value
    return value


def write_rows_atomically(path: Path, rows: Sequence[dict], float_format: str = CSV_FLOAT_FORMAT) -> Path:
    """`write_atomically` for records as a CSV table (the columns in order of first appearance, a
    missing value empty): the file pandas' `to_csv` writes for a run's rows (numbers, flags, text; a
    column mixing big integers with floats keeps the integers whole), without importing pandas."""
    columns = list(dict.fromkeys(key for row in rows for key in row))

    def write(temporary: Path) -> None:
        with open(temporary, "w", newline="") as handle:
            writer = csv.writer(handle, lineterminator="\n")
            writer.writerow(columns)
            writer.writerows([_cell(row.get(c), float_format) for c in columns] for row in rows)

    return write_atomically(path, write)


TEMPORARY_PATTERN = ".*.tmp"  # the names write_atomically gives its temporary files


def remove_stale_temporaries(folder: Path) -> list[Path]:
    """Delete the temporary files that writes killed before their rename left in `folder` (a
    SIGKILL skips the cleanup above); call it only where no write is under way. Returns them."""
    stale = [p for p in Path(folder).glob(TEMPORARY_PATTERN) if p.is_file()]
    for path in stale:
        path.unlink(missing_ok=True)
    return stale
