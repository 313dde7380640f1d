"""The fill's passive resistance in the three solvers (reports/loads/passive; docs/loads.md).

    .venv/bin/python scripts/loads_passive.py [--out reports/loads/passive] [--jobs 2]
        [--dem-set numerics.KEY=VALUE ...]

Runs each case's load on the rigid LP, the static engine and the DEM (in child processes, --jobs at a time;
those whose files OUT/runs holds already are read back), the mobilisation sweep and the settling arch, and
writes passive.md, capacities.csv, dem_numerics.csv, mobilisation.csv, settlement.csv,
settlement_numerics.csv (the settling arch with each engine's numerics halved and doubled), grid.csv,
arches_numerics.csv (other arches under the fill, the static engine's numerics halved and doubled) and
passive.pdf/.png.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from yadearch.reporting.loads_passive import write_passive_report
from yadearch.studies.dem_settings import add_dem_set_option, dem_settings_of


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("reports/loads/passive"))
    parser.add_argument("--jobs", type=int, default=2, choices=(1, 2, 3, 4))
    add_dem_set_option(parser)
    args = parser.parse_args()
    dem_settings = dem_settings_of(parser, args)
    start = time.time()
    print(write_passive_report(args.out, args.jobs, dem_settings=dem_settings))
    print(f"{time.time() - start:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
