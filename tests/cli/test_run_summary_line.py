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


def test_a_new_arch_on_the_models_values_is_warned_once_whether_the_run_is_made_or_reused(tmp_path, capfd):
    """The warning that a new arch took the 1:10 model's values came twice from a run made now, once in
    its log and once after its answer (open since the fifth user trial); a reused run, which logs
    nothing, says it after its answer."""
    coarse = ["run", "--preset", "set2", "--set", "n_voussoirs=15", *STATIC, "--out", str(tmp_path)]
    for _made_then_reused in range(2):
        assert main(coarse) == 0
        said = capfd.readouterr()
        assert (said.out + said.err).count("this arch is not the paper's but has the paper's 1:10 model's values") == 1
