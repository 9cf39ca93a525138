#!/usr/bin/env bash
# Opens the 3-D views (view.html) of three example runs in a real headless browser and checks
# them (scripts/browser/check.mjs): the default scene (tennis racket), four_bar and a flight
# scene (business_jet_doublet); then plays a 30-link chain and prints its frame time.
#
#   scripts/browser-tests.sh                # check (about a minute after the build)
#   scripts/browser-tests.sh --screenshots  # also store the default scene's screenshots in docs/view/
#
# Needs: Debian's chromium (installed with apt-get when missing), node and npm (playwright-core,
# pinned in scripts/browser/package-lock.json, is installed into a scratch folder), cargo.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
if ! command -v chromium >/dev/null 2>&1; then
    sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    $sudo apt-get install -y chromium
fi
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cp scripts/browser/package.json scripts/browser/package-lock.json scripts/browser/check.mjs "$scratch/"
(cd "$scratch" && npm ci --silent --no-audit --no-fund)

# the `test` profile (opt-level 1, dependencies too): after `cargo test --workspace` (as in
# .ci/run) this reuses its build instead of compiling a release binary
cargo build --profile test --quiet --bin vectrix
bin="${CARGO_TARGET_DIR:-$root/target}/debug/vectrix"
out="$scratch/out"
"$bin" run --quiet --out "$out" >/dev/null
"$bin" run examples/scenes/four_bar.toml --quiet --out "$out" >/dev/null
"$bin" run examples/scenes/business_jet_doublet.toml --quiet --out "$out" >/dev/null

# a chain of 30 pin-jointed rods (0.1 m, 0.1 kg) released from a slant under gravity
chain="$scratch/chain30.toml"
{
    printf 'name = "chain30"\nduration = 4.0\nsamples = 400\naccuracy = 1e-6\noutputs = ["energy"]\n'
    printf '\n[[effects]]\ntype = "uniform_gravity"\ng = [0.0, -9.81, 0.0]\n'
    parent=ground
    for k in $(seq 1 30); do
        offset="[0.1, 0.0, 0.0]"
        q="0.0"
        [ "$k" -eq 1 ] && { offset="[0.0, 0.0, 0.0]"; q="-0.5"; }
        printf '\n[[bodies]]\nname = "link%d"\nparent = "%s"\njoint = { type = "pin", axis = [0.0, 0.0, 1.0] }\n' "$k" "$parent"
        printf 'offset = %s\nmass = { shape = "rod", mass = 0.1, length = 0.1 }\ncom = [0.05, 0.0, 0.0]\nq = [%s]\n' "$offset" "$q"
        parent="link$k"
    done
} >"$chain"
"$bin" run "$chain" --quiet --out "$out" >/dev/null

shots=""
if [ "${1:-}" = "--screenshots" ]; then
    mkdir -p docs/view
    shots="$root/docs/view"
fi
node "$scratch/check.mjs" "$out" ${shots:+--screenshots "$shots"}
