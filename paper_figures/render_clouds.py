#!/usr/bin/env python3
"""Renders the point clouds a sweep saved (`save_clouds: true`) as PNG, like Figs. 4, 6, 7, 15.

    python3 paper_figures/render_clouds.py CONFIG_NAME [--results DIR] [--out DIR]

For every cell of results/CONFIG_NAME/results.jsonl with saved clouds, one PNG with up to
three panels from one fixed viewpoint: the noisy input coloured by the method's outlier
indicator (true outliers ringed when labels exist), the input coloured by the feature
indicator, and the output coloured by its distance to the clean surface (the error map of
Fig. 15, one colour scale per config). Needs Debian's python3-numpy and python3-matplotlib.
"""
import argparse
import json
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

PLY_TYPES = {"float": "f4", "double": "f8", "char": "i1", "uchar": "u1", "short": "i2",
             "ushort": "u2", "int": "i4", "uint": "u4"}
VIEW = dict(elev=28, azim=-58)  # one fixed viewpoint for every rendering


def read_ply(path):
    """The vertex properties of a binary little-endian PLY as a dict of numpy arrays."""
    with open(path, "rb") as f:
        if f.readline().strip() != b"ply":
            raise ValueError(f"{path}: not a PLY file")
        count, fields = 0, []
        while True:
            line = f.readline().decode("ascii").split()
            if not line:
                raise ValueError(f"{path}: truncated header")
            if line[0] == "format" and line[1] != "binary_little_endian":
                raise ValueError(f"{path}: expected binary_little_endian, got {line[1]}")
            if line[:2] == ["element", "vertex"]:
                count = int(line[2])
            elif line[0] == "property":
                fields.append((line[2], "<" + PLY_TYPES[line[1]]))
            elif line[0] == "end_header":
                break
        data = np.fromfile(f, dtype=np.dtype(fields), count=count)
    return {name: data[name] for name, _ in fields}


def set_axes_equal(axis, points):
    center = (points.max(axis=0) + points.min(axis=0)) / 2
    radius = (points.max(axis=0) - points.min(axis=0)).max() / 2
    for setter, c in zip((axis.set_xlim, axis.set_ylim, axis.set_zlim), center):
        setter(c - radius, c + radius)
    axis.set_axis_off()
    axis.view_init(**VIEW)


def scatter(axis, xyz, colors, title, **style):
    axis.scatter(xyz[:, 0], xyz[:, 1], xyz[:, 2], c=colors, s=0.6, linewidths=0,
                 depthshade=False, **style)
    set_axes_equal(axis, xyz)
    axis.set_title(title, fontsize=8)


def flag_colors(flags):
    return np.where(flags > 0.5, "#d62728", "#b0b0b0")


def slug(text):
    return re.sub(r"[^A-Za-z0-9.=_-]+", "_", text).strip("_")


def read_records(results, name):
    """The JSON records of results/NAME/results.jsonl, or None (with a message) if absent."""
    path = os.path.join(results, name, "results.jsonl")
    if not os.path.exists(path):
        print(f"skip {name}: no results in {path} (run: build/lpd sweep configs/{name}.yaml)")
        return None
    with open(path) as f:
        return [json.loads(line) for line in f if line.strip()]


def config_arguments(description):
    """The command line shared by the rendering scripts: config names, --results, --out."""
    parser = argparse.ArgumentParser(description=description)
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser.add_argument("configs", nargs="+", help="config names (results/NAME)")
    parser.add_argument("--results", default=os.path.join(root, "results"))
    parser.add_argument("--out", default=os.path.join(root, "paper_figures", "out"))
    return parser


def render_config(name, results, out):
    records = read_records(results, name)
    if records is None:
        return []
    clouds = os.path.join(results, name, "clouds")
    outputs = {r["cell_id"]: read_ply(os.path.join(clouds, r["cell_id"] + "_output.ply"))
               for r in records if os.path.exists(os.path.join(clouds, r["cell_id"] + "_output.ply"))}
    distances = [c["distance"] for c in outputs.values() if "distance" in c]
    top = float(np.percentile(np.concatenate(distances), 99)) if distances else 1.0
    written = []
    for record in records:
        cell = record["cell_id"]
        if cell not in outputs:
            continue
        cloud_in = read_ply(os.path.join(clouds, cell + "_input.ply"))
        cloud_out = outputs[cell]
        xyz_in = np.column_stack([cloud_in[c] for c in "xyz"])
        xyz_out = np.column_stack([cloud_out[c] for c in "xyz"])
        method = record["method"] + (f" ({record['method_parameters']})"
                                     if record.get("method_parameters") else "")
        panels = []
        if "outlier" in cloud_in:
            panels.append("outlier")
        if "feature" in cloud_in:
            panels.append("feature")
        if "distance" in cloud_out:
            panels.append("distance")
        if not panels:
            panels.append("input")
        figure = plt.figure(figsize=(4.2 * len(panels), 4.4))
        for p, panel in enumerate(panels):
            axis = figure.add_subplot(1, len(panels), p + 1, projection="3d")
            if panel == "outlier":
                flagged = int(cloud_in["outlier"].sum())
                title = f"outlier indicator: {flagged} flagged"
                if "true_outlier" in cloud_in and cloud_in["true_outlier"].sum() > 0:
                    truth = cloud_in["true_outlier"] > 0.5
                    hits = int((truth & (cloud_in["outlier"] > 0.5)).sum())
                    title += f", {hits} of {int(truth.sum())} true outliers"
                scatter(axis, xyz_in, flag_colors(cloud_in["outlier"]), title)
            elif panel == "feature":
                scatter(axis, xyz_in, flag_colors(cloud_in["feature"]),
                        f"feature indicator: {int(cloud_in['feature'].sum())} points")
            elif panel == "distance":
                mean = record.get("mean_distance_normalized") or float("nan")
                scatter(axis, xyz_out, cloud_out["distance"], "distance to the clean surface"
                        f" (mean {1e3 * mean:.2f}e-3 of diagonal)", cmap="viridis", vmin=0,
                        vmax=top)
            else:
                scatter(axis, xyz_in, "#4878a8", "input")
        figure.suptitle(f"{record['dataset']} | noise {record.get('noise_sigma', '')} | {method}",
                        fontsize=9)
        file = os.path.join(out, slug(f"{name}_{record['dataset']}_{record.get('noise_sigma', '')}"
                                      f"_{method}") + ".png")
        figure.savefig(file, dpi=110, bbox_inches="tight")
        plt.close(figure)
        print(f"wrote {file}")
        written.append(file)
    return written


def main():
    args = config_arguments(__doc__.splitlines()[0]).parse_args()
    os.makedirs(args.out, exist_ok=True)
    for name in args.configs:
        render_config(name, args.results, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
