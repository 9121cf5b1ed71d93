#!/usr/bin/env bash
# `lpd denoise --tile_points`: in one process and, when mpirun is installed, on 2 ranks. The
# ranks give the one-process result; tiles too small for a neighbourhood, more ranks than
# tiles and a tile that fails end the run with exit code 1, a message naming the problem (the
# tile, for a failure), no output file and no temporary files.
# Usage: cli_tiles_test.sh PATH_TO_LPD
lpd=$(realpath "$1")
source "$(dirname "$0")/cli_test_lib.sh"
# mpirun refuses root without these (CI runs as root).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_WAIT_POLICY=PASSIVE
# The tiles' temporary files go here; none may be left behind, also after a failure.
export TMPDIR="$dir/tmp"
mkdir -p "$TMPDIR"
cases=0

# refused NAME PATTERN COMMAND...: exits with 1, stderr matches PATTERN, no out.* left.
refused() {
  local name=$1 pattern=$2; shift 2
  cases=$((cases + 1))
  (cd "$dir" && timeout 120 "$@" >"$dir/stdout" 2>"$dir/stderr")
  local code=$?
  [ "$code" -ne 0 ] || fail "$name: exit code 0"
  grep -q -- "$pattern" "$dir/stderr" || fail "$name: no '$pattern' in: $(head -3 "$dir/stderr")"
  ls "$dir" | grep -q '^out' && fail "$name: left an output file"
  echo "$name: exit $code: $(grep -m1 -- "$pattern" "$dir/stderr")"
}

"$lpd" noise --shape=cad_part --points=6000 --sigma=0.005 -o "$dir/cloud.xyz" --quiet >/dev/null ||
  fail "lpd noise"
# Duplicates far from the surface: the k-d split gives them tiles of their own, which have no
# extent and fail.
cp "$dir/cloud.xyz" "$dir/duplicates.xyz"
for i in $(seq 3000); do echo "5 5 5"; done >>"$dir/duplicates.xyz"

cases=$((cases + 1))
"$lpd" denoise "$dir/cloud.xyz" -o "$dir/one.xyz" --tile_points=1500 --threads=2 --quiet \
  >"$dir/stdout" 2>"$dir/stderr" || fail "one process: $(tail -1 "$dir/stderr")"
grep -q "tiles 4 on 1 process" "$dir/stdout" || fail "one process: $(cat "$dir/stdout")"
[ "$(wc -l <"$dir/one.xyz")" -gt 5900 ] || fail "one process: $(wc -l <"$dir/one.xyz") points out"

# The input's attributes reach a tiled output as an untiled one: colours and an attribute
# named like one of lpd's fields (written input_tile), each point's from its input row.
cases=$((cases + 1))
awk 'BEGIN { print "ply\nformat ascii 1.0\nelement vertex 6000\nproperty double x\nproperty double y\nproperty double z\nproperty uchar red\nproperty uchar green\nproperty int tile\nend_header" }
     { print $1, $2, $3, NR % 256, (7 * NR) % 256, -NR }' "$dir/cloud.xyz" >"$dir/colours.ply"
"$lpd" denoise "$dir/colours.ply" -o "$dir/colours_out.ply" --tile_points=1500 --quiet \
  >/dev/null 2>"$dir/stderr" || fail "attributes: $(tail -1 "$dir/stderr")"
python3 - "$dir/colours_out.ply" <<'PY' || fail "attributes: the tiled output's attributes differ from the input's"
import struct, sys
data = open(sys.argv[1], "rb").read()
header, body = data.split(b"end_header\n", 1)
lines = header.decode().splitlines()
count = int(next(l for l in lines if l.startswith("element vertex")).split()[2])
props = [l.split()[1:] for l in lines if l.startswith("property")]
codes = {"double": "d", "float": "f", "uchar": "B", "int": "i", "uint": "I"}
names = [n for _, n in props]
assert names[6:9] == ["red", "green", "input_tile"] and "tile" in names[9:], names
record = struct.Struct("<" + "".join(codes[t] for t, _ in props))
for r in range(count):
    row = dict(zip(names, record.unpack_from(body, r * record.size)))
    line = row["source_index"] + 1  # the input's 1-based row
    assert (row["red"], row["green"], row["input_tile"]) == (line % 256, (7 * line) % 256, -line), row
