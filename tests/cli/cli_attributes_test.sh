#!/usr/bin/env bash
# Attributes survive: a binary PLY with uchar colours, a float intensity, an int class, a
# short of unknown meaning and a property named like one of lpd's own comes out with every
# one of them, bit for bit, on each kept point (read back by an independent reader), beside
# lpd's fields; an XYZ with colour columns comes out as XYZ with them.
# Usage: cli_attributes_test.sh PATH_TO_LPD
lpd=$(realpath "$1")
source "$(dirname "$0")/cli_test_lib.sh"
cd "$dir" || exit 1
python3 - <<'PY' || fail "writing the inputs failed"
import math, random, struct
random.seed(3)
rows = []
for i in range(3000):
    face, u, v = random.randrange(6), random.random(), random.random()
    p = [u, v, float(face % 2)] if face < 2 else ([u, float(face % 2), v] if face < 4 else [float(face % 2), u, v])
    # float32 values, so that the PLY and the XYZ hold the same points
    p = [struct.unpack("<f", struct.pack("<f", c + random.gauss(0, 0.004)))[0] for c in p]
    rows.append((p, random.randrange(256), random.randrange(256), random.randrange(256),
                 random.uniform(0, 1000), random.randrange(-5, 30), random.randrange(-32768, 32767),
                 random.uniform(0, 1)))
header = ("ply\nformat binary_little_endian 1.0\nelement vertex %d\n"
          "property float x\nproperty float y\nproperty float z\n"
          "property uchar red\nproperty uchar green\nproperty uchar blue\n"
          "property float intensity\nproperty int classification\nproperty short mystery\n"
          "property float outlier\nend_header\n" % len(rows))
with open("in.ply", "wb") as f:
    f.write(header.encode())
    for p, r, g, b, intensity, cls, mystery, outlier in rows:
        f.write(struct.pack("<fffBBBfihf", *p, r, g, b, intensity, cls, mystery, outlier))
with open("in.xyz", "w") as f:
    for p, r, g, b, *_ in rows:
        f.write("%r %r %r %d %d %d\n" % (p[0], p[1], p[2], r, g, b))
PY
"$lpd" denoise in.ply -o out.ply --quiet --max_iters=10 --threads=2 >/dev/null 2>err.txt ||
  fail "denoise of the PLY failed: $(tail -1 err.txt)"
"$lpd" denoise in.xyz -o out.xyz --quiet --max_iters=10 --threads=2 >/dev/null 2>err.txt ||
  fail "denoise of the XYZ failed: $(tail -1 err.txt)"
python3 - <<'PY' || fail "attributes lost"
import struct
def read_ply(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    codes = {"float": "f", "double": "d", "uchar": "B", "char": "b", "short": "h", "ushort": "H",
             "int": "i", "uint": "I"}
    names, fmt, count = [], "<", 0
    for line in data[:end].decode().splitlines():
        w = line.split()
        if w[:2] == ["element", "vertex"]: count = int(w[2])
        if w[:1] == ["property"]: names.append(w[2]); fmt += codes[w[1]]
    size = struct.calcsize(fmt)
    return [dict(zip(names, struct.unpack_from(fmt, data, end + i * size))) for i in range(count)]
inp, out = read_ply("in.ply"), read_ply("out.ply")
assert len(out) > 2900, len(out)
carried = ["red", "green", "blue", "intensity", "classification", "mystery"]
for row in out:
    source = inp[row["source_index"]]
    for name in carried:
        assert row[name] == source[name], (name, row[name], source[name])
    assert row["input_outlier"] == source["outlier"]  # renamed beside lpd's own 'outlier'
    assert row["outlier"] in (0.0, 1.0)
xyz_in = [l.split() for l in open("in.xyz")]
xyz_out = [l.split() for l in open("out.xyz")]
assert len(xyz_out) == len(out) and all(len(r) == 6 for r in xyz_out)
for row, line in zip(out, xyz_out):
    assert line[3:] == xyz_in[row["source_index"]][3:], (line, xyz_in[row["source_index"]])
print("ok   %d kept points keep colours, intensity, class and an unknown short bit for bit "
      "(PLY), and their colour columns (XYZ)" % len(out))
PY
finish "attribute cases"
