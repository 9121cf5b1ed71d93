#!/usr/bin/env bash
# Prints a Table 3 style scaling table: seconds per outer iteration of the local step
# (Eqs. 10 + 6) and the global step (Eqs. 9 + 7 + 8), microseconds per point, median CG
# iterations per outer iteration and peak memory, for n = 25K..1M points of a noisy
# procedural CAD part (sigma 0.5% of the diagonal) and k = 20, 50, 100. Every cell is one
# `lpd bench` run (3 outer x 2 inner iterations) on all cores.
# Usage: scripts/scaling_table.sh [N...]   (default 25000 50000 100000 200000 1000000;
#        about 2 minutes on 2 cores, 7 GB peak at 1M points and k = 100)
set -euo pipefail
cd "$(dirname "$0")/.."
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(25000 50000 100000 200000 1000000)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "| n | k | local s/iter | global s/iter | global us/point | CG iterations | peak MB | bytes/point |"
echo "|---|---|---|---|---|---|---|---|"
for n in "${sizes[@]}"; do
  input="$tmp/cad_part_$n.xyz"
  ./build/lpd noise --shape=cad_part --points="$n" --sigma=0.005 -o "$input" >/dev/null
  for k in 20 50 100; do
    ./build/lpd bench "$input" --k="$k" --max_iters=3 --energy_tolerance=0 >"$tmp/bench.txt"
    median_cg=$(awk '/^ +[0-9]+ +[0-9.]+ +[0-9.]+ +[0-9.]+ +[0-9]+$/ {print $5}' "$tmp/bench.txt" |
                sort -n | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}')
    awk -v n="$n" -v k="$k" -v cg="$median_cg" '
      /^median per iteration/ { local_s = $5; global_s = $8 }
      /^end to end/ { peak = $9; per_point = substr($11, 2) }
      END {
        printf "| %d | %d | %.3f | %.3f | %.2f | %d | %.0f | %d |\n", n, k, local_s, global_s,
               1e6 * global_s / n, cg, peak, per_point
      }' "$tmp/bench.txt"
  done
done
