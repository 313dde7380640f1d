"""The live-load validation (reports/loads): the rigid-block load multiplier against the mechanism
method on small arches, then the paper's arch and semicircles (docs/loads.md).

    .venv/bin/python scripts/loads_validation.py [--out reports/loads]

Writes loads.md, the tables (mechanism_check.csv, influence_line.csv, semicircle_acceleration.csv,
semicircle_friction.csv, published_point_load.csv, residual_capacity.csv, ...) and loads.pdf/.png;
about a minute and a half, no YADE.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from yadearch.reporting.loads import write_loads_report


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("reports/loads"))
    args = parser.parse_args()
    start = time.time()
    print(write_loads_report(args.out))
    print(f"{time.time() - start:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
