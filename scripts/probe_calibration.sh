#!/usr/bin/env bash
# The noise probe's reading on a plane (solvers/neighborhood_size.cc, kPlaneReadings): for
# each noise level, 20,000 Poisson-disk samples of two unit squares half a unit apart with
# isotropic Gaussian noise, the probe's sigma and spacing (one iteration's summary), and the
# read sigma over the true one. Prints: sigma (fraction of the clean diagonal 1.5), read
# sigma / read spacing, read sigma / true sigma.
# Usage: scripts/probe_calibration.sh [SIGMA ...]   (needs build/lpd and python3)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
lpd="${LPD:-$root/build/lpd}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
sigmas=("$@")
[ ${#sigmas[@]} -gt 0 ] || sigmas=(0.01 0.011 0.012 0.013 0.014 0.016 0.018 0.02 0.025 0.03 0.04)
echo "sigma read_sigma/read_spacing read_sigma/true_sigma"
for s in "${sigmas[@]}"; do
  "$lpd" noise --shape sheets:size=1,gap=0.5 --points 20000 --sampling poisson_disk \
      --sigma "$s" -o "$work/noisy.xyz" --overwrite --quiet > /dev/null
  "$lpd" denoise "$work/noisy.xyz" -o "$work/out.xyz" --overwrite --quiet --max_iters=1 \
      --summary_json "$work/summary.json" > /dev/null 2>&1
  python3 - "$s" "$work/noisy.xyz" "$work/summary.json" <<'PY'
import json, math, sys
sigma, xyz, summary = float(sys.argv[1]), sys.argv[2], sys.argv[3]
lo, hi = [math.inf] * 3, [-math.inf] * 3
for line in open(xyz):
    p = [float(v) for v in line.split()[:3]]
    lo = [min(a, b) for a, b in zip(lo, p)]
    hi = [max(a, b) for a, b in zip(hi, p)]
diagonal = math.dist(lo, hi)  # the probe's frame: the noisy cloud's diagonal is 1
derived = json.load(open(summary))["derived"]
true_sigma = sigma * 1.5 / diagonal  # the clean squares' diagonal is 1.5
print(f"{sigma:g} {derived['noise_sigma'] / derived['spacing']:.3f} "
      f"{derived['noise_sigma'] / true_sigma:.3f}")
PY
done
