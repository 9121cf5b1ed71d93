#!/usr/bin/env python3
"""Writes the thin-walled test meshes of docs/method.md ("Thin parts") as OFF files.

  hollow_box.off  a 1 x 0.8 x 0.6 box with a box cavity, walls 0.04 thick
  tube.off        a closed cylinder of radius 0.4, height 1.28, with a cylindrical cavity,
                  walls 0.04 thick
  chair.off       a seat 0.03 thick on four 0.04 x 0.04 legs, two back posts and three
                  slats 0.02 thick, on a 0.5 x 0.5 x 0.95 frame (boxes that touch or
                  overlap, as a triangle soup)

Sample them as the benchmark does, e.g.
  build/lpd noise --mesh chair.off --points 10000 --sampling poisson_disk \
      --noise_scale unit_sphere_radius --sigma 0.03 --seed 7 -o noisy.ply --clean_output clean.ply
Usage: scripts/thin_test_meshes.py [OUTPUT_DIR]
"""
import math
import os
import sys


def box(lo, hi, inward=False):
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    corners = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
               (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    faces = [(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4),
             (2, 3, 7), (2, 7, 6), (1, 2, 6), (1, 6, 5), (3, 0, 4), (3, 4, 7)]
    if inward:
        faces = [(a, c, b) for a, b, c in faces]
    return corners, faces


def closed_cylinder(radius, height, segments, inward=False):
    ring = [(radius * math.cos(2 * math.pi * i / segments),
             radius * math.sin(2 * math.pi * i / segments)) for i in range(segments)]
    vertices = [(x, y, -height / 2) for x, y in ring] + [(x, y, height / 2) for x, y in ring]
    bottom, top = 2 * segments, 2 * segments + 1
    vertices += [(0.0, 0.0, -height / 2), (0.0, 0.0, height / 2)]
    faces = []
    for i in range(segments):
        j = (i + 1) % segments
        faces += [(i, j, segments + j), (i, segments + j, segments + i),
                  (bottom, j, i), (top, segments + i, segments + j)]
    if inward:
        faces = [(a, c, b) for a, b, c in faces]
    return vertices, faces


def write_off(path, parts):
    vertices, faces = [], []
    for part_vertices, part_faces in parts:
        offset = len(vertices)
        vertices += part_vertices
        faces += [(a + offset, b + offset, c + offset) for a, b, c in part_faces]
    with open(path, "w") as out:
        out.write(f"OFF\n{len(vertices)} {len(faces)} 0\n")
        out.writelines("%.9g %.9g %.9g\n" % v for v in vertices)
        out.writelines("3 %d %d %d\n" % f for f in faces)
    print("wrote", path)


def main():
    directory = sys.argv[1] if len(sys.argv) > 1 else "."
    os.makedirs(directory, exist_ok=True)
    wall = 0.04
    write_off(os.path.join(directory, "hollow_box.off"),
              [box((0, 0, 0), (1, 0.8, 0.6)),
               box((wall, wall, wall), (1 - wall, 0.8 - wall, 0.6 - wall), inward=True)])
    write_off(os.path.join(directory, "tube.off"),
              [closed_cylinder(0.4, 1.28, 256),
               closed_cylinder(0.4 - wall, 1.28 - 2 * wall, 256, inward=True)])
    chair = [box((0, 0, 0.45), (0.5, 0.5, 0.48))]
    chair += [box((x, y, 0), (x + 0.04, y + 0.04, 0.45))
              for x, y in [(0, 0), (0.46, 0), (0, 0.46), (0.46, 0.46)]]
    chair += [box((x, 0.47, 0.48), (x + 0.04, 0.5, 0.95)) for x in (0, 0.46)]
    chair += [box((0.04, 0.48, z), (0.46, 0.5, z + 0.06)) for z in (0.6, 0.72, 0.84)]
    write_off(os.path.join(directory, "chair.off"), chair)


if __name__ == "__main__":
    main()
