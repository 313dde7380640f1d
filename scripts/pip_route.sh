#!/usr/bin/env bash
# The route without YADE (docs/install.md): a venv of PyPI's newest numpy, scipy, numba, pandas and
# matplotlib, without Debian's packages, then the tests there (YADE's skip: it cannot load beside numpy 2).
set -euo pipefail
cd "$(dirname "$0")/.."
PYTHON="${PYTHON:-python3}"
export NUMBA_CACHE_DIR="$PWD/.venv-pip/numba-cache"  # its numba compiles apart from the Debian route's cache
if [ ! -x .venv-pip/bin/python ]; then
    "$PYTHON" -m venv .venv-pip
fi
.venv-pip/bin/python -m pip install -q ".[test]"
.venv-pip/bin/python -c "import numpy, pandas, numba, scipy; print(f'pip route: numpy {numpy.__version__}, pandas {pandas.__version__}, numba {numba.__version__}, scipy {scipy.__version__}')"
.venv-pip/bin/python -m pytest -q -p no:cacheprovider -n auto --dist loadfile --deselect tests/test_lint.py "$@"
