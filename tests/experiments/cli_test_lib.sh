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
