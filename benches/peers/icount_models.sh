#!/bin/sh
# Instruction counts per call (valgrind callgrind; repeatable on a loaded machine) of RNEA, ABA,
# CRBA and their derivatives on the imported 3-D trees of examples/models/ (arm7.urdf,
# quadruped.urdf, humanoid.xml): vectrix (benches/models.rs, VECTRIX_ICOUNT_MODEL) against
# Pinocchio C++ (benches/peers/pin_models.cpp) on the models its own parsers make of the same
# files (written out by scripts/pin_model_dump.py with the peers' venv and rebuilt in C++),
# built for the same instruction set as a default Rust release build (x86-64: SSE2; valgrind
# cannot run AVX-512). Each count is (total at 2k calls − total at 1k calls) / 1k.
#
#   sh benches/peers/icount_models.sh                        # everything
#   sh benches/peers/icount_models.sh "rnea aba" "arm7.urdf"
set -e
cd "$(dirname "$0")/../.."
P=$(echo ${PEERS_VENV:-$HOME/.venv-peers}/lib/python3*/site-packages/cmeel.prefix)
PIN=${PEERS_BIN_MODELS:-$HOME/.cache/vectrix_pin_models_x86-64}
if [ ! -x "$PIN" ]; then
  mkdir -p "$(dirname "$PIN")"
  g++ -w -std=c++17 -O3 -march=x86-64 -DNDEBUG -DBOOST_MPL_LIMIT_LIST_SIZE=30 -DBOOST_MPL_LIMIT_VECTOR_SIZE=30 \
    -DBOOST_MPL_CFG_NO_PREPROCESSED_HEADERS -DBOOST_FUSION_INVOKE_MAX_ARITY=12 \
    -I"$P/include" -I"$P/include/eigen3" benches/peers/pin_models.cpp -o "$PIN"
fi
B=$(cargo bench --bench models --no-run 2>&1 | sed -n 's/.*Executable .*(\(.*\)).*/\1/p' | tail -1)
T=${TMPDIR:-/tmp}
total() { grep -E "^(summary|totals):" "$1" | tail -1 | awk '{print $2}'; }
ALGOS=${1:-"rnea aba crba rnea_derivatives aba_derivatives"}
MODELS=${2:-"arm7.urdf quadruped.urdf humanoid.xml"}
for m in $MODELS; do
  ${PEERS_VENV:-$HOME/.venv-peers}/bin/python scripts/pin_model_dump.py "examples/models/$m" "$T/$m.pin.txt"
  for a in $ALGOS; do
    for k in 1000 2000; do
      VECTRIX_ICOUNT_MODEL=$a:$m:$k valgrind --tool=callgrind --callgrind-out-file="$T/vxm.$k.out" "$B" > /dev/null 2>&1
      valgrind --tool=callgrind --callgrind-out-file="$T/pinm.$k.out" "$PIN" "$a" "$T/$m.pin.txt" "$k" > /dev/null 2>&1
    done
    v=$(( ($(total "$T/vxm.2000.out") - $(total "$T/vxm.1000.out")) / 1000 ))
    p=$(( ($(total "$T/pinm.2000.out") - $(total "$T/pinm.1000.out")) / 1000 ))
    echo "$m $a vectrix $v Pinocchio $p ratio $(awk "BEGIN { printf \"%.2f\", $v / $p }")"
  done
done
