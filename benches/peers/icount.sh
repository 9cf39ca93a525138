#!/bin/sh
# Instruction counts per call (valgrind callgrind), repeatable on a loaded machine, for
# vectrix (benches/dynamics.rs driver VECTRIX_ICOUNT) and Pinocchio C++ built for the same
# instruction set as a default Rust release build (PIN_MARCH=x86-64: SSE2; valgrind cannot
# run AVX-512). Each count is (total at 2k calls − total at 1k calls) / 1k, so set-up cancels.
#
#   sh benches/peers/icount.sh                  # all algorithms, n = 6 and 30
#   sh benches/peers/icount.sh "crba rnea" "6"
set -e
cd "$(dirname "$0")/../.."
PIN=${PEERS_BIN_X86_64:-$HOME/.cache/vectrix_pin_chain_x86-64}
[ -x "$PIN" ] || PIN_MARCH=x86-64 PEERS_BIN="$PIN" sh benches/peers/build.sh
B=$(cargo bench --bench dynamics --no-run 2>&1 | sed -n 's/.*Executable .*(\(.*\)).*/\1/p' | tail -1)
T=${TMPDIR:-/tmp}
total() { grep -E "^(summary|totals):" "$1" | tail -1 | awk '{print $2}'; }
ALGOS=${1:-"rnea aba crba rnea_derivatives aba_derivatives"}
NS=${2:-"6 30"}
for a in $ALGOS; do
  for n in $NS; do
    for k in 1000 2000; do
      VECTRIX_ICOUNT=$a:$n:$k valgrind --tool=callgrind --callgrind-out-file="$T/vx.$k.out" "$B" > /dev/null 2>&1
      case $a in *deriv*) base=200000;; *) base=2000000;; esac
      # the harness runs scale × base / n calls: choose the scale for exactly k calls
      scale=$(awk "BEGIN { printf \"%.12g\", ($k + 0.5) * $n / $base }")
      valgrind --tool=callgrind --callgrind-out-file="$T/pin.$k.out" "$PIN" "$a" "$scale" "$n" > /dev/null 2>&1
    done
    v=$(( ($(total "$T/vx.2000.out") - $(total "$T/vx.1000.out")) / 1000 ))
    p=$(( ($(total "$T/pin.2000.out") - $(total "$T/pin.1000.out")) / 1000 ))
    echo "$a n=$n vectrix $v Pinocchio $p ratio $(awk "BEGIN { printf \"%.2f\", $v / $p }")"
  done
done
