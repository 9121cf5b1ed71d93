#!/usr/bin/env bash
# Configures and builds lpd (Release) into build/ (or $LPD_BUILD_DIR).
# Usage: scripts/build.sh [extra cmake args]
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${LPD_BUILD_DIR:-build}
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build "$build_dir" -j "$(nproc)"
