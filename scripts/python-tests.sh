#!/usr/bin/env bash
# Builds the Python package in a fresh virtual environment and runs its pytest suite
# (python/tests: against scipy, python-control, Pinocchio's stored reference, Dask).
#
#   scripts/python-tests.sh            # needs Rust and Python ≥ 3.11 (python3), and PyPI
#
# The test dependencies are pinned; maturin comes from PyPI as the build backend. The
# extension is compiled into $CARGO_TARGET_DIR (default target/python, kept between runs).
set -euo pipefail
cd "$(dirname "$0")/.."
PY=${PYTHON:-python3}
VENV=$(mktemp -d)
trap 'rm -rf "$VENV"' EXIT
"$PY" -m venv "$VENV"
"$VENV/bin/pip" install -q --upgrade pip
export CARGO_TARGET_DIR=${CARGO_TARGET_DIR:-$PWD/target/python}
# the tests check results, not speed: optimize less than a user's `pip install` (opt-level 3)
# to keep the whole CI within its budget on 2 cores (scripts/python-bench.py is for speed)
export CARGO_PROFILE_RELEASE_OPT_LEVEL=${VECTRIX_PY_OPT_LEVEL:-1}
"$VENV/bin/pip" install -q ./python \
    "numpy==2.4.6" "scipy==1.17.1" "control==0.10.2" "pandas==3.1.1" \
    "dask[distributed]==${DASK_VERSION:-2026.8.0}" "hypothesis==${HYPOTHESIS_VERSION:-6.170.27}" "pytest==${PYTEST_VERSION:-9.2.0}"
"$VENV/bin/python" -c "import vectrix"
# run from outside python/ so that `import vectrix` is the installed package (with its compiled
# extension), not the source folder beside the tests
root=$PWD
cd "$VENV" && "$VENV/bin/python" -m pytest -q -p no:cacheprovider \
    --rootdir "$root/python" "$root/python/tests"
