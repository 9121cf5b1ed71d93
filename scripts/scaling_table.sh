#!/usr/bin/env bash
# Prints a Table 3 style scaling table: seconds per outer iteration of the local step
# (Eqs. 10 + 6) and the global step (Eqs. 9 + 7 + 8), microseconds per point, median CG
# iterations per outer iteration and peak memory, for n = 25K..1M points of a noisy
# procedural CAD part (sigma 0.5% of the diagonal) and k = 20, 50, 100. Every cell is the
# median over the outer iterations of `lpd bench` runs (3 outer x 2 inner iterations, all
# cores): one run at 1M points, three below 500K.
# Usage: scripts/scaling_table.sh [N...]   (default 25000 50000 100000 200000 1000000;
#        about 3 minutes on 2 cores, 7 GB peak at 1M points and k = 100)
# The balance column is the median ratio of the smoothness to the stitching share of K's
# diagonal (energy/term_balance.h), which decides how hard the T system is; at eta = 5000 it
# grows with n. With FIXED_BALANCE=1, eta is set for every n and k so that the balance stays
# what eta = 5000 gives at the first n (it goes like 1 / eta; a one-iteration bench run
# measures it at eta = 5000 first): the T system then keeps one conditioning at every n
# (docs/performance.md says why this isolates the solver).
set -euo pipefail
cd "$(dirname "$0")/.."
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(25000 50000 100000 200000 1000000)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# Column c of the per-iteration rows of bench.txt (iteration, local s, global s, whole s, CG
# iterations), median over every outer iteration of every run.
median_of_column() {
  awk -v c="$1" '/^ +[0-9]+ +[0-9.]+ +[0-9.]+ +[0-9.]+ +[0-9]+$/ {print $c}' "$tmp/bench.txt" |
    sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'
}
echo "| n | k | eta | balance | local s/iter | global s/iter | global us/point | CG iterations | peak MB | bytes/point |"
echo "|---|---|---|---|---|---|---|---|---|---|"
declare -A target  # FIXED_BALANCE: the balance to keep, per k
for n in "${sizes[@]}"; do
  input="$tmp/cad_part_$n.xyz"
  ./build/lpd noise --shape=cad_part --points="$n" --sigma=0.005 -o "$input" >/dev/null
  # Runs below 500K points take well under a second and vary more from run to run: 3 runs.
  repeats=1
  [ "$n" -lt 500000 ] && repeats=3
  for k in 20 50 100; do
    eta=5000
    if [ "${FIXED_BALANCE:-0}" = 1 ]; then
      balance=$(./build/lpd bench "$input" --preset=paper --k="$k" --max_iters=1 |
                awk '/^smoothness \/ stitching/ {print $NF}')
      [ -n "${target[$k]:-}" ] || target[$k]=$balance
      eta=$(awk -v b="$balance" -v t="${target[$k]}" 'BEGIN {printf "%.6g", 5000 * b / t}')
    fi
    : >"$tmp/bench.txt"
    for ((r = 0; r < repeats; ++r)); do
      ./build/lpd bench "$input" --preset=paper --k="$k" --max_iters=3 --energy_tolerance=0 \
        --eta="$eta" >>"$tmp/bench.txt"
    done
    awk -v n="$n" -v k="$k" -v eta="$eta" -v local_s="$(median_of_column 2)" \
        -v global_s="$(median_of_column 3)" -v cg="$(median_of_column 5)" '
      /^smoothness \/ stitching/ { balance = $NF }
      /^end to end/ { peak = $9; per_point = substr($11, 2) }
      END {
        printf "| %d | %d | %s | %.3g | %.3f | %.3f | %.2f | %d | %.0f | %d |\n", n, k, eta,
               balance, local_s, global_s, 1e6 * global_s / n, cg, peak, per_point
      }' "$tmp/bench.txt"
  done
done
