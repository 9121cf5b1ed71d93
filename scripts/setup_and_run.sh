#!/usr/bin/env bash
# One command for a fresh Debian 12 machine: install the dependencies, build, install lpd
# (the program, the C++ library with its CMake package, and the Python module, under
# /usr/local or $LPD_PREFIX), and run the main job. With no arguments it denoises the
# built-in noisy box and reports the distance to the clean box; any arguments are passed to
# `lpd denoise` (e.g. INPUT.xyz -o OUTPUT.ply --k=50).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
bash scripts/build.sh
prefix=${LPD_PREFIX:-/usr/local}
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || [ -w "$prefix" ] || sudo_cmd=(sudo)
"${sudo_cmd[@]}" cmake --install build --prefix "$prefix" > build/install_manifest.log
echo "installed lpd into $prefix (program, C++ library and CMake package, Python module)"
./build/lpd denoise "$@"
