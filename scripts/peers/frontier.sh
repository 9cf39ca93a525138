#!/bin/sh
# The work–precision frontier against every peer (issue 24), in one command:
#
#   sh scripts/peers/frontier.sh            # everything (~1 h on 2 cores)
#   sh scripts/peers/frontier.sh --quick    # a smoke run of the vectrix side only
#
# vectrix is built for the x86-64 baseline (what `cargo build` gives a user);
# FRONTIER_CPU=native builds it with -C target-cpu=native, as the compiled peers are built.
#
# A partial sitting: FRONTIER_ONLY=kepler-e0.9,chain-30 restricts every tool to those problems
# and FRONTIER_TOOLS="compiled scipy pinocchio" to those peers; it needs its own FRONTIER_RESULTS folder
# (a peer's file is rewritten with the problems it ran) and prints its table instead of writing
# the docs' figures and table.
#
# The references are committed data, written once by closed_form_reference_mp.py,
# chain_reference_mp.py and spatial_reference.sh (the arm and the quadruped, Pinocchio in
# quadruple precision); they are not rerun here.
#
# vectrix first (it also writes the problems' references), then the compiled peers right after
# it (issue 39: Pinocchio's C++ ABA and hand-written C++ right-hand sides inside Boost.Odeint,
# MuJoCo through its C API; built by cpp/build.sh from the wheels' headers, run by
# frontier_compiled.py), then the Python-driven peers one after the other, every tool
# single-threaded; then the cross-check of the reference, the figures
# docs/accuracy/peers-*.svg and the tables in docs/frontier.md. Points go to
# docs/accuracy/peers-data/*.json (override with FRONTIER_RESULTS). Needs the venv of
# ../shared/peers/README.md (PEERS_VENV, default ~/.venv-peers).
set -e
cd "$(dirname "$0")/../.."
export RAYON_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 MKL_NUM_THREADS=1
DATA=${FRONTIER_RESULTS:-docs/accuracy/peers-data}
export FRONTIER_RESULTS="$(pwd)/$DATA"
PY=${PEERS_VENV:-$HOME/.venv-peers}/bin/python
echo "machine: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc --all) CPUs; $(date -u +%Y-%m-%dT%H:%M:%SZ); load: $(uptime | sed 's/.*load average: //')"
# vectrix is built for the x86-64 baseline by default (the workspace's default, what a user's
# `cargo build` gives); FRONTIER_CPU=native builds it with -C target-cpu=native as the compiled
# peers are (-O3 -march=native), into its own target folder so that the main build's cache is
# left alone. Measured 2026-12-05 (docs/performance.md, Work-precision): native is 5-7 % faster on
# the chains and 1.4-1.6x slower with DOP853 on Kepler and the rigid body. The choice is made at
# compile time: whether kernels fuse multiply-add follows it (vectrix-simd's FUSED), so each
# build's errors are its own and are measured with it.
case "${FRONTIER_CPU:-baseline}" in
  native) FRONTIER_TARGET=${CARGO_TARGET_DIR:-target}/frontier-native; FRONTIER_RUSTFLAGS="-C target-cpu=native" ;;
  baseline) FRONTIER_TARGET=${CARGO_TARGET_DIR:-target}; FRONTIER_RUSTFLAGS="" ;;
  *) echo "FRONTIER_CPU must be baseline or native, not '$FRONTIER_CPU'" >&2; exit 2 ;;
esac
echo "vectrix built with RUSTFLAGS='$FRONTIER_RUSTFLAGS' (FRONTIER_CPU=${FRONTIER_CPU:-baseline})"
RUSTFLAGS="$FRONTIER_RUSTFLAGS" CARGO_TARGET_DIR="$FRONTIER_TARGET" cargo build --release --example frontier
FRONTIER=$FRONTIER_TARGET/release/examples/frontier
if [ "$1" = "--quick" ]; then
  "$FRONTIER" run --quick --out "$DATA"
  exit 0
fi
# the compiled peers are built before any timing starts
case " ${FRONTIER_TOOLS:-compiled} " in *" compiled "*) sh scripts/peers/cpp/build.sh ;; esac
if [ -n "$FRONTIER_ONLY" ]; then
  if [ "$DATA" = "docs/accuracy/peers-data" ]; then
    echo "FRONTIER_ONLY needs its own FRONTIER_RESULTS folder (the docs' data holds every problem)" >&2
    exit 2
  fi
  "$FRONTIER" run --out "$DATA" --only "$FRONTIER_ONLY"
else
  "$FRONTIER" run --out "$DATA"
fi
cd scripts/peers
for tool in ${FRONTIER_TOOLS:-compiled mujoco scipy pinocchio sympy}; do
  echo "== $tool (load: $(cut -d' ' -f1-3 /proc/loadavg))"
  $PY frontier_$tool.py
done
$PY check_reference.py
cd ../..
if [ -n "$FRONTIER_ONLY" ]; then
  mkdir -p "$DATA/svg"
  "$FRONTIER" plot --data "$DATA" --svg "$DATA/svg"
else
  "$FRONTIER" plot --data "$DATA" --svg docs/accuracy --doc docs/frontier.md
fi
echo "done: $(date -u +%Y-%m-%dT%H:%M:%SZ); load: $(uptime | sed 's/.*load average: //')"
