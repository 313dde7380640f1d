"""Cross-check finished runs against the rigid-block limit analysis of the same case: du and the
collapse hinges of each run beside du_rigid and the rigid mechanism, as a Markdown table
(`studies.limit_check`).

    .venv/bin/python scripts/limit_check.py reports/movements/* --out reports/movements/limit_check.md

A stiff-joint run should approach the rigid limit that counts what the run counts as collapse (a hinge
snap that moves a block further than the run's `runaway_mm`), its mechanism at the last equilibrium
being the rigid one at its limit within one interface a hinge (docs/validation.md); the limit that
survives every snap is shown beside it, and so is the compliant-hinge limit at the run's kn: what the
DEM should find at that stiffness. Exit code 1 if a run differs from its limit by more than
--tolerance (default 5 %) or a hinge by more than one interface.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from yadearch.atomic import write_text_atomically
from yadearch.studies.limit_check import limit_check_table


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("runs", nargs="+", type=Path, help="finished run folders")
    parser.add_argument("--tolerance", type=float, default=0.05, help="largest |du / du_rigid - 1|")
    parser.add_argument("--out", type=Path, help="also write the table to this Markdown file")
    args = parser.parse_args()
    text, passed = limit_check_table(args.runs, args.tolerance)
    print(text, end="")
    if args.out:
        write_text_atomically(args.out, text)
    return 0 if passed else 1


if __name__ == "__main__":
    sys.exit(main())
