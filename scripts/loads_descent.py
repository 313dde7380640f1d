"""The DEM past the peak against the static engine's arc length (reports/loads/descent; docs/loads.md).

    .venv/bin/python scripts/loads_descent.py [--out reports/loads/descent] [--jobs 2]

Runs every case's load path past its limit point on both engines (the DEM in child processes, --jobs at a
time; those whose files OUT/load_paths holds already are read back) and writes descent.md, descent.csv,
states.csv and descent.pdf/.png.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from yadearch.reporting.loads_descent import write_descent_report


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("reports/loads/descent"))
    parser.add_argument("--jobs", type=int, default=2, choices=(1, 2, 3, 4))
    args = parser.parse_args()
    start = time.time()
    print(write_descent_report(args.out, args.jobs))
    print(f"{time.time() - start:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
