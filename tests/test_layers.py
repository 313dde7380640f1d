"""The packages form layers and imports only go down them (docs/install.md, "Development: the
layers"): a package never imports one above it, only `dem/` imports YADE, and neither engine imports the
other (`launch/` above them picks one)."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest
from conftest import REPO

PACKAGE = REPO / "yadearch"
# top to bottom; the modules at the bottom (errors, atomic, markdown, children) and the version serve every layer
LAYERS = (
    "cli",
    "api",
    "reporting",
    "studies",
    "plotting",
    "analysis",
    "launch",
    "dem",
    "static",
    "results",
    "solve",
    "case",
    "model",
    "errors",
    "atomic",
    "markdown",
    "children",
)
ENTRY_POINTS = ("__init__", "__main__")  # the package's own surface: `import yadearch` reaches the API


def _imports(path: Path) -> set[str]:
    """The yadearch packages (and other top modules, e.g. yade) that `path` imports."""
    found = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom) and node.module:
            names = [f"{node.module}.{a.name}" for a in node.names] if node.module == "yadearch" else [node.module]
        elif isinstance(node, ast.Import):
            names = [a.name for a in node.names]
        else:
            continue
        for name in names:
            parts = name.split(".")
            found.add(parts[1] if parts[0] == "yadearch" and len(parts) > 1 else parts[0])
    return found


def _layer(path: Path) -> str:
    return path.relative_to(PACKAGE).parts[0].removesuffix(".py")


SOURCES = sorted(p for p in PACKAGE.rglob("*.py") if _layer(p) not in ENTRY_POINTS)


def test_every_module_belongs_to_a_layer():
    assert {_layer(p) for p in SOURCES} <= set(LAYERS)


@pytest.mark.parametrize("path", SOURCES, ids=lambda p: str(p.relative_to(PACKAGE)))
def test_imports_only_go_down(path):
    own = LAYERS.index(_layer(path))
    upward = {name for name in _imports(path) & set(LAYERS) if LAYERS.index(name) < own}
    assert not upward, f"{path.relative_to(REPO)} imports the layer(s) above it: {sorted(upward)}"
    if _layer(path) != "dem":
        assert "yade" not in _imports(path), f"{path.relative_to(REPO)} imports YADE outside dem/"


ENGINES = ("dem", "static")


@pytest.mark.parametrize(
    "path", [p for p in SOURCES if _layer(p) in ENGINES], ids=lambda p: str(p.relative_to(PACKAGE))
)
def test_neither_engine_imports_the_other(path):
    other = next(e for e in ENGINES if e != _layer(path))
    assert other not in _imports(path), f"{path.relative_to(REPO)} imports the other engine, {other}/"
