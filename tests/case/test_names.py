"""Run names and output paths are checked in one place (`case.names`) for every command and the API:
nothing outside the chosen folder, no empty or special names, no control characters (issue 42)."""

from __future__ import annotations

import pytest

from yadearch.case.config import case_from_dict
from yadearch.case.names import DERIVED_NAME_EXTRA, FILE, check_name, name_problem, output_path
from yadearch.errors import ArgumentTypeError, CaseError
from yadearch.launch.process import REPLACED_SUFFIX
from yadearch.results.lock import LOCK_SUFFIX
from yadearch.results.rundir import STAGING_PREFIX, STAGING_SUFFIX


def test_the_room_kept_for_derived_names_is_that_of_the_longest_one_a_run_makes():
    longest = max(len(STAGING_PREFIX) + len(suffix) for suffix in (STAGING_SUFFIX, REPLACED_SUFFIX, LOCK_SUFFIX))
    assert DERIVED_NAME_EXTRA == longest


@pytest.mark.parametrize("name", ["set2", "kn5.2", "kn0.1_n_voussoirs15", "arc de pierre", "voûte", "a-b+c", "x" * 245])
def test_plain_names_are_accepted(name):
    assert name_problem(name) is None and check_name(name) == name
    assert case_from_dict({"name": name}).name == name


@pytest.mark.parametrize(
    "name, words",
    [
        ("", "empty"),
        ("   ", "empty"),
        (".", "'.' or '..'"),
        ("..", "'.' or '..'"),
        ("../../x", "a path"),
        ("a/b", "a path"),
        (".x", "hidden"),
        (".x.partial", "hidden"),  # would be the staging folder of the run "x"
        (" x", "spaces"),
        ("a\tb", "control"),
        ("a\x00b", "control"),
        ("a\x7fb", "control"),
        ("x" * 246, "246 bytes"),
        ("é" * 123, "246 bytes"),  # bytes, not characters
    ],
)
def test_special_names_are_refused_saying_why(name, words):
    assert words in name_problem(name)
    with pytest.raises(CaseError, match="name must be a plain folder name"):
        case_from_dict({"name": name})


def test_a_name_of_another_type_is_a_type_error_naming_the_argument():
    with pytest.raises(ArgumentTypeError, match="case.name must be a str, got int 3"):
        check_name(3, "case.name")


@pytest.mark.parametrize("out", ["", " ", ".", "..", "/", "//", "x/..", "x/.", "a\nb", "x/.hidden", "x/" + "y" * 300])
def test_output_paths_that_name_no_folder_of_their_own_are_refused(out, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(CaseError, match="^out must be a path ending in a folder name of its own"):
        output_path(out)
    assert list(tmp_path.iterdir()) == []


def test_an_output_path_is_a_folder_or_a_file_as_asked(tmp_path):
    (tmp_path / "file").write_text("")
    (tmp_path / "folder").mkdir()
    assert output_path(tmp_path / "new") == tmp_path / "new"
    assert output_path(str(tmp_path / "folder")) == tmp_path / "folder"
    with pytest.raises(CaseError, match="must be a folder, got .*which is a file"):
        output_path(tmp_path / "file", "--out")
    with pytest.raises(CaseError, match="must be a file, got .*which is a folder"):
        output_path(tmp_path / "folder", "--out", FILE)
    with pytest.raises(ArgumentTypeError, match="out must be a path .*got int 123"):
        output_path(123)
    with pytest.raises(ArgumentTypeError, match="got bytes"):
        output_path(b"runs")
