#!/bin/sh
# Builds the compiled peers of the frontier (issue 39) against the headers and libraries that
# the pip wheels of the peers' venv ship (PEERS_VENV, default ~/.venv-peers): Pinocchio, Eigen
# and Boost (Odeint) from `pin`'s cmeel prefix (header-only use), libmujoco and its headers
# from the `mujoco` wheel. Same flags as ../shared/peers/cpp/build.sh (-O3 -march=native),
# single-threaded code. Binaries go to PEERS_BIN (default target/peers-cpp); PEERS_MARCH=x86-64-v3
# builds binaries valgrind can run (it has no AVX-512), for instruction counts.
set -e
cd "$(dirname "$0")"
SITE=$(echo ${PEERS_VENV:-$HOME/.venv-peers}/lib/python3*/site-packages)
P=$SITE/cmeel.prefix
MJ=$SITE/mujoco
OUT=${PEERS_BIN:-../../../target/peers-cpp}
mkdir -p "$OUT"
g++ -std=c++17 -O3 -march=${PEERS_MARCH:-native} -DNDEBUG -Wno-stringop-overread -DBOOST_MPL_LIMIT_LIST_SIZE=30 -DBOOST_MPL_LIMIT_VECTOR_SIZE=30 \
    -DBOOST_MPL_CFG_NO_PREPROCESSED_HEADERS -DBOOST_FUSION_INVOKE_MAX_ARITY=12 \
    -I"$P/include" -I"$P/include/eigen3" odeint_frontier.cpp -o "$OUT/odeint_frontier"
MJLIB=$(ls "$MJ"/libmujoco.so* | head -1)
gcc -std=c11 -O3 -march=${PEERS_MARCH:-native} -D_POSIX_C_SOURCE=199309L -I"$MJ/include" mujoco_frontier.c "$MJLIB" \
    -Wl,-rpath,"$MJ" -lm -o "$OUT/mujoco_frontier"
echo "built $OUT/odeint_frontier $OUT/mujoco_frontier"
