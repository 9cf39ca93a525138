#!/bin/sh
# Build the Pinocchio C++ timing harness (benches/peers/pin_chain.cpp) against the headers
# shipped in the `pin` wheel (venv at ${PEERS_VENV:-$HOME/.venv-peers}; see
# ../shared/peers/README.md for the venv). Header-only; about 3 minutes.
# Output: ${PEERS_BIN:-$HOME/.cache/vectrix_pin_chain}. PIN_MARCH (default native) selects
# the instruction set: valgrind cannot run AVX-512, so instruction counts use a second build
# with PIN_MARCH=x86-64 (SSE2, the same baseline as a default Rust release build).
set -e
cd "$(dirname "$0")"
P=${PEERS_VENV:-$HOME/.venv-peers}/lib/python3.11/site-packages/cmeel.prefix
OUT=${PEERS_BIN:-$HOME/.cache/vectrix_pin_chain}; mkdir -p "$(dirname "$OUT")"
g++ -w -std=c++17 -O3 -march=${PIN_MARCH:-native} -DNDEBUG -DBOOST_MPL_LIMIT_LIST_SIZE=30 -DBOOST_MPL_LIMIT_VECTOR_SIZE=30 \
    -DBOOST_MPL_CFG_NO_PREPROCESSED_HEADERS -DBOOST_FUSION_INVOKE_MAX_ARITY=12 \
    -I$P/include -I$P/include/eigen3 pin_chain.cpp -o "$OUT"
echo "built $OUT"
