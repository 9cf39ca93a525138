#!/usr/bin/env bash
# Developer loop: build the extension with cargo into $CARGO_TARGET_DIR and copy it next to the
# Python sources, so that `PYTHONPATH=python` imports it without a wheel.
set -euo pipefail
cd "$(dirname "$0")"
cargo build --release
cp "${CARGO_TARGET_DIR:-target}/release/lib_vectrix.so" vectrix/_vectrix.abi3.so
