#!/usr/bin/env bash
# SIGINT / SIGTERM during real runs:
# - a denoise stopped mid-iteration exits 130 (143 for SIGTERM) within about a second, says
#   so in one line, and leaves neither the output nor a temporary file;
# - a denoise stopped inside a stage without iterations (the k-NN build), and a reconstruction,
#   do the same through the watchdog;
# - a sweep stopped after its first cell exits 143, its CSV holds exactly the finished cells,
#   and a rerun resumes: it runs only the rest and ends with one row per cell.
# Usage: cli_interruption_test.sh PATH_TO_LPD
lpd=$(realpath "$1")
source "$(dirname "$0")/cli_test_lib.sh"

now() { date +%s.%N; }

# interrupt NAME SIGNAL EXPECTED_CODE WAIT_FOR_PATTERN ARGS...: runs lpd ARGS in $dir/NAME,
# sends SIGNAL once stderr matches WAIT_FOR_PATTERN ("" = half a second after the start),
# checks the exit
# code, the time to exit and that nothing but stdout/stderr is left.
interrupt() {
  local name=$1 signal=$2 expected=$3 pattern=$4; shift 4
  local before=$failures
  mkdir -p "$dir/$name"
  (cd "$dir/$name" && exec "$lpd" "$@" >stdout 2>stderr) &
  local pid=$!
  local waited=0
  [ -n "$pattern" ] || sleep 0.5
  while [ -n "$pattern" ] && ! grep -q "$pattern" "$dir/$name/stderr" 2>/dev/null; do
    sleep 0.05
    waited=$((waited + 1))
    [ "$waited" -lt 1200 ] || { fail "$name: '$pattern' never appeared"; kill -9 "$pid"; return; }
  done
  local start
  start=$(now)
  kill -s "$signal" "$pid"
  wait "$pid"
  local code=$?
  local seconds
  seconds=$(echo "$(now) - $start" | bc)
  [ "$code" -eq "$expected" ] || fail "$name: exit code $code, expected $expected"
  [ "$(echo "$seconds < 1.6" | bc)" -eq 1 ] || fail "$name: took $seconds s to stop"
  local left
  left=$(ls "$dir/$name" | grep -vE '^(stdout|stderr)$')
  [ -z "$left" ] || fail "$name: left behind: $left"
  tail -1 "$dir/$name/stderr" | grep -q "interrupted" ||
    fail "$name: last line does not say interrupted: $(tail -1 "$dir/$name/stderr")"
  [ "$failures" -eq "$before" ] &&
    echo "ok   $name: exit $code after $seconds s: $(tail -1 "$dir/$name/stderr")"
}

"$lpd" noise --shape=cad_part --points=120000 --sigma=0.005 -o "$dir/big.xyz" >/dev/null 2>&1 ||
  fail "lpd noise failed"
# Short iterations (the built-in box at 3,000 points, kept iterating): the solver stops at
# the next iteration, well within the watchdog's second even in a sanitizer build.
interrupt denoise_sigint_at_iteration INT 130 "^iter  2" denoise -o out.ply \
  --default_points=3000 --energy_tolerance=0 --max_iters=1000000
grep -q "lpd denoise: interrupted by SIGINT; no output written" \
  "$dir/denoise_sigint_at_iteration/stderr" || fail "denoise_sigint_at_iteration: not stopped at an iteration"
# Iterations longer than a second (120K points on a loaded machine): the watchdog ends it.
interrupt denoise_sigint INT 130 "^iter  2" denoise "$dir/big.xyz" -o out.ply
interrupt denoise_sigterm TERM 143 "^iter  1" denoise "$dir/big.xyz" -o out.xyz --threads=1
interrupt denoise_sigint_in_knn INT 130 "" denoise "$dir/big.xyz" -o out.ply --quiet
# A CGAL reconstruction has no iterations to stop at: the watchdog ends it.
interrupt reconstruct_sigterm TERM 143 "" reconstruct "$dir/big.xyz" -o out.off

# A sweep of four cells, one at a time: stop it after the first, then resume.
cat >"$dir/sweep.yaml" <<'YAML'
name: interrupted
seed: 1
parallel_cells: 1
ground_truth_samples: 20000
datasets:
  - shape: cad_part
    points: 6000
noise:
  - model: gaussian
    sigma: [0.005, 0.01, 0.015, 0.02]
methods:
  - method: lpd
YAML
results="$dir/sweep_results"
"$lpd" sweep "$dir/sweep.yaml" --results_dir="$results" --threads=1 >"$dir/sweep.out" 2>&1 &
pid=$!
waited=0
until [ -s "$results/results.csv" ] || [ "$waited" -ge 1200 ]; do sleep 0.05; waited=$((waited + 1)); done
kill -TERM "$pid"
wait "$pid"
code=$?
[ "$code" -eq 143 ] || fail "sweep: exit code $code after SIGTERM, expected 143"
done_rows=$(($(wc -l <"$results/results.csv") - 1))
records=$(grep -c cell_id "$results/results.jsonl")
[ "$done_rows" -ge 1 ] && [ "$done_rows" -lt 4 ] || fail "sweep: $done_rows rows after the stop"
[ "$done_rows" -eq "$records" ] || fail "sweep: CSV has $done_rows rows, JSONL $records records"
left=$(ls "$results" | grep -vE '^results\.(csv|jsonl)$')
[ -z "$left" ] || fail "sweep: left behind: $left"
"$lpd" sweep "$dir/sweep.yaml" --results_dir="$results" --threads=1 >"$dir/resume.out" 2>&1 ||
  fail "sweep resume failed: $(tail -2 "$dir/resume.out")"
grep -q "$((4 - done_rows)) run, $done_rows skipped" "$dir/resume.out" ||
  fail "sweep resume did not skip the finished cells: $(tail -2 "$dir/resume.out")"
rows=$(($(wc -l <"$results/results.csv") - 1))
[ "$rows" -eq 4 ] || fail "sweep: $rows rows after the resume, expected 4"
[ "$failures" -eq 0 ] && echo "ok   sweep: stopped after $done_rows of 4 cells (exit 143), resumed to 4 rows"
finish "interruption checks"
