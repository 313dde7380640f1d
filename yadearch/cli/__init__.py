"""The command line: thin click commands over the Python API."""

from yadearch.cli.commands import main

__all__ = ["main"]
