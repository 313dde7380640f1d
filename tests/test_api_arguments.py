"""The API checks its arguments like the command line (issue 42): every row of the argument table
(`api.arguments.ARGUMENTS`) is the type of its command-line option, each value generated from the row's
bounds is accepted or refused alike by both, and every API function refuses a wrong type or range
naming the argument before anything starts (no pool, no simulation, nothing written)."""

from __future__ import annotations

import inspect
import math

import click
import pytest

import yadearch as ya
from yadearch.api.arguments import ARGUMENTS, Argument, check_arguments
from yadearch.cli.commands import cli
from yadearch.cli.param_types import ArgumentType
from yadearch.errors import ArgumentTypeError, YadearchError

OPTIONS = {a.option: a for a in ARGUMENTS.values() if a.option}
API_FUNCTIONS = [ya.run, ya.reproduce, ya.limit, ya.sweep, ya.montecarlo, ya.calibrate, ya.robustness, ya.capacity]
API_FUNCTIONS += [ya.sensitivity]
NEEDED = {  # the required arguments of each function, valid, so that only the probed one is wrong
    "case": "set2",
    "out": "OUT",
    "samples": 2,
    "target_du_mm": 48.0,
    "kn_N_per_mm3": [1.0],
}


def probe_values(argument: Argument) -> list[float]:
    """Numbers around the row's bounds and beyond any, in API units."""
    values: list[float] = [math.nan, math.inf, -math.inf, 1.5, 0, -1, 2, 1e300]
    for bound in (argument.low, argument.high):
        if bound is not None:
            step = 1 if argument.kind is int else max(abs(bound) * 1e-9, 1e-12)
            values += [bound, bound - step, bound + step]
    return values


def cli_accepts(argument: Argument, text: str) -> bool:
    try:
        ArgumentType(argument).convert(text, None, None)
    except click.BadParameter as exc:
        assert "must be" in str(exc) and repr(text) in str(exc)
        return False
    return True


def api_accepts(argument: Argument, value: object) -> bool:
    try:
        check_arguments(**{argument.name: value})
    except (ArgumentTypeError, ValueError) as exc:
        assert str(exc).startswith(f"{argument.name} must be ") and "\n" not in str(exc)
        return False
    return True


@pytest.mark.parametrize("argument", [a for a in ARGUMENTS.values() if a.option], ids=lambda a: a.name)
def test_the_command_line_and_the_api_accept_the_same_values(argument):
    """Each number, typed in the option's unit, is accepted by both or refused by both."""
    for value in probe_values(argument):
        if argument.kind is int and math.isfinite(value) and not float(value).is_integer():
            assert not cli_accepts(argument, repr(value)) and not api_accepts(argument, value)
            continue
        api_value = int(value) if argument.kind is int and math.isfinite(value) else value
        scaled = api_value / argument.scale if argument.scale != 1 else api_value
        text = repr(scaled) if argument.kind is float else str(scaled)
        assert cli_accepts(argument, text) == api_accepts(argument, api_value), (argument.name, text, api_value)
    for text, value in (("abc", "abc"), ("2_0", "20"), ("", None if not argument.optional else "")):
        assert not cli_accepts(argument, text) and not api_accepts(argument, value), (argument.name, text)


def _options(command: click.Command):
    for param in command.params:
        if isinstance(param, click.Option):
            yield command.name, param


def test_every_option_of_an_api_argument_takes_its_type_from_the_table():
    seen = set()
    for command in cli.all_commands().values():  # the lazily imported commands too
        for name, option in _options(command):
            flag = option.opts[0]
            if flag in OPTIONS:
                assert isinstance(option.type, ArgumentType), (name, flag)
                assert option.type.argument is OPTIONS[flag], (name, flag)
                seen.add(flag)
    assert seen == set(OPTIONS)  # every row with an option is used by some command


def _calls():
    """(function, argument, bad value) for every checked argument of every API function."""
    for function in API_FUNCTIONS:
        for name in inspect.signature(function).parameters:
            if name in ARGUMENTS:
                argument = ARGUMENTS[name]
                bad = ["2", -1] if argument.kind is not bool else ["yes"]
                if argument.kind is float:
                    bad += [math.nan, math.inf]
                for value in bad:
                    yield function, name, value


@pytest.mark.parametrize("function, name, value", list(_calls()), ids=lambda x: getattr(x, "__name__", repr(x)))
def test_every_api_function_refuses_a_bad_argument_naming_it_before_anything_starts(
    function, name, value, tmp_path, monkeypatch
):
    from yadearch.studies.campaigns import executors

    def no_pool(*args, **kwargs):
        raise AssertionError("a pool was opened")

    monkeypatch.setattr(executors, "open_pool", no_pool)
    monkeypatch.chdir(tmp_path)
    parameters = inspect.signature(function).parameters
    arguments = {k: v for k, v in NEEDED.items() if k in parameters or (k == "kn_N_per_mm3" and function is ya.sweep)}
    arguments = {k: (str(tmp_path / "out") if v == "OUT" else v) for k, v in arguments.items()}
    with pytest.raises((TypeError, ValueError)) as error:
        function(**{**arguments, name: value})
    assert isinstance(error.value, YadearchError) and name in str(error.value), str(error.value)
    assert list(tmp_path.iterdir()) == []  # nothing written


@pytest.mark.parametrize(
    "call, words",
    [  # the issue's cases: each refused naming the argument
        (lambda: ya.sweep("set2", 123, kn_N_per_mm3=[1]), "out must be a path"),
        (lambda: ya.sweep("set2", "x", jobs="2", kn_N_per_mm3=[1]), "jobs must be an integer"),
        (lambda: ya.sweep("set2", "x", jobs=0, kn_N_per_mm3=[1]), r"jobs must be an integer in \[1, 1024\]"),
        (lambda: ya.sweep("set2", "x", timeout_s=-5, kn_N_per_mm3=[1]), "timeout_s must be a number in"),
        (lambda: ya.montecarlo("set2", "x", samples="10"), "samples must be an integer"),
        (lambda: ya.calibrate("set2", "48.9", "x"), "target_du_mm must be a number"),
        (lambda: ya.limit("set2", compliant="yes"), "compliant must be true or false"),
        (lambda: ya.run("set2", out="", engine="static"), "out must be a path ending in a folder name"),
        (lambda: ya.run(ya.preset("set2").replace(name="x"), out=".", engine="static"), r"not '\.', '\.\.' or '/'"),
        (lambda: ya.open_run(42), "path must be a run folder"),
        (lambda: ya.report("reports/set2", "x"), "runs must be a list of run folders"),
    ],
)
def test_the_issues_api_mistakes_are_refused_naming_the_argument(call, words, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises((TypeError, ValueError), match=words):
        call()
    assert list(tmp_path.iterdir()) == []


def test_a_case_renamed_by_hand_is_checked_when_it_runs(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    case = ya.preset("set2")
    case.name = "../escape"  # a dataclass field set directly skips case_from_dict's check
    with pytest.raises(ValueError, match="name must be a plain folder name"):
        ya.run(case, engine="static")
    assert list(tmp_path.iterdir()) == [] and not (tmp_path.parent / "escape").exists()
