#!/usr/bin/env bash
# lpd noise / metrics / sweep from the command line:
# - bad input gives one stderr line, a non-zero exit and no output;
# - outlier labels written by `lpd noise` survive denoise and are scored by `lpd metrics`;
# - configs/smoke.yaml runs and its CSV has one row per cell with finite metrics.
# Usage: cli_experiments_test.sh PATH_TO_LPD PATH_TO_SMOKE_CONFIG
lpd=$(realpath "$1")
smoke=$(realpath "$2")
source "$(dirname "$0")/cli_test_lib.sh"

# expect_error NAME COMMAND ARGS...: fails with exactly one stderr line, leaves nothing.
expect_error() {
  local name=$1; shift
  local before=$failures
  mkdir -p "$dir/$name"
  (cd "$dir/$name" && "$lpd" "$@" >stdout 2>stderr)
  local code=$?
  local lines
  lines=$(wc -l <"$dir/$name/stderr")
  [ "$code" -ne 0 ] || fail "$name: exit code 0"
  [ "$lines" -eq 1 ] || fail "$name: $lines stderr lines: $(cat "$dir/$name/stderr")"
  local left
  left=$(ls "$dir/$name" | grep -vE '^(stdout|stderr)$')
  [ -z "$left" ] || fail "$name: left behind: $left"
  [ "$failures" -eq "$before" ] && echo "ok   $name: $(cat "$dir/$name/stderr")"
}

printf 'name: x\ndatasets: [\n' >"$dir/broken.yaml"
printf 'name: x\ndatasets:\n  - shape: cube\nmethods:\n  - method: lpd\n    lamda: 2\n' >"$dir/typo.yaml"
expect_error sweep_missing_config sweep "$dir/none.yaml"
expect_error sweep_broken_yaml sweep "$dir/broken.yaml"
expect_error sweep_unknown_key sweep "$dir/typo.yaml"
printf 'name: x\ndatasets:\n  - shape: cube\nmethods:\n  - method: ceres\n    inner_iters: 3\n' >"$dir/ceres_schedule.yaml"
expect_error sweep_schedule_with_ceres sweep "$dir/ceres_schedule.yaml"
expect_error noise_no_source noise -o out.ply
expect_error noise_two_sources noise --shape=cube --mesh=x.off -o out.ply
expect_error noise_bad_shape noise --shape=cone:apex_angle=200 -o out.ply
expect_error noise_bad_model noise --shape=cube --noise_model=pink -o out.ply
expect_error noise_negative_sigma noise --shape=cube --sigma=-1 -o out.ply
expect_error metrics_no_ground_truth metrics "$dir/none.ply"

# Labels survive: 100 labelled outliers are all accounted for (found + missed = 100).
"$lpd" noise --shape=cube --points=6000 --sigma=0.002 --outlier_count=100 -o "$dir/noisy.ply" >/dev/null ||
  fail "lpd noise failed"
"$lpd" denoise "$dir/noisy.ply" -o "$dir/out.ply" --quiet --mu_l=4.2e-5 >/dev/null 2>&1 ||
  fail "lpd denoise failed"
"$lpd" metrics "$dir/out.ply" --ground_truth=shape:cube --input="$dir/noisy.ply" >"$dir/metrics.txt" ||
  fail "lpd metrics failed: $(cat "$dir/metrics.txt")"
expect_error metrics_bad_shape metrics "$dir/noisy.ply" --ground_truth=shape:teapot
expect_error metrics_missing_mesh metrics "$dir/noisy.ply" --ground_truth="$dir/none.off"
line=$(grep '^outlier detection' "$dir/metrics.txt")
found=$(echo "$line" | sed -E 's/.*true ([0-9]+).*/\1/')
missed=$(echo "$line" | sed -E 's/.*missed ([0-9]+).*/\1/')
[ "$((found + missed))" -eq 100 ] || fail "outlier labels lost: $line"
[ "$found" -ge 50 ] || fail "outlier recall too low: $line"
echo "ok   labels survive: $line"

# --summary_json: counts that match the output file, every pass, the parameters given; and
# the output's header names the version and the parameters.
"$lpd" denoise "$dir/noisy.ply" -o "$dir/summarized.ply" --quiet --max_iters=8 --outliers=mark \
  --summary_json="$dir/summary.json" >/dev/null 2>&1 || fail "denoise --summary_json failed"
python3 - "$dir/summary.json" "$dir/summarized.ply" <<'PY' || fail "summary does not match the output"
import json, sys
summary = json.load(open(sys.argv[1]))
header = open(sys.argv[2], "rb").read().split(b"end_header")[0].decode()
vertices = int(next(l.split()[2] for l in header.splitlines() if l.startswith("element vertex")))
counts = summary["counts"]
assert counts["output_points"] == vertices == counts["input_points"], (counts, vertices)
assert counts["removed"] == 0 and counts["outliers_flagged"] > 0, counts
assert summary["parameters_given"] == {"max_iters": "8", "outliers": "mark"}, summary
assert summary["parameters"]["outliers"] == "mark" and summary["derived"]["k"] >= 12
assert len(summary["passes"]) == 1 and summary["passes"][0]["iterations"] <= 8
assert "comment lpd parameters preset=default" in header and "outliers=mark" in header
assert "comment lpd derived k=" in header
# The stages' times, in the order they ran, add up to the run's (less what is not a stage).
seconds = summary["seconds"]
stages = seconds["stages"]
assert list(stages)[:6] == ["far points and repeats", "order and probe", "graph",
                            "initial state", "solve", "projection"], stages
assert all(s >= 0 for s in stages.values()) and stages["solve"] > 0, stages
assert 0.5 * seconds["total"] <= sum(stages.values()) <= seconds["total"] + 1e-6, seconds
print("ok   summary_json:", counts)
PY
expect_error summary_json_is_output denoise "$dir/noisy.ply" -o s.ply --summary_json=./s.ply
expect_error state_is_output denoise "$dir/noisy.ply" -o ./s.xyz --save_state=s.xyz

# The smoke sweep: one row per cell, every metric present and finite, resumable.
if ! "$lpd" sweep "$smoke" --results_dir="$dir/smoke" >"$dir/sweep.txt" 2>"$dir/sweep.err"; then
  fail "smoke sweep failed: $(tail -3 "$dir/sweep.err")"
fi
cells=$(sed -E -n 's/^sweep [^:]+: ([0-9]+) cells.*/\1/p' "$dir/sweep.txt")
rows=$(($(wc -l <"$dir/smoke/results.csv") - 1))
[ -n "$cells" ] && [ "$rows" -eq "$cells" ] || fail "smoke: $rows CSV rows for ${cells:-?} cells"
bad=$(awk -F, 'NR == 1 { for (c = 1; c <= NF; ++c) col[$c] = c; next }
  { split("mse mcd snr_db mean_distance_normalized seconds", names, " ");
    for (i in names) { v = $col[names[i]]; if (v == "" || v ~ /nan|inf/) print "row " NR-1 ": " names[i] "=" v } }' \
  "$dir/smoke/results.csv")
[ -z "$bad" ] || fail "smoke: missing or non-finite metrics: $bad"
"$lpd" sweep "$smoke" --results_dir="$dir/smoke" >"$dir/sweep2.txt" 2>/dev/null
grep -q " 0 run, $cells skipped" "$dir/sweep2.txt" || fail "smoke rerun did not skip: $(cat "$dir/sweep2.txt")"
echo "ok   smoke sweep: $rows rows, all metrics finite, rerun skipped every cell"

finish "experiment CLI checks"
