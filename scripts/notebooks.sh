#!/usr/bin/env bash
# Re-executes the notebooks in docs/notebooks/ with the real evcxr Jupyter kernel and stores
# their outputs in place, so that a reader sees results and figures without running anything.
# Fails (exit 1) when any cell of any notebook ends in an error.
#
#   scripts/notebooks.sh                          # every notebook
#   scripts/notebooks.sh docs/notebooks/02-*.ipynb  # some
#
# Tools live in a local prefix, never system-wide: $VECTRIX_NOTEBOOK_TOOLS, else ./.notebook-tools
#   <prefix>/bin/evcxr_jupyter   cargo install --root <prefix> evcxr_jupyter   (when missing)
#   <prefix>/venv                python venv with nbconvert and nbclient        (when missing)
#   <prefix>/jupyter             JUPYTER_PATH/JUPYTER_DATA_DIR: the "rust" kernelspec
#   <prefix>/evcxr-work          EVCXR_TMPDIR shared by the notebooks run one after another, so
#                                that the second notebook reuses the first one's build of vectrix
#   <prefix>/evcxr-config        EVCXR_CONFIG_DIR (empty: no personal init.evcxr leaks in)
# The notebooks run one at a time (they share evcxr-work). Timings per notebook are printed.
set -euo pipefail
cd "$(dirname "$0")/.."
root="$PWD"

prefix="${VECTRIX_NOTEBOOK_TOOLS:-$root/.notebook-tools}"
mkdir -p "$prefix"
prefix="$(cd "$prefix" && pwd)"
evcxr_version="0.22.0"

# 1. The kernel.
if ! [ -x "$prefix/bin/evcxr_jupyter" ]; then
    echo "installing evcxr_jupyter $evcxr_version into $prefix (takes a while: it builds rust-analyzer parts)"
    CARGO_BUILD_BUILD_DIR="$prefix/build" cargo install evcxr_jupyter --version "$evcxr_version" --locked --root "$prefix"
fi

# 2. nbconvert and nbclient.
venv="$prefix/venv"
if ! [ -x "$venv/bin/jupyter-nbconvert" ]; then
    echo "creating a python venv with nbconvert and nbclient in $venv"
    python3 -m venv "$venv"
    "$venv/bin/pip" install --quiet nbconvert nbclient ipykernel
fi

# 3. The kernelspec, in the prefix (evcxr_jupyter --install writes under $JUPYTER_PATH).
export JUPYTER_PATH="$prefix/jupyter"
export JUPYTER_DATA_DIR="$prefix/jupyter"
export JUPYTER_CONFIG_DIR="$prefix/jupyter-config"
export JUPYTER_RUNTIME_DIR="$prefix/jupyter-runtime"
mkdir -p "$JUPYTER_CONFIG_DIR" "$JUPYTER_RUNTIME_DIR"
if ! [ -f "$JUPYTER_PATH/kernels/rust/kernel.json" ]; then
    "$prefix/bin/evcxr_jupyter" --install >/dev/null
fi

# 4. evcxr's working directory, shared by the notebooks run one after another.
export EVCXR_TMPDIR="$prefix/evcxr-work"
export EVCXR_CONFIG_DIR="$prefix/evcxr-config"
mkdir -p "$EVCXR_TMPDIR" "$EVCXR_CONFIG_DIR"

if [ "$#" -gt 0 ]; then
    notebooks=("$@")
else
    notebooks=(docs/notebooks/[0-9][0-9]-*.ipynb)
fi

failed=0
for nb in "${notebooks[@]}"; do
    start=$(date +%s)
    # nbconvert stops at the first error cell (and exits non-zero); --inplace keeps the file's
    # outputs only when the whole notebook ran.
    if "$venv/bin/jupyter-nbconvert" --to notebook --execute --inplace \
        --ExecutePreprocessor.kernel_name=rust \
        --ExecutePreprocessor.timeout=1800 \
        --ExecutePreprocessor.startup_timeout=120 \
        "$nb" >"$prefix/last.log" 2>&1; then
        echo "ok      $nb ($(($(date +%s) - start)) s)"
    else
        echo "FAILED  $nb ($(($(date +%s) - start)) s)"
        tail -n 40 "$prefix/last.log"
        failed=1
    fi
done

# A stored error output anywhere is a failure too (e.g. a notebook executed by hand).
if "$venv/bin/python" - "${notebooks[@]}" <<'EOF'; then :; else failed=1; fi
import json, sys
bad = 0
for path in sys.argv[1:]:
    for i, cell in enumerate(json.load(open(path))["cells"]):
        for out in cell.get("outputs", []):
            if out.get("output_type") == "error":
                print(f"error output in {path}, cell {i}: {out.get('ename')}: {out.get('evalue')}")
                bad = 1
sys.exit(bad)
EOF

exit "$failed"
