#!/usr/bin/env bash
# Set up yadearch on Debian 12: YADE and the scientific stack from Debian (one consistent numpy 1.24),
# then a virtual environment that sees them (--system-site-packages) with yadearch installed editable.
set -euo pipefail
cd "$(dirname "$0")/.."

DEBIAN_PACKAGES=(yade python3-venv python3-pip python3-setuptools python3-numpy python3-pandas
                 python3-matplotlib python3-scipy python3-click python3-tomli-w python3-tqdm
                 python3-dask python3-distributed python3-pytest python3-pytest-xdist python3-numba
                 python3-hypothesis python3-threadpoolctl python3-nbclient python3-ipykernel python3-nbformat
                 python3-multiprocess python3-vtk9 python3-notebook ffmpeg xvfb xauth)

missing=()
for pkg in "${DEBIAN_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
done
if [ ${#missing[@]} -gt 0 ]; then
    echo "setup: installing Debian packages: ${missing[*]}"
    SUDO=""
    [ "$(id -u)" -ne 0 ] && SUDO="sudo"
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
fi

# YADE runs on Debian's /usr/bin/python3 (3.11); the venv is built on it and sees Debian's packages.
if [ ! -x .venv/bin/python ]; then
    /usr/bin/python3 -m venv --system-site-packages .venv
fi
.venv/bin/python -m pip install -q --no-build-isolation --no-deps -e .
# the notebooks' kernel ("python3") is the venv's Python when Jupyter runs from the venv
# (`.venv/bin/python -m notebook examples/`): Debian's own python3 kernel cannot import yadearch
.venv/bin/python -Xfrozen_modules=off -m ipykernel install --prefix .venv --name python3 --display-name "Python 3 (yadearch .venv)" >/dev/null
# SALib (the sensitivity study's Sobol sampling and estimators) is not in Debian: pip, without its
# dependencies, which are all Debian's (numpy, scipy, pandas, matplotlib, multiprocess)
.venv/bin/python -m pip install -q --no-deps "SALib==1.4.7"
# ruff and mypy (the linter, formatter and type checker the tests run) are optional: without them those
# tests skip; pinned, because a new release formats or flags code differently
.venv/bin/python -m pip install -q "ruff==0.17.6" "mypy==2.4.1" 2>/dev/null || echo "setup: ruff or mypy unavailable, their tests will be skipped"
.venv/bin/python - <<'PY'
import numpy, pandas, matplotlib, click, tomli_w, dask, distributed, numba, SALib, vtkmodules  # noqa: F401  the whole stack imports
from yadearch.dem.yade_env import import_yade
import_yade()
import yade.config
from yadearch.solve.statics import compile_kernels
compile_kernels()  # the static engine's numba kernel, compiled once into its cache
from yadearch.solve.descending import compile_kernel
compile_kernel()  # ... and the load path's descending branch's
print(f"setup: ok (numpy {numpy.__version__}, YADE {yade.config.version})")
PY
