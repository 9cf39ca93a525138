#!/bin/sh
# The stiff work–precision sitting (issue 34 item 4), in one command, every tool back to back on
# the same machine, single-threaded:
#
#   sh scripts/peers/stiff.sh        # ~10 min on 2 cores
#
# vectrix (RADAU5, BDF, DOP853: crates/ode/examples/stiff_work), then scipy's Radau/BDF/LSODA
# (stiff_scipy.py), MuJoCo's implicitfast/RK4 on the mechanisms (stiff_mujoco.py) and diffsol's
# BDF/ESDIRK34/TR-BDF2 on Robertson and Van der Pol (diffsol_stiff/, built in a scratch crate
# outside the repository: DIFFSOL_SCRATCH, default ../scratch-diffsol next to the checkout).
# Every build happens before the first timing. Points go to docs/accuracy/stiff-data/<tool>.json
# (override with STIFF_RESULTS: then figures go to that folder's svg/ and the docs are left
# alone); then the figures docs/accuracy/stiff-*.svg and the tables between the STIFF-TABLES
# markers of docs/accuracy.md (stiff_report.py). Needs the venv of ../shared/peers/README.md
# (PEERS_VENV, default ~/.venv-peers).
set -e
cd "$(dirname "$0")/../.."
export RAYON_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 MKL_NUM_THREADS=1
REPO=$(pwd)
DATA=${STIFF_RESULTS:-docs/accuracy/stiff-data}
export STIFF_RESULTS="$REPO/$DATA"
case "$DATA" in /*) export STIFF_RESULTS="$DATA" ;; esac
PY=${PEERS_VENV:-$HOME/.venv-peers}/bin/python
TARGET=${CARGO_TARGET_DIR:-$REPO/target}
SCRATCH=${DIFFSOL_SCRATCH:-$REPO/../scratch-diffsol}
stamp() { echo "$(date -u +%Y-%m-%dT%H:%M:%SZ); $(cut -d' ' -f1-3 /proc/loadavg)"; }

# builds first
cargo build --release -p vectrix-ode --example stiff_work
mkdir -p "$SCRATCH/src"
sed "s#REPO#$REPO#g" scripts/peers/diffsol_stiff/Cargo.toml.txt > "$SCRATCH/Cargo.toml"
sed "s#REPO#$REPO#g" scripts/peers/diffsol_stiff/main.rs > "$SCRATCH/src/main.rs"
(cd "$SCRATCH" && CARGO_TARGET_DIR="$TARGET/diffsol" cargo build --release)
RAW=$(mktemp -d)

echo "sitting start: $(date -u)"
uptime
mkdir -p "$STIFF_RESULTS"
S=$(stamp); "$TARGET/release/examples/stiff_work" run > "$RAW/vectrix.jsonl"; E=$(stamp)
$PY scripts/peers/stiff_report.py collect vectrix "$RAW/vectrix.jsonl" "$S" "$E"
cd scripts/peers
S=$(stamp); $PY stiff_scipy.py > "$RAW/scipy.jsonl"; E=$(stamp)
$PY stiff_report.py collect scipy "$RAW/scipy.jsonl" "$S" "$E"
S=$(stamp); $PY stiff_mujoco.py > "$RAW/mujoco.jsonl"; E=$(stamp)
$PY stiff_report.py collect mujoco "$RAW/mujoco.jsonl" "$S" "$E"
cd "$REPO"
S=$(stamp); "$TARGET/diffsol/release/scratch_diffsol" > "$RAW/diffsol.jsonl"; E=$(stamp)
$PY scripts/peers/stiff_report.py collect diffsol "$RAW/diffsol.jsonl" "$S" "$E"
echo "sitting end: $(date -u)"
uptime

if [ "$DATA" != "docs/accuracy/stiff-data" ]; then
  mkdir -p "$STIFF_RESULTS/svg"
  "$TARGET/release/examples/stiff_work" plot --data "$STIFF_RESULTS" --svg "$STIFF_RESULTS/svg"
  $PY scripts/peers/stiff_report.py targets
else
  "$TARGET/release/examples/stiff_work" plot --data "$STIFF_RESULTS" --svg docs/accuracy
  $PY scripts/peers/stiff_report.py targets --doc docs/accuracy.md
fi
rm -r "$RAW"
