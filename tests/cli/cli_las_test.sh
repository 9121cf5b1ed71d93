#!/usr/bin/env bash
# LAS: files written here by an independent writer (Python, from the ASPRS specification) in
# every supported version and point format, with extra bytes and a variable-length record,
# are denoised with --outliers=mark into LAS: every field of every point survives except
# the classification, which is 7 exactly on the points the same run flags (its PLY output
# says which), the coordinates are that run's within half a scale step, and the header keeps
# the scale, offset and record, with bounds and counts of the points written. LAZ and
# waveform formats are refused in one line.
# Usage: cli_las_test.sh PATH_TO_LPD
lpd=$(realpath "$1")
source "$(dirname "$0")/cli_test_lib.sh"
cd "$dir" || exit 1
cat >las.py <<'PY'
import random, struct, sys
CORE = {0: 20, 1: 28, 2: 26, 3: 34, 6: 30, 7: 36, 8: 38}
def header_size(minor): return 375 if minor == 4 else 235 if minor == 3 else 227
def write(path, minor, fmt, points, fields, extra, vlr, scale, offset):
    n, length = len(points), CORE[fmt] + extra
    h = bytearray(header_size(minor))
    h[0:4] = b"LASF"; h[24] = 1; h[25] = minor; h[26:26 + 4] = b"test"
    struct.pack_into("<HIIBH", h, 94, len(h), len(h) + len(vlr), 1 if vlr else 0, fmt, length)
    if fmt < 6: struct.pack_into("<I", h, 107, n)
    struct.pack_into("<6d", h, 131, *scale, *offset)
    if minor == 4: struct.pack_into("<Q", h, 247, n)
    body = bytearray()
    for p, f in zip(points, fields):
        r = bytearray(length)
        struct.pack_into("<3iH", r, 0, *[round((p[c] - offset[c]) / scale[c]) for c in range(3)],
                         f["intensity"])
        if fmt < 6:
            r[14] = f["return_number"] | f["number_of_returns"] << 3 | f["edge_of_flight_line"] << 7
            r[15] = f["classification"] | f["synthetic"] << 5
            struct.pack_into("<bBH", r, 16, f["scan_angle"] // 200, f["user_data"], f["point_source_id"])
            at = 20
            if fmt in (1, 3): struct.pack_into("<d", r, at, f["gps_time"]); at += 8
            if fmt in (2, 3): struct.pack_into("<3H", r, at, *f["rgb"])
        else:
            r[14] = f["return_number"] | f["number_of_returns"] << 4
            r[15] = f["synthetic"] | f["edge_of_flight_line"] << 7
            struct.pack_into("<BBhHd", r, 16, f["classification"], f["user_data"], f["scan_angle"],
                             f["point_source_id"], f["gps_time"])
            if fmt >= 7: struct.pack_into("<3H", r, 30, *f["rgb"])
            if fmt == 8: struct.pack_into("<H", r, 36, f["nir"])
        for b in range(extra): r[CORE[fmt] + b] = f["extra"][b]
        body += r
    open(path, "wb").write(bytes(h) + vlr + body)
def cube(n, seed):
    rng = random.Random(seed)
    points, fields = [], []
    for i in range(n):
        face, u, v = rng.randrange(6), rng.random(), rng.random()
        p = [u, v, face % 2] if face < 2 else ([u, face % 2, v] if face < 4 else [face % 2, u, v])
        p = [1000 + 10 * c + rng.gauss(0, 0.04) for c in p]
        if i % 97 == 0: p = [1000 + rng.uniform(-5, 15) for _ in range(3)]  # stray returns
        points.append(p)
        fields.append(dict(intensity=rng.randrange(65536), return_number=1 + i % 3,
                           number_of_returns=3, edge_of_flight_line=i % 2,
                           classification=2 + i % 3, synthetic=i % 2, scan_angle=rng.randrange(-3000, 3000),
                           user_data=rng.randrange(256), point_source_id=rng.randrange(65536),
                           gps_time=rng.uniform(0, 1e6), rgb=[rng.randrange(65536) for _ in range(3)],
                           nir=rng.randrange(65536), extra=[rng.randrange(256) for _ in range(3)]))
    return points, fields
if __name__ == "__main__":
    vlr = struct.pack("<H16sHH32s", 0, b"test_user", 12345, 8, b"a record lpd must keep") + b"8 bytes!"
    for minor, fmt in [(2, 0), (2, 1), (2, 2), (3, 3), (4, 6), (4, 7), (4, 8)]:
        points, fields = cube(3000, fmt)
        write("in_%d.las" % fmt, minor, fmt, points, fields, 3, vlr, [0.001, 0.001, 0.0005],
              [1000.0, 999.5, 1000.25])
PY
python3 las.py || fail "writing the LAS inputs failed"
for fmt in 0 1 2 3 6 7 8; do
  "$lpd" denoise "in_$fmt.las" -o "out_$fmt.las" --outliers=mark --quiet --threads=2 \
    --max_iters=10 >/dev/null 2>"err_$fmt.txt" || fail "format $fmt: $(tail -1 "err_$fmt.txt")"
  "$lpd" denoise "in_$fmt.las" -o "out_$fmt.ply" --outliers=mark --quiet --threads=2 \
    --max_iters=10 >/dev/null 2>&1 || fail "format $fmt to PLY failed"
done
python3 - <<'PY' || fail "LAS outputs do not match"
import struct
def read_las(path):
    d = open(path, "rb").read()
    assert d[:4] == b"LASF"
    minor, hsize, offset, nvlr, fmt, length = d[25], *struct.unpack_from("<HIIBH", d, 94)
    n = struct.unpack_from("<I", d, 107)[0] or (struct.unpack_from("<Q", d, 247)[0] if minor == 4 else 0)
    scale, off = struct.unpack_from("<3d", d, 131), struct.unpack_from("<3d", d, 155)
    bounds = struct.unpack_from("<6d", d, 179)
    records = [d[offset + i * length: offset + (i + 1) * length] for i in range(n)]
    xyz = [[struct.unpack_from("<i", r, 4 * c)[0] * scale[c] + off[c] for c in range(3)] for r in records]
    cls = [r[15] & 31 if fmt < 6 else r[16] for r in records]
    return dict(minor=minor, fmt=fmt, length=length, n=n, scale=scale, off=off, bounds=bounds,
                vlr=d[hsize:offset], nvlr=nvlr, records=records, xyz=xyz, cls=cls)
def read_ply(path):
    d = open(path, "rb").read()
    end = d.index(b"end_header\n") + 11
    codes = {"float": "f", "double": "d", "uchar": "B", "char": "b", "short": "h", "ushort": "H", "int": "i", "uint": "I"}
    names, fmt = [], "<"
    for line in d[:end].decode().splitlines():
        w = line.split()
        if w[:2] == ["element", "vertex"]: n = int(w[2])
        if w[:1] == ["property"]: names.append(w[2]); fmt += codes[w[1]]
    size = struct.calcsize(fmt)
    return [dict(zip(names, struct.unpack_from(fmt, d, end + i * size))) for i in range(n)]
for f in (0, 1, 2, 3, 6, 7, 8):
    a, b, ply = read_las("in_%d.las" % f), read_las("out_%d.las" % f), read_ply("out_%d.ply" % f)
    assert (b["minor"], b["fmt"], b["length"], b["scale"], b["off"], b["vlr"], b["nvlr"]) == \
           (a["minor"], a["fmt"], a["length"], a["scale"], a["off"], a["vlr"], a["nvlr"]), f
    assert b["n"] == a["n"] == len(ply), (f, b["n"], len(ply))
    flagged = 0
    for i, (ra, rb, p) in enumerate(zip(a["records"], b["records"], ply)):
        assert p["source_index"] == i
        cls_at = 15 if f < 6 else 16
        mask = 31 if f < 6 else 255
        # every byte but the coordinates and the class bits is the input's
        same_a = ra[12:cls_at] + bytes([ra[cls_at] & ~mask & 255]) + ra[cls_at + 1:]
        same_b = rb[12:cls_at] + bytes([rb[cls_at] & ~mask & 255]) + rb[cls_at + 1:]
        assert same_a == same_b, (f, i)
        expected = 7 if p["outlier"] else a["cls"][i]
        assert b["cls"][i] == expected, (f, i, b["cls"][i], expected)
        flagged += p["outlier"] == 1
        for c, key in enumerate("xyz"):
            assert abs(b["xyz"][i][c] - p[key]) <= b["scale"][c] / 2 + 1e-9, (f, i, c)
    lo = [min(x[c] for x in b["xyz"]) for c in range(3)]
    hi = [max(x[c] for x in b["xyz"]) for c in range(3)]
    assert list(b["bounds"]) == [hi[0], lo[0], hi[1], lo[1], hi[2], lo[2]], (f, b["bounds"])
    assert flagged >= 25, (f, flagged)  # the stray returns (one point in 97)
print("ok   LAS 1.2-1.4, formats 0-3 and 6-8: fields, extra bytes, record, scale and offset "
      "kept; class 7 exactly on the flagged points; bounds and counts of the output")
PY
printf 'LASF' >short.las
"$lpd" denoise short.las -o x.ply 2>err.txt && fail "a truncated LAS was accepted"
grep -q "ends inside the LAS header" err.txt || fail "truncated LAS: $(cat err.txt)"
python3 -c "
d = bytearray(open('in_0.las', 'rb').read()); d[104] |= 0x80; open('in.laz', 'wb').write(d)
d = bytearray(open('in_0.las', 'rb').read()); d[104] = 4; open('waveform.las', 'wb').write(d)"
"$lpd" denoise in.laz -o x.ply 2>err.txt && fail "LAZ was accepted"
grep -q "LAZ (compressed LAS).*laszip" err.txt || fail "LAZ: $(cat err.txt)"
"$lpd" denoise waveform.las -o x.ply 2>err.txt && fail "format 4 was accepted"
grep -q "point format 4 is not supported" err.txt || fail "format 4: $(cat err.txt)"
"$lpd" denoise in_0.las -o x.laz 2>err.txt && fail "writing LAZ was accepted"
grep -q "LAZ (compressed LAS) is not supported" err.txt || fail "LAZ output: $(cat err.txt)"
finish "LAS cases"
