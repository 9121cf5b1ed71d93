#!/usr/bin/env bash
# Shared-machine table of docs/performance.md: wall time of `lpd denoise` on FANDISK 0.01 at
# the defaults with 1 and 2 threads, with waiting OpenMP threads as lpd sets them (a spin of
# 1,000 rounds, then sleep), as libgomp's default leaves them (GOMP_SPINCOUNT=300000, what lpd
# ran with before), sleeping at once (OMP_WAIT_POLICY=PASSIVE) or always spinning (ACTIVE):
# on an idle machine, beside one busy core, and as two runs started at once. Median of
# REPEATS runs (default 3).
# Usage: scripts/shared_machine_table.sh [REPEATS]    (build/lpd; ../shared/data or $LPD_DATA)
set -euo pipefail
cd "$(dirname "$0")/.."
repeats=${1:-3}
data=${LPD_DATA:-../shared/data}
input="$data/noisy/fandisk_noise_0.01.xyz"
[ -f "$input" ] || { echo "missing $input (set LPD_DATA)"; exit 1; }
work=$(mktemp -d)
busy_pid=""
trap '[ -n "$busy_pid" ] && kill "$busy_pid" 2>/dev/null; rm -rf "$work"' EXIT

# Seconds of one run (the slower of two when `pair`), with policy $1 and $2 threads.
run_once() {
  local policy=$1 threads=$2 pair=$3 start end
  local environment=(env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT)
  case $policy in
    libgomp) environment+=(GOMP_SPINCOUNT=300000) ;;
    PASSIVE|ACTIVE) environment+=(OMP_WAIT_POLICY="$policy") ;;
  esac
  start=$(date +%s.%N)
  "${environment[@]}" build/lpd denoise "$input" -o "$work/a.ply" --overwrite --quiet \
    --threads="$threads" >/dev/null 2>&1 &
  local first=$!
  if [ "$pair" = yes ]; then
    "${environment[@]}" build/lpd denoise "$input" -o "$work/b.ply" --overwrite --quiet \
      --threads="$threads" >/dev/null 2>&1 &
    wait $!
  fi
  wait "$first"
  end=$(date +%s.%N)
  awk "BEGIN {print $end - $start}"
}

median() { sort -n | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }

measure() {
  local policy=$1 threads=$2 pair=$3
  for _ in $(seq "$repeats"); do run_once "$policy" "$threads" "$pair"; done | median
}

echo "| condition | waiting threads | 1 thread (s) | 2 threads (s) | 2 threads / 1 thread |"
echo "|---|---|---|---|---|"
for condition in idle "one busy core" "two runs at once"; do
  if [ "$condition" = "one busy core" ]; then
    (while :; do :; done) &
    busy_pid=$!
  fi
  pair=no
  [ "$condition" = "two runs at once" ] && pair=yes
  for policy in lpd libgomp PASSIVE ACTIVE; do
    one=$(measure "$policy" 1 "$pair")
    two=$(measure "$policy" 2 "$pair")
    case $policy in
      lpd) label="spin 1,000, then sleep (lpd)" ;;
      libgomp) label="spin 300,000 (libgomp, before)" ;;
      PASSIVE) label="sleep at once (PASSIVE)" ;;
      ACTIVE) label="always spin (ACTIVE)" ;;
    esac
    printf '| %s | %s | %.2f | %.2f | %.2f |\n' "$condition" "$label" "$one" "$two" \
      "$(awk "BEGIN {print $two / $one}")"
  done
  if [ -n "$busy_pid" ]; then
    kill "$busy_pid"
    wait "$busy_pid" 2>/dev/null || true
    busy_pid=""
  fi
done
