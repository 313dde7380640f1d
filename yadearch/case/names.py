"""Run names and output paths, checked in this one place for every command and the API: a name is
a plain folder name a run can derive its staging and lock names from, and an output path ends in a
name of its own, so nothing is ever written outside the chosen folder."""

from __future__ import annotations

import os
import re
import tempfile
from pathlib import Path

from yadearch.errors import ArgumentTypeError, CaseError

# A run folder NAME also makes .NAME.partial, .NAME.replaced and .NAME.lock beside it: the longest
# adds 10 characters (tests/case/test_names.py checks this against the suffixes the run uses).
DERIVED_NAME_EXTRA = 10
NAME_MAX_BYTES = 255  # Linux's limit on one name (bytes); a file system may allow fewer (pathconf)
CONTROL_CHARACTERS = re.compile(r"[\x00-\x1f\x7f-\x9f]")
SPECIAL_NAMES = ("", ".", "..")
FOLDER, FILE = "folder", "file"
EXAMPLES = {FOLDER: "runs/case", FILE: "runs/result.json"}


def name_problem(name: str, limit: int = NAME_MAX_BYTES - DERIVED_NAME_EXTRA) -> str | None:
    """Why `name` cannot name a run folder (None: it can): empty, '.', '..', a path, hidden (the
    staging folders' namespace), control characters, or more than `limit` bytes."""
    if name.strip() in SPECIAL_NAMES:
        return "an empty name or '.' or '..'"
    if "/" in name:
        return "a path (a name has no '/')"
    if name.startswith("."):
        return "a hidden name (one starting with '.', kept for the run's staging folders)"
    if name != name.strip():
        return "a name with leading or trailing spaces"
    if CONTROL_CHARACTERS.search(name):
        return "a name with control characters"
    size = len(name.encode("utf-8", "surrogateescape"))
    if size > limit:
        return f"{size} bytes long; at most {limit} (the file system's limit less {DERIVED_NAME_EXTRA}: staging)"
    return None


def check_name(name: object, argument: str = "name") -> str:
    """`name` if it can name a run folder, else CaseError (ArgumentTypeError if not a str) naming
    `argument`, the value and what is accepted."""
    if not isinstance(name, str):
        raise ArgumentTypeError(f"{argument} must be a str, got {type(name).__name__} {name!r:.40}")
    problem = name_problem(name)
    if problem:
        raise CaseError(
            f"{argument} must be a plain folder name (not empty, '.' or '..'; no '/'; not hidden; no "
            f"control characters), got {name!r:.60}: {problem}"
        )
    return name


def output_path(value: object, argument: str = "out", kind: str = FOLDER) -> Path:
    """`value` as the output folder (or file, `kind`) a command writes, after checking that it is a
    path ending in a name of its own (not '', '.', '..' or '/'), that this name can be a run folder's
    on its file system, and that it is not a file where a folder is wanted (or the reverse)."""
    if isinstance(value, bytes) or not isinstance(value, (str, os.PathLike)):
        raise ArgumentTypeError(
            f"{argument} must be a path (str or pathlib.Path), got {type(value).__name__} {value!r:.40}"
        )
    text = os.fspath(value)
    accepted = f"a path ending in a {kind} name of its own, e.g. {EXAMPLES[kind]}"
    if not isinstance(text, str) or not text.strip():
        raise CaseError(f"{argument} must be {accepted}, got {text!r}")
    if CONTROL_CHARACTERS.search(text):
        raise CaseError(f"{argument} must be {accepted} without control characters, got {text!r:.60}")
    path = Path(text)
    last = text.rstrip("/").rsplit("/", 1)[-1]  # Path drops a trailing '.', which would hide 'x/.'
    if last in SPECIAL_NAMES or path.name in SPECIAL_NAMES:
        raise CaseError(f"{argument} must be {accepted} (not '.', '..' or '/'), got {text!r}")
    problem = name_problem(path.name, _name_limit(path))
    if problem:
        raise CaseError(f"{argument} must be {accepted}, got {text!r:.60}: its last part is {problem}")
    if kind == FOLDER and path.is_file():
        raise CaseError(f"{argument} must be a folder, got {text!r}, which is a file")
    if kind == FILE and path.is_dir():
        raise CaseError(f"{argument} must be a file, got {text!r}, which is a folder")
    return path


def _name_limit(path: Path) -> int:
    """The longest name (bytes) a run folder may have beside `path`, on its file system."""
    parent = next((p for p in (path.parent, *path.parent.parents) if p.is_dir()), Path("."))
    try:
        limit = os.pathconf(parent, "PC_NAME_MAX")
    except (OSError, ValueError):
        limit = NAME_MAX_BYTES
    return limit - DERIVED_NAME_EXTRA


def writable_folder(folder: Path, argument: str = "out") -> Path:
    """`folder`, created if missing, once a file can be written in it; else CaseError in one line
    naming `argument` (a read-only or pseudo file system refused before any work, not after it)."""
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise CaseError(f"{argument}: cannot create the folder {str(folder)!r} ({exc.strerror})") from None
    try:  # a probe, not os.access: root passes that on read-only and pseudo file systems
        with tempfile.TemporaryFile(dir=folder):
            pass
    except OSError as exc:
        raise CaseError(f"{argument}: cannot write in the folder {str(folder)!r} ({exc.strerror})") from None
    return folder
