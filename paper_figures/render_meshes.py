#!/usr/bin/env python3
"""Renders the meshes a sweep reconstructed (`reconstructions:`) side by side, like Figs. 13-14.

    python3 paper_figures/render_meshes.py CONFIG_NAME [--results DIR] [--out DIR]
                                           [--reconstruction advancing_front|scale_space]

For every row of the config (dataset and noise), each method's best grid point by MSE (the
cell Table 1 reports) is drawn flat-shaded from one fixed viewpoint: one PNG per method and
one with all methods of the row side by side. Needs python3-numpy and python3-matplotlib.
"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

from render_clouds import VIEW, config_arguments, read_records, set_axes_equal, slug  # noqa: E402

BASE_COLOR = np.array([0.78, 0.80, 0.86])


def read_off(path):
    """Vertices (n x 3) and triangles (m x 3) of an OFF file with triangular faces."""
    with open(path) as f:
        tokens = f.read().split()
    if not tokens or tokens[0] != "OFF":
        raise ValueError(f"{path}: not an OFF file")
    num_vertices, num_faces = int(tokens[1]), int(tokens[2])
    numbers = np.array(tokens[4:4 + 3 * num_vertices + 4 * num_faces], dtype=float)
    vertices = numbers[:3 * num_vertices].reshape(-1, 3)
    faces = numbers[3 * num_vertices:].reshape(-1, 4)
    if faces.size and not np.all(faces[:, 0] == 3):
        raise ValueError(f"{path}: only triangles are supported")
    return vertices, faces[:, 1:].astype(int)


def view_direction():
    """Unit vector from the scene toward the camera of VIEW (matplotlib's convention)."""
    elev, azim = math.radians(VIEW["elev"]), math.radians(VIEW["azim"])
    return np.array([math.cos(elev) * math.cos(azim), math.cos(elev) * math.sin(azim),
                     math.sin(elev)])


def draw_mesh(axis, vertices, triangles, title):
    """Flat shading: each face lit by a light near the camera, both sides alike."""
    corners = vertices[triangles]
    normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    lengths = np.linalg.norm(normals, axis=1, keepdims=True)
    normals = normals / np.where(lengths > 0, lengths, 1)
    light = view_direction() + np.array([0.3, -0.2, 0.4])
    light /= np.linalg.norm(light)
    intensity = 0.25 + 0.75 * np.abs(normals @ light)
    colors = np.clip(intensity[:, None] * BASE_COLOR, 0, 1)
    axis.add_collection3d(Poly3DCollection(corners, facecolors=colors, edgecolors="none",
                                           linewidths=0))
    set_axes_equal(axis, vertices[np.unique(triangles)])
    axis.set_box_aspect(None, zoom=1.2)  # matplotlib's 3D axes leave wide margins
    axis.set_title(title, fontsize=8)


def best_cells(records):
    """{(dataset, noise): {method: record}} with the lowest normalized MSE per method."""
    rows = {}
    for record in records:
        sigma = record.get("noise_sigma")
        noise = "as_given" if sigma is None else str(sigma)
        if record.get("num_outliers"):
            noise += f"_{record['num_outliers']}_outliers"
        key = (record["dataset"], noise)
        method = record["method"]
        mse = record.get("mse_normalized")
        mse = math.inf if mse is None else float(mse)
        best = rows.setdefault(key, {}).get(method)
        if best is None or mse < float(best.get("mse_normalized") or math.inf):
            rows[key][method] = record
    return rows


def method_title(record):
    mse = record.get("mse_normalized")
    text = record["method"]
    if record.get("method_parameters"):
        text += f"\n{record['method_parameters']}"
    if mse is not None:
        text += f"\nMSE {float(mse) / 1e-5:.2f}e-5"
    return text


def render_config(name, results, out, reconstruction="advancing_front"):
    records = read_records(results, name)
    if records is None:
        return []
    meshes = os.path.join(results, name, "meshes")
    order = ["none", "lpd", "ceres", "bilateral", "jet", "wlop"]
    written = []
    for (dataset, noise), methods in sorted(best_cells(records).items()):
        cells = [(m, methods[m]) for m in sorted(methods, key=lambda m: (order.index(m)
                                                                          if m in order else 99))]
        loaded = []
        for method, record in cells:
            file = os.path.join(meshes, f"{record['cell_id']}_{reconstruction}.off")
            if os.path.exists(file):
                loaded.append((method, record, read_off(file)))
        if not loaded:
            continue
        stem = slug(f"{name}_{dataset}_{noise}_{reconstruction}")
        figure = plt.figure(figsize=(3.4 * len(loaded), 3.8))
        for index, (method, record, (vertices, triangles)) in enumerate(loaded):
            axis = figure.add_subplot(1, len(loaded), index + 1, projection="3d")
            draw_mesh(axis, vertices, triangles, method_title(record))
            single = plt.figure(figsize=(4, 4.2))
            draw_mesh(single.add_subplot(projection="3d"), vertices, triangles,
                      method_title(record))
            file = os.path.join(out, f"{stem}_{method}.png")
            single.savefig(file, dpi=110, bbox_inches="tight")
            plt.close(single)
            written.append(file)
        figure.suptitle(f"{dataset} | noise {noise.replace('_', ' ')} | "
                        f"{reconstruction.replace('_', ' ')}",
                        fontsize=9)
        file = os.path.join(out, f"{stem}.png")
        figure.savefig(file, dpi=110, bbox_inches="tight")
        plt.close(figure)
        written.append(file)
        print(f"wrote {file} and {len(loaded)} single renderings")
    return written


def main():
    parser = config_arguments(__doc__.splitlines()[0])
    parser.add_argument("--reconstruction", default="advancing_front",
                        choices=["advancing_front", "scale_space"])
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    for name in args.configs:
        render_config(name, args.results, args.out, args.reconstruction)
    return 0


if __name__ == "__main__":
    sys.exit(main())
