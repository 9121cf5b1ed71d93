#!/usr/bin/env bash
# One command for a fresh Debian 12 machine: install the dependencies, build, and run the main
# job. With no arguments it denoises the built-in noisy box and reports the distance to the
# clean box; any arguments are passed to `lpd denoise` (e.g. INPUT.xyz -o OUTPUT.ply --k=50).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
bash scripts/build.sh
./build/lpd denoise "$@"
