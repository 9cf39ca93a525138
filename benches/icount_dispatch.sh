#!/bin/sh
# Instruction counts per call (valgrind callgrind; repeatable on a loaded machine) of the f64
# fast paths: the rotation conversions, Hooke's law over many strains and the planar ABA, through
# the VECTRIX_ICOUNT drivers of benches/{rotation,kernel,dynamics}.rs. Each count is
# (total at 2k passes − total at 1k passes) / (1k × inputs per pass), so set-up cancels.
# docs/performance.md "Static dispatch".
#
#   sh benches/icount_dispatch.sh                    # the default build
#   sh benches/icount_dispatch.sh --features fma     # extra cargo arguments for the build
set -e
cd "$(dirname "$0")/.."
T=${TMPDIR:-/tmp}
exe() { b=$1; shift; cargo bench --bench "$b" --no-run "$@" 2>&1 | sed -n 's/.*Executable .*(\(.*\)).*/\1/p' | tail -1; }
total() { grep -E "^(summary|totals):" "$1" | tail -1 | awk '{print $2}'; }
count() { # binary spec k
  VECTRIX_ICOUNT=$2:$3 valgrind --tool=callgrind --callgrind-out-file="$T/icd.$3.out" "$1" > /dev/null 2>&1
  total "$T/icd.$3.out"
}
per() { # binary spec k1 k2 inputs
  a=$(count "$1" "$2" "$3"); b=$(count "$1" "$2" "$4")
  awk "BEGIN { printf \"%.1f\", ($b - $a) / (($4 - $3) * $5) }"
}
R=$(exe rotation "$@"); K=$(exe kernel "$@"); D=$(exe dynamics "$@")
for c in matrix_to_quaternion matrix_to_rotvec axis_angle_to_quaternion rotvec_to_quaternion \
  quaternion_to_rotvec quaternion_to_euler321 euler321_to_quaternion batched_from_rotvec batched_as_euler321; do
  echo "$c $(per "$R" $c 1000 2000 256)"
done
echo "hooke_apply_many (per strain) $(per "$K" hooke_apply_many 100 200 1024)"
for n in 6 30; do echo "aba n=$n (per call) $(per "$D" aba:$n 1000 2000 1)"; done
