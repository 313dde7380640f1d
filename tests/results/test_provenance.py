"""A run's provenance (results/provenance.py): the checked-out commit, '+dirty' where a tracked file of
the package is modified (it asked git about a folder under the package that does not exist, and called
every modified tree clean: sixth user trial)."""

from __future__ import annotations

import shutil
import subprocess

import pytest

from yadearch.results.provenance import tree_revision

pytestmark = pytest.mark.skipif(shutil.which("git") is None, reason="needs git")


def _git(folder, *args: str) -> str:
    return subprocess.run(["git", *args], cwd=folder, capture_output=True, text=True, check=True).stdout.strip()


def test_a_modified_package_is_dirty_and_a_clean_one_not(tmp_path):
    package = tmp_path / "pkg"
    package.mkdir()
    (package / "module.py").write_text("x = 1\n")
    (tmp_path / "README").write_text("outside the package\n")
    _git(tmp_path, "init", "-q")
    _git(tmp_path, "-c", "user.name=t", "-c", "user.email=t@t", "commit", "-q", "--allow-empty", "-m", "start")
    _git(tmp_path, "add", ".")
    _git(tmp_path, "-c", "user.name=t", "-c", "user.email=t@t", "commit", "-q", "-m", "files")
    head = _git(tmp_path, "rev-parse", "--short=12", "HEAD")
    assert tree_revision(package) == head
    (tmp_path / "README").write_text("changed outside\n")
    assert tree_revision(package) == head  # only the package's own files count
    (package / "module.py").write_text("x = 2\n")
    assert tree_revision(package) == f"{head}+dirty"
