#!/usr/bin/env bash
# The defaults at their own stopping point against the same run continued to 50 iterations
# (--energy_tolerance=0), on the shared models with a clean mesh: mean exact distance to the
# mesh over its bounding-box diagonal, and the ratio (50 iterations / stop).
# Usage: scripts/convergence_table.sh [LPD_DATA]   (about 2 minutes on 2 cores)
set -euo pipefail
cd "$(dirname "$0")/.."
data=${1:-${LPD_DATA:-../shared/data}}
[ -f "$data/meshes/fandisk.off" ] || { echo "no test data in $data" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mean() { ./build/lpd metrics "$1" --ground_truth="$2" | awk '/^mean_distance/ {print $3}'; }
echo "| input | iterations at stop | distance at stop | distance after 50 | ratio |"
echo "|---|---|---|---|---|"
for name in fandisk_noise_0.01 fandisk_noise_0.03 joint_noise_0.01 joint_noise_0.03; do
  mesh="$data/meshes/${name%_noise*}.off"
  ./build/lpd denoise "$data/noisy/$name.xyz" -o "$tmp/stop.xyz" --quiet >"$tmp/log.txt" 2>/dev/null
  ./build/lpd denoise "$data/noisy/$name.xyz" -o "$tmp/50.xyz" --quiet --energy_tolerance=0 \
    >/dev/null 2>&1
  iterations=$(grep -o 'iterations [0-9]*' "$tmp/log.txt" | awk '{print $2}')
  stop=$(mean "$tmp/stop.xyz" "$mesh")
  fifty=$(mean "$tmp/50.xyz" "$mesh")
  awk -v n="$name" -v it="$iterations" -v a="$stop" -v b="$fifty" \
    'BEGIN { printf "| %s | %s | %.4e | %.4e | %.3f |\n", n, it, a, b, b / a }'
  rm -f "$tmp/stop.xyz" "$tmp/50.xyz"
done
