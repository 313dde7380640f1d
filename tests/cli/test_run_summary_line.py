"""The line `yadearch run` ends with names the fold's mechanism where the joints open after the runaway
make another one (eighth user trial: "hinges at collapse 4I 39E 56E", three hinges, read as no
mechanism): the shallow arch (set 2 at embrace 75 deg) on joints of kn 10 000 folds on 1I 4I 39E 56E,
and 1I closes again as it falls. The paper's set 2, whose runaway opens the mode's joints a joint
away, keeps its one list."""

from __future__ import annotations

from yadearch.cli.commands import main

STATIC = ["--engine", "static", "--no-figures", "--no-check"]


def test_the_folds_mode_is_named_where_the_runaway_opens_another_mechanism(tmp_path, capsys):
    shallow = ["run", "--preset", "set2", "--set", "embrace_deg=75", "--kn", "10000", *STATIC]
    assert main([*shallow, "--out", str(tmp_path / "shallow")]) == 0
    line = next(s for s in capsys.readouterr().out.splitlines() if " du = " in s)
    assert "hinges at collapse 4I 39E 56E (the fold's mode: 1I 4I 39E 56E, four-hinge mechanism)" in line
    assert main(["run", "--preset", "set2", *STATIC, "--out", str(tmp_path / "set2")]) == 0
    line = next(s for s in capsys.readouterr().out.splitlines() if " du = " in s)
    assert "hinges at collapse 1E 9I 29E 56E, static engine" in line
