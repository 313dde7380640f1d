"""The command line starts light (issues 43 and 45): `import yadearch.cli` imports no command's
heavy modules (pandas, matplotlib, scipy, dask, the studies), each command is imported when it is
invoked, and a static run without figures imports no plotting module. What makes a single static
run fast from the command line is asserted here as structure, not timed (docs/speed.md)."""

from __future__ import annotations

import json
import subprocess
import sys

import click
from click.testing import CliRunner
from conftest import REPO

from yadearch.cli.commands import LAZY_COMMANDS, cli

HEAVY = ("pandas", "matplotlib", "scipy", "dask", "distributed", "numba", "SALib", "yadearch.studies")


def _imported_after(code: str, *names: str) -> list[str]:
    """The modules among `names` (or their submodules) that a fresh interpreter has imported after `code`."""
    probe = (
        f"{code}\nimport json, sys\n"
        f"print(json.dumps(sorted({{n for n in {names!r} for m in sys.modules if m == n or m.startswith(n + '.')}})))"
    )
    done = subprocess.run([sys.executable, "-c", probe], cwd=REPO, capture_output=True, text=True, check=True)
    return json.loads(done.stdout.splitlines()[-1])


def test_importing_the_command_line_imports_no_heavy_module():
    assert _imported_after("import yadearch.cli", *HEAVY, "yadearch.api.arguments", "yadearch.cli.campaigns") == []


def test_the_python_api_package_imports_its_modules_on_first_use():
    assert _imported_after("import yadearch.api", *HEAVY, "yadearch.api.runs") == []
    assert _imported_after("from yadearch.api import run", "matplotlib", "dask", "yadearch.api.campaigns") == []


def test_a_static_run_without_figures_imports_no_plotting_module(tmp_path):
    run = (
        "from yadearch.cli.commands import main\n"
        "assert main(['run', '--preset', 'set2', '--engine', 'static', '--set', 'geometry.n_voussoirs=9', "
        f"'--no-figures', '--out', {str(tmp_path / 'run')!r}]) == 0"
    )
    probed = ("matplotlib", "dask", "scipy.optimize", "pandas", "scipy.special", "yadearch.plotting")
    imported = _imported_after(run, *probed, "yadearch.solve.load_path", "yadearch.studies")
    assert (tmp_path / "run" / "summary.json").is_file()
    # nothing drawn, no table library, no live load's solver; cli.options parses --set values with the
    # campaigns' parser (yadearch.studies.campaigns.grid, light)
    assert set(imported) <= {"yadearch.studies"}


def test_help_lists_every_command_with_its_one_line_help():
    commands = cli.all_commands()
    assert set(LAZY_COMMANDS) <= set(commands) and all(commands[name].name == name for name in LAZY_COMMANDS)
    shown = CliRunner().invoke(cli, ["--help"]).output
    for name, command in commands.items():
        assert f"  {name} " in shown and command.get_short_help_str(limit=45)[:20] in shown, name


def test_a_lazy_command_is_the_module_s_own():
    context = click.Context(cli)
    for name, module in LAZY_COMMANDS.items():
        assert cli.get_command(context, name) is getattr(sys.modules[module], name)


def test_help_lists_the_lazy_commands_without_importing_them():
    """`yadearch --help` reads each lazy command's one-line help from its module's source: the list is
    the one the imported commands give, and none of their modules (nor pandas, matplotlib, ...) loads."""
    listing = (
        "from click.testing import CliRunner\n"
        "from yadearch.cli.commands import cli\n"
        "assert 'Commands:' in CliRunner().invoke(cli, ['--help']).output"
    )
    assert _imported_after(listing, *HEAVY, *set(LAZY_COMMANDS.values())) == []
    both = (
        "from click.testing import CliRunner\n"
        "from yadearch.cli.commands import cli\n"
        "lazy = CliRunner().invoke(cli, ['--help']).output\n"
        "cli.all_commands()\n"
        "assert CliRunner().invoke(cli, ['--help']).output == lazy, lazy"
    )
    subprocess.run([sys.executable, "-c", both], cwd=REPO, check=True)
