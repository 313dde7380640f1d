"""The DEM past the peak against the static engine's arc length (reports/loads/descent; docs/loads.md).

    .venv/bin/python scripts/loads_descent.py [--out reports/loads/descent] [--jobs 2]
        [--dem-set numerics.KEY=VALUE ...]

Runs every case's load path past its limit point on both engines (the DEM in child processes, --jobs at a
time; those whose files OUT/load_paths holds already are read back) and writes descent.md, descent.csv,
states.csv and descent.pdf/.png. --dem-set gives every DEM run a numerical setting (the DEM's numerics
varied from its value) and names it in descent.md's command.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from yadearch.reporting.loads_descent import write_descent_report
from yadearch.studies.dem_settings import add_dem_set_option, dem_settings_of


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("reports/loads/descent"))
    parser.add_argument("--jobs", type=int, default=2, choices=(1, 2, 3, 4))
    add_dem_set_option(parser)
    args = parser.parse_args()
    dem_settings = dem_settings_of(parser, args)
    start = time.time()
    print(write_descent_report(args.out, args.jobs, dem_settings=dem_settings))
    print(f"{time.time() - start:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
