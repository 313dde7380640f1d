"""The code stays lint-clean, formatted and type-clean (ruff check, ruff format and mypy, configured in
pyproject.toml); each check is skipped where its tool is not installed."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import REPO

ROOT = REPO


def _ruff() -> str | None:
    beside_python = Path(sys.executable).with_name("ruff")
    return str(beside_python) if beside_python.is_file() else shutil.which("ruff")


@pytest.mark.skipif(_ruff() is None, reason="ruff is not installed (scripts/setup.sh installs it)")
def test_ruff_finds_nothing():
    result = subprocess.run(
        [_ruff(), "check", "yadearch", "tests", "scripts"], cwd=ROOT, capture_output=True, text=True
    )
    assert result.returncode == 0, result.stdout + result.stderr


@pytest.mark.skipif(_ruff() is None, reason="ruff is not installed (scripts/setup.sh installs it)")
def test_the_code_is_as_ruff_formats_it():
    result = subprocess.run(
        [_ruff(), "format", "--check", "yadearch", "tests", "scripts"], cwd=ROOT, capture_output=True, text=True
    )
    assert result.returncode == 0, result.stdout + result.stderr


def _mypy_available() -> bool:
    return subprocess.run([sys.executable, "-m", "mypy", "--version"], capture_output=True).returncode == 0


@pytest.mark.skipif(not _mypy_available(), reason="mypy is not installed (scripts/setup.sh installs it)")
def test_mypy_finds_nothing():
    result = subprocess.run(
        [sys.executable, "-m", "mypy", "yadearch", "scripts"], cwd=ROOT, capture_output=True, text=True
    )
    assert result.returncode == 0, result.stdout + result.stderr
