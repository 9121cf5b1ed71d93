#!/usr/bin/env bash
# Installs lpd's build and test dependencies from Debian 12 packages, only those missing.
# Usage: scripts/install_deps.sh [EXTRA_PACKAGE...]   (uses sudo when not root; extra
# packages, e.g. clang libfuzzer-14-dev for scripts/fuzz.sh, are installed too)
set -euo pipefail

packages=(
  build-essential cmake git pkg-config
  libeigen3-dev libceres-dev libgoogle-glog-dev libgflags-dev
  libnanoflann-dev libgtest-dev libbenchmark-dev libcgal-dev libyaml-cpp-dev liblzf-dev
  libopenmpi-dev openmpi-bin
  python3 python3-dev python3-matplotlib python3-numpy python3-pytest time
  pybind11-dev python3-pybind11 python3-open3d
  "$@"
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#packages[@]} packages already installed"
  exit 0
fi

sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
echo "install_deps: installing ${missing[*]}"
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
