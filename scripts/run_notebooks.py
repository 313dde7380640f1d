"""Execute the example notebooks in place, so that they are committed with their outputs (tables and
figures inline): `.venv/bin/python scripts/run_notebooks.py [NOTEBOOK ...]` (default: every notebook
in examples/; the quickstart's DEM runs take about a minute). The tests execute copies with the same
function and check that the outputs mean what the committed ones say (tests/test_notebooks*.py)."""

from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
from pathlib import Path

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"
KERNEL = "yadearch"
TIMEOUT_S = 900  # per cell
BACKEND = "Agg"  # the runner chooses matplotlib's backend; the notebooks draw without pyplot


def execute_notebook(source: Path, target: Path) -> dict:
    """Run every cell of `source` on this interpreter (Debian's, with YADE) in a scratch folder and
    write the notebook with its outputs (progress bars left out) to `target`; returns it."""
    import nbclient
    import nbformat

    notebook = nbformat.read(source, as_version=4)
    with tempfile.TemporaryDirectory(prefix="yadearch-notebook-") as scratch:
        kernel = Path(scratch) / "kernels" / KERNEL
        kernel.mkdir(parents=True)
        (kernel / "kernel.json").write_text(
            json.dumps(
                {
                    "argv": [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"],
                    "display_name": "Python 3 (yadearch)",
                    "language": "python",
                    "env": {"MPLBACKEND": BACKEND},
                }
            )
        )
        previous = os.environ.get("JUPYTER_PATH")
        os.environ["JUPYTER_PATH"] = scratch
        try:
            nbclient.NotebookClient(
                notebook, kernel_name=KERNEL, timeout=TIMEOUT_S, resources={"metadata": {"path": scratch}}
            ).execute()
        finally:
            if previous is None:
                os.environ.pop("JUPYTER_PATH", None)
            else:
                os.environ["JUPYTER_PATH"] = previous
    for cell in notebook.cells:  # progress bars (standard error) are a run's, not the notebook's, output
        if cell.cell_type == "code":
            cell.outputs = [o for o in cell.outputs if not (o.output_type == "stream" and o.name == "stderr")]
    notebook.metadata["kernelspec"] = {"display_name": "Python 3", "language": "python", "name": "python3"}
    nbformat.write(notebook, target)
    return notebook


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("notebooks", nargs="*", type=Path, default=sorted(EXAMPLES.glob("*.ipynb")))
    for path in parser.parse_args().notebooks:
        execute_notebook(path, path)
        print(f"executed {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
