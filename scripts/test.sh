#!/usr/bin/env bash
# Installs missing dependencies, builds, and runs the whole test suite with ctest.
# Tests on the shared models read ../shared/data (or $LPD_DATA) and skip when it is absent.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)"
