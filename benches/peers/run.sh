#!/bin/sh
# vectrix's tree algorithms beside Pinocchio C++ in one sitting: for each algorithm (rnea,
# aba, crba, rnea_derivatives, aba_derivatives) and chain length n (1, 6, 12, 30), three
# interleaved rounds of the vectrix driver (VECTRIX_TIME in benches/dynamics.rs) and the C++
# harness (benches/peers/pin_chain.cpp), each printing a JSON line with the median, min and
# max of seven repetitions per call. Builds the harness first if it is missing.
#
#   sh benches/peers/run.sh            # all; about 4 minutes on a quiet machine
#   sh benches/peers/run.sh crba 6     # one algorithm, one n
#
# Run on a quiet machine with RAYON_NUM_THREADS=1; quote medians, and the min on a loaded one.
set -e
cd "$(dirname "$0")/../.."
PIN=${PEERS_BIN:-$HOME/.cache/vectrix_pin_chain}
[ -x "$PIN" ] || sh benches/peers/build.sh
B=$(cargo bench --bench dynamics --no-run 2>&1 | sed -n 's/.*Executable .*(\(.*\)).*/\1/p' | tail -1)
ALGOS=${1:-"rnea aba crba rnea_derivatives aba_derivatives"}
NS=${2:-"1 6 12 30"}
for a in $ALGOS; do
  for n in $NS; do
    case $a in *deriv*) iters=$((200000 / n));; *) iters=$((2000000 / n));; esac
    for r in 1 2 3; do
      VECTRIX_TIME=$a:$n:$iters "$B"
      "$PIN" "$a" 1 "$n" | head -1
    done
  done
done
