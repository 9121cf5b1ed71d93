#!/usr/bin/env python3
"""Wall time of `lpd denoise` at its defaults against another lpd build, on the learned
denoisers' benchmark protocol (docs/performance.md, "Time against the first benchmark's
build").

Each cell is drawn once with this build's `lpd noise --seed 1`: Poisson-disk samples of every
mesh and procedural thin part (scripts/learned_benchmark.py), isotropic Gaussian noise in the
unit-sphere frame. The two builds then run on it in turn, --repeats times each, and each
keeps its best wall time (starting the program and reading and writing the PLY included).
Prints a Markdown table, reference -> this build (ratio), per shape and cell, with the mean
and the largest ratio of each column; ratios over --bound are in bold.

Usage:
  scripts/time_against_build.py --reference OTHER_LPD [--lpd build/lpd] [--repeats 2]
      [--sizes 10000 50000] [--sigmas 0.01 0.02 0.03] [--meshes FILE_OR_DIR ...]
      [--no-thin] [--bound 1.5] [--work DIR]
The benchmark issue's first build, for instance:
  git worktree add /tmp/first 2efe2bb
  cmake -S /tmp/first -B /tmp/first/build -DCMAKE_BUILD_TYPE=Release
  make -C /tmp/first/build -j2 lpd            # then --reference /tmp/first/build/lpd
Run it alone on the machine: single runs vary by up to 1.3x on a 2-core machine. The 78
cells take about 25 minutes at --repeats 2.
"""
import argparse
import pathlib
import subprocess
import sys
import tempfile
import time

sys.dont_write_bytecode = True  # no __pycache__ left in scripts/ by the import below
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from learned_benchmark import ROOT, THIN_SHAPES, default_meshes, expand  # noqa: E402


def draw(lpd, source, size, sigma, path):
    """Writes the seed-1 draw of one cell to `path` (kept if it is there already)."""
    if path.exists():
        return
    kind, value = source
    command = [str(lpd), "noise", f"--{kind}", str(value), "--points", str(size),
               "--sampling", "poisson_disk", "--noise_scale", "unit_sphere_radius",
               "--sigma", str(sigma), "--seed", "1", "-o", str(path)]
    done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        sys.exit(f"time_against_build: `{' '.join(command)}` failed: {done.stderr.strip()}")


def seconds(lpd, cloud, output):
    """Wall seconds of one default run of `lpd` on `cloud`."""
    command = [str(lpd), "denoise", str(cloud), "-o", str(output), "--overwrite", "--quiet"]
    start = time.perf_counter()
    done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    elapsed = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"time_against_build: `{' '.join(command)}` failed: {done.stderr.strip()}")
    return elapsed


def print_table(shapes, columns, times, bound):
    print("| shape | " + " | ".join(label for label, _ in columns) + " |")
    print("|---" * (len(columns) + 1) + "|")
    ratios = {column: [] for _, column in columns}
    for shape in shapes:
        cells = []
        for _, column in columns:
            reference, ours = times[(shape, column)]
            ratio = ours / reference
            ratios[column].append(ratio)
            cell = f"{reference:.2f} -> {ours:.2f} ({ratio:.2f}x)"
            cells.append(f"**{cell}**" if ratio > bound else cell)
        print(f"| {shape} | " + " | ".join(cells) + " |")
    print("| mean ratio | " + " | ".join(
        f"{sum(r) / len(r):.2f}x" for r in ratios.values()) + " |")
    print("| max ratio | " + " | ".join(f"{max(r):.2f}x" for r in ratios.values()) + " |")
    for size in sorted({column[0] for _, column in columns}):
        reference = sum(t[0] for (_, column), t in times.items() if column[0] == size)
        ours = sum(t[1] for (_, column), t in times.items() if column[0] == size)
        print(f"\n{size // 1000}K in all: {reference:.1f} -> {ours:.1f} s "
              f"({ours / reference:.2f}x)", end="")
    over = sum(1 for r in ratios.values() for x in r if x > bound)
    print(f"; {over} of {len(times)} cells over {bound}x")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--reference", required=True, type=pathlib.Path,
                        help="the other build's lpd program")
    parser.add_argument("--lpd", type=pathlib.Path, default=ROOT / "build" / "lpd")
    parser.add_argument("--repeats", type=int, default=2)
    parser.add_argument("--sizes", type=int, nargs="+", default=[10000, 50000])
    parser.add_argument("--sigmas", type=float, nargs="+", default=[0.01, 0.02, 0.03])
    parser.add_argument("--meshes", nargs="+")
    parser.add_argument("--no-thin", action="store_true")
    parser.add_argument("--bound", type=float, default=1.5)
    parser.add_argument("--work", type=pathlib.Path,
                        help="where the draws go and are reused (default: a new temporary "
                             "directory)")
    args = parser.parse_args()
    for program in (args.reference, args.lpd):
        if not program.is_file():
            sys.exit(f"time_against_build: no such program: {program}")
    if args.repeats < 1:
        sys.exit("time_against_build: --repeats must be at least 1")
    meshes = expand(args.meshes) if args.meshes else default_meshes()
    sources = [(mesh.stem, ("mesh", mesh)) for mesh in meshes]
    if not args.no_thin:
        sources += [(name, ("shape", shape)) for name, shape in THIN_SHAPES]
    if not sources:
        sys.exit("time_against_build: no meshes found (set LPD_DATA or give --meshes)")
    work = args.work or pathlib.Path(tempfile.mkdtemp(prefix="lpd_timing_"))
    work.mkdir(parents=True, exist_ok=True)
    columns = [(f"{size // 1000}K {100 * sigma:g}%", (size, sigma))
               for size in args.sizes for sigma in args.sigmas]
    times = {}
    for name, source in sources:
        for _, (size, sigma) in columns:
            cloud = work / f"{name}_{size}_{sigma}.ply"
            draw(args.lpd, source, size, sigma, cloud)
            best = [float("inf"), float("inf")]
            for _ in range(args.repeats):
                for b, program in enumerate((args.reference, args.lpd)):
                    best[b] = min(best[b], seconds(program, cloud, work / f"out{b}.ply"))
            times[(name, (size, sigma))] = tuple(best)
            print(f"{name} {size} {sigma}: {best[0]:.2f} -> {best[1]:.2f} s",
                  file=sys.stderr, flush=True)
    print_table([name for name, _ in sources], columns, times, args.bound)


if __name__ == "__main__":
    main()
