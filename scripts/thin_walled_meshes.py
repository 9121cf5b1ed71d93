#!/usr/bin/env python3
"""Writes three thin-walled test meshes (OFF) for the learned denoisers' benchmark protocol:
parts whose walls meet at junctions, as cast and furniture parts do, none of them tuned on.

  cup.off      a cup turned about z: outer radius 0.5, height 0.8, wall and bottom 0.03
  chair.off    four legs 0.05 square, a seat 0.04 thick, two back posts and three slats 0.02
  bracket.off  a plate 0.04 thick, four ribs 0.025 thick standing on it, a back wall 0.04

Faces are split into triangles of about 0.02, so that the mesh-to-result half of P2M reads
coverage as on scanned meshes. Pieces that touch keep their own faces (the mesh is a union
of closed or open boxes, not a solid), as many benchmark meshes do.

Usage:
  scripts/thin_walled_meshes.py OUT_DIR
  scripts/learned_benchmark.py --meshes OUT_DIR --no-thin --results DIR
"""
import math
import pathlib
import sys

CELL = 0.02  # target triangle size


def box(lo, hi, skip=()):
    """The faces of the box [lo, hi] in triangles of about CELL; skip holds (axis, side)
    pairs of faces to leave out (side 0 at lo, 1 at hi)."""
    vertices, faces = [], []
    for axis in range(3):
        b, c = (axis + 1) % 3, (axis + 2) % 3
        for side in (0, 1):
            if (axis, side) in skip:
                continue
            nb = max(1, math.ceil((hi[b] - lo[b]) / CELL))
            nc = max(1, math.ceil((hi[c] - lo[c]) / CELL))
            base = len(vertices)
            for i in range(nb + 1):
                for j in range(nc + 1):
                    p = [0.0, 0.0, 0.0]
                    p[axis] = hi[axis] if side else lo[axis]
                    p[b] = lo[b] + (hi[b] - lo[b]) * i / nb
                    p[c] = lo[c] + (hi[c] - lo[c]) * j / nc
                    vertices.append(p)
            for i in range(nb):
                for j in range(nc):
                    a = base + i * (nc + 1) + j
                    faces += [(a, a + nc + 1, a + nc + 2), (a, a + nc + 2, a + 1)]
    return vertices, faces


def revolve(profile, steps=160):
    """The surface swept by the (r, z) polyline `profile` about the z axis."""
    vertices, faces = [], []
    m = len(profile)
    for k in range(steps):
        angle = 2 * math.pi * k / steps
        vertices += [[r * math.cos(angle), r * math.sin(angle), z] for r, z in profile]
    for k in range(steps):
        k2 = (k + 1) % steps
        for i in range(m - 1):
            a, b = k * m + i, k2 * m + i
            faces += [(a, b, b + 1), (a, b + 1, a + 1)]
    return vertices, faces


def subdivide(profile):
    """The polyline with points about CELL apart along each segment."""
    out = []
    for (r0, z0), (r1, z1) in zip(profile[:-1], profile[1:]):
        n = max(1, math.ceil(math.hypot(r1 - r0, z1 - z0) / CELL))
        out += [(r0 + (r1 - r0) * i / n, z0 + (z1 - z0) * i / n) for i in range(n)]
    return out + [profile[-1]]


def union(parts):
    vertices, faces = [], []
    for v, f in parts:
        offset = len(vertices)
        vertices += v
        faces += [(a + offset, b + offset, c + offset) for a, b, c in f]
    return vertices, faces


def cup():
    wall = 0.03
    return revolve(subdivide([(0, 0), (0.5, 0), (0.5, 0.8), (0.5 - wall, 0.8),
                              (0.5 - wall, wall), (0, wall)]))


def chair():
    parts = []
    for x in (0.0, 0.45):
        for y in (0.0, 0.45):  # legs, open at the top where the seat covers them
            parts.append(box((x, y, 0.0), (x + 0.05, y + 0.05, 0.45), skip={(2, 1)}))
    parts.append(box((0.0, 0.0, 0.45), (0.5, 0.5, 0.49)))
    for x in (0.0, 0.45):  # back posts
        parts.append(box((x, 0.46, 0.49), (x + 0.04, 0.5, 1.0)))
    for z in (0.65, 0.8, 0.95):  # slats, open at their ends against the posts
        parts.append(box((0.04, 0.475, z), (0.45, 0.495, z + 0.04), skip={(0, 0), (0, 1)}))
    return union(parts)


def bracket():
    parts = [box((0.0, 0.0, 0.0), (1.0, 0.6, 0.04))]
    for x in (0.1, 0.35, 0.6, 0.85):  # ribs, open at the bottom where the plate covers them
        parts.append(box((x, 0.0, 0.04), (x + 0.025, 0.56, 0.35), skip={(2, 0)}))
    parts.append(box((0.0, 0.56, 0.04), (1.0, 0.6, 0.5), skip={(2, 0)}))
    return union(parts)


def write_off(path, vertices, faces):
    with open(path, "w") as out:
        out.write(f"OFF\n{len(vertices)} {len(faces)} 0\n")
        out.writelines("%.7f %.7f %.7f\n" % tuple(p) for p in vertices)
        out.writelines("3 %d %d %d\n" % f for f in faces)


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: thin_walled_meshes.py OUT_DIR")
    out = pathlib.Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    for name, make in (("cup", cup), ("chair", chair), ("bracket", bracket)):
        write_off(out / f"{name}.off", *make())
        print(out / f"{name}.off")


if __name__ == "__main__":
    main()
