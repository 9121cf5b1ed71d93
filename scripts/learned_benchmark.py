#!/usr/bin/env python3
"""The learned denoisers' benchmark protocol (ScoreDenoise, IterativePFN, P2P-Bridge), run on
any set of clean meshes: writes a sweep config, runs it with `lpd sweep` (resumable), and
prints per-shape and mean CD / P2M x 1e4 tables in Markdown.

Protocol: Poisson-disk samples of each mesh (10K and 50K), isotropic Gaussian noise of 1%, 2%
and 3% of the clean samples' unit-sphere radius, CD against the clean samples and P2M against
the mesh, both in the unit-sphere frame (experiments/evaluation/benchmark_metrics.h). Methods:
the noisy input, lpd at its defaults, and CGAL bilateral smoothing over a small grid, of which
the table keeps, per noise level and size, the setting with the lowest mean CD over all shapes
(tuned against the ground truth, a bound on what a user could reach with it).

Usage:
  scripts/learned_benchmark.py [--meshes FILE_OR_DIR ...] [--sizes 10000 50000]
                               [--sigmas 0.01 0.02 0.03] [--no-thin] [--seed 1]
                               [--variant NAME=VALUE[,VALUE...] ...] [--results DIR]
  scripts/learned_benchmark.py --table-only --results DIR
Default meshes: every mesh of ${LPD_DATA:-../shared/data}/meshes except the 8-vertex cube,
plus procedural thin parts (two plates, two parallel sheets, a thin cylinder).
"""
import argparse
import collections
import csv
import math
import os
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
MESH_SUFFIXES = {".off", ".obj", ".ply", ".stl"}
# Thin parts in the unit-sphere frame: plate thickness 0.03 / 0.06 of a unit square is
# 4.2 / 8.5 noise deviations at 1% (radius 0.707) and 1.4 / 2.8 at 3%.
THIN_SHAPES = [
    ("plate_t0.03", "box:size_x=1,size_y=1,size_z=0.03"),
    ("plate_t0.06", "box:size_x=1,size_y=1,size_z=0.06"),
    ("sheets_gap0.04", "sheets:size=1,gap=0.04"),
    ("thin_cylinder", "cylinder:radius=0.03,height=1"),
]
BILATERAL_GRID = {"k": [30, 60, 120], "sharpness_angle": [25]}


def default_meshes():
    data = pathlib.Path(os.environ.get("LPD_DATA", ROOT.parent / "shared" / "data"))
    meshes = sorted(p for p in (data / "meshes").glob("*") if p.suffix in MESH_SUFFIXES)
    return [p for p in meshes if p.stem != "cube"]


def expand(paths):
    meshes = []
    for path in map(pathlib.Path, paths):
        if path.is_dir():
            meshes += sorted(p for p in path.iterdir() if p.suffix.lower() in MESH_SUFFIXES)
        elif path.is_file():
            meshes.append(path)
        else:
            sys.exit(f"learned_benchmark: no such mesh or directory: {path}")
    if not meshes:
        sys.exit("learned_benchmark: no meshes found")
    return meshes


def write_config(path, meshes, sizes, sigmas, thin, variants, seed):
    lines = [
        "# Written by scripts/learned_benchmark.py: the learned denoisers' benchmark protocol.",
        "name: learned_benchmark",
        f"seed: {seed}",
        "parallel_cells: 1",
        "datasets:",
    ]
    for size in sizes:
        label = f"{size // 1000}k"
        for mesh in meshes:
            lines += [f"  - mesh: {mesh.resolve()}", f"    name: {mesh.stem}@{label}",
                      f"    points: {size}", "    sampling: poisson_disk"]
        for name, shape in (THIN_SHAPES if thin else []):
            lines += [f"  - shape: {shape}", f"    name: {name}@{label}",
                      f"    points: {size}", "    sampling: poisson_disk"]
    lines += ["noise:", "  - model: gaussian", "    scale: unit_sphere_radius",
              f"    sigma: [{', '.join(str(s) for s in sigmas)}]",
              "methods:", "  - method: none", "  - method: lpd"]
    for variant in variants:  # NAME=VALUE[,VALUE...]: one lpd row per value
        name, values = variant.split("=", 1)
        lines += ["  - method: lpd", f"    {name}: [{', '.join(values.split(','))}]"]
    lines.append("  - method: bilateral")
    for key, values in BILATERAL_GRID.items():
        lines.append(f"    {key}: [{', '.join(str(v) for v in values)}]")
    path.write_text("\n".join(lines) + "\n")


def number(text):
    try:
        return float(text)
    except ValueError:
        return math.nan


def load(results):
    rows = list(csv.DictReader(open(results / "results.csv")))
    # (shape, size, sigma) -> method label -> (cd, p2m, seconds)
    cells = collections.defaultdict(dict)
    for row in rows:
        shape, size = row["dataset"].rsplit("@", 1)
        label = row["method"]
        if row["method_parameters"]:
            label += " " + row["method_parameters"]
        cells[(shape, size, number(row["noise_sigma"]))][label] = (
            number(row["cd_x1e4"]), number(row["p2m_x1e4"]), number(row["seconds"]))
    return cells


def mean(values):
    values = [v for v in values if not math.isnan(v)]
    return sum(values) / len(values) if values else math.nan