assert count > 5900, count
PY

# A LAS input streams a record at a time and keeps its fields.
cases=$((cases + 1))
"$lpd" noise --shape=cad_part --points=6000 --sigma=0.005 -o "$dir/cloud.las" --quiet >/dev/null ||
  fail "lpd noise .las"
"$lpd" denoise "$dir/cloud.las" -o "$dir/las_out.ply" --tile_points=1500 --quiet \
  >/dev/null 2>"$dir/stderr" || fail "LAS input: $(tail -1 "$dir/stderr")"
head -c 2000 "$dir/las_out.ply" | grep -a -q "property uchar classification" ||
  fail "LAS input: no classification in the tiled output"
# And a LAS output, a record at a time: the tiled PLY's points (to the LAS scale), its
# outliers kept by --outliers=mark as class 7, the header's count and bounds those of the
# records.
cases=$((cases + 1))
"$lpd" noise --shape=cad_part --points=6000 --sigma=0.005 --outlier_ratio=0.05 \
  -o "$dir/noisy_with_outliers.las" --quiet >/dev/null || fail "lpd noise outliers .las"
for out in marked.las marked.ply; do
  "$lpd" denoise "$dir/noisy_with_outliers.las" -o "$dir/$out" --tile_points=1500 --outliers=mark --quiet \
    >/dev/null 2>"$dir/stderr" || fail "LAS output: $(tail -1 "$dir/stderr")"
done
python3 - "$dir/marked.las" "$dir/marked.ply" <<'PY' || fail "LAS output: records differ from the tiled PLY"
import struct, sys
las = open(sys.argv[1], "rb").read()
offset, = struct.unpack_from("<I", las, 96)
length, count = struct.unpack_from("<HI", las, 105)
scale, shift = struct.unpack_from("<3d", las, 131), struct.unpack_from("<3d", las, 155)
high_low = struct.unpack_from("<6d", las, 179)
assert len(las) == offset + count * length, (len(las), offset, count, length)
records = [struct.unpack_from("<3i", las, offset + i * length) for i in range(count)]
points = [[x * s + o for x, s, o in zip(r, scale, shift)] for r in records]
classes = [las[offset + i * length + 15] & 31 for i in range(count)]
ply = open(sys.argv[2], "rb").read()
header, body = ply.split(b"end_header\n", 1)
lines = header.decode().splitlines()
props = [l.split()[1:] for l in lines if l.startswith("property")]
codes = {"double": "d", "float": "f", "uchar": "B", "char": "b", "ushort": "H", "short": "h",
         "int": "i", "uint": "I"}
record = struct.Struct("<" + "".join(codes[t] for t, _ in props))
names = [n for _, n in props]
rows = [dict(zip(names, record.unpack_from(body, r * record.size))) for r in range(count)]
assert len(body) == count * record.size
for p, c, row in zip(points, classes, rows):
    assert max(abs(a - row[k]) for a, k in zip(p, "xyz")) <= max(scale), (p, row)
    assert (c == 7) == (row["outlier"] == 1), (c, row["outlier"])
for axis in range(3):
    values = [p[axis] for p in points]
    assert abs(high_low[2 * axis] - max(values)) < 1e-12 and abs(high_low[2 * axis + 1] - min(values)) < 1e-12
assert sum(classes[i] == 7 for i in range(count)) > 100, sum(c == 7 for c in classes)
PY

refused tiles_below_a_neighbourhood "fewer than the 41" "$lpd" denoise cloud.xyz -o out.xyz --tile_points=40
refused tiles_with_resume "cannot be combined" "$lpd" denoise cloud.xyz -o out.xyz --tile_points=1500 --save_state=out.lpds
refused tiles_with_input_normals "input_normals" "$lpd" denoise cloud.xyz -o out.xyz --tile_points=1500 --initialization=input_normals
refused halo_radii_zero "halo_radii" "$lpd" denoise cloud.xyz -o out.xyz --tile_points=1500 --halo_radii=0
refused failing_tile "tile [0-9]* of [0-9]* (.*) failed" "$lpd" denoise duplicates.xyz -o out.xyz --tile_points=1500

