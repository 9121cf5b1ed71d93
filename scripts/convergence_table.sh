#!/usr/bin/env bash
# The defaults at their own stopping point against the same run continued to 50 and to 100
# iterations (the stopping tests off), on the shared models with a clean mesh and on two
# low-noise mesh samples (k at its floor of 12, where the progress test stops the run): mean
# exact distance to the mesh over its bounding-box diagonal, and the ratios to the stop.
# Usage: scripts/convergence_table.sh [LPD_DATA]   (about 4 minutes on 2 cores)
set -euo pipefail
cd "$(dirname "$0")/.."
data=${1:-${LPD_DATA:-../shared/data}}
[ -f "$data/meshes/fandisk.off" ] || { echo "no test data in $data" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mean() { ./build/lpd metrics "$1" --ground_truth="$2" | awk '/^mean_distance/ {print $3}'; }
./build/lpd noise --mesh="$data/meshes/fandisk.off" --points=25000 --sigma=0.0012 \
  -o "$tmp/fandisk_mesh_0.0012.ply" >/dev/null
./build/lpd noise --mesh="$data/meshes/bunny.off" --points=30000 --sigma=0.0008 \
  -o "$tmp/bunny_mesh_0.0008.ply" >/dev/null
echo "| input | iterations at stop | distance at stop | after 50 | after 100 | ratios |"
echo "|---|---|---|---|---|---|"
for input in "$data"/noisy/{fandisk,joint}_noise_0.0{1,3}.xyz "$tmp"/*_mesh_*.ply; do
  name=$(basename "${input%.*}")
  mesh="$data/meshes/${name%%_*}.off"
  ./build/lpd denoise "$input" -o "$tmp/stop.xyz" --quiet >"$tmp/log.txt" 2>/dev/null
  iterations=$(grep -o 'iterations [0-9]*' "$tmp/log.txt" | awk '{print $2}')
  row=("$(mean "$tmp/stop.xyz" "$mesh")")
  for n in 50 100; do
    ./build/lpd denoise "$input" -o "$tmp/$n.xyz" --quiet --energy_tolerance=0 \
      --progress_tolerance=0 --motion_tolerance=0 --max_iters="$n" >/dev/null 2>&1
    row+=("$(mean "$tmp/$n.xyz" "$mesh")")
  done
  awk -v n="$name" -v it="$iterations" -v a="${row[0]}" -v b="${row[1]}" -v c="${row[2]}" \
    'BEGIN { printf "| %s | %s | %.4e | %.4e | %.4e | %.3f / %.3f |\n", n, it, a, b, c, b / a, c / a }'
  rm -f "$tmp"/{stop,50,100}.xyz
done
