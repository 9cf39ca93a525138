#!/bin/sh
# The extended-precision reference end states of the frontier's spatial trees (issue 39 item 4),
# written to tests/data/spatial_reference.json (read by examples/frontier and by
# frontier_compiled.py): Pinocchio's ABA in IEEE quadruple precision on the model its own URDF
# parser makes of examples/models/arm7.urdf, integrated by Gragg–Bulirsch–Stoer with fixed macro
# steps (scripts/peers/cpp/spatial_reference.cpp, which says how). Needs the peers' venv
# (PEERS_VENV, default ~/.venv-peers): `pin` for the model dump, its cmeel headers to build.
#
#   sh scripts/peers/spatial_reference.sh          # ~2 min to build, ~1 min to run
#
# The problems (kept in step with examples/frontier/problems.rs ARM7_Q0, QUADRUPED_*, TREE_T),
# τ = 0, g = 9.81 m/s² along −z, t ≤ 1 s: arm7 from rest at q(0) = (0.3, 1.2, −0.5, −0.8, 0.4,
# 0.6, −0.2) rad; the quadruped's trunk at its placement (0.45 m up), level, turning at
# ω = (0.3, 0.5, 1.0) rad/s in its own frame, the legs at rest bent (hip, thigh, calf: fl 0.2, 0.7,
# −1.4; fr −0.2, 0.7, −1.4; hl 0.2, −0.7, 1.4; hr −0.2, −0.7, 1.4 rad), falling freely. End
# states in the common form of scripts/peers/cpp/pin_dump.hpp.
set -e
cd "$(dirname "$0")/../.."
PY=${PEERS_VENV:-$HOME/.venv-peers}/bin/python
P=$(echo ${PEERS_VENV:-$HOME/.venv-peers}/lib/python3*/site-packages/cmeel.prefix)
BIN=${PEERS_BIN:-target/peers-cpp}
mkdir -p "$BIN"
g++ -std=c++17 -O2 -w -fext-numeric-literals -DBOOST_MPL_LIMIT_LIST_SIZE=30 -DBOOST_MPL_LIMIT_VECTOR_SIZE=30 \
    -DBOOST_MPL_CFG_NO_PREPROCESSED_HEADERS -DBOOST_FUSION_INVOKE_MAX_ARITY=12 \
    -I"$P/include" -I"$P/include/eigen3" scripts/peers/cpp/spatial_reference.cpp -o "$BIN/spatial_reference" -lquadmath
T=$(mktemp -d)
"$PY" scripts/pin_model_dump.py examples/models/arm7.urdf "$T/arm7.pin.txt"
ARM7=$("$BIN/spatial_reference" "$T/arm7.pin.txt" 1.0 256 0.3,1.2,-0.5,-0.8,0.4,0.6,-0.2 4)
"$PY" scripts/pin_model_dump.py examples/models/quadruped.urdf "$T/quadruped.pin.txt"
QUADRUPED=$("$BIN/spatial_reference" "$T/quadruped.pin.txt" 1.0 64 \
  0,0,0,0,0,0,1,0.2,0.7,-1.4,-0.2,0.7,-1.4,0.2,-0.7,1.4,-0.2,-0.7,1.4 4 \
  0,0,0,0.3,0.5,1.0,0,0,0,0,0,0,0,0,0,0,0,0)
rm -r "$T"
cat > tests/data/spatial_reference.json <<JSON
{"source": "scripts/peers/spatial_reference.sh (Pinocchio ABA in float128, GBS K = 12 at fixed macro steps)",
 "trees": {"arm7": $ARM7,
           "quadruped": $QUADRUPED}}
JSON
echo "wrote tests/data/spatial_reference.json"
