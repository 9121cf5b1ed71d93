#!/usr/bin/env bash
# Regenerates the FANDISK comparison with the public reference implementation: mean exact
# distance from the output points to the clean mesh over its bounding-box diagonal, for
# k = 20 and 50, with the paper preset's schedule (5 outer x 2 inner) and the reference's
# (5 outer x 5 inner). Usage: scripts/fandisk_reference_table.sh [LPD_DATA]   (~1 min)
set -euo pipefail
cd "$(dirname "$0")/.."
data=${1:-${LPD_DATA:-../shared/data}}
[ -f "$data/meshes/fandisk.off" ] || { echo "no FANDISK data in $data" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mean() { ./build/lpd metrics "$1" --ground_truth="$data/meshes/fandisk.off" | awk '/^mean_distance/ {print $3}'; }
echo "| noise | input | k | schedule (outer x inner) | output | reference (k=50, 5x5) | time |"
echo "|---|---|---|---|---|---|---|"
for noise in 0.01 0.03; do
  input="$data/noisy/fandisk_noise_$noise.xyz"
  reference=$([ "$noise" = 0.01 ] && echo 1.39e-3 || echo 2.16e-3)
  for k in 20 50; do
    for inner in 2 5; do
      out="$tmp/out_${noise}_${k}_${inner}.xyz"
      seconds=$( { /usr/bin/time -f %e ./build/lpd denoise "$input" -o "$out" --preset=paper \
                   --k="$k" --inner_iters="$inner" --energy_tolerance=0 --quiet >/dev/null; } 2>&1 | tail -1)
      echo "| $noise | $(mean "$input") | $k | 5 x $inner | $(mean "$out") | $reference | ${seconds} s |"
    done
  done
done