# A signal stops a tiled run with 128 + its number and removes the tiles' files (checked at
# the end with the others).
cases=$((cases + 1))
"$lpd" noise --shape=cad_part --points=300000 --sigma=0.005 -o "$dir/large.xyz" --quiet >/dev/null
"$lpd" denoise "$dir/large.xyz" -o "$dir/out_interrupted.xyz" --tile_points=100000 --quiet \
  >/dev/null 2>"$dir/stderr" &
pid=$!
sleep 1.5
kill -INT "$pid"
wait "$pid"
code=$?
[ "$code" -eq 130 ] || fail "interrupted tiled run: exit code $code: $(tail -1 "$dir/stderr")"
[ ! -e "$dir/out_interrupted.xyz" ] || fail "interrupted tiled run: left an output"
echo "interrupted: exit $code: $(tail -1 "$dir/stderr")"

# 2,000 points in tiles of 100 under a limit of 10 open files: the merge holds a few files
# open however many tiles there are (it opened every tile file at once), and writes the
# same bytes as without the limit.
cases=$((cases + 1))
head -2000 "$dir/cloud.xyz" >"$dir/small.xyz"
"$lpd" denoise "$dir/small.xyz" -o "$dir/few_files.ply" --tile_points=100 --quiet --threads=1 \
  >/dev/null 2>"$dir/unlimited.err" || fail "tiles of 100 points: $(tail -1 "$dir/unlimited.err")"
(ulimit -n 10 && "$lpd" denoise "$dir/small.xyz" -o "$dir/limited.ply" --tile_points=100 \
   --quiet --threads=1 >/dev/null 2>"$dir/limited.err") ||
  fail "ulimit -n 10: $(tail -1 "$dir/limited.err")"
cmp -s "$dir/few_files.ply" "$dir/limited.ply" || fail "ulimit -n 10 changed the tiled output"

if command -v mpirun >/dev/null; then
  # Under --sanitize, Open MPI's runtime leaks at exit from plugins it has unloaded, which
  # LeakSanitizer cannot name or suppress; the one-process cases above check lpd's own code.
  mpi=(env ASAN_OPTIONS="${ASAN_OPTIONS:-}:detect_leaks=0" timeout 300 mpirun --oversubscribe
       -np 2)
  cases=$((cases + 1))
  "${mpi[@]}" "$lpd" denoise "$dir/cloud.xyz" -o "$dir/two.xyz" --tile_points=1500 --quiet \
    >"$dir/stdout" 2>"$dir/stderr" || fail "2 ranks: $(tail -3 "$dir/stderr")"
  grep -q "tiles 4 on 2 processes" "$dir/stdout" || fail "2 ranks: $(cat "$dir/stdout")"
  # The same tiles with 1 thread each instead of 2: the same points up to rounding.
  python3 - "$dir/one.xyz" "$dir/two.xyz" <<'PY' || fail "2 ranks differ from one process"
import sys
one = [list(map(float, l.split())) for l in open(sys.argv[1])]
two = [list(map(float, l.split())) for l in open(sys.argv[2])]
assert len(one) == len(two), (len(one), len(two))
worst = max(abs(a - b) for p, q in zip(one, two) for a, b in zip(p, q))
assert worst < 1e-6, worst
PY
  refused more_ranks_than_tiles "2 ranks for 1 tile" "${mpi[@]}" "$lpd" denoise cloud.xyz -o out.xyz --tile_points=6000
  # At 1200 points per tile the duplicates' tile is tile 6 of 8, which rank 1 takes.
  refused failing_tile_on_rank_1 "tile 6 of 8 (rank 1) failed" "${mpi[@]}" "$lpd" denoise duplicates.xyz -o out.xyz --tile_points=1200
else
  echo "mpirun not found: the 2-rank cases are skipped (apt-get install openmpi-bin)"
fi
[ -z "$(ls "$TMPDIR")" ] || fail "temporary files left behind: $(ls "$TMPDIR")"
finish "$cases tiled cases"
