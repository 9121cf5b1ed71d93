#!/usr/bin/env bash
# Times lpd end to end (read, k-NN, optimize, project, write) against the public reference
# implementation's figures measured on a 2-core machine with 2 threads and its schedule
# (5 outer iterations of 1 local step and 5 global passes) and the paper preset, and a
# 1M-point procedural run at k = 20 (5 outer x 2 inner). Prints wall seconds, peak memory
# and the mean distance to the clean FANDISK mesh. A second table times the same
# ACCESSORY and 1M-point inputs at lpd's defaults (run to convergence, k from the data).
# Usage: scripts/reference_timings.sh [LPD_DATA]   (about 5 minutes on 2 cores)
set -euo pipefail
cd "$(dirname "$0")/.."
data=${1:-${LPD_DATA:-../shared/data}}
[ -f "$data/noisy/fandisk_noise_0.01.xyz" ] || { echo "no test data in $data" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "| input | n | k | lambda | schedule | lpd s | reference s | speed-up | lpd MB | reference MB | memory ratio | mean distance / diagonal |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
# run NAME INPUT N K LAMBDA INNER REFERENCE_SECONDS REFERENCE_MB
run() {
  local out="$tmp/$1_k$4.xyz"
  /usr/bin/time -f "%e %M" -o "$tmp/time.txt" ./build/lpd denoise "$2" -o "$out" \
    --preset=paper --k="$4" \
    --lambda="$5" --max_iters=5 --inner_iters="$6" --energy_tolerance=0 --quiet >/dev/null 2>"$tmp/log.txt"
  read -r seconds kilobytes <"$tmp/time.txt"
  local distance="-"
  if [[ $1 == fandisk* ]]; then
    distance=$(./build/lpd metrics "$out" --ground_truth="$data/meshes/fandisk.off" |
               awk '/^mean_distance/ {print $3}')
  fi
  awk -v name="$1" -v n="$3" -v k="$4" -v lambda="$5" -v inner="$6" -v s="$seconds" \
      -v kb="$kilobytes" -v rs="$7" -v rmb="$8" -v d="$distance" 'BEGIN {
    mb = kb / 1024
    speedup = rs == "-" ? "-" : sprintf("%.1fx", rs / s)
    ratio = rmb == "-" ? "-" : sprintf("%.2f", mb / rmb)
    printf "| %s | %d | %d | %s | 5 x %d | %.2f | %s | %s | %.0f | %s | %s | %s |\n",
           name, n, k, lambda, inner, s, rs, speedup, mb, rmb, ratio, d
  }'
}
run fandisk_noise_0.01 "$data/noisy/fandisk_noise_0.01.xyz" 25894 20 1 5 3.8 145
run fandisk_noise_0.01 "$data/noisy/fandisk_noise_0.01.xyz" 25894 50 1 5 7.3 295
run accessory_noise_0.01 "$data/noisy/accessory_noise_0.01.xyz" 50000 150 2 5 42.8 1290
./build/lpd noise --shape=cad_part --points=1000000 --sigma=0.005 -o "$tmp/cad_part_1m.xyz" \
  >/dev/null
run cad_part_1m "$tmp/cad_part_1m.xyz" 1000000 20 1 2 - -

echo
echo "| input (defaults) | k chosen | iterations | lpd s | lpd MB | mean distance / diagonal |"
echo "|---|---|---|---|---|---|"
# run_default NAME INPUT GROUND_TRUTH
run_default() {
  local out="$tmp/$1_default.xyz"
  /usr/bin/time -f "%e %M" -o "$tmp/time.txt" ./build/lpd denoise "$2" -o "$out" --quiet \
    >"$tmp/stdout.txt" 2>/dev/null
  read -r seconds kilobytes <"$tmp/time.txt"
  local distance="-"
  [ -n "$3" ] && distance=$(./build/lpd metrics "$out" --ground_truth="$3" |
                            awk '/^mean_distance/ {print $3}')
  local k iterations
  k=$(awk '/^k / {print $2}' "$tmp/stdout.txt")
  iterations=$(grep -o 'iterations [0-9]*' "$tmp/stdout.txt" | awk '{print $2}')
  awk -v name="$1" -v k="$k" -v it="$iterations" -v s="$seconds" -v kb="$kilobytes" \
      -v d="$distance" 'BEGIN {
      printf "| %s | %s | %s | %.2f | %.0f | %s |\n", name, k, it, s, kb / 1024, d
    }'
}
run_default accessory_noise_0.01 "$data/noisy/accessory_noise_0.01.xyz" ""
run_default cad_part_1m "$tmp/cad_part_1m.xyz" shape:cad_part
