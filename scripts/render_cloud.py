#!/usr/bin/env python3
"""A picture of one lpd output, for a person: PNG with up to two panels from one viewpoint.

    python3 scripts/render_cloud.py OUTPUT.ply [--color outlier|feature|FIELD] \\
        [--input NOISY.xyz|.ply] [--view ELEV,AZIM] -o picture.png

Left: OUTPUT's points coloured by a field it carries (a 0/1 flag in red over grey, any other
field on a colour scale: outlier_score, feature_score, intensity, a sweep's distance to the
clean surface, ...). Right, with --input: the input the run started from, its removed
points (those no output point comes from, by source_index) in red over the kept ones. Needs
Debian's python3-numpy and python3-matplotlib.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "paper_figures"))
import render_clouds  # noqa: E402  (read_ply, the viewpoint and the scatter style)
from render_clouds import flag_colors, plt, read_ply, scatter  # noqa: E402


def read_points(path):
    if path.endswith(".ply"):
        ply = read_ply(path)
        return np.stack([ply["x"], ply["y"], ply["z"]], axis=1).astype(float)
    return np.loadtxt(path, comments="#", usecols=(0, 1, 2), ndmin=2)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("output", help="a PLY written by lpd denoise")
    parser.add_argument("--color", default="outlier_score", help="field of OUTPUT to colour by")
    parser.add_argument("--input", help="the input of the run: show its removed points")
    parser.add_argument("--view", default=None, help="elevation,azimuth in degrees")
    parser.add_argument("-o", "--out", required=True, help="PNG to write")
    args = parser.parse_args()
    if args.view:
        elev, azim = (float(v) for v in args.view.split(","))
        render_clouds.VIEW.update(elev=elev, azim=azim)
    ply = read_ply(args.output)
    xyz = np.stack([ply["x"], ply["y"], ply["z"]], axis=1).astype(float)
    if args.color not in ply:
        sys.exit(f"{args.output} has no field '{args.color}' (it has {', '.join(ply)})")
    values = ply[args.color].astype(float)
    panels = 2 if args.input else 1
    figure = plt.figure(figsize=(5.5 * panels, 5.5), dpi=150)
    axis = figure.add_subplot(1, panels, 1, projection="3d")
    if set(np.unique(values)) <= {0.0, 1.0}:
        scatter(axis, xyz, flag_colors(values),
                f"{os.path.basename(args.output)}: {args.color} ({int(values.sum())} of {len(values)})")
    else:
        scatter(axis, xyz, values, f"{os.path.basename(args.output)}: {args.color}", cmap="viridis")
    if args.input:
        source = read_points(args.input)
        removed = np.ones(len(source), bool)
        removed[ply["source_index"].astype(np.int64)] = False
        order = np.argsort(removed)  # removed points drawn last, on top
        axis = figure.add_subplot(1, panels, 2, projection="3d")
        scatter(axis, source[order], flag_colors(removed[order].astype(float)),
                f"{os.path.basename(args.input)}: removed points ({removed.sum()} of {len(source)})")
    for axis in figure.axes:
        axis.set_box_aspect(None, zoom=1.5)
    figure.tight_layout()
    figure.savefig(args.out)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
