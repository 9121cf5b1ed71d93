#!/usr/bin/env bash
# Fuzzes every reader (point clouds, state files, sweep configs) with libFuzzer (clang, AddressSanitizer + UBSan), starting
# from the seed corpus in tests/fuzz/corpus/FORMAT. New interesting inputs go to
# build-fuzz/corpus/FORMAT, crashes to build-fuzz/crashes/FORMAT; copy a crash into
# tests/fuzz/corpus/FORMAT once fixed, so the ctest replay keeps it as a regression test.
# Usage: scripts/fuzz.sh [SECONDS_PER_READER=600] [FORMAT...]   (default: xyz ply off obj las pcd state sweep)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
shift || true
formats=("$@")
[ ${#formats[@]} -gt 0 ] || formats=(xyz ply off obj las pcd state sweep)
bash scripts/install_deps.sh clang libfuzzer-14-dev
CXX=clang++ CC=clang cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLPD_FUZZ=ON \
  >/dev/null
targets=()
for format in "${formats[@]}"; do targets+=(--target "fuzz_${format}"); done
cmake --build build-fuzz -j "$(nproc)" "${targets[@]}" >/dev/null
for format in "${formats[@]}"; do
  mkdir -p "build-fuzz/corpus/$format" "build-fuzz/crashes/$format"
  echo "== $format: $seconds s"
  ./build-fuzz/tests/fuzz/fuzz_${format} "build-fuzz/corpus/$format" \
    "tests/fuzz/corpus/$format" -max_total_time="$seconds" -rss_limit_mb=2048 \
    -max_len="$([ "$format" = state ] && echo 16384 || echo 4096)" -print_final_stats=1 -artifact_prefix="build-fuzz/crashes/$format/" \
    >"build-fuzz/$format.log" 2>&1 || echo "$format: the fuzzer stopped on a finding"
  grep -E "DONE|stat::number_of_executed_units|stat::new_units_added|runtime error|ERROR|SUMMARY" \
    "build-fuzz/$format.log" | tail -6
  ls "build-fuzz/crashes/$format"
done
