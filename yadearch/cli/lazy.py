"""The command line's lazy group: a command defined in another module is imported when it is invoked,
and `--help` lists it from its module's source, so that a single static run starts in a fraction of a
second (docs/speed.md)."""

from __future__ import annotations

import ast
from importlib import import_module
from importlib.util import find_spec
from pathlib import Path

import click

# The commands defined in other modules, imported only when invoked (or listed by --help): a command
# imports what it needs (pandas, matplotlib, the studies) and no other command's, so that a single
# static run starts in a fraction of a second (docs/speed.md).
LAZY_COMMANDS = {
    "sweep": "yadearch.cli.campaigns",
    "calibrate": "yadearch.cli.campaigns",
    "robustness": "yadearch.cli.campaigns",
    "montecarlo": "yadearch.cli.montecarlo",
    "capacity": "yadearch.cli.capacity",
    "loads": "yadearch.cli.loads",
    "limit": "yadearch.cli.limit",
    "survey": "yadearch.cli.survey",
    "piers": "yadearch.cli.survey",
    "sensitivity": "yadearch.cli.sensitivity",
    "animate": "yadearch.cli.views",
    "export": "yadearch.cli.views",
}


class LazyGroup(click.Group):
    """A group whose commands in LAZY_COMMANDS are imported from their module on first use; listing
    them (--help) reads their one-line help from their module's source without importing it."""

    listing = False  # format_commands is at work: a lazy command not yet imported stands in by its help

    def list_commands(self, ctx: click.Context) -> list[str]:
        return sorted({*self.commands, *LAZY_COMMANDS})

    def get_command(self, ctx: click.Context, cmd_name: str) -> click.Command | None:
        if cmd_name not in self.commands and cmd_name in LAZY_COMMANDS:
            if self.listing:
                return click.Command(cmd_name, help=_docstring(LAZY_COMMANDS[cmd_name], cmd_name))
            command = getattr(import_module(LAZY_COMMANDS[cmd_name]), cmd_name)
            self.add_command(command, cmd_name)
        return self.commands.get(cmd_name)

    def format_commands(self, ctx: click.Context, formatter: click.HelpFormatter) -> None:
        self.listing = True
        try:
            super().format_commands(ctx, formatter)
        finally:
            self.listing = False

    def all_commands(self) -> dict[str, click.Command]:
        """Every command by name, the lazy ones imported (for tests and documentation)."""
        context = click.Context(self)
        return {name: command for name in self.list_commands(context) if (command := self.get_command(context, name))}


def _docstring(module: str, function: str) -> str | None:
    """The docstring of `function` in `module`, read from its source (the module is not imported)."""
    spec = find_spec(module)
    assert spec is not None and spec.origin is not None, module  # LAZY_COMMANDS names installed modules
    tree = ast.parse(Path(spec.origin).read_text(encoding="utf-8"))
    found = (node for node in tree.body if isinstance(node, ast.FunctionDef) and node.name == function)
    return ast.get_docstring(next(found))
