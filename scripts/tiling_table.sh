#!/usr/bin/env bash
# Tiled against untiled denoising on a procedural cad_part at 0.5% noise: time, peak memory
# and mean distance to the clean surface, over all points and over the seam points (those
# within one halo of another tile, the `seam` field of the tiled output), for the same
# points in both runs.
# Usage: scripts/tiling_table.sh [POINTS] [TILE_POINTS] [extra lpd denoise flags for the
#        tiled run, e.g. --halo_radii=2]     (2M points, 500K per tile: about 2 minutes)
# Set MPIRUN="mpirun -np 2" to run the tiled run on ranks.
set -euo pipefail
cd "$(dirname "$0")/.."
points=${1:-2000000}
tile_points=${2:-500000}
shift $(($# < 2 ? $# : 2))
lpd=$(realpath build/lpd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
"$lpd" noise --shape=cad_part --points="$points" --sigma=0.005 --seed=11 -o "$tmp/in.ply" \
  --quiet >/dev/null

# run NAME [launcher...] -- [flags...]: prints "seconds peak_kb"
run() {
  local name=$1; shift
  /usr/bin/time -f "%e %M" -o "$tmp/$name.time" "$@" >"$tmp/$name.log" 2>"$tmp/$name.err" ||
    { cat "$tmp/$name.err" >&2; exit 1; }
  cat "$tmp/$name.time"
}
mean() { "$lpd" metrics "$1" --ground_truth=shape:cad_part | awk '/^mean_distance/ {print $3}'; }

read -r whole_s whole_kb < <(run whole "$lpd" denoise "$tmp/in.ply" -o "$tmp/whole.ply" --quiet)
read -r tiled_s tiled_kb < <(run tiled ${MPIRUN:-} "$lpd" denoise "$tmp/in.ply" -o "$tmp/tiled.ply" \
  --quiet --tile_points="$tile_points" "$@")
# The seam points of the tiled run, and the same input points in the untiled run (numpy:
# Debian's python3-numpy, so the system python first).
python=$(command -v /usr/bin/python3 || command -v python3)
"$python" - "$tmp" <<'PY'
import sys
import numpy as np
d = sys.argv[1]
def read_ply(path):
    with open(path, "rb") as f:
        names, types, count = [], [], 0
        while True:
            line = f.readline().decode().strip()
            if line.startswith("element vertex"):
                count = int(line.split()[2])
            elif line.startswith("property"):
                _, t, name = line.split()
                types.append({"float": "<f4", "double": "<f8", "float32": "<f4",
                              "float64": "<f8", "int": "<i4", "uint": "<u4", "uchar": "u1"}[t])
                names.append(name)
            elif line == "end_header":
                break
        return np.fromfile(f, dtype=np.dtype(list(zip(names, types))), count=count)
tiled = read_ply(f"{d}/tiled.ply")
whole = read_ply(f"{d}/whole.ply")
seam = tiled[tiled["seam"] > 0]
position = {int(s): i for i, s in enumerate(whole["source_index"])}
rows = [position[int(s)] for s in seam["source_index"] if int(s) in position]
for name, cloud in (("seam_tiled", seam), ("seam_whole", whole[rows])):
    np.savetxt(f"{d}/{name}.xyz", np.stack([cloud["x"], cloud["y"], cloud["z"]], axis=1))
print(len(seam), file=open(f"{d}/seam_count", "w"))
PY
tiles=$(grep -o "tiles [0-9]* on [0-9]* process[a-z]* x [0-9]* threads\?" "$tmp/tiled.log")
halo=$(grep -o "halo points [0-9]*" "$tmp/tiled.log" | awk '{print $3}')
echo "cad_part $points points, 0.5% noise; tiled: $tiles, tile_points $tile_points $*, halo points $halo"
echo
echo "| run | time | peak memory | mean distance / diagonal | at the $(cat "$tmp/seam_count") seam points |"
echo "|---|---|---|---|---|"
awk -v s="$whole_s" -v kb="$whole_kb" -v a="$(mean "$tmp/whole.ply")" -v b="$(mean "$tmp/seam_whole.xyz")" \
  'BEGIN { printf "| untiled | %.1f s | %.0f MB | %.4e | %.4e |\n", s, kb / 1024, a, b }'
awk -v s="$tiled_s" -v kb="$tiled_kb" -v a="$(mean "$tmp/tiled.ply")" -v b="$(mean "$tmp/seam_tiled.xyz")" \
  'BEGIN { printf "| tiled | %.1f s | %.0f MB | %.4e | %.4e |\n", s, kb / 1024, a, b }'
