"""The DEM against the static engine on live loads (reports/loads/engines; docs/loads.md).

    .venv/bin/python scripts/loads_engines.py [--out reports/loads/engines] [--jobs 2]
        [--dem-set numerics.KEY=VALUE ...]

Runs every case's load path on both engines (the DEM in child processes, --jobs at a time; those whose
files OUT/load_paths holds already are read back) and writes engines.md, engines.csv, numerics.csv,
influence.csv, held.csv and engines.pdf/.png; about 15 minutes of YADE on two cores from scratch
(850 s on an AMD EPYC).
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from yadearch.reporting.loads_engines import write_engines_report
from yadearch.studies.dem_settings import add_dem_set_option, dem_settings_of


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("reports/loads/engines"))
    parser.add_argument("--jobs", type=int, default=2, choices=(1, 2, 3, 4))
    add_dem_set_option(parser)
    args = parser.parse_args()
    dem_settings = dem_settings_of(parser, args)
    start = time.time()
    print(write_engines_report(args.out, args.jobs, dem_settings=dem_settings))
    print(f"{time.time() - start:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
