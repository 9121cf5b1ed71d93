#!/usr/bin/env bash
# Pipes: the same points through a file, a FIFO, standard input and standard output give the
# same output bytes (XYZ and PLY inputs), and lpd noise writes to standard output too; '-'
# without a format is refused in one line.
# Usage: cli_pipes_test.sh PATH_TO_LPD
lpd=$(realpath "$1")
source "$(dirname "$0")/cli_test_lib.sh"
cd "$dir" || exit 1
run() { "$lpd" denoise "$@" --quiet --threads=2 --max_iters=10; }

"$lpd" noise --shape=cube --points=4000 --sigma=0.004 -o noisy.xyz >/dev/null 2>&1 ||
  fail "lpd noise failed"
"$lpd" noise --shape=cube --points=4000 --sigma=0.004 -o noisy.ply >/dev/null 2>&1 ||
  fail "lpd noise failed"
# lpd noise to standard output: the same cloud, the summary on stderr.
"$lpd" noise --shape=cube --points=4000 --sigma=0.004 -o - --output_format=xyz \
  >noise_stdout.xyz 2>noise_stdout.err || fail "lpd noise -o - failed: $(cat noise_stdout.err)"
cmp -s noisy.xyz noise_stdout.xyz || fail "lpd noise -o - wrote another cloud than -o FILE"
for format in xyz ply; do
  run "noisy.$format" -o "file_$format.xyz" >/dev/null 2>&1 || fail "$format file run failed"
  mkfifo "fifo.$format"
  cat "noisy.$format" >"fifo.$format" &
  run "fifo.$format" -o "fifo_$format.xyz" >/dev/null 2>"fifo_$format.err" ||
    fail "$format through a FIFO: $(tail -1 "fifo_$format.err")"
  wait
  run - --input_format="$format" -o "stdin_$format.xyz" <"noisy.$format" >/dev/null 2>&1 ||
    fail "$format from standard input failed"
  cat "noisy.$format" | run - --input_format="$format" -o - --output_format=xyz \
    >"stdout_$format.xyz" 2>"stdout_$format.err" || fail "$format to standard output failed"
  for way in fifo stdin stdout; do
    cmp -s "file_$format.xyz" "${way}_$format.xyz" ||
      fail "$format: $way output differs from the file run's"
  done
  grep -q "^points in 4000" "stdout_$format.err" ||
    fail "$format: with -o - the summary belongs on stderr"
done
# Without OMP_WAIT_POLICY or GOMP_SPINCOUNT lpd restarts itself with a short spin: standard
# input, the output and the result survive the restart.
env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT "$lpd" denoise - --input_format=xyz -o - --output_format=xyz --quiet \
  --threads=2 --max_iters=10 <noisy.xyz >restarted.xyz 2>/dev/null || fail "restart failed"
cmp -s file_xyz.xyz restarted.xyz || fail "the restart with a short spin changed the output"
run - -o x.xyz <noisy.xyz >/dev/null 2>err.txt && fail "'-' without --input_format accepted"
[ "$(wc -l <err.txt)" -eq 1 ] && grep -q "needs --input_format" err.txt ||
  fail "'-' without --input_format: $(cat err.txt)"
run noisy.xyz -o - >/dev/null 2>err.txt && fail "'-o -' without --output_format accepted"
grep -q "needs --output_format" err.txt || fail "'-o -' without --output_format: $(cat err.txt)"
[ "$failures" -eq 0 ] && echo "ok   file, FIFO, stdin and stdout give the same output (xyz, ply)"
finish "pipe cases"
