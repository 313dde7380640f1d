"""The sensitivity study's figures drawn again from the tables it wrote (a change of the figures, no
run): the tornado, the Sobol indices and their convergence.

    .venv/bin/python scripts/sensitivity_figures.py [--out reports/sensitivity]

The study itself: `yadearch sensitivity` (docs/validation-imperfections.md has the committed one's command).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from yadearch.studies.sensitivity.study import redraw_figures


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("reports/sensitivity"))
    args = parser.parse_args()
    redraw_figures(args.out)
    print(f"figures -> {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