def print_tables(results):
    cells = load(results)
    levels = sorted({(size, sigma) for _, size, sigma in cells},
                    key=lambda level: (int(level[0][:-1]), level[1]))
    shapes = sorted({shape for shape, _, _ in cells})
    # The bilateral setting with the lowest mean CD over the shapes, per size and level.
    best_bilateral = {}
    for size, sigma in levels:
        settings = collections.defaultdict(list)
        for shape in shapes:
            for label, figures in cells.get((shape, size, sigma), {}).items():
                if label.startswith("bilateral"):
                    settings[label].append(figures[0])
        if settings:
            best_bilateral[(size, sigma)] = min(settings, key=lambda s: mean(settings[s]))
    columns = [f"{size} {sigma * 100:g}%" for size, sigma in levels]
    print("## Means over shapes (CD / P2M x 1e4)\n")
    print("| method | " + " | ".join(columns) + " |")
    print("|---" * (len(columns) + 1) + "|")
    thin = {name for name, _ in THIN_SHAPES}
    groups = [("", shapes), (", meshes", [s for s in shapes if s not in thin]),
              (", thin parts", [s for s in shapes if s in thin])]
    for group, members in groups:
        if not members or (group and len(members) == len(shapes)):
            continue
        variants = sorted({label for cell in cells.values() for label in cell
                           if label.startswith("lpd ")})
        for method in ["none", "lpd", *variants, "bilateral"]:
            row = []
            for size, sigma in levels:
                label = best_bilateral.get((size, sigma)) if method == "bilateral" else method
                figures = [cells[(s, size, sigma)].get(label) for s in members
                           if (s, size, sigma) in cells]
                figures = [f for f in figures if f]
                row.append(f"{mean([f[0] for f in figures]):.2f} / "
                           f"{mean([f[1] for f in figures]):.2f}" if figures else "")
            name = {"none": "noisy input", "lpd": "lpd (defaults)",
                    "bilateral": "CGAL bilateral, best setting per column"}.get(
                        method, f"lpd --{method[4:]}")
            print(f"| {name}{group} ({len(members)}) | " + " | ".join(row) + " |")
    if best_bilateral:
        print("\nBilateral settings: " + "; ".join(
            f"{size} {sigma * 100:g}%: {label.split(' ', 1)[1]}"
            for (size, sigma), label in best_bilateral.items()))
    print("\n## Per shape: lpd CD / P2M x 1e4 (noisy input in brackets; ! = worse than the input)\n")
    print("| shape | " + " | ".join(columns) + " |")
    print("|---" * (len(columns) + 1) + "|")
    worse = 0
    for shape in shapes:
        row = []
        for size, sigma in levels:
            cell = cells.get((shape, size, sigma), {})
            if "lpd" not in cell or "none" not in cell:
                row.append("")
                continue
            (cd, p2m, _), (cd0, p2m0, _) = cell["lpd"], cell["none"]
            mark = "!" if cd > cd0 or p2m > p2m0 else ""
            worse += bool(mark)
            row.append(f"{cd:.2f} / {p2m:.2f} ({cd0:.2f} / {p2m0:.2f}){mark}")
        print(f"| {shape} | " + " | ".join(row) + " |")
    print("\n## Per shape: lpd seconds\n")
    print("| shape | " + " | ".join(columns) + " |")
    print("|---" * (len(columns) + 1) + "|")
    for shape in shapes:
        row = [f"{cells[(shape, size, sigma)]['lpd'][2]:.2f}"
               if "lpd" in cells.get((shape, size, sigma), {}) else ""
               for size, sigma in levels]
        print(f"| {shape} | " + " | ".join(row) + " |")
    print(f"\n{worse} cells where lpd's output is worse than its noisy input in CD or P2M.")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--meshes", nargs="+", help="mesh files or directories")
    parser.add_argument("--sizes", nargs="+", type=int, default=[10000, 50000])
    parser.add_argument("--sigmas", nargs="+", type=float, default=[0.01, 0.02, 0.03])
    parser.add_argument("--no-thin", action="store_true", help="leave out the thin parts")
    parser.add_argument("--seed", type=int, default=1,
                        help="the draws' seed (samples and noise); the tables in docs/ are seed 1")
    parser.add_argument("--results",
                        help="results directory (default: results/learned_benchmark, with "
                             "_seedN after it for a seed other than 1)")
    parser.add_argument("--threads", type=int, default=0, help="0: all cores")
    parser.add_argument("--table-only", action="store_true", help="only print the tables")
    parser.add_argument("--variant", action="append", default=[], metavar="NAME=VALUES",
                        help="also run lpd with --NAME=VALUE for each of the comma-separated "
                             "values (repeatable), e.g. k_radius_sigmas=3.5,4.6")
    parser.add_argument("--lpd", default=str(ROOT / "build" / "lpd"), help="the lpd binary")
    args = parser.parse_args()
    default_results = "results/learned_benchmark" + (f"_seed{args.seed}" if args.seed != 1 else "")
    results = pathlib.Path(args.results or default_results)
    if not args.table_only:
        meshes = expand(args.meshes) if args.meshes else default_meshes()
        results.mkdir(parents=True, exist_ok=True)
        config = results / "learned_benchmark.yaml"
        write_config(config, meshes, args.sizes, args.sigmas, not args.no_thin, args.variant,
                     args.seed)
        command = [args.lpd, "sweep", str(config), f"--results_dir={results}"]
        if args.threads:
            command.append(f"--threads={args.threads}")
        subprocess.run(command, check=True)
    print_tables(results)


if __name__ == "__main__":
    main()
