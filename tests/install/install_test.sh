#!/usr/bin/env bash
# `cmake --install` into a temporary prefix, then a project of its own finds the package
# (find_package(lpd)), builds against it and runs; the installed Python module imports.
# Usage: install_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1
source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
test -f "$work/prefix/include/lpd/denoise.h"
test -f "$work/prefix/lib/cmake/lpd/lpdConfig.cmake"
test -x "$work/prefix/bin/lpd"
cmake -S "$source/tests/install/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" \
      -DCMAKE_BUILD_TYPE=Release > "$work/configure.log"
cmake --build "$work/consumer" -j 2 > "$work/build.log"
"$work/consumer/consumer"
site=$(find "$work/prefix" -type d -name lpd -path '*-packages/*' | head -1)
if [ -n "$site" ]; then
  (cd "$work" && PYTHONPATH=$(dirname "$site") /usr/bin/python3 -c \
     "import lpd, numpy; print('python module', lpd.__version__, 'from', lpd.__file__)")
fi
echo "install test passed"
