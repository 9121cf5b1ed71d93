# Shared by the CLI test scripts (sourced): a scratch directory removed on exit, a failure
# counter and `fail MESSAGE`, and `finish` to report and exit with the failure count.
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
finish() {
  [ "$failures" -eq 0 ] && echo "all $1 passed"
  exit "$failures"
}

# denoise_finite NAME INPUT [FLAGS...]: lpd denoise INPUT (as $lpd) succeeds and writes only
# finite coordinates, whose number it leaves in $finite_count; otherwise it fails the case
# and returns 1. (Not to be called in a subshell: the failure count would be lost.)
denoise_finite() {
  local name=$1 input=$2
  shift 2
  local out="$dir/out_$name.xyz"
  if ! timeout 120 "$lpd" denoise "$input" -o "$out" --quiet "$@" >"$dir/stdout" 2>"$dir/stderr"; then
    fail "$name: failed: $(tail -1 "$dir/stderr")"
    return 1
  fi
  if grep -qiE 'nan|inf' "$out"; then
    fail "$name: non-finite output"
    return 1
  fi
  finite_count=$(wc -l <"$out")
}
