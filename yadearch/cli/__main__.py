"""`python -m yadearch.cli` runs the command line."""

import sys

from yadearch.cli.commands import main

sys.exit(main())
